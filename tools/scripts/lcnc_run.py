#!/usr/bin/env python3
"""The display of linuxcnc-time.sh's headless LinuxCNC: runs one program.

LinuxCNC starts this as its [DISPLAY] program (`lcnc_run.py -ini INI`); it
drives the machine through the `linuxcnc` Python module the way a GUI
would: ESTOP reset, machine on, home all joints, auto mode, open the
program, run it, and poll the status until the interpreter is idle and the
motion queue empty. Then it exits, and LinuxCNC shuts down with it.

Environment (set by linuxcnc-time.sh):
  LCNC_TIME_PROGRAM  the program to run
  LCNC_TIME_OUT      where to write the result, `key value` lines
  LCNC_TIME_DEADLINE seconds since the epoch at which to give up

The timing itself is HAL's, on the servo thread (linuxcnc-time.sh's HAL
file): two integrators add one servo period per servo-thread run, one
always (total), one only while motion is not in position (moving). Their
values just before the run and after it is done give the program's time in
servo periods, which the non-realtime host's lateness does not change (the
planner too advances by one nominal period per run). Written:
  moving_s  the servo time with motion out of position (the trajectory)
  total_s   the servo time from the run command to done (with dwells,
            tool changes, and this script's polling latency)
  wall_s    the host's wall time for the same span, for comparison
The module is built for the system's Python 3 (/usr/bin/python3); under
another Python the script runs itself there.
"""
import os
import subprocess
import sys
import time

try:
    import linuxcnc
except ImportError:
    if os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3") and os.path.exists("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.stderr.write("lcnc_run.py: no linuxcnc Python module (linuxcnc-uspace)\n")
    sys.exit(2)

POLL_S = 0.01


def fail(msg):
    sys.stderr.write("lcnc_run.py: %s\n" % msg)
    out = os.environ.get("LCNC_TIME_OUT")
    if out:
        with open(out, "a") as f:
            f.write("error %s\n" % msg.replace("\n", " "))
    sys.exit(1)


def deadline():
    return float(os.environ.get("LCNC_TIME_DEADLINE", time.time() + 600))


def getp(pin):
    # halcmd rather than the hal module's get_value: present in every 2.x.
    r = subprocess.run(["halcmd", "-s", "getp", pin], capture_output=True, text=True)
    if r.returncode != 0:
        fail("halcmd getp %s: %s" % (pin, r.stderr.strip()))
    return float(r.stdout.strip())


def check_errors(err):
    # Operator and NML errors end the run (a limit, a bad word); the rest
    # (messages, displays' text) is only passed on.
    while True:
        e = err.poll()
        if not e:
            return
        kind, text = e
        if kind in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
            fail("LinuxCNC error: %s" % text)
        sys.stderr.write("lcnc_run.py: LinuxCNC message: %s\n" % text)


def wait_for(what, cond, s, err):
    while True:
        s.poll()
        check_errors(err)
        if cond():
            return
        if time.time() > deadline():
            fail("timed out waiting for %s" % what)
        time.sleep(POLL_S)


def main():
    program = os.environ.get("LCNC_TIME_PROGRAM")
    out = os.environ.get("LCNC_TIME_OUT")
    if not program or not out:
        fail("LCNC_TIME_PROGRAM and LCNC_TIME_OUT must be set")
    s = linuxcnc.stat()
    c = linuxcnc.command()
    err = linuxcnc.error_channel()
    # The display starts once task is up; its first status may lag a little.
    while True:
        try:
            s.poll()
            break
        except linuxcnc.error:
            if time.time() > deadline():
                fail("no status from LinuxCNC's task")
            time.sleep(0.1)
    c.state(linuxcnc.STATE_ESTOP_RESET)
    c.wait_complete()
    c.state(linuxcnc.STATE_ON)
    c.wait_complete()
    wait_for("machine on", lambda: s.task_state == linuxcnc.STATE_ON, s, err)
    c.mode(linuxcnc.MODE_MANUAL)
    c.wait_complete()
    c.home(-1)
    c.wait_complete()
    njoints = s.joints
    wait_for("homing", lambda: all(s.homed[j] for j in range(njoints)), s, err)
    c.mode(linuxcnc.MODE_AUTO)
    c.wait_complete()
    wait_for("auto mode", lambda: s.task_mode == linuxcnc.MODE_AUTO, s, err)
    c.program_open(program)
    c.wait_complete()
    s.poll()
    g54 = s.g5x_offset[:3] if s.g5x_index == 1 else None
    moving0 = getp("lcnc-time-moving.out")
    total0 = getp("lcnc-time-total.out")
    wall0 = time.monotonic()
    c.auto(linuxcnc.AUTO_RUN, 0)
    # Running until the interpreter has started, then until it is idle
    # again with nothing queued and motion at rest.
    started = [False]

    def done():
        if s.interp_state != linuxcnc.INTERP_IDLE:
            started[0] = True
            return False
        return started[0] and s.queue == 0 and s.inpos

    wait_for("the program to finish", done, s, err)
    wall = time.monotonic() - wall0
    moving = getp("lcnc-time-moving.out") - moving0
    total = getp("lcnc-time-total.out") - total0
    with open(out, "w") as f:
        f.write("moving_s %.6f\ntotal_s %.6f\nwall_s %.6f\n" % (moving, total, wall))
        if g54 is not None:
            f.write("g54 %s\n" % " ".join("%g" % v for v in g54))
        f.write("ok 1\n")
    c.state(linuxcnc.STATE_OFF)
    c.wait_complete()


if __name__ == "__main__":
    main()
