/* page_replay.js - play/pause and speed: the cut held to machine
 * time at 1x, 10x or 100x, or as fast as it goes (max, the default: Run as
 * before); pause/resume (the button or space), the speed changed on the
 * way; Replay runs the last program again at the chosen speed. The pacing
 * is engine_replay.js's. */
"use strict";
(function () {
  var $ = function (id) { return document.getElementById(id); };
  var pace = null, lastBlob = null;
  function speed() { return parseFloat($("speed").value) || 0; }
  /* The last program run, for Replay: the blob its source reads. */
  var plainSource = dexmill.blobSource;
  dexmill.blobSource = function (blob) {
    lastBlob = blob;
    return plainSource(blob);
  };
  dexmillPage.extend({
    created: function (e) {
      pace = dexmill.pace(speed());
      e.pace = pace;
      $("pause").textContent = "pause";
    },
    finished: function (e) { e.pace = null; pace = null; }
  });
  function togglePause() {
    if (!pace) return;
    pace.paused = !pace.paused;
    $("pause").textContent = pace.paused ? "resume" : "pause";
    if (pace.paused) dexmillPage.status($("status").textContent + " (paused)");
  }
  $("pause").addEventListener("click", togglePause);
  $("speed").addEventListener("change", function () { if (pace) pace.setSpeed(speed()); });
  $("replay").addEventListener("click", function () {
    if (!lastBlob) { dexmillPage.status("run a program first"); return; }
    dexmillPage.running = dexmillPage.run(dexmill.blobSource(lastBlob));
    dexmillPage.running.catch(function (err) { dexmillPage.status("error: " + err.message); });
  });
  document.addEventListener("keydown", function (ev) {
    var t = ev.target && ev.target.tagName;
    if (ev.key !== " " || t === "INPUT" || t === "SELECT" || t === "TEXTAREA" || t === "BUTTON") return;
    togglePause();
    ev.preventDefault();
  });
})();
