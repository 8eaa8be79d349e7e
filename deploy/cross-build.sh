#!/usr/bin/env bash
# Cross-compiles Puddle for a Raspberry Pi 4/5 (aarch64, Raspberry Pi OS bookworm) on a Debian 12
# amd64 machine, into build-aarch64/. With --test it then runs the unit tests under qemu-user, makes
# the arm64 .deb and installs it on an arm64 root (--test-deb: only the .deb part).
# Safe to run again: it installs and unpacks only what is missing. Uses sudo when not root.
#
# The libraries are Debian 12's arm64 packages, the same ones setup.sh lists, but unpacked into a
# sysroot (build-aarch64-sysroot/) rather than installed as multiarch :arm64 packages: on bookworm
# libopenimageio-dev:arm64 cannot sit beside the amd64 one (it needs OpenCV, which needs GDAL, whose
# gdal-plugins is not Multi-Arch: same), so apt would remove the native OpenImageIO. apt still picks
# the packages: it resolves them for arm64 against an empty package database and only downloads.
set -euo pipefail
cd "$(dirname "$0")/.."

build="build-aarch64"
sysroot=${PUDDLE_SYSROOT:-$PWD/build-aarch64-sysroot}
run_tests=0
case "${1:-}" in
    --test) run_tests=1 ;;      # the unit tests, then the .deb checks
    --test-deb) run_tests=2 ;;  # only the .deb checks (the unit tests take long under emulation)
    "") ;;
    *) echo "usage: deploy/cross-build.sh [--test | --test-deb]" >&2; exit 2 ;;
esac

sudo=""
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "cross-build: run as root or install sudo" >&2; exit 1; }
    sudo="sudo"
fi
apt_get=(apt-get -o DPkg::Lock::Timeout=300)

# --- the build machine: cross compiler, build tools, qemu-user; arm64 package lists for apt --------
host_packages=(crossbuild-essential-arm64 cmake ninja-build pkg-config qemu-user-static proot)
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

# The .deb of package $1 at version $2 in apt's download folder.
deb_file() {
    local deb="$sysroot.apt/archives/${1}_${2//:/%3a}_arm64.deb"
    [ -f "$deb" ] || deb="${deb%_arm64.deb}_all.deb"
    [ -f "$deb" ] || { echo "cross-build: $1 $2 was not downloaded to $sysroot.apt/archives" >&2; return 1; }
    echo "$deb"
}

# Unpacks the packages named on stdin ("name version" lines) into $1 and records them in a dpkg
# database there ($1/var/lib/dpkg) as installed, from their own control data: the status entry from
# the control file, info/<package>.list from what dpkg-deb unpacked, and the shlibs, symbols and other
# control files beside it. No maintainer script runs. The file lists name paths as seen from $2: ""
# for a root whose own dpkg reads them, $1 for the sysroot, where dpkg-query runs on this machine and
# gets the paths at which dpkg-shlibdeps found the libraries.
unpack_packages() {
    local root=$1 prefix=$2 db="$1/var/lib/dpkg" ctl name version deb info f
    mkdir -p "$db/info" "$db/updates" "$db/triggers"
    echo arm64 > "$db/arch"
    echo 1 > "$db/info/format"  # multiarch names: info/libc6:arm64.list, as dpkg writes them
    : > "$db/status"
    ctl=$(mktemp -d)
    while read -r name version; do
        deb=$(deb_file "$name" "$version") || { rm -rf "$ctl"; return 1; }
        rm -rf "${ctl:?}"/*
        dpkg-deb -e "$deb" "$ctl"
        info=$name
        grep -qx 'Multi-Arch: same' "$ctl/control" && info="$name:arm64"
        dpkg-deb -X "$deb" "$root" | sed -e 's|^\./$|/.|' -e 's|^\./|/|' -e 's|/$||' \
            -e "/^\/\.\$/!s|^|$prefix|" > "$db/info/$info.list"
        for f in "$ctl"/*; do
            [ "${f##*/}" = control ] || cp -p "$f" "$db/info/$info.${f##*/}"
        done
        { sed -e '/^[[:space:]]*$/d' -e '/^Package:/a Status: install ok installed' "$ctl/control"; echo; } \
            >> "$db/status"
    done
    rm -rf "$ctl"
    # Links that maintainer scripts (update-alternatives) would have made.
    for alt in blas/libblas.so.3 lapack/liblapack.so.3; do
        if [ -e "$root/usr/lib/aarch64-linux-gnu/$alt" ]; then
            ln -sfn "$alt" "$root/usr/lib/aarch64-linux-gnu/$(basename "$alt")"
        fi
    done
}

# The sysroot's dpkg database is what lets dpkg-shlibdeps (run by cpack) turn the libraries the arm64
# binary links into Depends: which package owns each library, and that package's shlibs/symbols file.
if [ -f "$sysroot/.puddle-packages" ] && [ "$(cat "$sysroot/.puddle-packages")" = "$wanted" ] &&
    [ -s "$sysroot/var/lib/dpkg/status" ]; then
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
    unpack_packages "$sysroot" "$sysroot" <<<"$wanted"
    # Absolute links (libm.so -> /lib/...) must point into the sysroot, not at the build machine.
    find "$sysroot" -type l -lname '/*' -print0 | while IFS= read -r -d '' link; do
        ln -sfn "$(realpath -ms --relative-to="$(dirname "$link")" "$sysroot$(readlink "$link")")" "$link"
    done
    echo "$wanted" > "$sysroot/.puddle-packages"
fi

# --- configure, build, test -------------------------------------------------------------------------
cmake -S . -B "$build" -G Ninja -DCMAKE_TOOLCHAIN_FILE=deploy/toolchain-aarch64.cmake \
    -DPUDDLE_SYSROOT="$sysroot" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build"
file "$build/puddle" 2>/dev/null || true
[ $run_tests -ne 0 ] || exit 0

set +e  # every check runs and says PASS or FAIL; the list of failures at the end sets the exit status
failed=()
if [ $run_tests -eq 1 ]; then
    ctest --test-dir "$build" -L unit --output-on-failure -j2 || failed+=("unit tests (ctest -L unit above)")
fi

# --- the .deb on an arm64 root: dpkg installs it, its scripts run, the binary starts ---------------
# The root (build-aarch64-root/, made afresh each run) holds what `apt install ./puddle_*.deb` brings
# on a board, Depends and Recommends, resolved by apt against Debian 12 arm64, plus dpkg and dash to
# install it and systemd for systemd-sysusers. Those are unpacked and recorded as installed like the
# sysroot (their own scripts do not run); puddle is then installed by the root's own arm64 dpkg, so its
# maintainer scripts run. proot runs dpkg and everything it starts under qemu-user, without the
# binfmt_misc registration that a chroot would need.
root=$PWD/build-aarch64-root
log=$(mktemp)
trap 'rm -f "$log"' EXIT
check() {  # check NAME COMMAND...: one PASS/FAIL line, the command's output only on failure
    if "${@:2}" >"$log" 2>&1; then
        echo "cross-build: PASS $1"
    else
        echo "cross-build: FAIL $1"
        tail -n 40 "$log" | sed 's/^/    /'
        failed+=("$1")
        return 1
    fi
}
on_root() {  # runs an arm64 command in the root, as root, with a clean environment
    proot -q qemu-aarch64-static -r "$root" -b /dev -b /proc -b /sys -w / \
        /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin LC_ALL=C.UTF-8 "$@"
}
make_deb() {
    rm -f "$build"/puddle_*.deb
    (cd "$build" && cpack -G DEB) || return 1
    deb=$(ls "$PWD/$build"/puddle_*_arm64.deb) && [ "$(dpkg-deb --field "$deb" Architecture)" = arm64 ]
}
# What dpkg checks for at start (sh, rm, tar, diff, ldconfig), the base users and systemd-sysusers;
# apt adds no Essential package by itself to an empty root.
root_tools=(dpkg dash coreutils tar diffutils libc-bin base-passwd systemd)
make_root() {
    local wanted
    wanted=$("${apt_arm64[@]}" -o APT::Install-Recommends=1 install -s "$deb" "${root_tools[@]}" 2>&1 |
        sed -n 's/^Inst \([^ ]*\) (\([^ ]*\) .*/\1 \2/p' | grep -v '^puddle ' | sort)
    if [ -z "$wanted" ]; then
        echo "apt cannot install $deb on Debian 12 arm64:"
        "${apt_arm64[@]}" install -s "$deb"
        return 1
    fi
    "${apt_arm64[@]}" -o APT::Install-Recommends=1 install -d -y -qq "$deb" "${root_tools[@]}" || return 1
    rm -rf "$root" && mkdir -p "$root"
    unpack_packages "$root" "" <<<"$wanted" || return 1
    # What base-files', base-passwd's and libc-bin's scripts do on a new system: /tmp, the base users,
    # the library cache.
    # shellcheck disable=SC2174  # $root exists (made above): only tmp is created, and -m is meant for it
    mkdir -p -m 1777 "$root/tmp"
    cp "$root/usr/share/base-passwd/passwd.master" "$root/etc/passwd"
    cp "$root/usr/share/base-passwd/group.master" "$root/etc/group"
    on_root ldconfig
    echo "$(wc -l <<<"$wanted") packages"
}
install_deb() {
    cp "$deb" "$root/tmp/puddle.deb"
    # shellcheck disable=SC2016  # ${Status} is dpkg-query's format field, not a shell expansion
    on_root dpkg -i /tmp/puddle.deb &&
        [ "$(on_root dpkg-query -W -f '${Status}' puddle)" = "install ok installed" ] &&
        [ -x "$root/usr/bin/puddle" ] && [ -f "$root/etc/puddle/puddle.toml" ] &&
        [ -f "$root/usr/lib/puddle/libpuddle-images.so" ]
}
postinst_made_user() {  # systemd-sysusers puddle.conf, from the postinst
    local group
    grep -E '^puddle:' "$root/etc/passwd" || { echo "no user puddle in $root/etc/passwd"; return 1; }
    for group in video render input gpio; do
        grep -E "^$group:.*[:,]puddle(,|\$)" "$root/etc/group" || { echo "puddle is not in group $group"; return 1; }
    done
}
starts() {
    local out
    out=$(on_root puddle --version) || return 1
    echo "$out"
    local version
    version=$(dpkg-deb --field "$deb" Version)
    [ "$out" = "puddle ${version%%-*}" ] || { echo "expected: puddle ${version%%-*}"; return 1; }
}
check_runs() {  # no screen, camera or GPIO chip here; Mesa's llvmpipe (the Recommends) is the GPU
    local out rc
    out=$(on_root puddle --check); rc=$?
    echo "$out"
    [ $rc -eq 0 ] || { echo "exit status $rc, expected 0"; return 1; }
    grep -q '^  OK    /etc/puddle/puddle.toml: valid' <<<"$out" &&
        grep -A1 '^\[GPU' <<<"$out" | grep -q '^  OK    .*llvmpipe.*OpenGL ES 3'
}
purge() {
    on_root dpkg --purge puddle && [ ! -e "$root/usr/bin/puddle" ] && [ ! -e "$root/etc/puddle/puddle.toml" ]
}
if check "cpack makes an arm64 .deb" make_deb; then
    echo "cross-build: $deb"; dpkg-deb --field "$deb" Depends Recommends
    if check "an arm64 root from Debian 12 packages (what apt install of the .deb brings)" make_root; then
        if check "dpkg -i installs the .deb on the arm64 root (postinst ran)" install_deb; then
            check "the postinst made user puddle in groups video, render, input, gpio" postinst_made_user
            check "puddle --version starts and prints the package's version" starts
            check "puddle --check exits 0: config valid, GPU OK on Mesa llvmpipe" check_runs
            check "dpkg --purge removes it (prerm and postrm ran)" purge
        fi
    fi
fi
if [ ${#failed[@]} -gt 0 ]; then
    printf 'cross-build: FAILED: %s\n' "${failed[@]}" >&2
    exit 1
fi
echo "cross-build: all passed"
