# CMake toolchain: cross-compile Puddle for a Raspberry Pi 4/5 running Raspberry Pi OS bookworm (arm64).
#
# The compiler is Debian's crossbuild-essential-arm64 (aarch64-linux-gnu-g++); headers, libraries,
# pkg-config files and CMake packages come from a sysroot of Debian 12 arm64 packages, which
# deploy/cross-build.sh unpacks (see there why it is a sysroot and not multiarch :arm64 packages).
#
#   cmake -S . -B build-aarch64 -G Ninja -DCMAKE_TOOLCHAIN_FILE=deploy/toolchain-aarch64.cmake
#
# PUDDLE_SYSROOT (cache variable or environment) overrides the default build-aarch64-sysroot/.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(PUDDLE_DEB_ARCH arm64)                 # the .deb's Architecture (CMakeLists.txt, CPack section)
set(PUDDLE_MULTIARCH aarch64-linux-gnu)    # where the sysroot's libraries lie

if(NOT PUDDLE_SYSROOT)
    if(DEFINED ENV{PUDDLE_SYSROOT})
        set(PUDDLE_SYSROOT "$ENV{PUDDLE_SYSROOT}")
    else()
        get_filename_component(PUDDLE_SYSROOT "${CMAKE_CURRENT_LIST_DIR}/../build-aarch64-sysroot" ABSOLUTE)
    endif()
endif()
set(PUDDLE_SYSROOT "${PUDDLE_SYSROOT}" CACHE PATH "arm64 sysroot (deploy/cross-build.sh makes it)")
if(NOT EXISTS "${PUDDLE_SYSROOT}/usr/lib/aarch64-linux-gnu/libc.so")
    message(FATAL_ERROR "toolchain-aarch64: no arm64 sysroot at ${PUDDLE_SYSROOT}: run deploy/cross-build.sh, "
        "or pass -DPUDDLE_SYSROOT=<dir>")
endif()
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES PUDDLE_SYSROOT)

set(CMAKE_SYSROOT "${PUDDLE_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)   # cmake, pkg-config and qemu are the build machine's
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)    # libraries, headers and packages only the Pi's
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config (EGL, GLES, GBM, DRM, X11, OpenImageIO, libgpiod) reads only the arm64 .pc files.
set(ENV{PKG_CONFIG_DIR} "")
set(ENV{PKG_CONFIG_PATH} "")
set(ENV{PKG_CONFIG_LIBDIR}
    "${PUDDLE_SYSROOT}/usr/lib/aarch64-linux-gnu/pkgconfig:${PUDDLE_SYSROOT}/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${PUDDLE_SYSROOT}")

# Tests run under qemu-user when it is installed. Discovery waits for ctest, so building never runs
# an arm64 binary and works without qemu.
find_program(PUDDLE_QEMU_AARCH64 NAMES qemu-aarch64-static qemu-aarch64)
if(PUDDLE_QEMU_AARCH64)
    set(CMAKE_CROSSCOMPILING_EMULATOR "${PUDDLE_QEMU_AARCH64};-L;${PUDDLE_SYSROOT}")
endif()
set(CMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE PRE_TEST)
