# shellcheck shell=bash
# The host's part of the VM's GPIO test, sourced by tests/vm/run (it uses run's $here, $src, $build, $out,
# $cache, $deb, $kdir, $kver, $kconfig, $puddle, $image_diff, resolve and record):
#   gpio_host_prepare   puts gpio-sim (built for the booted kernel by tests/vm/gpio_sim/build), configfs
#                       and Debian 12's gpioinfo into the initramfs, and the libgpiod 2 binary when
#                       tests/vm/gpio_sim/build-gpiod2 can make one; status 1 (with a SKIP or FAIL
#                       recorded) when the gpio test cannot run
#   gpio_host_env       the lines for the VM's vm.env
#   gpio_host_compare   after the VM: the screendumps with the knobs turned against headless renders
# shellcheck disable=SC2154  # run's variables

gpio_tools=""         # a folder with Debian 12's gpiod tools unpacked (gpioinfo), or empty
gpio_puddle2=""       # the puddle binary built against libgpiod 2, or empty
gpio_puddle2_why=""   # why there is none

gpio_host_prepare() {
    local dest=$out/initramfs/modules list=$out/initramfs/modules/gpio.list mods rc ko
    # configfs (a module in Debian's kernel) carries gpio-sim's chips; base.list modules are loaded already.
    resolve configfs | grep -v -x -F -f "$dest/base.list" >"$list" || true
    while read -r ko; do
        mkdir -p "$dest/$(dirname "$ko")" && cp "$kdir/lib/modules/$kver/$ko" "$dest/$ko"
    done <"$list"
    if grep -q -E '^CONFIG_GPIO_SIM=m' "$kconfig"; then
        resolve gpio-sim | grep -v -x -F -f "$dest/base.list" | grep -v -x -F -f "$list" >>"$list.new"
        while read -r ko; do
            mkdir -p "$dest/$(dirname "$ko")" && cp "$kdir/lib/modules/$kver/$ko" "$dest/$ko"
        done <"$list.new"
        cat "$list.new" >>"$list" && rm -f "$list.new"
    elif ! grep -q -E '^CONFIG_GPIO_SIM=y' "$kconfig"; then
        # Debian's kernels: built out of tree at test time (cached after the first run).
        mods=$("$here/gpio_sim/build" "$cache" "$deb" 2>"$out/gpio-sim-build.log")
        rc=$?
        cat "$out/gpio-sim-build.log"
        if [ $rc -eq 77 ]; then
            record SKIP "gpio: kernel $kver has no gpio-sim and it cannot be built here: $(tail -n 1 "$out/gpio-sim-build.log")"
            return 1
        elif [ $rc -ne 0 ]; then
            record FAIL "gpio: $(tail -n 1 "$out/gpio-sim-build.log")"
            return 1
        fi
        mkdir -p "$dest/extra" && cp "$mods/irq_sim.ko" "$mods/gpio-sim.ko" "$dest/extra/" || return 1
        printf 'extra/irq_sim.ko\nextra/gpio-sim.ko\n' >>"$list"
    fi
    gpio_fetch_tools
    gpio_build_v2
    return 0
}

# gpioinfo shows what the kernel reports for each line (consumer, active-low, bias). Debian 12 has it in
# the gpiod package, for the host's libgpiod2; unpacked into the cache (the VM sees the host's root).
gpio_fetch_tools() {
    local version dir
    version=$(dpkg-query -W -f '${Version}' libgpiod2 2>/dev/null) || return 0
    dir=$cache/gpiod-tools-$version
    if [ ! -x "$dir/usr/bin/gpioinfo" ]; then
        local tmp
        tmp=$(mktemp -d "$cache/tmp.XXXXXX") || return 0
        if (cd "$tmp" && apt-get download "gpiod=$version") >"$out/gpiod-tools.log" 2>&1; then
            dpkg -x "$tmp"/gpiod_*.deb "$dir"
        fi
        rm -rf "$tmp"
    fi
    if [ -x "$dir/usr/bin/gpioinfo" ]; then
        gpio_tools=$dir
    else
        record NOTE "gpio: no gpioinfo (apt-get download gpiod=$version failed: $out/gpiod-tools.log); the lines' flags are read from debugfs"
    fi
}

# The same checks against the libgpiod 2 backend: tests/vm/gpio_sim/build-gpiod2 makes a puddle with
# Debian 13's libgpiod from the main build's objects and its v2 backend, in seconds, in
# PUDDLE_VM_GPIOD2_BUILD (default BUILD/gpiod2). PUDDLE_VM_GPIOD2=off leaves that part out.
gpio_build_v2() {
    local dir=${PUDDLE_VM_GPIOD2_BUILD:-$build/gpiod2} start=$SECONDS rc
    if [ "${PUDDLE_VM_GPIOD2:-on}" = off ]; then
        gpio_puddle2_why="PUDDLE_VM_GPIOD2=off"
        return
    fi
    say "gpio: linking puddle with libgpiod 2 in $dir"
    "$here/gpio_sim/build-gpiod2" "$src" "$build" "$dir" "$cache" >"$out/gpiod2-build.log" 2>&1
    rc=$?
    if [ $rc -eq 0 ]; then
        gpio_puddle2=$dir/puddle
        say "gpio: $(tail -n 1 "$out/gpiod2-build.log") ($((SECONDS - start)) s)"
    elif [ $rc -eq 77 ]; then
        gpio_puddle2_why=$(tail -n 1 "$out/gpiod2-build.log")
    else
        record FAIL "gpio-v2: building puddle against libgpiod 2 failed: $(tail -n 1 "$out/gpiod2-build.log") (log: $out/gpiod2-build.log)"
        gpio_puddle2_why="its build failed"
    fi
}

gpio_host_env() {
    echo "VM_GPIO_TOOLS=\"$gpio_tools\""
    echo "VM_PUDDLE_GPIOD2=\"$gpio_puddle2\""
    echo "VM_GPIOD2_WHY=\"${gpio_puddle2_why//\"/\'}\""
}

# Each knob run left TAG-knobs.ppm (a screendump with the encoder and the switch turned) and
# share/TAG-knobs.txt (its frame number, then the --set arguments the knobs amount to). It must match a
# headless render of that frame with those values, and differ from one without them.
gpio_host_compare() {
    local file tag frame sets base=()
    for file in "$out"/share/gpio*-knobs.txt; do
        [ -f "$file" ] || continue
        tag=$(basename "$file" -knobs.txt)
        { read -r frame; read -r sets; } <"$file"
        [ -f "$out/$tag-knobs.ppm" ] || { record FAIL "$tag-screendump: no screendump $tag-knobs.ppm"; continue; }
        # shellcheck disable=SC2206  # word splitting wanted: PUDDLE_SETS and the knobs' --set list
        base=(--backend headless --size "${W}x${H}" --frames "$frame" --fps-cap "$FPS" --seed "$SEED"
              $PUDDLE_SETS --config "$out/share/$tag-look.toml")
        # shellcheck disable=SC2086
        if ! "$puddle" "${base[@]}" $sets --screenshot "$out/$tag-turned.png" >"$out/$tag-headless.log" 2>&1 ||
            ! "$puddle" "${base[@]}" --screenshot "$out/$tag-unturned.png" >>"$out/$tag-headless.log" 2>&1; then
            record FAIL "$tag-screendump: the headless reference render failed (see $out/$tag-headless.log)"
            continue
        fi
        local verdict
        if verdict=$("$image_diff" "$out/$tag-knobs.ppm" "$out/$tag-turned.png" --mean "$MEAN_MAX" \
            --threshold "$OFF_THRESHOLD" --fraction "$OFF_FRACTION" --diff "$out/$tag-knobs-diff.png" 2>&1); then
            record PASS "$tag-screendump: frame $frame on screen matches a headless render with $sets: $verdict"
        else
            record FAIL "$tag-screendump: frame $frame on screen is not a render with $sets: $verdict"
        fi
        # Exit 1 is "outside the tolerance"; 2 (an unreadable picture) proves nothing.
        verdict=$("$image_diff" "$out/$tag-knobs.ppm" "$out/$tag-unturned.png" --mean "$MEAN_MAX" \
            --threshold "$OFF_THRESHOLD" --fraction "$OFF_FRACTION" 2>&1)
        case $? in
            0) record FAIL "$tag-screendump: frame $frame looks as if no knob had moved: $verdict" ;;
            1) record PASS "$tag-screendump: differs from the render without the knobs ($verdict)" ;;
            *) record FAIL "$tag-screendump: comparing with the render without the knobs: $verdict" ;;
        esac
    done
}
