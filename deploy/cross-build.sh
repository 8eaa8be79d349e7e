#!/usr/bin/env bash
# Cross-compiles Puddle for a Raspberry Pi 4/5 (aarch64, Raspberry Pi OS bookworm) on a Debian 12
# amd64 machine, into build-aarch64/. With --test it then runs the unit tests under qemu-user.
# Safe to run again: it installs and unpacks only what is missing. Uses sudo when not root.
#
# The libraries are Debian 12's arm64 packages, the same ones setup.sh lists, but unpacked into a
# sysroot (build-aarch64-sysroot/) rather than installed as multiarch :arm64 packages: on bookworm
# libopenimageio-dev:arm64 cannot sit beside the amd64 one (it needs OpenCV, which needs GDAL, whose
# gdal-plugins is not Multi-Arch: same), so apt would remove the native OpenImageIO. apt still picks
# the packages: it resolves them for arm64 against an empty package database and only downloads.
set -euo pipefail
cd "$(dirname "$0")/.."

build=build-aarch64
sysroot=${PUDDLE_SYSROOT:-$PWD/build-aarch64-sysroot}
run_tests=0
case "${1:-}" in
    --test) run_tests=1 ;;
    "") ;;
    *) echo "usage: deploy/cross-build.sh [--test]" >&2; exit 2 ;;
esac

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "cross-build: run as root or install sudo" >&2; exit 1; }
    sudo="sudo"
fi
apt_get=(apt-get -o DPkg::Lock::Timeout=300)

# --- the build machine: cross compiler, build tools, qemu-user; arm64 package lists for apt --------
host_packages=(crossbuild-essential-arm64 cmake ninja-build pkg-config qemu-user-static)
updated=0
if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    echo "cross-build: dpkg --add-architecture arm64"
    $sudo dpkg --add-architecture arm64
    $sudo "${apt_get[@]}" update -qq
    updated=1
fi
missing=()
for p in "${host_packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "cross-build: installing ${missing[*]}"
    [ $updated -eq 1 ] || $sudo "${apt_get[@]}" update -qq
    updated=1
    DEBIAN_FRONTEND=noninteractive $sudo "${apt_get[@]}" install -y -qq --no-install-recommends "${missing[@]}"
fi

# --- the sysroot: the -dev packages of setup.sh, for arm64, and everything they depend on ----------
# Every -dev package but the build machine's own tools (dpkg-dev for cpack, clang's sanitizer runtime).
mapfile -t target_packages < <(sed -n '/^packages=(/,/^)/p' deploy/setup.sh | sed 's/#.*//' |
    tr -s ' \t' '\n' | grep -E -- '-dev$' | grep -v -x -E 'dpkg-dev|libclang-rt-[0-9]+-dev')
target_packages+=(libc6-dev libstdc++-12-dev)

apt_arm64=(apt-get -o Debug::NoLocking=1 -o Dir::State::status="$sysroot.apt/status"
    -o Dir::Cache::archives="$sysroot.apt/archives" -o APT::Architecture=arm64
    -o APT::Architectures::=arm64 -o APT::Install-Recommends=0)
mkdir -p "$sysroot.apt/archives/partial"
: > "$sysroot.apt/status"
resolve() { "${apt_arm64[@]}" install -s "${target_packages[@]}" 2>&1 | sed -n 's/^Inst \([^ ]*\) (\([^ ]*\) .*/\1 \2/p' | sort; }
if ! wanted=$(resolve) || [ -z "$wanted" ]; then
    # No arm64 package lists yet (or stale ones): fetch them once and try again.
    [ $updated -eq 1 ] || $sudo "${apt_get[@]}" update -qq
    wanted=$(resolve)
fi
[ -n "$wanted" ] || { echo "cross-build: apt cannot resolve ${target_packages[*]} for arm64" >&2; exit 1; }

if [ -f "$sysroot/.puddle-packages" ] && [ "$(cat "$sysroot/.puddle-packages")" = "$wanted" ]; then
    echo "cross-build: sysroot $sysroot is up to date ($(wc -l <<<"$wanted") packages)"
else
    echo "cross-build: unpacking $(wc -l <<<"$wanted") arm64 packages into $sysroot"
    if [ -n "$(ls -A "$sysroot" 2>/dev/null)" ] && [ ! -e "$sysroot/.puddle-sysroot" ]; then
        echo "cross-build: $sysroot is not empty and was not made by this script; not replacing it" >&2
        exit 1
    fi
    "${apt_arm64[@]}" install -d -y -qq "${target_packages[@]}"
    rm -rf "$sysroot"
    mkdir -p "$sysroot"
    touch "$sysroot/.puddle-sysroot"
    while read -r name version; do
        deb="$sysroot.apt/archives/${name}_${version//:/%3a}_arm64.deb"
        [ -f "$deb" ] || deb="${deb%_arm64.deb}_all.deb"
        [ -f "$deb" ] || { echo "cross-build: $name $version was not downloaded" >&2; exit 1; }
        dpkg-deb -x "$deb" "$sysroot"
    done <<<"$wanted"
    # Absolute links (libm.so -> /lib/...) must point into the sysroot, not at the build machine.
    find "$sysroot" -type l -lname '/*' -print0 | while IFS= read -r -d '' link; do
        ln -sfn "$(realpath -ms --relative-to="$(dirname "$link")" "$sysroot$(readlink "$link")")" "$link"
    done
    # Links that maintainer scripts (update-alternatives) would have made.
    for alt in blas/libblas.so.3 lapack/liblapack.so.3; do
        if [ -e "$sysroot/usr/lib/aarch64-linux-gnu/$alt" ]; then
            ln -sfn "$alt" "$sysroot/usr/lib/aarch64-linux-gnu/$(basename "$alt")"
        fi
    done
    echo "$wanted" > "$sysroot/.puddle-packages"
fi

# --- configure, build, test -------------------------------------------------------------------------
cmake -S . -B "$build" -G Ninja -DCMAKE_TOOLCHAIN_FILE=deploy/toolchain-aarch64.cmake \
    -DPUDDLE_SYSROOT="$sysroot" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build"
file "$build/puddle" 2>/dev/null || true
if [ $run_tests -eq 1 ]; then
    ctest --test-dir "$build" -L unit --output-on-failure -j2
fi
