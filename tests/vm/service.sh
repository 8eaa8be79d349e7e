# Sourced by tests/vm/guest.sh for the test "service": the .deb the host just built (VM_DEB), installed
# with dpkg -i into the VM's overlay and run by systemd (PID 1 here) as a user installs it, with the
# unit's hardening as shipped. Reports one VMTEST line per check:
#   service-install   dpkg -i makes the user, its groups and the unit
#   service-limit     a unit that cannot start (a config out of range: exit 2) stops after its start limit
#   service-start     enable --now: active only after the first presented frame, under the hardening
#   service-frame     (the host) the screen shows the frame a headless render gives
#   service-cache     /var/cache/puddle (CacheDirectory) holds Mesa's shader cache
#   service-journal   the start-up summary at priority info, no warning
#   service-watchdog  kill -STOP: the watchdog kills it, systemd restarts it, the picture comes back
#   service-reload    systemctl reload rereads the config; an edit applies on the next frames
#   service-state     knob state in StateDirectory survives a restart (needs a GPIO chip: else SKIP)
#   service-stop      systemctl stop ends it; (the host) the console is back as it was
#   service-purge     dpkg --purge removes the unit, /var/lib/puddle, /var/cache/puddle and the config, nothing runs
# The pace: the test's config (as a user edits /etc/puddle/puddle.toml) is small enough for llvmpipe
# in an emulated CPU, and a drop-in adds --fixed-step --fps-cap, --hold-after SVC_FRAME and --log-level
# debug to ExecStart (as `systemctl edit puddle` would; nothing in it touches the hardening), so the
# picture held on screen is the one a headless render of SVC_FRAME frames gives on the host.
# shellcheck shell=bash disable=SC2154 # out, say, screendump: guest.sh

svc=puddle.service
svc_shots=$out/service-shots.txt   # NAME FRAME: screendumps for the host to compare
SVC_FRAME=3                        # the frame the host compares (the kms test's too)

# Sets KEY in [SECTION] of /etc/puddle/puddle.toml, as a user editing it would (sed -i: a new file
# renamed over the old, which the running display's watcher sees).
svc_set() {  # section key value
    local config=/etc/puddle/puddle.toml
    if ! awk -v s="[$1]" -v k="$2" '$0 == s { in_s = 1; next } /^\[/ { in_s = 0 }
            in_s && $1 == k && $2 == "=" { found = 1 } END { exit !found }' "$config"; then
        say "FAIL service: $config has no '$2 = ' in [$1] to edit"
        return 1
    fi
    sed -i "/^\[$1\]/,/^\[/ s|^$2 = .*|$2 = $3|" "$config"
}

svc_show() { systemctl show -p "$1" --value "$svc"; }

# Follows this invocation's lines in the journal until one matches the glob $2 (prints it), for at
# most $3 seconds; the first $4 matches (default 0) are passed over, as lines from before.
svc_wait_line() {  # invocation pattern seconds [skip]
    local line skip=${4:-0}
    while IFS= read -r line; do
        # shellcheck disable=SC2053 # $2 is a glob
        [[ $line == $2 ]] || continue
        ((skip-- > 0)) && continue
        echo "$line"
        return 0
    done < <(timeout "$3" journalctl -f -n all -o cat "_SYSTEMD_INVOCATION_ID=$1" 2>/dev/null)
    return 1
}
svc_count_lines() {  # invocation pattern
    journalctl -o cat "_SYSTEMD_INVOCATION_ID=$1" | grep -c -F -- "$2"
}

# Waits for the service to be active with a main process other than $1, for at most $2 seconds.
svc_wait_active() {  # old_pid seconds
    local i pid
    for ((i = 0; i < $2 * 2; ++i)); do
        pid=$(svc_show MainPID)
        [ "$(svc_show ActiveState)" = active ] && [ "$pid" != 0 ] && [ "$pid" != "$1" ] && return 0
        sleep 0.5
    done
    return 1
}

# Once the held picture of frame SVC_FRAME is on screen (the drop-in's --hold-after: every later frame is
# the same picture), asks the host for a screendump NAME and notes the frame. Two flips after the hold
# began, every flip done or pending shows the held picture, so what the host sees is certain; stopping
# the process at a journal line could not say that: a flip queued before the stop completes during it.
svc_screendump() {  # name
    local inv
    inv=$(svc_show InvocationID)
    if ! svc_wait_line "$inv" "hold: the picture of frame $SVC_FRAME stays on screen*" 120 >/dev/null ||
        ! svc_wait_line "$inv" "kms: frame $((SVC_FRAME + 2)) on screen" 60 >/dev/null; then
        say "FAIL $1: the held frame $SVC_FRAME never reached the screen (journalctl -u puddle)"
        return 1
    fi
    screendump "$1" && echo "$1 $SVC_FRAME" >>"$svc_shots"
}

svc_install() {
    if ! dpkg -i "$VM_DEB" >"$out/service-dpkg.log" 2>&1; then
        say "FAIL service-install: dpkg -i $(basename "$VM_DEB"): $(tail -n 1 "$out/service-dpkg.log")"
        return 1
    fi
    local groups fragment
    groups=$(id -nG puddle 2>/dev/null)
    fragment=$(svc_show FragmentPath)
    if [ -z "$groups" ]; then
        say "FAIL service-install: dpkg -i made no user puddle (postinst: systemd-sysusers)"
    elif [[ " $groups " != *" video "*" render "* && " $groups " != *" render "*" video "* ]] ||
        [[ " $groups " != *" input "* || " $groups " != *" gpio "* ]]; then
        say "FAIL service-install: user puddle is in '$groups', not video, render, input and gpio"
    elif [ "$(svc_show LoadState)" != loaded ] || [[ $fragment != */lib/systemd/system/puddle.service ]]; then
        say "FAIL service-install: systemd does not see the packaged unit (LoadState $(svc_show LoadState), $fragment)"
    else
        say "PASS service-install: dpkg -i $(basename "$VM_DEB"): user puddle in $groups; unit $fragment"
        return 0
    fi
    return 1
}

# The test's settings, as a user would make them for a slow board: a small wave field and sky, the
# checkerboard ground (no procedural paving), few drops, a fixed seed and no adaptive scale (the
# screen's refresh would lower the render scale while llvmpipe lags); the drop-in
# also gives a board this slow more time: TimeoutStartSec (llvmpipe in an emulated CPU took 30 to 64 s
# to its first frame with no shader cache) and WatchdogSec 20 (a frame takes 1.5 to 2.5 s here, 4 to 8 s
# beside the rest of ctest; systemd arms the watchdog only once start-up is complete). Without
# a GPIO chip, a switch on puddle's mock GPIO backend (fed from svc_knobs) is the state check's knob; with
# the gpio test's gpio-sim chip (tests/vm/gpio.sh, which runs before this and leaves it configured but not
# live) it is a switch on that real chip, opened by the service as user puddle through the shipped udev
# rule's gpio group, wired as docs/configuration.md shows (chip by label, line by name, pull-up, active low).
svc_knobs=/run/vm/knobs.txt
svc_real_chip=0
svc_configure() {
    svc_set rain seed 7 && svc_set rain drop_count 32 && svc_set rain intensity 1.5 &&
        svc_set wave resolution 128 && svc_set render target_fps 0 && svc_set environment face_size 32 &&
        svc_set ground checkerboard true && svc_set wave model '"reference"' && svc_set puddle shape '"box"' ||
        return 1
    local gpio=""
    if [ -d /sys/kernel/config/gpio-sim/puddle ] && declare -F gpio_sim_live >/dev/null && gpio_sim_live 1; then
        local n
        for n in 17 18 22 27; do gpio_pull $n up; done  # the contacts open
        {
            printf '\n[[knob]]\nkind = "switch"\nchip = "%s"\nline = "GPIO27"\nbias = "pull-up"\nactive_low = true\nparam = "overlay.rain"\n' "$gpio_label"
            printf '\n[[knob]]\nkind = "encoder"\nchip = "%s"\na = "GPIO17"\nb = "GPIO18"\nbias = "pull-up"\nactive_low = true\nparam = "look.vignette"\nstep = 0.2\nacceleration = 0\n' "$gpio_label"
            printf '\n[[knob]]\nkind = "button"\nchip = "%s"\nline = "GPIO22"\nbias = "pull-up"\nactive_low = true\naction = "next-preset"\n' "$gpio_label"
        } >>/etc/puddle/puddle.toml
        svc_real_chip=1
    elif ! ls /dev/gpiochip* >/dev/null 2>&1; then
        printf '\n[[knob]]\nkind = "switch"\nline = 22\nparam = "overlay.rain"\n' >>/etc/puddle/puddle.toml
        : >"$svc_knobs" && chmod 644 "$svc_knobs"
        gpio=" --gpio mock:$svc_knobs"
    fi
    cp /etc/puddle/puddle.toml "$out/service.toml"
    local exec_start
    exec_start=$(grep -m1 '^ExecStart=' "$(svc_show FragmentPath)")
    mkdir -p /etc/systemd/system/$svc.d
    printf '[Service]\nTimeoutStartSec=300\nWatchdogSec=20\nExecStart=\n%s --fixed-step --fps-cap %s --hold-after %s --log-level debug%s\n' \
        "$exec_start" "$VM_FPS" "$SVC_FRAME" "$gpio" >/etc/systemd/system/$svc.d/vm-test.conf
    systemctl daemon-reload
}

# A restart loop is bounded: with a config puddle refuses (exit 2), systemd restarts it until the
# unit's start limit, then leaves it failed.
svc_limit() {
    svc_set rain intensity 9 || return 1
    local burst interval result t0=$SECONDS
    burst=$(svc_show StartLimitBurst) interval=$(svc_show StartLimitIntervalUSec)
    systemctl start "$svc" >/dev/null 2>&1
    # Until systemd gives up (failed: with Restart=always only the start limit leaves it there; Result
    # keeps the first failure, exit-code), or more restarts than the limit allows, or 5 minutes.
    while [ $((SECONDS - t0)) -lt 300 ]; do
        [ "$(svc_show ActiveState)" = failed ] && break
        [ "$(svc_show NRestarts)" -gt "$burst" ] && break
        sleep 0.5
    done
    local restarts state
    restarts=$(svc_show NRestarts) state=$(svc_show ActiveState) result=$(svc_show Result)
    if [ "$state" != failed ]; then
        systemctl stop "$svc" 2>/dev/null  # before the config is mended: no full start for nothing
        say "FAIL service-limit: a config puddle refuses restarted it $restarts times in $((SECONDS - t0)) s and it goes on (StartLimitIntervalSec=$interval, StartLimitBurst=$burst; $state)"
    elif ! journalctl -u puddle -o cat | grep -q "Start request repeated too quickly"; then
        say "FAIL service-limit: failed after $restarts restarts, but systemd did not log the start limit"
    elif pgrep -u puddle >/dev/null; then
        say "FAIL service-limit: the unit failed, but a puddle process runs"
    elif ! journalctl -u puddle -o cat | grep -q 'rain.intensity = 9 is out of range'; then
        say "FAIL service-limit: the journal does not say why it failed (rain.intensity = 9 out of range)"
    else
        say "PASS service-limit: a config out of range: $((restarts + 1)) starts in $((SECONDS - t0)) s, then 'Start request repeated too quickly' and failed ($result; StartLimitBurst $burst in $interval)"
    fi
    svc_set rain intensity 1.5
    systemctl reset-failed "$svc" 2>/dev/null
}

svc_start() {
    screendump console-before-service || { say "FAIL service-start: no screendump of the console"; return 1; }
    local t0 rc
    t0=$(date +%s)
    systemctl enable --now "$svc" >"$out/service-enable.log" 2>&1
    rc=$?
    svc_t0=$t0
    local pid inv state
    pid=$(svc_show MainPID) inv=$(svc_show InvocationID) state=$(svc_show ActiveState)
    if [ $rc -ne 0 ] || [ "$state" != active ]; then
        say "FAIL service-start: systemctl enable --now puddle: exit $rc, $state: $(journalctl -u puddle -p warning -o cat -n 1)"
        return 1
    fi
    # Type=notify: READY=1 after the first presented frame. journald's time of the "frame 1" line and
    # PID 1's of READY come by two paths, so a little slack; a READY sent before the first frame is
    # drawn is seconds early here (llvmpipe under emulation).
    local started ready frame1
    started=$(svc_show ExecMainStartTimestampMonotonic) ready=$(svc_show ActiveEnterTimestampMonotonic)
    frame1=$(journalctl -o export "_SYSTEMD_INVOCATION_ID=$inv" | awk -v RS= -F '\n' '{
            for (i = 1; i <= NF; i++) {
                if ($i ~ /^__MONOTONIC_TIMESTAMP=/) t = substr($i, 23)
                if ($i == "MESSAGE=kms: frame 1 on screen") { print t; exit }
            } }')
    # The hardening, as the kernel sees the process: its user, groups, no new privileges, a seccomp
    # filter, no capabilities.
    local status uid gids nnp seccomp cap want_gids="" g
    status=$(cat "/proc/$pid/status")
    uid=$(awk '$1 == "Uid:" { print $2 }' <<<"$status")
    gids=" $(awk '$1 == "Groups:" { $1 = ""; print }' <<<"$status") "
    nnp=$(awk '$1 == "NoNewPrivs:" { print $2 }' <<<"$status")
    seccomp=$(awk '$1 == "Seccomp:" { print $2 }' <<<"$status")
    cap=$(awk '$1 == "CapEff:" { print $2 }' <<<"$status")
    for g in video render input gpio; do
        [[ $gids == *" $(getent group $g | cut -d: -f3) "* ]] || want_gids+="$g "
    done
    local dropins
    dropins=$(svc_show DropInPaths)
    if [ -z "$frame1" ]; then
        say "FAIL service-start: active, but no 'kms: frame 1 on screen' in its journal"
    elif [ "$frame1" -gt $((ready + 1000000)) ]; then
        say "FAIL service-start: READY=1 came $(((frame1 - ready) / 1000)) ms before the first frame was on screen"
    elif [ "$uid" != "$(id -u puddle)" ] || [ -n "$want_gids" ]; then
        say "FAIL service-start: runs as uid $uid with groups$gids(want puddle, missing: ${want_gids:-none})"
    elif [ "$nnp" != 1 ] || [ "$seccomp" != 2 ] || [ "$cap" != 0000000000000000 ]; then
        say "FAIL service-start: hardening not in force: NoNewPrivs $nnp, Seccomp $seccomp, CapEff $cap"
    elif [ "$dropins" != /etc/systemd/system/$svc.d/vm-test.conf ]; then
        say "FAIL service-start: unexpected drop-ins: $dropins"
    else
        say "PASS service-start: active $(((ready - started) / 1000)) ms after start, frame 1 on screen at $(((frame1 - started) / 1000)) ms; user puddle in video render input gpio, NoNewPrivs, seccomp filter, no capabilities"
    fi
    svc_screendump service-frame
    # The unit's CacheDirectory: systemd made /var/cache/puddle for the user puddle, and Mesa keeps the
    # shaders it compiled there (MESA_SHADER_CACHE_DIR), so a restart does not compile them again.
    local cache=/var/cache/puddle files
    files=$(find "$cache" -type f 2>/dev/null | wc -l)
    if [ ! -d "$cache" ] || [ "$(stat -c %U "$cache")" != puddle ]; then
        say "FAIL service-cache: no $cache owned by puddle (CacheDirectory=puddle): $(stat -c '%U %a' "$cache" 2>&1)"
    elif ! tr '\0' '\n' <"/proc/$pid/environ" | grep -q -x "MESA_SHADER_CACHE_DIR=$cache"; then
        say "FAIL service-cache: the process has no MESA_SHADER_CACHE_DIR=$cache"
    elif [ "$files" -eq 0 ]; then
        say "FAIL service-cache: Mesa wrote no shader to $cache after the first frames"
    else
        say "PASS service-cache: $cache (owner puddle) holds $files files of Mesa's shader cache after the first start"
    fi
}

svc_journal() {
    local summary warnings
    summary=$(journalctl -u puddle --since "@$svc_t0" -p info..info -o cat | grep -c '^started: ')
    warnings=$(journalctl -u puddle --since "@$svc_t0" -p warning -o cat)
    if [ "$summary" -ne 1 ]; then
        say "FAIL service-journal: $summary start-up summary lines ('started: ...') at priority info (want 1)"
    elif [ -n "$warnings" ]; then
        say "FAIL service-journal: a warning: $(head -n 1 <<<"$warnings")"
    else
        say "PASS service-journal: $(journalctl -u puddle --since "@$svc_t0" -p info..info -o cat | grep -m1 '^started: ' | cut -c 1-150); no warning"
    fi
}

svc_watchdog() {
    local pid inv watchdog_s restart_s abort_s t0 i
    pid=$(svc_show MainPID) inv=$(svc_show InvocationID)
    # "10s"; a stopped process cannot take the watchdog's SIGABRT, so TimeoutAbortSec counts too.
    watchdog_s=$(svc_show WatchdogUSec) restart_s=$(svc_show RestartUSec) abort_s=$(svc_show TimeoutAbortUSec)
    if [[ ! $watchdog_s =~ ^[0-9]+s$ || ! $restart_s =~ ^[0-9]+s$ || ! $abort_s =~ ^[0-9]+s$ ]]; then
        say "FAIL service-watchdog: WatchdogSec $watchdog_s, RestartSec $restart_s, TimeoutAbortSec $abort_s: this test reads whole seconds under 1 min"
        return 1
    fi
    watchdog_s=${watchdog_s%s} restart_s=${restart_s%s} abort_s=${abort_s%s}
    t0=$(date +%s.%N)
    kill -STOP "$pid"
    local restarted=""
    for ((i = 0; i < (watchdog_s + abort_s + restart_s + 10) * 4; ++i)); do
        if [ "$(svc_show MainPID)" != "$pid" ] && [ "$(svc_show MainPID)" != 0 ]; then
            restarted=$(date +%s.%N)
            break
        fi
        sleep 0.25
    done
    local took
    took=$(awk -v a="$t0" -v b="${restarted:-$t0}" 'BEGIN { printf "%.1f", b - a }')
    if [ -z "$restarted" ]; then
        kill -CONT "$pid" 2>/dev/null
        say "FAIL service-watchdog: no new process $((watchdog_s + abort_s + restart_s + 10)) s after kill -STOP (WatchdogSec=$watchdog_s, TimeoutAbortSec=$abort_s, RestartSec=$restart_s)"
        return 1
    fi
    if ! journalctl -o cat "INVOCATION_ID=$inv" | grep -q -i 'watchdog timeout'; then
        say "FAIL service-watchdog: restarted after ${took} s, but systemd logged no watchdog timeout"
    elif awk -v t="$took" -v m=$((watchdog_s + abort_s + restart_s + 2)) 'BEGIN { exit !(t > m) }'; then
        say "FAIL service-watchdog: restarted ${took} s after kill -STOP, more than WatchdogSec $watchdog_s + TimeoutAbortSec $abort_s + RestartSec $restart_s (+2)"
    elif kill -0 "$pid" 2>/dev/null; then
        say "FAIL service-watchdog: the stopped process $pid still exists beside the new one"
    elif ! svc_wait_active "$pid" 90; then
        say "FAIL service-watchdog: the new process did not become active (TimeoutStartSec)"
    else
        say "PASS service-watchdog: watchdog timeout, new process ${took} s after kill -STOP (WatchdogSec $watchdog_s + TimeoutAbortSec $abort_s + RestartSec $restart_s), active again"
    fi
    svc_screendump service-watchdog
}

svc_reload() {
    local inv pid
    inv=$(svc_show InvocationID) pid=$(svc_show MainPID)
    # An unchanged file: only SIGHUP can make this reload (the watcher sees no write).
    systemctl reload "$svc"
    if ! svc_wait_line "$inv" 'config: reloaded: no value changed' 60 >/dev/null; then
        say "FAIL service-reload: systemctl reload puddle: no 'config: reloaded' in the journal within 60 s"
        return 1
    fi
    svc_set rain drop_count 40
    systemctl reload "$svc"
    local line
    if ! line=$(svc_wait_line "$inv" 'config: reloaded: *rain.drop_count 32 -> 40 (config)*' 60); then
        say "FAIL service-reload: the edited rain.drop_count = 40 was not applied within 60 s"
    elif [ "$(svc_show MainPID)" != "$pid" ]; then
        say "FAIL service-reload: the reload restarted the process"
    else
        say "PASS service-reload: SIGHUP rereads the config; an edit applies: '$line'"
    fi
    svc_set rain drop_count 32
}

# Knob state in $STATE_DIRECTORY survives `systemctl restart`: a knob is turned, the service saves
# the state (as user puddle, through ProtectSystem=strict, where only the StateDirectory is writable),
# and the restarted process restores it.
svc_state() {
    local chips=(/dev/gpiochip*)
    if [ $svc_real_chip -eq 0 ] && [ -e "${chips[0]}" ]; then
        say "SKIP service-state: ${chips[*]} present but not the gpio test's gpio-sim chip: no knob to turn"
        return 0
    fi
    # The switch (svc_configure) sets overlay.rain: on the gpio-sim chip the contact closes (pull-down on
    # an active-low line with puddle's pull-up), on the mock backend line 22 goes to 1.
    local inv saved state=/var/lib/puddle/state.toml knob="a switch (mock GPIO)"
    inv=$(svc_show InvocationID)
    saved=$(svc_count_lines "$inv" "state: knob values saved to $state")
    if [ $svc_real_chip -eq 1 ]; then
        knob="a switch on GPIO27 of gpio-sim's /dev/$gpio_chip (group $(stat -c %G "/dev/$gpio_chip"), mode $(stat -c %a "/dev/$gpio_chip"))"
        gpio_pull 27 down
    else
        echo "gpiochip0 22 1" >>"$svc_knobs"
    fi
    if ! svc_wait_line "$inv" "state: knob values saved to $state" 60 "$saved" >/dev/null; then
        say "FAIL service-state: no 'state: knob values saved to $state' within 60 s of $knob: $(journalctl -o cat "_SYSTEMD_INVOCATION_ID=$inv" -p warning -n 1)"
        return 1
    fi
    if [ "$(stat -c %U "$state")" != puddle ] || ! grep -q 'rain.*true' "$state"; then
        say "FAIL service-state: $state: $(stat -c '%U %a' "$state"), holds: $(tr '\n' ' ' <"$state" | cut -c 1-120)"
        return 1
    fi
    # The state folder is the user's data: Mesa's shader cache belongs in the unit's CacheDirectory.
    if [ -e /var/lib/puddle/.cache ]; then
        # shellcheck disable=SC2012  # only a few names, for the message
        say "FAIL service-state: /var/lib/puddle/.cache exists: Mesa keeps its shader cache in the state folder ($(ls /var/lib/puddle/.cache | head -n 3 | tr '\n' ' '))"
        return 1
    fi
    : >"$svc_knobs"  # the restarted process reads the script again from its start
    local pid restored
    pid=$(svc_show MainPID)
    systemctl restart "$svc"
    inv=$(svc_show InvocationID)
    if ! svc_wait_active "$pid" 90; then
        say "FAIL service-state: not active again after systemctl restart"
    elif ! restored=$(svc_wait_line "$inv" "state: 1 knob value(s) restored from $state" 30); then
        say "FAIL service-state: the restarted process did not restore the knob value from $state"
    else
        say "PASS service-state: $knob set overlay.rain, saved by the service in $state (owner puddle); after systemctl restart: '$restored'"
    fi
}

# The encoder and the button on the real chip, turned while the service runs as its own user: the
# parameter changes and the preset steps, as the journal of this invocation says.
svc_gpio_knobs() {
    if [ $svc_real_chip -eq 0 ]; then
        say "SKIP service-gpio: no gpio-sim chip (the gpio test makes it: --tests \"gpio service\")"
        return 0
    fi
    local inv turned pressed
    inv=$(svc_show InvocationID)
    gpio_turn cw 2
    if ! turned=$(svc_wait_line "$inv" "*look.vignette * -> *" 120); then
        say "FAIL service-gpio: 2 detents of the encoder on GPIO17/GPIO18 changed nothing in 120 s"
        return 1
    fi
    gpio_pull 22 down; sleep 0.3; gpio_pull 22 up
    if ! pressed=$(svc_wait_line "$inv" "*preset: * (knob)*" 120); then
        say "FAIL service-gpio: pressing GPIO22 stepped no preset in 120 s"
        return 1
    fi
    say "PASS service-gpio: as user puddle on /dev/$gpio_chip: the encoder '$turned', the button '$pressed'"
}

svc_stop() {
    local rc
    systemctl stop "$svc"
    rc=$?
    local state left
    state=$(svc_show ActiveState) left=$(pgrep -u puddle | tr '\n' ' ')
    screendump console-after-service || say "FAIL service-stop: no screendump after the stop"
    if [ $rc -ne 0 ] || [ "$state" != inactive ]; then
        say "FAIL service-stop: systemctl stop puddle: exit $rc, $state"
    elif [ -n "$left" ]; then
        say "FAIL service-stop: puddle processes left: $left"
    else
        say "PASS service-stop: inactive, no process of user puddle left"
    fi
}

# dpkg --purge while a start is under way: prerm stops it, postrm removes /var/lib/puddle, dpkg the
# unit and the conffile. The user stays (Debian policy: system users are not removed).
svc_purge() {
    rm -rf /etc/systemd/system/$svc.d
    systemctl daemon-reload
    systemctl start --no-block "$svc"
    local i
    for ((i = 0; i < 40; ++i)); do [ "$(svc_show MainPID)" != 0 ] && break; sleep 0.25; done
    local running
    running=$(svc_show MainPID)
    if ! dpkg --purge puddle >"$out/service-purge.log" 2>&1; then
        say "FAIL service-purge: dpkg --purge puddle: $(tail -n 1 "$out/service-purge.log")"
        return 1
    fi
    sleep 1
    local left="" p
    for p in /usr/lib/systemd/system/$svc /lib/systemd/system/$svc /var/lib/puddle /var/cache/puddle /etc/puddle/puddle.toml \
        /etc/systemd/system/multi-user.target.wants/$svc /usr/bin/puddle; do
        [ -e "$p" ] && left+="$p "
    done
    if [ -n "$left" ]; then
        say "FAIL service-purge: left behind: $left"
    elif pgrep -u puddle >/dev/null; then
        say "FAIL service-purge: a puddle process still runs: $(pgrep -a -u puddle | head -n 1)"
    elif [ "$(svc_show LoadState)" != not-found ]; then
        say "FAIL service-purge: systemd still knows the unit ($(svc_show LoadState), $(svc_show ActiveState))"
    else
        say "PASS service-purge: unit, /var/lib/puddle, /var/cache/puddle and the config removed, nothing running (a start was under way: main PID ${running}); the user puddle stays"
    fi
}

service_test() {
    if [ -z "${VM_DEB:-}" ]; then
        say "SKIP service: ${VM_DEB_SKIP:-no .deb from the host}"
        return
    fi
    if [ "$(cat /proc/1/comm)" != systemd ]; then
        say "FAIL service: PID 1 is $(cat /proc/1/comm), not systemd"
        return
    fi
    : >"$svc_shots"
    svc_install || return
    svc_configure || return
    svc_limit
    svc_start || return
    svc_journal
    svc_watchdog
    svc_reload
    svc_state
    svc_gpio_knobs
    svc_stop
    svc_purge
}
service_test
