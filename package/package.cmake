# Installing and packaging (make package BOARD=...): the binary, the
# board's default configuration, a systemd unit and the docs, as a .deb.
# A board whose camera is libcamera gets V4L2 in a build without the
# libcamera backend (a cross build: Raspberry Pi OS's libcamera is not
# Debian's, so build on the board for the Pi camera), and says so.
set(RL_CALIB_NOTE "")
if(RL_BOARD_CAMERA STREQUAL "libcamera" AND NOT LIBCAMERA_FOUND)
  set(RL_BOARD_CAMERA v4l2)
  set(RL_BOARD_CAMERA_DEVICE /dev/video0)
  set(RL_CALIB_NOTE "# This build has no libcamera backend (built without libcamera-dev, e.g.\n# cross-built): a USB camera over V4L2. For the Raspberry Pi camera, build\n# on the Pi: make package BOARD=${RL_BOARD}\n")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/ringloc.yaml.in ${CMAKE_BINARY_DIR}/package/ringloc.yaml @ONLY)
# the unit waits for the serial device: /dev/serial0 -> dev-serial0.device
string(REGEX REPLACE "^/" "" RL_SERIAL_UNIT "${RL_BOARD_SERIAL}")
string(REPLACE "/" "-" RL_SERIAL_UNIT "${RL_SERIAL_UNIT}")
set(RL_SERIAL_UNIT "${RL_SERIAL_UNIT}.device")
configure_file(${CMAKE_CURRENT_LIST_DIR}/ringloc.service.in ${CMAKE_BINARY_DIR}/package/ringloc.service @ONLY)

# Two packages: `ringloc`, what the robot's computer runs (ringloc-fw, its
# configuration and unit: libpng and libyaml only), and `ringloc-tools`,
# the desktop command line (gen, plan, detect, locate, monitor: cairo too).
install(TARGETS ringloc-fw RUNTIME DESTINATION bin COMPONENT firmware)
install(FILES ${CMAKE_BINARY_DIR}/package/ringloc.yaml DESTINATION /etc/ringloc COMPONENT firmware)
install(FILES ${CMAKE_BINARY_DIR}/package/ringloc.service DESTINATION /lib/systemd/system
        COMPONENT firmware)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION share/doc/ringloc COMPONENT firmware)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION share/doc/ringloc/docs COMPONENT firmware
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
# the web view's drop-in for the unit (network for http:), copied by hand
install(FILES ${PROJECT_SOURCE_DIR}/package/ringloc-web.conf DESTINATION share/doc/ringloc COMPONENT firmware)
install(TARGETS ringloc RUNTIME DESTINATION bin COMPONENT tools)
# the modules loaded on first use (hal/rl_module.h), in /usr/lib/ringloc
# (../lib/ringloc from the programs' /usr/bin): the camera's with the
# robot's package, the survey's with the tools
if(TARGET ringloc-libcamera)
  install(TARGETS ringloc-libcamera LIBRARY DESTINATION lib/ringloc COMPONENT firmware)
endif()
if(TARGET ringloc-ceres)
  install(TARGETS ringloc-ceres LIBRARY DESTINATION lib/ringloc COMPONENT tools)
endif()

# `ringloc-fuse`, what a controller computer installs to build against
# rl_fuse (issue 27): the library, static and shared, its three headers
# under include/ringloc, ringloc-fuse.pc, and the ARIA example's source.
configure_file(${CMAKE_CURRENT_LIST_DIR}/ringloc-fuse.pc.in ${CMAKE_BINARY_DIR}/package/ringloc-fuse.pc @ONLY)
install(TARGETS ringloc_fuse ringloc_fuse_shared
        ARCHIVE DESTINATION lib COMPONENT fuse
        LIBRARY DESTINATION lib COMPONENT fuse NAMELINK_COMPONENT fuse)
install(FILES ${PROJECT_SOURCE_DIR}/firmware/include/rl_fuse.h ${PROJECT_SOURCE_DIR}/firmware/include/rl_packet.h
        ${PROJECT_SOURCE_DIR}/firmware/include/rl_error.h DESTINATION include/ringloc COMPONENT fuse)
install(FILES ${CMAKE_BINARY_DIR}/package/ringloc-fuse.pc DESTINATION lib/pkgconfig COMPONENT fuse)
# the ARIA example and the project's whole-or-nothing file writer it logs through
install(FILES ${PROJECT_SOURCE_DIR}/tools/aria/ringloc_aria_fuse.cpp ${PROJECT_SOURCE_DIR}/hal/io/rl_outfile.c
        ${PROJECT_SOURCE_DIR}/hal/io/rl_outfile.h DESTINATION share/doc/ringloc-fuse/examples COMPONENT fuse)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ringloc)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL firmware tools fuse)
set(CPACK_DEBIAN_FIRMWARE_PACKAGE_NAME ringloc)
set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME ringloc-tools)
set(CPACK_DEBIAN_FUSE_PACKAGE_NAME ringloc-fuse)
set(CPACK_DEBIAN_FUSE_PACKAGE_DEPENDS "libc6 (>= 2.34)")
set(CPACK_DEBIAN_FUSE_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_FUSE_DESCRIPTION "ringloc on the robot's controller: rl_fuse, odometry fused with ringloc's pose frames (library, headers, pkg-config, ARIA example)")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_CONTACT "ringloc developers <ringloc@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "robot self-localization from ring-coded ceiling landmarks")
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${RL_DEB_ARCH})
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
# the shared libraries each binary links (Debian bookworm / Raspberry Pi OS names)
set(RL_FW_DEPENDS "libc6 (>= 2.34), libpng16-16, libyaml-0-2, libturbojpeg0, passwd")
if(LIBCAMERA_FOUND)
  string(APPEND RL_FW_DEPENDS ", libstdc++6, libcamera0.0.3 | libcamera0.2 | libcamera0.3")
endif()
if(MHD_FOUND) # the web view (--http)
  string(APPEND RL_FW_DEPENDS ", libmicrohttpd12")
endif()
set(CPACK_DEBIAN_FIRMWARE_PACKAGE_DEPENDS "${RL_FW_DEPENDS}")
set(RL_TOOLS_DEPENDS "libc6 (>= 2.34), libpng16-16, libyaml-0-2, libcairo2, libturbojpeg0")
if(MHD_FOUND) # `ringloc run --http`
  string(APPEND RL_TOOLS_DEPENDS ", libmicrohttpd12")
endif()
if(TARGET ringloc_survey) # a desktop build: `ringloc survey` (json-c) and its solver's module (Ceres
  # Solver, linked in whole; the libraries it links: glog, SuiteSparse, ATLAS)
  string(APPEND RL_TOOLS_DEPENDS ", libjson-c5, libstdc++6, libgoogle-glog0v6, libspqr2, libcholmod3, libcxsparse3,"
         " libatlas3-base")
endif()
set(CPACK_DEBIAN_TOOLS_PACKAGE_DEPENDS "${RL_TOOLS_DEPENDS}")
set(CPACK_DEBIAN_FIRMWARE_DESCRIPTION "robot self-localization from ring-coded ceiling landmarks (firmware)")
set(CPACK_DEBIAN_TOOLS_DESCRIPTION "ringloc desktop tools: print, plan, detect, locate, survey, monitor")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_FIRMWARE_PACKAGE_CONTROL_EXTRA
    "${CMAKE_CURRENT_LIST_DIR}/postinst;${CMAKE_CURRENT_LIST_DIR}/conffiles")
include(CPack)
