# Sourced by tests/vm/guest.sh with vivid loaded on /dev/video0 (see the HOOK comment there).
# 1. The reflection shows vivid's picture: a headless render with environment.source = camera, which
#    must report streaming, and the same render reflecting the cubemap, which the host compares with it
#    (camera-reflection in tests/vm/run: they must differ clearly).
# 2. Unplugging: unbinding vivid's device while puddle streams from it (as a USB camera pulled out: the
#    open descriptor then fails with ENODEV; `rmmod` itself is refused while the device is open) brings
#    back the cubemap; puddle keeps running and ends cleanly on SIGTERM. The device is bound again
#    afterwards for the unload check that follows.
# shellcheck shell=bash disable=SC2154  # out: tests/vm/guest.sh
camera_puddle_test() {
    local log pid rc i
    # shellcheck disable=SC2206  # VM_PUDDLE_SETS: the run's --set list (tests/vm/run), split on purpose
    local common=(--backend headless --size 160x90 --seed "$VM_SEED" --frames 8 $VM_PUDDLE_SETS)
    local cam=(--set environment.source=camera --set environment.camera_device=/dev/video0
               --set environment.camera_width="$VM_W" --set environment.camera_height="$VM_H")

    local t0=$SECONDS cubemap_rc
    "$VM_PUDDLE" "${common[@]}" --screenshot "$out/camera-cubemap.png" >"$out/camera-cubemap.log" 2>&1
    cubemap_rc=$?
    local t1=$SECONDS
    "$VM_PUDDLE" "${common[@]}" "${cam[@]}" --screenshot "$out/camera-vivid.png" >"$out/camera-vivid.log" 2>&1
    rc=$?
    say "NOTE camera: 8 frames reflecting the cubemap took $((t1 - t0)) s, reflecting the camera $((SECONDS - t1)) s"
    if [ "$cubemap_rc" -ne 0 ]; then
        say "FAIL camera-puddle: puddle reflecting the cubemap exited $cubemap_rc (log: camera-cubemap.log)"
    elif [ "$rc" -ne 0 ]; then
        say "FAIL camera-puddle: puddle with the camera exited $rc (log: camera-vivid.log)"
    elif ! grep -q "camera: streaming" "$out/camera-vivid.log"; then
        say "FAIL camera-puddle: puddle never streamed from /dev/video0: $(grep -m1 -E '^(warning|error)' "$out/camera-vivid.log")"
    else
        # The host compares the two pictures (camera-reflection, tests/vm/run): the image tool's
        # libraries take 15 s to load in here.
        say "PASS camera-puddle: $(grep -m1 -o 'camera: streaming.*' "$out/camera-vivid.log")"
    fi

    # Unplug mid-run.
    log=$out/camera-unplug.log
    # shellcheck disable=SC2086
    "$VM_PUDDLE" --backend headless --size 160x90 --frames 0 $VM_PUDDLE_SETS "${cam[@]}" >"$log" 2>&1 &
    pid=$!
    # Twice a second: each poll starts programs, which the VM's one emulated CPU takes from puddle.
    for i in $(seq 1 120); do grep -q "camera: streaming" "$log" && break; sleep 0.5; done
    if ! grep -q "camera: streaming" "$log"; then
        say "FAIL camera-unplug-run: puddle did not stream before the unplug"
        kill -TERM "$pid" 2>/dev/null; wait "$pid"
    else
        echo vivid.0 >/sys/bus/platform/drivers/vivid/unbind
        # shellcheck disable=SC2034  # i only counts the polls
        for i in $(seq 1 60); do grep -q "back to the cubemap" "$log" && break; sleep 0.5; done
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
