# Thin wrapper around CMake. Every target checks dependencies first
# (tools/deps.sh installs them as root, or prints the apt-get line).
#
#   make host            build the host binaries into build/
#   make host-test       build and run every test (CTest)
#   make host-test-asan  the same tests under AddressSanitizer + UBSan (build-asan/)
#   make bench           recognition benchmarks (figures, not pass/fail)
#   make clean

BUILD      ?= build
BUILD_ASAN ?= build-asan
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=

.PHONY: all deps host host-test host-test-asan bench clean

all: host

deps:
	@sh tools/deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CMAKE_ARGS)

host: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

host-test: host
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

$(BUILD_ASAN)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD_ASAN) -DCMAKE_BUILD_TYPE=Debug -DRL_SANITIZE=ON $(CMAKE_ARGS)

host-test-asan: deps $(BUILD_ASAN)/CMakeCache.txt
	cmake --build $(BUILD_ASAN) -j $(JOBS)
	cd $(BUILD_ASAN) && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD) $(BUILD_ASAN)
