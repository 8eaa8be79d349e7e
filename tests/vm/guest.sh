#!/bin/bash
# Runs inside the test VM as the oneshot unit puddle-vm-test.service, under systemd, on an overlay of
# the host's root file system (see tests/vm/init), so every program here is the host's own: the
# puddle binary just built, bash, v4l2-ctl, Mesa, systemd, dpkg. It reports to
# the host on the serial console with lines that start with "VMTEST:":
#   VMTEST: PASS name: what held          VMTEST: FAIL name: what went wrong
#   VMTEST: SKIP name: why                VMTEST: screendump NAME (the host answers "VMTEST-ACK NAME")
# The host (tests/vm/run) takes the screendumps through the QEMU monitor and compares the pictures.
set -u
# shellcheck source=/dev/null
. /run/vm/vm.env
out=/run/vm/out
busybox=/run/vm/busybox
serial=/dev/ttyS0
# Every puddle started here compiles its shaders through Mesa's disk cache, kept by the host between runs
# (tests/vm/run, PUDDLE_VM_SHADER_CACHE); what a run adds is copied back at the end. Mesa works on a copy
# in memory: pointed at the share itself it wrote only its index there, no shader. The service has a
# cache of its own, the unit's CacheDirectory (service.sh checks it).
shader_store=/run/vm/shader-cache
if [ "${VM_SHADER_CACHE:-0}" = 1 ] && mountpoint -q "$shader_store" && mkdir -p /run/vm/tmp/shader-cache &&
    cp -R "$shader_store/." /run/vm/tmp/shader-cache/ && touch /run/vm/tmp/shader-cache.copied; then
    export MESA_SHADER_CACHE_DIR=/run/vm/tmp/shader-cache
fi

say() { echo "VMTEST: $*"; }

# The host's answers arrive on the serial line; keep it open so nothing typed in between is lost.
exec 5<"$serial"
stty -F "$serial" -echo 2>/dev/null

# Asks the host to save the screen as $out/NAME.ppm and waits until it has.
screendump() {
    local line
    say "screendump $1"
    while IFS= read -r -t 120 line <&5; do
        [[ $line == *"VMTEST-ACK $1"* ]] && return 0
    done
    return 1
}

# Loads the modules of one list that tests/vm/run resolved on the host (in load order), with
# parameters for the last one (the driver itself).
load_modules() {
    local list=$1 params=$2 module last
    last=$(tail -n 1 "/run/vm/modules/$list.list")
    while read -r module; do
        local name=${module##*/}
        name=${name%.ko}
        # A dependency an earlier test loaded (rc-core, videobuf2 for vivid) stays loaded: insmod again fails.
        [ "$module" != "$last" ] && [ -d "/sys/module/${name//-/_}" ] && continue
        if [ "$module" = "$last" ]; then
            # shellcheck disable=SC2086
            "$busybox" insmod "/run/vm/modules/$module" $params || return 1
        else
            "$busybox" insmod "/run/vm/modules/$module" || return 1
        fi
    done < "/run/vm/modules/$list.list"
}

wait_for() {  # path, tenths of a second
    local i
    for ((i = 0; i < $2; ++i)); do
        [ -e "$1" ] && return 0
        sleep 0.1
    done
    return 1
}

# --- KMS: the real binary on virtio-gpu ---------------------------------------------------------
# Puddle runs with --fixed-step, so frame N on the screen is the picture a headless render of N frames
# gives on the host. When frame VM_SHOT_FRAME is on screen (its page flip is done; the binary logs it
# at debug level) the script stops it, the host takes a screendump, and it goes on to VM_FRAMES frames,
# exits and must give the console back: a screendump after the run must match the one before.
kms_test() {
    if ! wait_for /dev/dri/card0 50; then
        say "FAIL kms: no /dev/dri/card0 after loading the DRM driver"
        return
    fi
    # Text on the framebuffer console, so "the console came back" is more than black against black.
    printf '\n  puddle VM test: the text console before and after puddle --backend kms\n' >/dev/tty1
    screendump console-before || { say "FAIL kms: no screendump of the console"; return; }
    local fifo=$TMPDIR/puddle-kms.log line pid rc shots=0 shown=0
    mkfifo "$fifo"
    # shellcheck disable=SC2086  # VM_PUDDLE_SETS: the run's --set list (tests/vm/run), split on purpose
    "$VM_PUDDLE" --backend kms --size "${VM_W}x${VM_H}" --frames "$VM_FRAMES" --fixed-step --fps-cap "$VM_FPS" \
        --seed "$VM_SEED" $VM_PUDDLE_SETS --log-level debug --screenshot "$out/kms-self.png" >"$fifo" 2>&1 &
    pid=$!
    while IFS= read -r line; do
        echo "puddle| $line"
        echo "$line" >>"$out/kms.log"
        [[ $line == *"kms: frame "*" on screen"* ]] && shown=$((shown + 1))
        if [[ $line == *"kms: frame $VM_SHOT_FRAME on screen"* ]]; then
            kill -STOP "$pid"
            screendump kms-frame && shots=1
            kill -CONT "$pid"
        fi
    done <"$fifo"
    wait "$pid"
    rc=$?
    screendump console-after || say "FAIL kms: no screendump after the run"
    local described
    described=$(grep -m1 -o 'kms: /dev/dri/card[0-9]* [^ ]* [0-9]*x[0-9]*@[0-9]*' "$out/kms.log")
    if [ "$rc" -ne 0 ]; then
        say "FAIL kms: puddle --backend kms exited with $rc (log: kms.log)"
    elif [ -z "$described" ]; then
        say "FAIL kms: puddle did not log the card, connector and mode it chose"
    elif [ "$shown" -ne "$VM_FRAMES" ]; then
        say "FAIL kms: $shown of $VM_FRAMES frames reached the screen"
    elif [ "$shots" -ne 1 ]; then
        say "FAIL kms: frame $VM_SHOT_FRAME never reached the screen, or the host took no screendump"
    elif grep -q -E '^(warning|error): kms' "$out/kms.log"; then
        say "FAIL kms: $(grep -m1 -E '^(warning|error): kms' "$out/kms.log")"
    else
        say "PASS kms: $described, $shown page flips, exit 0"
    fi
}

# --- camera: vivid on /dev/video0 -----------------------------------------------------------------
# Streams a few frames of each format vivid offers that the camera feature reads (YUYV, NV12, MJPEG)
# and keeps the first frame of each for the host to check; then unloads vivid.
camera_test() {
    if ! load_modules vivid "n_devs=1 node_types=0x1"; then
        say "FAIL camera: loading vivid"
        return
    fi
    if ! wait_for /dev/video0 50; then
        say "FAIL camera: vivid loaded but no /dev/video0"
        return
    fi
    if ! command -v v4l2-ctl >/dev/null; then
        say "SKIP camera: v4l2-ctl is not installed on the host (apt-get install v4l-utils)"
    else
        local formats fmt size frame streamed=""
        formats=$(v4l2-ctl -d /dev/video0 --list-formats 2>&1)
        for fmt in YUYV NV12 MJPG; do
            if ! grep -q "'$fmt'" <<<"$formats"; then
                say "NOTE camera: vivid does not offer $fmt"
                continue
            fi
            case $fmt in
                YUYV) frame=$((VM_W * VM_H * 2)) ;;
                NV12) frame=$((VM_W * VM_H * 3 / 2)) ;;
                *) frame=0 ;;
            esac
            rm -f "$TMPDIR/vivid-$fmt.raw"
            if ! v4l2-ctl -d /dev/video0 --set-fmt-video="width=$VM_W,height=$VM_H,pixelformat=$fmt" \
                --stream-mmap=3 --stream-count=4 --stream-to="$TMPDIR/vivid-$fmt.raw" >"$TMPDIR/v4l2.log" 2>&1; then
                say "FAIL camera: streaming $fmt: $(tail -n 1 "$TMPDIR/v4l2.log")"
                continue
            fi
            size=$(stat -c %s "$TMPDIR/vivid-$fmt.raw" 2>/dev/null || echo 0)
            if [ "$size" -lt "$frame" ] || [ "$size" -eq 0 ] || { [ "$frame" -gt 0 ] && [ $((size % frame)) -ne 0 ]; }; then
                say "FAIL camera: $fmt: $size bytes, not whole frames of $frame"
                continue
            fi
            [ "$frame" -gt 0 ] && say "NOTE camera: $fmt: $((size / frame)) frames of ${VM_W}x${VM_H} streamed" 
            head -c "$frame" "$TMPDIR/vivid-$fmt.raw" >"$out/vivid-$fmt.raw"
            streamed+="$fmt "
        done
        if [ -n "$streamed" ]; then
            say "PASS camera: /dev/video0 streamed ${streamed% } at ${VM_W}x${VM_H}"
        else
            say "FAIL camera: no format streamed"
        fi
    fi

    # HOOK (camera feature): when puddle has environment.source = "camera", tests/vm/camera.sh is
    # sourced here with vivid loaded on /dev/video0. It can use $VM_PUDDLE, $out (the host sees it as
    # build/vm-test/share), $TMPDIR, say, screendump NAME (the host saves build/vm-test/NAME.ppm) and
    # "$busybox" rmmod vivid; it reports its own VMTEST lines. It is the place for: the reflection shows
    # vivid's test pattern, and `rmmod vivid` mid-run falls back to the cubemap and keeps running. It
    # must leave vivid loaded (the unload check below follows it).
    if [ "$VM_PUDDLE_HAS_CAMERA" -gt 0 ]; then
        if [ -f "$VM_SRC/tests/vm/camera.sh" ]; then
            # shellcheck source=/dev/null
            . "$VM_SRC/tests/vm/camera.sh"
        else
            say "FAIL camera-puddle: puddle has environment.source but tests/vm/camera.sh is missing"
        fi
    else
        say "SKIP camera-puddle: this puddle has no environment.source (the camera feature is not merged)"
    fi

    if "$busybox" rmmod vivid && [ ! -e /dev/video0 ]; then
        say "PASS camera-unload: rmmod vivid removed /dev/video0"
    else
        say "FAIL camera-unload: vivid did not unload cleanly"
    fi
}

# --- GPIO: gpio-sim ---------------------------------------------------------------------------------
# tests/vm/run built gpio-sim for this kernel (Debian's has none) and put it in modules/gpio.list; the
# checks (a chip through configfs, the knobs turned by writing its lines' pulls, on libgpiod 1 and 2)
# are in tests/vm/gpio.sh.
gpio_test() {
    # shellcheck source=tests/vm/gpio.sh
    . "$VM_SRC/tests/vm/gpio.sh"
}

# --- power: display.power off and on again on virtio-gpu (issue 19) ---------------------------------
# Puddle runs on KMS with a config that the test rewrites: display.power = false must switch the
# connector off (DPMS, so virtio-gpu's scanout goes inactive) and true must bring the same mode back with
# the picture. The host takes screendumps before, while off and after, and compares their brightness.
power_test() {
    if ! wait_for /dev/dri/card0 50; then
        say "FAIL power: no /dev/dri/card0 after loading the DRM driver"
        return
    fi
    local config=$TMPDIR/power.toml fifo=$TMPDIR/puddle-power.log line pid rc step=0 shots=""
    printf '[display]\npower = true\n' >"$config"
    mkfifo "$fifo"
    # shellcheck disable=SC2086
    "$VM_PUDDLE" --backend kms --size "${VM_W}x${VM_H}" --frames 400 --fixed-step --fps-cap "$VM_FPS" \
        --seed "$VM_SEED" $VM_PUDDLE_SETS --config "$config" --log-level debug >"$fifo" 2>&1 &
    pid=$!
    set_power() {  # a rename, as editors save: the config watcher reloads
        printf '[display]\npower = %s\n' "$1" >"$config.new" && mv "$config.new" "$config"
    }
    while IFS= read -r line; do
        echo "$line" >>"$out/power.log"
        case $step in
            0) if [[ $line == *"kms: frame 2 on screen"* ]]; then
                   kill -STOP "$pid"; screendump power-before && shots+="before "; kill -CONT "$pid"
                   set_power false; step=1
               fi ;;
            1) if [[ $line == *"output off (DPMS off)"* ]]; then
                   sleep 2; screendump power-off && shots+="off "
                   set_power true; step=2
               fi ;;
            2) [[ $line == *"output on (DPMS on)"* ]] && step=3 ;;
            3) if [[ $line == *"kms: frame "*" on screen"* ]]; then
                   kill -STOP "$pid"; screendump power-on && shots+="on "; kill -CONT "$pid"
                   kill -TERM "$pid"; step=4
               fi ;;
        esac
    done <"$fifo"
    wait "$pid"
    rc=$?
    if [ "$rc" -ne 0 ]; then
        say "FAIL power: puddle exited with $rc (log: power.log)"
    elif [ "$step" -ne 4 ]; then
        say "FAIL power: stopped at step $step of 4 (before, off, on, picture back); log: power.log"
    elif [ "$shots" != "before off on " ]; then
        say "FAIL power: screendumps taken: ${shots:-none}"
    elif grep -q -E '^(warning|error): kms' "$out/power.log"; then
        say "FAIL power: $(grep -m1 -E '^(warning|error): kms' "$out/power.log")"
    else
        say "PASS power: $(grep -m1 -o 'kms: [^ ]* [^ ]* output off (DPMS off)' "$out/power.log"), then on; the picture came back"
    fi
}

# --- cec: display.power through HDMI-CEC on vivid's emulated adapters (issue 19) ----------------------
# vivid with one HDMI input and one HDMI output makes two CEC adapters, the output's hooked to the
# input's: the input side plays the TV (cec-ctl --tv, and --monitor records what arrives), and puddle
# drives the output side. display.power = false must send <Standby>, true <Image View On> and
# <Active Source>, and the TV must see them arrive.
cec_test() {
    if ! load_modules vivid "n_devs=1 node_types=0x101 num_inputs=1 input_types=0x3 num_outputs=1 output_types=0x1"; then
        say "FAIL cec: loading vivid with an HDMI input and output"
        return
    fi
    if ! wait_for /dev/cec1 50; then
        say "FAIL cec: vivid loaded but no /dev/cec0 and /dev/cec1 (CONFIG_VIDEO_VIVID_CEC?)"
        "$busybox" rmmod vivid
        return
    fi
    if ! command -v cec-ctl >/dev/null; then
        say "SKIP cec: cec-ctl is not installed on the host (apt-get install v4l-utils)"
        "$busybox" rmmod vivid
        return
    fi
    local tv="" source="" dev
    for dev in /dev/cec0 /dev/cec1; do  # the input adapter has as many ports as inputs; it is the TV
        if cec-ctl -d "$dev" 2>&1 | grep -q -i "vivid-[0-9]*-vid-cap"; then tv=$dev; else source=$dev; fi
    done
    [ -n "$tv" ] || { tv=/dev/cec0; source=/dev/cec1; }
    cec-ctl -d "$tv" --tv >"$out/cec-tv.log" 2>&1
    cec-ctl -d "$tv" --monitor >"$out/cec-monitor.log" 2>&1 &
    local monitor=$! config=$TMPDIR/cec.toml fifo=$TMPDIR/puddle-cec.log line pid rc step=0
    printf '[display]\npower = true\ncec = true\ncec_device = "%s"\n' "$source" >"$config"
    mkfifo "$fifo"
    "$VM_PUDDLE" --backend headless --size 64x36 --frames 0 --config "$config" >"$fifo" 2>&1 &
    pid=$!
    (sleep 120; kill -TERM "$pid" 2>/dev/null) &  # runs until stopped: a step that never comes ends here
    local guard=$!
    set_cec_power() {
        printf '[display]\npower = %s\ncec = true\ncec_device = "%s"\n' "$1" "$source" >"$config.new" &&
            mv "$config.new" "$config"
    }
    while IFS= read -r line; do
        echo "$line" >>"$out/cec.log"
        case $step in
            0) if [[ $line == *"config: watching"* ]]; then set_cec_power false; step=1; fi ;;
            1) if [[ $line == *"cec: "*"<Standby>"* ]]; then set_cec_power true; step=2; fi ;;
            2) if [[ $line == *"cec: "*"<Image View On> and <Active Source>"* ]]; then kill -TERM "$pid"; step=3; fi ;;
        esac
    done <"$fifo"
    wait "$pid"
    rc=$?
    kill "$guard" 2>/dev/null
    sleep 1
    kill "$monitor" 2>/dev/null
    wait "$monitor" 2>/dev/null
    local seen
    seen=$(grep -i -o -E 'STANDBY|IMAGE_VIEW_ON|ACTIVE_SOURCE' "$out/cec-monitor.log" | tr '[:lower:]' '[:upper:]' | sort -u | tr '\n' ' ')
    if [ "$rc" -ne 0 ]; then
        say "FAIL cec: puddle exited with $rc (log: cec.log)"
    elif [ "$step" -ne 3 ]; then
        say "FAIL cec: stopped at step $step of 3 (off sent, on sent); log: cec.log, cec-monitor.log"
    elif [ "$seen" != "ACTIVE_SOURCE IMAGE_VIEW_ON STANDBY " ]; then
        say "FAIL cec: the TV adapter $tv saw: ${seen:-nothing} (cec-monitor.log)"
    else
        say "PASS cec: puddle on $source sent <Standby>, <Image View On> and <Active Source>; the TV on $tv saw them ($(grep -m1 -o 'cec: [^(]*acknowledged[^)]*' "$out/cec.log" || true))"
    fi
    "$busybox" rmmod vivid || say "NOTE cec: vivid did not unload"
}

say "NOTE boot: the tests start $(cut -d ' ' -f 1 /proc/uptime) s after the kernel (systemd $(systemctl --version | awk 'NR == 1 { print $2 }'), $(systemctl is-system-running 2>/dev/null))"
for t in $VM_TESTS; do
    t0=$(cut -d ' ' -f 1 /proc/uptime)
    case $t in
        kms) kms_test ;;
        camera) camera_test ;;
        gpio) gpio_test ;;
        power) power_test ;;
        cec) cec_test ;;
        service)
            # shellcheck source=tests/vm/service.sh
            . "$VM_SRC/tests/vm/service.sh" ;;
        *) say "FAIL $t: unknown test" ;;
    esac
    say "NOTE time: $t took $(awk -v t0="$t0" '{ printf "%.0f", $1 - t0 }' /proc/uptime) s"
done
if [ -n "${MESA_SHADER_CACHE_DIR:-}" ]; then
    written=$(find "$MESA_SHADER_CACHE_DIR" -type f -newer /run/vm/tmp/shader-cache.copied | wc -l)
    # Only what this run wrote: another VM may share the folder (a file is written whole, then renamed).
    (cd "$MESA_SHADER_CACHE_DIR" && find . -type f -newer /run/vm/tmp/shader-cache.copied | while read -r f; do
        mkdir -p "$shader_store/$(dirname "$f")" && cp "$f" "$shader_store/$f.tmp$$" && mv "$shader_store/$f.tmp$$" "$shader_store/$f"
    done) || say "NOTE shader cache: copying it back to the host failed"
    say "NOTE shader cache: $written files written, $(find "$MESA_SHADER_CACHE_DIR" -type f | wc -l) in all"
fi
# The VM's journal, for whoever reads the results (build/vm-test/share/journal.txt).
journalctl -b -o short-monotonic --no-pager >"$out/journal.txt" 2>&1
