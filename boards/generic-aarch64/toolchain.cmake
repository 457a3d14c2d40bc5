# generic-aarch64: the common aarch64 cross toolchain.
include(${CMAKE_CURRENT_LIST_DIR}/../common/aarch64-linux-gnu.cmake)
