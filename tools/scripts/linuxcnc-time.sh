#!/usr/bin/env bash
# LinuxCNC's own time for a program: runs it in a headless LinuxCNC
# simulator (linuxcnc-uspace: the real trajectory planner, in real time)
# with the machine's limits, and prints
#   linuxcnc_s S
# (seconds, 3 decimals) for time-compare.sh's last column.
#
#   tools/scripts/linuxcnc-time.sh MACHINE.ini PROGRAM
#   env: LCNC_TIMEOUT_S (default 600) the whole run's limit;
#        LCNC_KEEP=1 keeps the temporary configuration (its path on stderr).
#
# The configuration is built in a temporary folder after LinuxCNC's shipped
# sim sample (sim/axis/axis_mm.ini with core_sim.hal's loopback): trivkins,
# X Y Z on joints 0 1 2, a 1 ms servo thread, and from MACHINE its [TRAJ]
# LINEAR_UNITS and per axis MAX_VELOCITY, MAX_ACCELERATION, MIN_LIMIT,
# MAX_LIMIT (the least velocity and acceleration and the narrowest travel of
# [AXIS_x] and [JOINT_n], as `dexmill run --machine` takes them), written to
# both the AXIS_x and the JOINT_n section. [TRAJ] MAX_LINEAR_VELOCITY is
# MACHINE's if it gives one, else the length of the axes' velocity vector
# (no path can go faster, so it never binds); MAX_LINEAR_ACCELERATION
# likewise. MACHINE's [EMCIO] TOOL_TABLE and [RS274NGC] SUBROUTINE_PATH are
# passed on (relative to MACHINE's folder); without a tool table, one of
# tools 1-99 with no length offset, so that T and M6 do not fail. The
# parameter file is a fresh one: G54 active and zero, no G92.
# Homing is in place (HOME_SEARCH_VEL 0) at 0, or the nearest limit.
# The display is tools/scripts/lcnc_run.py (no GUI, no X).
#
# Measurement: a count of servo periods, not wall time. On a shared,
# non-realtime host uspace's servo thread runs late now and then, so wall
# time from run to done stretches; but the planner advances exactly one
# nominal servo period per servo-thread run whatever the lateness, so
# counting runs measures the trajectory's own time. The HAL file adds two
# `integ` components to the servo thread, each integrating 1 (through a
# `mux2`) times the nominal period: one always, one only while
# motion.in-position is false (the planner has motion queued or moving).
# linuxcnc_s is the latter between the run command and done (the
# trajectory: dwells and tool changes, where motion is in position, are
# left out, as are the start-up and the polling's latency); the total and
# the wall time go to stderr for comparison.
#
# Only one LinuxCNC can run on a host (its shared memory and lock file are
# global), so this refuses to start when one is running (never kills it),
# and on exit, error or timeout kills what it started: the linuxcnc
# launcher's process group and the rtapi_app it brought up.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
die() { echo "linuxcnc-time: $*" >&2; exit 1; }
[ $# -eq 2 ] || { echo "usage: linuxcnc-time.sh MACHINE.ini PROGRAM" >&2; exit 2; }
machine=$1 program=$2
[ -r "$machine" ] || die "cannot read machine file $machine"
[ -r "$program" ] || die "cannot read program $program"
command -v linuxcnc >/dev/null || die "linuxcnc missing: run tools/scripts/install-deps.sh oracle"
timeout_s=${LCNC_TIMEOUT_S:-600}
machine_dir=$(cd "$(dirname "$machine")" && pwd)
program=$(cd "$(dirname "$program")" && pwd)/$(basename "$program")

if [ -e /tmp/linuxcnc.lock ] || pgrep -x rtapi_app >/dev/null || pgrep -x milltask >/dev/null; then
  die "another LinuxCNC is running on this host (lock file /tmp/linuxcnc.lock or rtapi_app/milltask); not touching it"
fi

# ini SECTION KEY: the first value of KEY in [SECTION] of MACHINE, empty if none.
ini() {
  awk -v sec="$1" -v key="$2" '
    /^[ \t]*\[/ { s = $0; gsub(/[][ \t\r]/, "", s); next }
    s == sec {
      line = $0; sub(/^[ \t]+/, "", line)
      if (line ~ /^[#;]/) next
      k = line; sub(/[ \t]*=.*/, "", k)
      if (k != key) next
      v = line; sub(/^[^=]*=[ \t]*/, "", v); sub(/[ \t\r]+$/, "", v)
      print v; exit
    }' "$machine"
}
# least / greatest of the non-empty arguments (empty when all are).
least() { printf '%s\n' "$@" | awk 'NF { if (n++ == 0 || $1 + 0 < m + 0) m = $1 } END { if (n) print m }'; }
most() { printf '%s\n' "$@" | awk 'NF { if (n++ == 0 || $1 + 0 > m + 0) m = $1 } END { if (n) print m }'; }

units=$(ini TRAJ LINEAR_UNITS); units=${units:-mm}
case $units in mm|metric) units=mm;; inch|in|imperial) units=inch;; *) die "LINEAR_UNITS '$units' not mm or inch";; esac
letters="X Y Z"
declare -A vel acc lo hi
j=0
for a in $letters; do
  vel[$a]=$(least "$(ini AXIS_$a MAX_VELOCITY)" "$(ini JOINT_$j MAX_VELOCITY)")
  acc[$a]=$(least "$(ini AXIS_$a MAX_ACCELERATION)" "$(ini JOINT_$j MAX_ACCELERATION)")
  lo[$a]=$(most "$(ini AXIS_$a MIN_LIMIT)" "$(ini JOINT_$j MIN_LIMIT)")
  hi[$a]=$(least "$(ini AXIS_$a MAX_LIMIT)" "$(ini JOINT_$j MAX_LIMIT)")
  [ -n "${vel[$a]}" ] && [ -n "${acc[$a]}" ] || die "$machine: no MAX_VELOCITY / MAX_ACCELERATION for axis $a"
  # No travel given: LinuxCNC's default of +-1e99 would do, a wide one reads better.
  lo[$a]=${lo[$a]:--1e6} hi[$a]=${hi[$a]:-1e6}
  j=$((j + 1))
done
norm() { awk -v x="$1" -v y="$2" -v z="$3" 'BEGIN { printf "%.6g", sqrt(x * x + y * y + z * z) }'; }
maxvel=$(ini TRAJ MAX_LINEAR_VELOCITY); maxvel=${maxvel:-$(norm "${vel[X]}" "${vel[Y]}" "${vel[Z]}")}
maxacc=$(ini TRAJ MAX_LINEAR_ACCELERATION); maxacc=${maxacc:-$(norm "${acc[X]}" "${acc[Y]}" "${acc[Z]}")}

tmp=$(mktemp -d /tmp/lcnc-time.XXXXXX)
lcnc_pid= rtapi_pids=
cleanup() {
  rc=$?
  trap - EXIT INT TERM
  if [ -n "$lcnc_pid" ]; then
    # The launcher's own Cleanup runs on TERM; then the whole group, hard.
    kill -TERM -- "-$lcnc_pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 -- "-$lcnc_pid" 2>/dev/null || break; sleep 0.2; done
    kill -KILL -- "-$lcnc_pid" 2>/dev/null || true
  fi
  # rtapi_app may have left the group; kill only the ones that appeared
  # after this script checked none was running.
  for p in $rtapi_pids $(pgrep -x rtapi_app 2>/dev/null || true); do
    if [ -n "$lcnc_pid" ]; then kill -KILL "$p" 2>/dev/null || true; fi
  done
  if [ -n "$lcnc_pid" ] && [ -e /tmp/linuxcnc.lock ] && ! pgrep -x milltask >/dev/null; then rm -f /tmp/linuxcnc.lock; fi
  if [ "${LCNC_KEEP:-0}" = 1 ]; then echo "linuxcnc-time: configuration kept in $tmp" >&2; else rm -rf "$tmp"; fi
  exit $rc
}
trap cleanup EXIT
trap 'exit 130' INT TERM

home_of() {  # 0 when inside [lo, hi], else the nearer limit
  awk -v l="$1" -v h="$2" 'BEGIN { v = 0; if (v < l + 0) v = l; if (v > h + 0) v = h; print v }'
}

tool_table=$(ini EMCIO TOOL_TABLE)
if [ -n "$tool_table" ]; then
  case $tool_table in /*) ;; *) tool_table=$machine_dir/$tool_table;; esac
  [ -r "$tool_table" ] || die "$machine: TOOL_TABLE $tool_table not readable"
  # LinuxCNC rewrites its tool table on tool changes; give it a copy.
  cp "$tool_table" "$tmp/tool.tbl"
else
  for t in $(seq 99); do echo "T$t P$t Z0 D0 ;"; done >"$tmp/tool.tbl"
fi
sub_path=
if [ -n "$(ini RS274NGC SUBROUTINE_PATH)" ]; then
  IFS=: read -r -a dirs <<<"$(ini RS274NGC SUBROUTINE_PATH)"
  for d in "${dirs[@]}"; do
    case $d in /*) ;; *) d=$machine_dir/$d;; esac
    sub_path=${sub_path:+$sub_path:}$d
  done
fi

# A fresh parameter file: G54 (5220 = 1) with every offset zero.
printf '5220\t1.000000\n' >"$tmp/sim.var"

{
  cat <<EOF
# Written by linuxcnc-time.sh from $machine (LinuxCNC's sim/axis sample).
[EMC]
VERSION = 1.1
MACHINE = dexmill-linuxcnc-time
DEBUG = 0
[DISPLAY]
DISPLAY = $here/lcnc_run.py
CYCLE_TIME = 0.100
POSITION_OFFSET = RELATIVE
POSITION_FEEDBACK = ACTUAL
MAX_FEED_OVERRIDE = 1.0
[TASK]
TASK = milltask
CYCLE_TIME = 0.001
[RS274NGC]
PARAMETER_FILE = $tmp/sim.var
EOF
  [ -n "$sub_path" ] && echo "SUBROUTINE_PATH = $sub_path"
  cat <<EOF
[EMCMOT]
EMCMOT = motmod
COMM_TIMEOUT = 1.0
BASE_PERIOD = 0
SERVO_PERIOD = 1000000
[EMCIO]
EMCIO = io
CYCLE_TIME = 0.100
TOOL_TABLE = $tmp/tool.tbl
[HAL]
HALFILE = $tmp/sim.hal
[TRAJ]
COORDINATES = X Y Z
LINEAR_UNITS = $units
ANGULAR_UNITS = degree
DEFAULT_LINEAR_VELOCITY = $maxvel
MAX_LINEAR_VELOCITY = $maxvel
DEFAULT_LINEAR_ACCELERATION = $maxacc
MAX_LINEAR_ACCELERATION = $maxacc
[KINS]
KINEMATICS = trivkins
JOINTS = 3
EOF
  j=0
  for a in $letters; do
    cat <<EOF
[AXIS_$a]
MAX_VELOCITY = ${vel[$a]}
MAX_ACCELERATION = ${acc[$a]}
MIN_LIMIT = ${lo[$a]}
MAX_LIMIT = ${hi[$a]}
[JOINT_$j]
TYPE = LINEAR
HOME = $(home_of "${lo[$a]}" "${hi[$a]}")
MAX_VELOCITY = ${vel[$a]}
MAX_ACCELERATION = ${acc[$a]}
MIN_LIMIT = ${lo[$a]}
MAX_LIMIT = ${hi[$a]}
BACKLASH = 0
FERROR = 1e9
MIN_FERROR = 1e9
HOME_OFFSET = 0
HOME_SEARCH_VEL = 0
HOME_LATCH_VEL = 0
HOME_USE_INDEX = NO
HOME_IGNORE_LIMITS = NO
HOME_SEQUENCE = 0
EOF
    j=$((j + 1))
  done
} >"$tmp/sim.ini"

# core_sim.hal's loopback (position command is the feedback, estop and
# tool change looped), the spindle always at speed, and the two timers.
cat >"$tmp/sim.hal" <<'EOF'
loadrt [KINS]KINEMATICS
loadrt [EMCMOT]EMCMOT base_period_nsec=[EMCMOT]BASE_PERIOD servo_period_nsec=[EMCMOT]SERVO_PERIOD num_joints=[KINS]JOINTS
addf motion-command-handler servo-thread
addf motion-controller servo-thread
net Xpos joint.0.motor-pos-cmd => joint.0.motor-pos-fb
net Ypos joint.1.motor-pos-cmd => joint.1.motor-pos-fb
net Zpos joint.2.motor-pos-cmd => joint.2.motor-pos-fb
net estop-loop iocontrol.0.user-enable-out iocontrol.0.emc-enable-in
net tool-prep-loop iocontrol.0.tool-prepare iocontrol.0.tool-prepared
net tool-change-loop iocontrol.0.tool-change iocontrol.0.tool-changed
setp spindle.0.at-speed 1
loadrt not names=lcnc-time-notinpos
loadrt mux2 names=lcnc-time-gate
loadrt integ names=lcnc-time-moving,lcnc-time-total
net lcnc-inpos motion.in-position => lcnc-time-notinpos.in
net lcnc-moving-bit lcnc-time-notinpos.out => lcnc-time-gate.sel
setp lcnc-time-gate.in0 0
setp lcnc-time-gate.in1 1
net lcnc-moving-one lcnc-time-gate.out => lcnc-time-moving.in
setp lcnc-time-total.in 1
addf lcnc-time-notinpos servo-thread
addf lcnc-time-gate servo-thread
addf lcnc-time-moving servo-thread
addf lcnc-time-total servo-thread
EOF

# LinuxCNC refuses a file that ends without M2, M30 or a closing %
# ("File ended with no percent sign or program end"), which other
# controllers' programs often do: it runs a copy with an M2 after the last
# line (nothing after a program end or a closing % is read, so a program
# that has one runs unchanged).
ext=${program##*/}; case $ext in *.*) ext=.${ext##*.};; *) ext=;; esac
{ cat "$program"; printf '\nM2\n'; } >"$tmp/program$ext"
program=$tmp/program$ext
export LCNC_TIME_PROGRAM=$program LCNC_TIME_OUT=$tmp/result
# uspace's rtapi_app refuses to run as root without a fallback user to
# drop to (RTAPI_UID); nobody's will do for a simulator.
# Its socket (RTAPI_FIFO_PATH) then has to be in a folder that user may
# write to.
if [ "$(id -u)" = 0 ]; then
  export RTAPI_UID=${RTAPI_UID:-$(id -u nobody)}
  mkdir -p "$tmp/rtapi"; chmod 755 "$tmp"; chown "$RTAPI_UID" "$tmp/rtapi"
  export RTAPI_FIFO_PATH=$tmp/rtapi/.rtapi_fifo
fi
# On an error the launcher copies its logs into $HOME; keep them here.
export HOME=$tmp
export LCNC_TIME_DEADLINE=$(( $(date +%s) + timeout_s ))
# Its own session and process group, so that all of it can be killed.
setsid linuxcnc "$tmp/sim.ini" >"$tmp/linuxcnc.log" 2>&1 </dev/null &
lcnc_pid=$!
start=$(date +%s)
while kill -0 "$lcnc_pid" 2>/dev/null; do
  rtapi_pids=$(pgrep -x rtapi_app 2>/dev/null || true)
  if [ $(( $(date +%s) - start )) -gt "$timeout_s" ]; then
    tail -20 "$tmp/linuxcnc.log" >&2
    die "timed out after $timeout_s s (LCNC_TIMEOUT_S)"
  fi
  # Done once the display has written its result; the launcher's shutdown
  # is not waited for.
  grep -q '^ok ' "$tmp/result" 2>/dev/null && break
  sleep 0.5
done
if ! grep -q '^ok ' "$tmp/result" 2>/dev/null; then
  tail -20 "$tmp/linuxcnc.log" >&2
  sed -n 's/^error /linuxcnc-time: /p' "$tmp/result" 2>/dev/null >&2 || true
  die "LinuxCNC did not finish the program (its log above)"
fi
val() { sed -n "s/^$1 //p" "$tmp/result"; }
echo "linuxcnc-time: moving $(val moving_s) s, total $(val total_s) s (servo periods), wall $(val wall_s) s" >&2
awk -v s="$(val moving_s)" 'BEGIN { printf "linuxcnc_s %.3f\n", s }'
