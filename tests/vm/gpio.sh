# Sourced by tests/vm/guest.sh's gpio_test: puddle's knobs on a real kernel GPIO chip.
# gpio-sim (built out of tree for this kernel by tests/vm/gpio_sim/build; the host put it in the
# initramfs as modules/gpio.list) makes a chip through configfs whose lines are named like a Raspberry
# Pi's header. Writing pull-up/pull-down to a line's sim_gpioN/pull is a contact closing or opening: the
# consumer gets real edge events from the kernel's GPIO character device.
#
# The knobs (docs/configuration.md's wiring: pull-ups, active low): an encoder on GPIO17/GPIO18 turning
# look.vignette, a push button on GPIO22 stepping the preset, a switch on GPIO27 for overlay.rain;
# chip by label, lines by name. Each check is one VMTEST line; TAG names the backend (gpio: libgpiod 1,
# gpio-v2: libgpiod 2).
#
# Seams, so the same checks can run against the service (puddle started by systemd as its own user):
# what is started is gpio_puddle_start CONFIG STATE LOG (how puddle starts; its log lines must reach
# LOG), gpio_puddle_pause/gpio_puddle_resume (hold the picture for a screendump), gpio_puddle_stop
# (returns puddle's exit status); the checks only read LOG and STATE and write the sim's pull files.
# A caller may define these four before sourcing this file; these defaults run puddle as a child.
# shellcheck shell=bash disable=SC2154  # out, say, wait_for, load_modules, screendump: tests/vm/guest.sh

gpio_sim_cfg=/sys/kernel/config/gpio-sim/puddle
gpio_label=puddle-sim
gpio_chip=""      # gpiochipN while the chip is live
gpio_platform=""  # gpio-sim.N while the chip is live

# --- the chip --------------------------------------------------------------------------------------
gpio_sim_setup() {
    load_modules gpio "" || { say "FAIL gpio-chip: loading configfs, irq_sim and gpio-sim (modules/gpio.list)"; return 1; }
    # systemd's sys-kernel-config.mount may be mounting it at this moment (early in a short run, systemd
    # is still starting): a mount that fails is tried again until one of the two has it there.
    local _
    for _ in $(seq 1 50); do
        mountpoint -q /sys/kernel/config && break
        mount -t configfs none /sys/kernel/config 2>/dev/null && break
        sleep 0.1
    done
    mountpoint -q /sys/kernel/config ||
        { say "FAIL gpio-chip: cannot mount configfs on /sys/kernel/config"; return 1; }
    mountpoint -q /sys/kernel/debug || mount -t debugfs none /sys/kernel/debug 2>/dev/null
    [ -d /sys/kernel/config/gpio-sim ] || { say "FAIL gpio-chip: gpio-sim loaded but no /sys/kernel/config/gpio-sim"; return 1; }
    mkdir -p "$gpio_sim_cfg/gpio-bank0" || return 1
    echo 32 >"$gpio_sim_cfg/gpio-bank0/num_lines"
    echo "$gpio_label" >"$gpio_sim_cfg/gpio-bank0/label"
    local n
    for n in 17 18 22 27; do
        mkdir -p "$gpio_sim_cfg/gpio-bank0/line$n" && echo "GPIO$n" >"$gpio_sim_cfg/gpio-bank0/line$n/name"
    done
    gpio_sim_live 1 || { say "FAIL gpio-chip: live=1 made no /dev/gpiochipN"; return 1; }
    say "PASS gpio-chip: gpio-sim made /dev/$gpio_chip ($gpio_platform, label $gpio_label, 32 lines, GPIO17/18/22/27 named)"
}

# live=1 makes the platform device and its gpiochip (the numbers can change each time); live=0 removes them.
gpio_sim_live() {
    echo "$1" >"$gpio_sim_cfg/live" || return 1
    [ "$1" = 1 ] || { gpio_chip="" gpio_platform=""; return 0; }
    gpio_chip=$(cat "$gpio_sim_cfg/gpio-bank0/chip_name")
    gpio_platform=$(cat "$gpio_sim_cfg/dev_name")
    wait_for "/dev/$gpio_chip" 50
}

# A contact: "down" closes it (the line reads low, active), "up" opens it (the pull-up wins).
gpio_pull() {
    echo "pull-$2" >"/sys/devices/platform/$gpio_platform/$gpio_chip/sim_gpio$1/pull"
    # The kernel timestamps an edge in its interrupt handler but reads the level for the event later, in
    # a thread: two changes closer than that thread's delay (long in a loaded emulated VM) would both
    # report the last level. A hand turning a knob is slower than this anyway.
    sleep 0.25
}
gpio_value() { cat "/sys/devices/platform/$gpio_platform/$gpio_chip/sim_gpio$1/value"; }

# One detent of the encoder (A GPIO17, B GPIO18; at rest both open). Clockwise A closes first; the
# decoder (src/io/quadrature_decoder.cpp) counts that as +1.
gpio_turn() {  # cw|ccw, count
    local i
    for ((i = 0; i < $2; ++i)); do
        if [ "$1" = cw ]; then
            gpio_pull 17 down; gpio_pull 18 down; gpio_pull 17 up; gpio_pull 18 up
        else
            gpio_pull 18 down; gpio_pull 17 down; gpio_pull 18 up; gpio_pull 17 up
        fi
        sleep 0.3
    done
}

# --- puddle (the seams) ----------------------------------------------------------------------------
if ! declare -F gpio_puddle_start >/dev/null; then
    gpio_puddle_start() {  # config, state, log
        # shellcheck disable=SC2086
        "$gpio_binary" --backend kms --size "${VM_W}x${VM_H}" --frames 0 --fixed-step --fps-cap "$VM_FPS" \
            --seed "$VM_SEED" $VM_PUDDLE_SETS --config "$1" --state "$2" --log-level debug >"$3" 2>&1 &
        gpio_pid=$!
    }
    gpio_puddle_pause() { kill -STOP "$gpio_pid"; }
    gpio_puddle_resume() { kill -CONT "$gpio_pid"; }
    gpio_puddle_stop() { kill -TERM "$gpio_pid"; wait "$gpio_pid"; }
    gpio_puddle_alive() { kill -0 "$gpio_pid" 2>/dev/null; }
fi

# --- reading the log -------------------------------------------------------------------------------
# gpio_mark remembers how far the log is read; gpio_wait waits for a line matching an extended regex
# after the mark (it sets gpio_line), at most SECONDS.
gpio_mark() { gpio_from=$(($(wc -l <"$gpio_log") + 1)); }
gpio_after() { tail -n "+$gpio_from" "$gpio_log"; }
# Deadlines are wall-clock seconds: one poll can take long in a loaded emulated VM (the log is on 9p).
# A poll starts three programs, which the VM's one emulated CPU takes from puddle: twice a second, not
# ten times (at ten, the gpio part took twice as long).
gpio_wait() {  # regex, seconds
    local end=$((SECONDS + $2))
    while [ $SECONDS -lt $end ]; do
        gpio_line=$(gpio_after | grep -E -m1 -- "$1") && return 0
        gpio_puddle_alive || { gpio_line=""; return 1; }
        sleep 0.5
    done
    gpio_line=""
    return 1
}
# The value a parameter has after the last change the log shows ("knob: look.vignette 0.5 -> 1.1").
gpio_value_of() { grep -o -E "$1 [^ ]+ -> [^ ,]+" "$gpio_log" | tail -n 1 | sed 's/.* -> //'; }
gpio_wait_value() {  # param, value, seconds
    local end=$((SECONDS + $3))
    while [ $SECONDS -lt $end ]; do
        [ "$(gpio_value_of "$1")" = "$2" ] && return 0
        gpio_puddle_alive || return 1
        sleep 0.5
    done
    return 1
}
gpio_frame() { grep -o 'kms: frame [0-9]* on screen' "$gpio_log" | tail -n 1 | grep -o '[0-9]*' ; }

# What the kernel reports for the chip's lines: gpioinfo's flags (Debian 12's gpiod tools, unpacked by
# the host), else debugfs's summary; gpio_line_info picks one line from it (one gpioinfo for all lines:
# each start of a program takes about a second in an emulated CPU).
gpio_has_tools() { [ -n "$VM_GPIO_TOOLS" ] && [ -x "$VM_GPIO_TOOLS/usr/bin/gpioinfo" ]; }
gpio_chip_info() {
    if gpio_has_tools; then "$VM_GPIO_TOOLS/usr/bin/gpioinfo" "$gpio_chip"; else cat /sys/kernel/debug/gpio; fi
}
gpio_line_info() {  # chip info, line number
    if gpio_has_tools; then
        grep -E "^[[:space:]]*line[[:space:]]+$2:" <<<"$1"
    else
        grep -E "\(GPIO$2 " <<<"$1"
    fi
}

# --- the checks, on one binary -----------------------------------------------------------------------
gpio_knobs_run() {  # tag, binary
    local tag=$1 dir=$TMPDIR/$1 n info ok frame
    gpio_binary=$2
    gpio_log=$out/$tag.log
    mkdir -p "$dir"
    local state=$dir/state.toml config=$dir/puddle.toml
    # The look the picture check reproduces on the host, then the knobs.
    printf '[look]\nvignette = 0.5\n\n[overlay]\nrain = false\n' >"$out/$tag-look.toml"
    {
        cat "$out/$tag-look.toml"
        local common="chip = \"$gpio_label\"
bias = \"pull-up\"
active_low = true"
        printf '\n[[knob]]\nkind = "encoder"\n%s\na = "GPIO17"\nb = "GPIO18"\nparam = "look.vignette"\nstep = 0.2\nacceleration = 0\n' "$common"
        printf '\n[[knob]]\nkind = "button"\n%s\nline = "GPIO22"\naction = "next-preset"\n' "$common"
        printf '\n[[knob]]\nkind = "switch"\n%s\nline = "GPIO27"\nparam = "overlay.rain"\n' "$common"
    } >"$config"
    rm -f "$state" "$gpio_log"
    # Contacts open but no pull-up yet: the sim's own default pull is down, so only the knobs' bias
    # (requested by puddle) can make the lines read high.
    for n in 17 18 22 27; do gpio_pull $n down; done
    : >"$gpio_log"
    gpio_mark
    gpio_puddle_start "$config" "$state" "$gpio_log"

    # 1. Lines by name, bias and active-low as the kernel reports them.
    if ! gpio_wait 'kms: frame 1 on screen' 600; then
        say "FAIL $tag-lines: puddle showed no frame (log: $tag.log): $(grep -m1 -E '^(warning|error)' "$gpio_log")"
        gpio_puddle_alive && gpio_puddle_stop
        return
    fi
    ok=1
    local chip_info
    chip_info=$(gpio_chip_info)
    for n in 17 18 22 27; do
        info=$(gpio_line_info "$chip_info" $n)
        echo "$info" >>"$out/$tag-lineinfo.txt"
        if [[ $info != *puddle* ]] || ! grep -q -i 'active.low' <<<"$info"; then
            say "FAIL $tag-lines: GPIO$n is not held by puddle as active-low: ${info:-no such line}"; ok=0
        elif [ -n "$VM_GPIO_TOOLS" ] && [[ $info != *pull-up* ]]; then
            say "FAIL $tag-lines: GPIO$n has no pull-up bias: $info"; ok=0
        elif [ "$(gpio_value $n)" != 1 ]; then
            say "FAIL $tag-lines: GPIO$n reads $(gpio_value $n) with puddle's pull-up (the sim's own pull is down)"; ok=0
        fi
    done
    [ $ok = 1 ] && say "PASS $tag-lines: GPIO17, 18, 22, 27 on chip $gpio_label resolved and held by puddle, active-low, pull-up applied (the lines read 1): $(gpio_line_info "$chip_info" 17 | tr -s ' \t' ' ')"

    # 2. The encoder: 3 detents clockwise (0.5 -> 1.1), then 1 back (0.9).
    gpio_turn cw 3
    if ! gpio_wait_value look.vignette 1.1 180; then
        say "FAIL $tag-encoder: 3 detents clockwise: look.vignette is $(gpio_value_of look.vignette), expected 1.1 (0.5 + 3 x 0.2)"
    else
        gpio_turn ccw 1
        if gpio_wait_value look.vignette 0.9 180; then
            say "PASS $tag-encoder: 3 detents clockwise took look.vignette 0.5 -> 1.1, 1 back -> 0.9"
        else
            say "FAIL $tag-encoder: 1 detent counter-clockwise: look.vignette is $(gpio_value_of look.vignette), expected 0.9"
        fi
    fi

    # 3. The switch: closing it turns the rain overlay on.
    gpio_pull 27 down
    if gpio_wait_value overlay.rain true 180; then
        say "PASS $tag-switch: closing GPIO27 set overlay.rain true"
    else
        say "FAIL $tag-switch: overlay.rain is $(gpio_value_of overlay.rain), expected true after closing GPIO27"
    fi

    # 4. The picture: two frames after the changes, held for a screendump (the host compares it with a
    # headless render of that frame with the knobs' values, tests/vm/gpio_sim/host.sh).
    frame=$(gpio_frame)
    gpio_mark
    if gpio_wait "kms: frame $((frame + 2)) on screen" 180; then
        gpio_puddle_pause
        frame=$(gpio_frame)
        screendump "$tag-knobs" &&
            printf '%s\n%s\n' "$frame" "--set look.vignette=$(gpio_value_of look.vignette) --set overlay.rain=$(gpio_value_of overlay.rain)" \
                >"$out/$tag-knobs.txt"
        gpio_puddle_resume
    else
        say "FAIL $tag-screendump: no frame reached the screen after the knobs moved"
    fi

    # 5. The saved state: 3 s after the last change.
    if gpio_wait 'state: knob values saved' 180 && grep -q -x 'vignette = 0.9' "$state" &&
        grep -q -x 'rain = true' "$state"; then
        say "PASS $tag-state: $(basename "$state") holds vignette = 0.9 and rain = true"
    else
        say "FAIL $tag-state: the state file does not hold the knobs' values: $(tr '\n' ' ' <"$state" 2>/dev/null || echo 'no file')"
    fi

    # 6. The button steps the preset.
    gpio_mark
    gpio_pull 22 down; sleep 0.3; gpio_pull 22 up
    if gpio_wait 'preset: .* \(knob\)' 180; then
        say "PASS $tag-button: pressing GPIO22: $gpio_line"
    else
        say "FAIL $tag-button: pressing GPIO22 logged no preset change"
    fi

    # 7. Unplugged mid-run: one warning for the chip and its three knobs; the retry (every 3 s) picks it up again.
    gpio_mark
    gpio_sim_live 0
    sleep 8
    local warnings
    warnings=$(gpio_after | grep -c '^warning: gpio')
    gpio_after | grep '^warning' >"$out/$tag-unplug-warnings.txt"
    gpio_mark
    gpio_sim_live 1
    for n in 17 18 22 27; do gpio_pull $n up; done
    gpio_pull 27 down  # the switch is still closed
    if [ "$warnings" -ne 1 ]; then
        say "FAIL $tag-unplug: removing the chip gave $warnings gpio warning(s), expected one for the chip and its 3 knobs: $(head -c 300 "$out/$tag-unplug-warnings.txt" | tr '\n' ' ')"
    elif ! gpio_wait 'gpio: knob .*encoder.* works now' 120; then
        say "FAIL $tag-unplug: the encoder did not come back within 120 s of live=1 (log: $tag.log)"
    else
        gpio_turn cw 1
        if gpio_wait_value look.vignette 1.1 180; then
            say "PASS $tag-unplug: live=0 gave one warning for the chip's 3 knobs ($(head -n 1 "$out/$tag-unplug-warnings.txt" | cut -c1-120)); after live=1 ($gpio_chip) the encoder turned again: look.vignette 0.9 -> 1.1"
        else
            say "FAIL $tag-unplug: after live=1 a detent did not change look.vignette (still $(gpio_value_of look.vignette))"
        fi
    fi

    gpio_puddle_stop
    local rc=$?
    [ $rc -eq 0 ] || say "FAIL $tag-exit: puddle exited with $rc on SIGTERM (log: $tag.log)"
}

gpio_sim_test() {
    gpio_sim_setup || return
    gpio_knobs_run gpio "$VM_PUDDLE"
    if [ -n "$VM_PUDDLE_GPIOD2" ]; then
        gpio_knobs_run gpio-v2 "$VM_PUDDLE_GPIOD2"
    else
        say "SKIP gpio-v2: no puddle built against libgpiod 2: ${VM_GPIOD2_WHY:-unknown}"
    fi
    gpio_sim_live 0
}
gpio_sim_test
