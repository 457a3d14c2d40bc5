# Thin wrapper around CMake. Every target checks dependencies first
# (tools/deps.sh installs them as root, or prints the apt-get line).
#
#   make host            build the host binaries into build/
#   make host-test       build and run every test (CTest)
#   make host-test-asan  the same tests built with clang under AddressSanitizer + UBSan (build-asan/),
#                        with the plain-C matcher (RL_NO_VECTOR_EXT) instead of the vector one;
#                        its fixtures rendered by the renderer's code uninstrumented at -O2 (the
#                        same bytes), the instrumented renderer checked against it (render_checked)
#   make host-test-asan-vector  the unit tests that run the core's vector paths (the
#                        labeller's run bounds, the gathers and their AVX2 clones, the polar
#                        scan, rl_ray, the matcher's kernels), built with
#                        GCC under AddressSanitizer + UBSan with the vectors on
#                        (build-asan-vec/): host-test-asan runs the plain C instead
#   make demo            the firmware on a bundled drive: poses over a pty, report
#   make bench           recognition, pose, place and survey benchmarks (figures, not pass/fail),
#                        with the time of each stage of the recognizer (docs/design.md) and
#                        tracked frames beside full ones (docs/tracking.md)
#   make bench-real REAL=DIR  ringloc and AprilTag 3 on real photos with landmarks placed in them
#   make fuzz [FUZZ_SECONDS=60]  libFuzzer (clang, ASan + UBSan) on the recognizer, the PNG
#                        reader, the YAML loaders, the pose solver, the frame decoder,
#                        the survey's JSON-lines input and first map, the web view's
#                        request handling and status JSON;
#                        MSan on those without libpng and libyaml
#   make soak [SOAK_FRAMES=200000]  the firmware's loop for a long run, its serial line
#                        vanishing every few seconds: heap calls, RSS, frames after reopening
#   make sim ARIA_DIR=DIR AMRISIM=DIR [SIM_RUNS="clean disturbed"]  ringloc steering AMRISim's
#                        simulated Pioneer 3-DX round a route on its fused pose, judged against
#                        the simulator's truth (docs/sim.md; not in CI: AriaCoda and AMRISim are
#                        built outside this tree, and it says how when they are missing)
#   make cross BOARD=rpi4                 cross build for a board, tests under qemu
#   make package BOARD=rpi4               the board's .deb (build-rpi4/package/)
#   make flash BOARD=rpi4 TARGET=pi@robot [DRY_RUN=1]  install it over ssh
#   make clean

BUILD      ?= build
BUILD_ASAN ?= build-asan
BUILD_ASAN_VEC ?= build-asan-vec
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_ARGS ?=
# CMake's generator for a build folder it has not configured yet: Ninja where
# it is installed (Debian's ninja-build, which tools/deps.sh installs as root;
# the host build in two thirds of the
# Makefiles' wall time, docs/results.md "CI's time"), else CMake's default. A
# folder already configured keeps its generator (CMake refuses to change it),
# and a CMAKE_GENERATOR in the environment is CMake's to use.
# Shell code, run when the recipe's line runs: $(call GEN,DIR)
GEN = $$([ -n "$$CMAKE_GENERATOR" ] || [ -f "$(1)/CMakeCache.txt" ] || ! command -v ninja >/dev/null 2>&1 || echo -G Ninja)

.PHONY: all deps host host-test host-test-asan host-test-asan-vector bench bench-real demo fuzz soak sim clean

# `make sim` (issue 42, tools/sim/sim.sh): one run per word of SIM_RUNS, into
# SIM_DIR/WORD: clean (the route as it is), disturbed (ringloc's frames cut
# for 3 s in the middle, the robot pushed aside). The ARIA example is built
# where the build folder is configured with ARIA_DIR.
SIM_DIR  ?= $(BUILD)/sim
SIM_RUNS ?= clean disturbed
AMRISIM  ?=
ARIA_DIR ?=

sim: deps
	@if [ -n "$(ARIA_DIR)" ]; then cmake -S . -B $(BUILD) $(call GEN,$(BUILD)) -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DARIA_DIR=$(abspath $(ARIA_DIR)) $(CMAKE_ARGS) > /dev/null; \
	  else $(MAKE) --no-print-directory $(BUILD)/CMakeCache.txt; fi
	cmake --build $(BUILD) -j $(JOBS) --target ringloc ringloc-render ringloc-fw ringloc-sim-line ringloc-sim-report
	@if grep -q '^ARIA_LIBRARY:FILEPATH=.*Aria' $(BUILD)/CMakeCache.txt; then \
	  cmake --build $(BUILD) -j $(JOBS) --target ringloc-aria-fuse; fi
	@rc=0; for run in $(SIM_RUNS); do \
	  case $$run in clean) a= ;; disturbed) a="--cut --push" ;; \
	  *) echo "make sim: SIM_RUNS: '$$run' is neither clean nor disturbed" >&2; exit 2 ;; esac; \
	  echo "make sim: the $$run run, into $(SIM_DIR)/$$run"; \
	  AMRISIM=$(if $(AMRISIM),$(abspath $(AMRISIM))) sh tools/sim/sim.sh $(BUILD) $(SIM_DIR)/$$run $$a; \
	  r=$$?; [ $$r = 2 ] && exit 2; [ $$r = 0 ] || rc=$$r; \
	done; exit $$rc

SOAK_FRAMES ?= 200000
SOAK_DIR    ?= $(BUILD)/soak

soak: host
	@[ -f $(SOAK_DIR)/map.yaml ] || $(BUILD)/tools/ringloc-render --out $(SOAK_DIR) --path rect \
	  --frames 16 --mount 0.12,-0.03,0.02 --write-map $(SOAK_DIR)/map.yaml \
	  --write-camera $(SOAK_DIR)/camera.yaml --write-robot $(SOAK_DIR)/robot.yaml
	$(BUILD)/tools/ringloc-soak --frames $(SOAK_FRAMES) --reopen-every 3 $(SOAK_DIR)

# Fuzzing: each target FUZZ_SECONDS under ASan + UBSan, and the targets
# without libpng and libyaml under MSan too, JOBS at a time
# (tools/fuzz.sh); a crash stops the run and leaves its input beside the
# target as crash-NAME-*. Each tree builds its targets and what they link,
# not the firmware's programs and libraries they do not use.
BUILD_FUZZ        ?= build-fuzz
BUILD_FUZZ_MSAN   ?= build-fuzz-msan
FUZZ_SECONDS      ?= 60
FUZZ_TARGETS      ?= recog png yaml pose packet survey place http
FUZZ_MSAN_TARGETS ?= recog pose packet place http

fuzz:
	@sh tools/deps.sh fuzz
	cmake -S . -B $(BUILD_FUZZ) $(call GEN,$(BUILD_FUZZ)) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DRL_FUZZ=ON -DCMAKE_BUILD_TYPE=Debug $(CMAKE_ARGS)
	cmake --build $(BUILD_FUZZ) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_TARGETS))
	cmake -S . -B $(BUILD_FUZZ_MSAN) $(call GEN,$(BUILD_FUZZ_MSAN)) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DRL_FUZZ=ON -DRL_FUZZ_SANITIZE=memory -DCMAKE_BUILD_TYPE=Debug $(CMAKE_ARGS)
	cmake --build $(BUILD_FUZZ_MSAN) -j $(JOBS) --target $(addprefix fuzz_,$(FUZZ_MSAN_TARGETS))
	sh tools/fuzz.sh $(FUZZ_SECONDS) $(JOBS) $(foreach t,$(FUZZ_TARGETS),$(BUILD_FUZZ):$(t)) \
	  $(foreach t,$(FUZZ_MSAN_TARGETS),$(BUILD_FUZZ_MSAN):$(t))

# Boards (boards/<name>): cross build, tests under qemu, package, install.
BOARD       ?= rpi4
BUILD_BOARD ?= build-$(BOARD)
TARGET      ?=

.PHONY: cross package flash

cross:
	@sh tools/deps.sh $(if $(filter host,$(BOARD)),host,cross)
	cmake -S . -B $(BUILD_BOARD) $(call GEN,$(BUILD_BOARD)) -DCMAKE_TOOLCHAIN_FILE=$(CURDIR)/boards/$(BOARD)/toolchain.cmake \
	  -DRL_BOARD=$(BOARD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)
	cmake --build $(BUILD_BOARD) -j $(JOBS)
	cd $(BUILD_BOARD) && ctest --output-on-failure -j $(JOBS)

package: cross
	cd $(BUILD_BOARD) && cpack -G DEB -B package
	@ls $(BUILD_BOARD)/package/*.deb

flash: package
	sh tools/flash.sh $(if $(DRY_RUN),--dry-run) $(TARGET) $(BUILD_BOARD)/package/ringloc_*.deb

# Benchmark frames: rendered once per size (AprilTag twins included).
BENCH_FRAMES ?= 20
BENCH_DIR    ?= $(BUILD)/bench

all: host

deps:
	@sh tools/deps.sh

$(BUILD)/CMakeCache.txt: | deps
	cmake -S . -B $(BUILD) $(call GEN,$(BUILD)) -DCMAKE_BUILD_TYPE=RelWithDebInfo $(CMAKE_ARGS)

host: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

host-test: host
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

host-test-asan:
	@sh tools/deps.sh asan
	@if [ -f $(BUILD_ASAN)/CMakeCache.txt ] && ! grep -q '^CMAKE_C_COMPILER:.*clang' $(BUILD_ASAN)/CMakeCache.txt; then \
	  echo "host-test-asan: $(BUILD_ASAN) was configured for another compiler; starting it afresh with clang"; \
	  rm -rf $(BUILD_ASAN); fi
	cmake -S . -B $(BUILD_ASAN) $(call GEN,$(BUILD_ASAN)) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_BUILD_TYPE=Debug -DRL_SANITIZE=ON -DRL_NO_VECTOR_EXT=ON -DRL_FIXTURE_COUNT=12 $(CMAKE_ARGS)
	cmake --build $(BUILD_ASAN) -j $(JOBS)
	cd $(BUILD_ASAN) && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp ctest --output-on-failure -j $(JOBS)

# host-test-asan builds with RL_NO_VECTOR_EXT (the plain-C matcher: CI runs
# each matcher's suite once), which also turns off every other vector path
# of the core, and with clang, which has no AVX2 clones (rl_clones.h): none
# of them ran under a sanitizer (twelfth session). This build keeps them on,
# with GCC (its target_clones: the AVX2 clones run where the processor has
# AVX2), and builds and runs only the unit tests that reach them: odd
# widths, strides wider than the width and buffers that end at the last
# pixel (the vectors' tails) are theirs. The bad inputs through `ringloc`
# (options, files, YAML) reach no vector path and run in host-test-asan.
ASAN_VEC_TESTS ?= test_polar test_polar_scan test_ray test_refine test_label_bounds test_label_chunks \
                  test_match test_profile test_recog test_oracles
ASAN_VEC_NONE  :=
ASAN_VEC_RUN   ?= ^($(subst $(ASAN_VEC_NONE) ,|,$(strip $(ASAN_VEC_TESTS))))$$

host-test-asan-vector:
	@sh tools/deps.sh asan
	@if [ -f $(BUILD_ASAN_VEC)/CMakeCache.txt ] && ! grep -q '^CMAKE_C_COMPILER:.*gcc' $(BUILD_ASAN_VEC)/CMakeCache.txt; then \
	  echo "host-test-asan-vector: $(BUILD_ASAN_VEC) was configured for another compiler; starting it afresh with gcc"; \
	  rm -rf $(BUILD_ASAN_VEC); fi
	cmake -S . -B $(BUILD_ASAN_VEC) $(call GEN,$(BUILD_ASAN_VEC)) -DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ \
	  -DCMAKE_BUILD_TYPE=Debug -DRL_SANITIZE=ON -DRL_NO_VECTOR_EXT=OFF -DRL_FIXTURE_COUNT=12 $(CMAKE_ARGS)
	cmake --build $(BUILD_ASAN_VEC) -j $(JOBS) --target $(ASAN_VEC_TESTS)
	cd $(BUILD_ASAN_VEC) && LSAN_OPTIONS=suppressions=$(CURDIR)/tests/lsan.supp \
	  ctest --output-on-failure -j $(JOBS) -R '$(ASAN_VEC_RUN)'

demo: host
	sh tools/demo.sh

bench: host
	@for size in 640x480 1280x960; do \
	  [ -f $(BENCH_DIR)/$$size/cluttered_000_tag.png ] || \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/$$size --set cluttered \
	    --count $(BENCH_FRAMES) --seed 3 --size $$size --twin || exit 1; \
	done
	@[ -f $(BENCH_DIR)/moving/moving_000_tag.png ] || \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/moving --set moving --count $(BENCH_FRAMES) --seed 7 \
	    --rock 0.03 --twin
	@[ -f $(BENCH_DIR)/glare/glare_000.png ] || \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/glare --set glare --count $(BENCH_FRAMES) --seed 3
	@[ -f $(BENCH_DIR)/drive/circle_007.png ] || { \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/drive --path straight --frames 8 --rock 0.03 \
	    --mount 0.12,-0.03,0.02 --write-map $(BENCH_DIR)/drive/map.yaml \
	    --write-camera $(BENCH_DIR)/drive/camera.yaml --write-robot $(BENCH_DIR)/drive/robot.yaml && \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/drive --path rect --frames 8 --rock 0.03 --mount 0.12,-0.03,0.02 && \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/drive --path circle --frames 8 --rock 0.03 --mount 0.12,-0.03,0.02; }
	@# the demo's drive (tools/demo.sh: 15/20/20 frames a path, its mount and rocking), which a
	@# robot's speeds can track; `drive` above (8 frames a path) moves 0.34-0.75 m a frame
	@[ -f $(BENCH_DIR)/demodrive/complete ] || { rm -rf $(BENCH_DIR)/demodrive && sh tools/demo_drive.sh $(BUILD)/tools/ringloc-render \
	  $(BENCH_DIR)/demodrive && cp $(BENCH_DIR)/demodrive/robot_true.yaml $(BENCH_DIR)/demodrive/robot.yaml; }
	@[ -f $(BENCH_DIR)/site/random_099.png ] || { mkdir -p $(BENCH_DIR)/site && \
	  $(BUILD)/tools/ringloc-render --write-camera $(BENCH_DIR)/site/camera.yaml \
	    --write-robot $(BENCH_DIR)/site/robot.yaml --mount 0.12,-0.03,0.02 && \
	  $(BUILD)/host/ringloc plan --area 60x40 --pitch 0.61 --camera $(BENCH_DIR)/site/camera.yaml \
	    --ceiling-height 2.75 --camera-height 0.88 --map-out $(BENCH_DIR)/site/map.yaml >$(BENCH_DIR)/site/plan.json && \
	  $(BUILD)/tools/ringloc-render --site-map $(BENCH_DIR)/site/map.yaml --out $(BENCH_DIR)/site --path random \
	    --frames 100 --seed 9 --mount 0.12,-0.03,0.02; }
	@[ -f $(BENCH_DIR)/track/circle_059.png ] || { \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/track --path rect --frames 60 --rock 0.03 \
	    --mount 0.12,-0.03,0.02 --write-map $(BENCH_DIR)/track/map.yaml \
	    --write-camera $(BENCH_DIR)/track/camera.yaml --write-robot $(BENCH_DIR)/track/robot.yaml && \
	  $(BUILD)/tools/ringloc-render --out $(BENCH_DIR)/track --path circle --frames 60 --rock 0.03 \
	    --mount 0.12,-0.03,0.02 --look moving; }
	@[ -f $(BENCH_DIR)/site/corner_143.png ] || \
	  $(BUILD)/tools/ringloc-render --site-map $(BENCH_DIR)/site/map.yaml --out $(BENCH_DIR)/site --path corner \
	    --frames 144 --seed 4 --mount 0.12,-0.03,0.02
	$(BUILD)/tools/ringloc-bench $(BENCH_DIR)/640x480 $(BENCH_DIR)/1280x960 $(BENCH_DIR)/moving \
	  --local $(BENCH_DIR)/glare \
	  --pose $(BENCH_DIR)/drive --site $(BENCH_DIR)/site \
	  --track $(BENCH_DIR)/demodrive: --track $(BENCH_DIR)/drive: --track $(BENCH_DIR)/track:rect_ --track $(BENCH_DIR)/track:circle_ \
	  --track $(BENCH_DIR)/site:corner_
	@[ -f $(BENCH_DIR)/survey/detect.jsonl ] || \
	  $(BUILD)/tools/ringloc-survey-synth --camera $(BENCH_DIR)/drive/camera.yaml --out $(BENCH_DIR)/survey
	@echo "survey: 2,000 landmarks (ring6, ids repeating) from 20,000 frames of detect JSON lines, one thread:"
	OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 $(BUILD)/host/ringloc survey --family ring6 \
	  --camera $(BENCH_DIR)/survey/camera.yaml --robot $(BENCH_DIR)/survey/robot.yaml --origin 61 --axis 62 \
	  --out $(BENCH_DIR)/survey/survey.yaml $(BENCH_DIR)/survey/detect.jsonl 2>/dev/null
	@echo "survey against the site's truth:"
	@$(BUILD)/tools/ringloc-survey-synth --compare $(BENCH_DIR)/survey/map_true.yaml $(BENCH_DIR)/survey/survey.yaml

# Real ceiling photos (PNG, never committed: their path on the command
# line) with ring landmarks and AprilTag twins placed in them.
REAL ?=
bench-real: host
	@[ -n "$(REAL)" ] || { echo "bench-real: give the photos' folder: make bench-real REAL=DIR (PNG files)" >&2; exit 2; }
	@[ -d "$(REAL)" ] || { echo "bench-real: $(REAL): no such folder" >&2; exit 2; }
	$(BUILD)/tools/ringloc-bench --real $(REAL)

clean:
	rm -rf $(BUILD) $(BUILD_ASAN) $(BUILD_ASAN_VEC) $(BUILD_FUZZ) $(BUILD_FUZZ_MSAN)
