#!/usr/bin/env bash
# Installs what Puddle needs to build, run and test, from Debian 12 / Raspberry Pi OS (bookworm)
# packages. Safe to run again. Uses sudo when not root.
set -euo pipefail

packages=(
    build-essential cmake ninja-build pkg-config
    libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri   # EGL + GLES 3, Mesa (llvmpipe when there is no GPU)
    libgbm-dev libdrm-dev                                 # the kms backend
    libx11-dev                                            # the window backend
    libglm-dev libtomlplusplus-dev libcli11-dev libspdlog-dev libfmt-dev
    libopenimageio-dev                                    # reading images (libpuddle-images.so)
    libpng-dev                                            # writing the screenshot PNG
    libgpiod-dev libv4l-dev libjpeg-dev                   # knobs and camera
    libmosquitto-dev nlohmann-json3-dev                   # remote control over MQTT (libmosquitto1 at run time)
    mosquitto mosquitto-clients openssl                   # the remote tests: a real broker, clients, a test CA
    libgtest-dev libgmock-dev libbenchmark-dev            # tests and puddle-bench
    xvfb xauth                                            # the window backend's test runs under Xvfb
    dpkg-dev systemd                                      # the .deb (cpack, dpkg-shlibdeps); unit checks
    clang libclang-rt-14-dev                              # tests/fuzz/run: libFuzzer and the sanitizers
    clang-format                                          # tests/format/run: the checked-in .clang-format
    shellcheck                                            # tests/format/shellcheck (ctest shellcheck): the shell scripts
)
# The VM test (tests/vm/run) boots an amd64 Debian kernel under QEMU and runs the host's binary in it.
if [ "$(dpkg --print-architecture)" = amd64 ]; then
    packages+=(qemu-system-x86 busybox-static cpio kmod v4l-utils)
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: run as root or install sudo" >&2; exit 1; }
    sudo="sudo"
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#packages[@]} packages already installed"
    exit 0
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
