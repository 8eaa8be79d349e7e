# Sourced by tests/vm/guest.sh with vivid loaded on /dev/video0 (see the HOOK comment there).
# 1. The reflection shows vivid's picture: a headless render with environment.source = camera differs
#    clearly from the same render reflecting the cubemap, and the camera reported streaming.
# 2. Unplugging: unbinding vivid's device while puddle streams from it (as a USB camera pulled out: the
#    open descriptor then fails with ENODEV; `rmmod` itself is refused while the device is open) brings
#    back the cubemap; puddle keeps running and ends cleanly on SIGTERM. The device is bound again
#    afterwards for the unload check that follows.
# shellcheck shell=bash
camera_puddle_test() {
    local diff_tool log pid rc i
    diff_tool="$(dirname "$VM_PUDDLE")/tests/puddle-image-diff"
    # shellcheck disable=SC2206  # VM_PUDDLE_SETS: the run's --set list (tests/vm/run), split on purpose
    local common=(--backend headless --size 160x90 --seed "$VM_SEED" --frames 8 $VM_PUDDLE_SETS)
    local cam=(--set environment.source=camera --set environment.camera_device=/dev/video0
               --set environment.camera_width="$VM_W" --set environment.camera_height="$VM_H")

    "$VM_PUDDLE" "${common[@]}" --screenshot "$out/camera-cubemap.png" >"$out/camera-cubemap.log" 2>&1
    "$VM_PUDDLE" "${common[@]}" "${cam[@]}" --screenshot "$out/camera-vivid.png" >"$out/camera-vivid.log" 2>&1
    rc=$?
    if [ "$rc" -ne 0 ]; then
        say "FAIL camera-puddle: puddle with the camera exited $rc (log: camera-vivid.log)"
    elif ! grep -q "camera: streaming" "$out/camera-vivid.log"; then
        say "FAIL camera-puddle: puddle never streamed from /dev/video0: $(grep -m1 -E '^(warning|error)' "$out/camera-vivid.log")"
    elif "$diff_tool" "$out/camera-vivid.png" "$out/camera-cubemap.png" --mean 2 >/dev/null 2>&1; then
        say "FAIL camera-puddle: the reflection with vivid looks like the cubemap"
    else
        say "PASS camera-puddle: $(grep -m1 -o 'camera: streaming.*' "$out/camera-vivid.log"); the reflection differs from the cubemap"
    fi

    # Unplug mid-run.
    log=$out/camera-unplug.log
    # shellcheck disable=SC2086
    "$VM_PUDDLE" --backend headless --size 160x90 --frames 0 $VM_PUDDLE_SETS "${cam[@]}" >"$log" 2>&1 &
    pid=$!
    for i in $(seq 1 600); do grep -q "camera: streaming" "$log" && break; sleep 0.1; done
    if ! grep -q "camera: streaming" "$log"; then
        say "FAIL camera-unplug-run: puddle did not stream before the unplug"
        kill -TERM "$pid" 2>/dev/null; wait "$pid"
    else
        echo vivid.0 >/sys/bus/platform/drivers/vivid/unbind
        for i in $(seq 1 300); do grep -q "back to the cubemap" "$log" && break; sleep 0.1; done
        sleep 2
        if ! kill -0 "$pid" 2>/dev/null; then
            wait "$pid"
            say "FAIL camera-unplug-run: puddle died when vivid was removed (exit $?; log: camera-unplug.log)"
        elif ! grep -q "back to the cubemap" "$log"; then
            kill -TERM "$pid"; wait "$pid"
            say "FAIL camera-unplug-run: no fallback to the cubemap logged after rmmod vivid"
        else
            kill -TERM "$pid"; wait "$pid"; rc=$?
            if [ "$rc" -eq 0 ]; then
                say "PASS camera-unplug-run: $(grep -m1 -o '[^:]*: .*back to the cubemap' "$log" | head -c 160); exit 0 on SIGTERM"
            else
                say "FAIL camera-unplug-run: exit $rc after SIGTERM"
            fi
        fi
        echo vivid.0 >/sys/bus/platform/drivers/vivid/bind 2>/dev/null
        wait_for /dev/video0 50 || say "FAIL camera-unplug-run: vivid's device did not come back after bind"
    fi
}
camera_puddle_test
