/* engine_replay.js - a live replay's pace for Engine.run (dexmill.js): the
 * cut held to the program's estimated machine time (dm_progress
 * machine_time_us) times a speed, or paused. dexmill.pace() makes one;
 * Engine.run asks pace.wait(engine) before each step: -1 (full speed, not
 * paused: cut as fast as it goes), 0 (due: cut a little), or the ms the cut
 * is ahead of the wall clock (or paused: show the frame and wait). */
"use strict";
dexmill.pace = function (speed) {
  var base = null, pausedAt = null, p = {
    speed: speed || 0,  /* machine seconds a wall second; 0: as fast as it goes */
    paused: false,
    machineUs: 0
  };
  function machine(e) {
    e.x.web_progress();
    return Number(e.x.web_machine_time_us());
  }
  p.wait = function (e) {
    var now = performance.now();
    if (p.paused) {
      if (pausedAt === null) pausedAt = now;
      return 30;
    }
    if (pausedAt !== null) {  /* paused time does not count */
      if (base !== null) base += now - pausedAt;
      pausedAt = null;
    }
    if (!p.speed) return -1;
    p.machineUs = machine(e);
    if (base === null) base = now - p.machineUs / 1000 / p.speed;
    return Math.max(0, base + p.machineUs / 1000 / p.speed - now);
  };
  /* A new speed, from where the cut is: no jump in machine time. */
  p.setSpeed = function (s) {
    p.speed = s || 0;
    base = p.speed ? performance.now() - p.machineUs / 1000 / p.speed : null;
  };
  return p;
};
