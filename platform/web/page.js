/* page.js - index.html's script: the form's options to a job, the file cut
 * in pieces, the frame drawn as it goes; dexmillPage.run(source) is what
 * the Run button and the browser test (tools/scripts/web-test.sh) call,
 * dexmillPage.running the Run button's job (tools/scripts/web-stream-test.sh
 * waits for it). A topic of the page (page_*.js, after this file in
 * dexmill.js) adds its part with dexmillPage.extend(hooks): each hook
 * optional, called in the order extended:
 *   options(o)                 the job's options from the form, before the job is made
 *   prepare(source, o)         async, before the job: may read the program first (o filled in)
 *   created(e, o)              the job made (e the Engine), before the cut
 *   sliced(e, progress, drawn) between slices of the cut
 *   finished(e, result)        after the cut and the last drawing (result: what run returns) */
"use strict";
var dexmillPage = (function () {
  var $ = function (id) { return document.getElementById(id); };
  var engine = dexmill.load();
  function status(text) { $("status").textContent = text; }
  function line(p, ms) {
    return p.state + ": line " + p.line + ", " + p.linesRead + " lines read, " + p.moves + " moves, " +
      p.removedMm3.toFixed(3) + " mm3 removed, machine time " + p.machineSeconds.toFixed(1) + " s, " +
      p.errors + " errors, " + p.warnings + " warnings" + (ms === undefined ? "" : ", " + ms.toFixed(0) + " ms");
  }
  var hooks = [];
  function each(name, args) {
    for (var k = 0; k < hooks.length; ++k) if (hooks[k][name]) hooks[k][name].apply(null, args);
  }
  async function run(source) {
    var e = await engine, canvas = $("view-canvas");
    angles = null;
    var o = { stock: $("stock").value, tool: $("tool").value, grid: $("grid").value, size: $("size").value,
              view: $("view").value, antialias: $("antialias").checked, decorations: $("decorations").checked };
    each("options", [o]);
    for (var k = 0; k < hooks.length; ++k) if (hooks[k].prepare) await hooks[k].prepare(source, o);
    e.job(o);
    each("created", [e, o]);
    canvas.width = e.width;
    canvas.height = e.height;
    var ctx = canvas.getContext("2d", { willReadFrequently: true });
    $("errors").textContent = "";
    $("hash").textContent = "-";
    var t0 = performance.now();
    var p = await e.run(source, { onSlice: function (q, drawn) {
      if (drawn) e.draw(ctx);
      status(line(q));
      each("sliced", [e, q, drawn]);
    } });
    var ms = performance.now() - t0;
    e.draw(ctx);
    e.inputErrors().forEach(function (err) {
      var li = document.createElement("li");
      li.textContent = (source.name || "program") + ":" + err.line + ":" + err.col + ": error: " + err.message;
      $("errors").appendChild(li);
    });
    var hash = dexmill.fnv1aRgb(ctx.getImageData(0, 0, e.width, e.height).data);
    $("hash").textContent = hash;
    status(line(p, ms));
    var result = { hash: hash, ms: ms, width: e.width, height: e.height, progress: p };
    each("finished", [e, result]);
    return result;
  }
  /* Orbit: a drag (mouse, pen or one finger) turns the eye, half a degree a
   * pixel; drawn once a display frame; the hash is the frame's after it. */
  var drag = null, angles = null, pending = false, ready = null;  /* ready: the engine once loaded */
  engine.then(function (e) { ready = e; });
  $("view-canvas").addEventListener("pointerdown", function (ev) {
    if (!ready || !ready.width) return;
    angles = angles || dexmill.PRESET_ANGLES[$("view").value].slice();
    drag = { x: ev.clientX, y: ev.clientY, az: angles[0], el: angles[1] };
    try { this.setPointerCapture(ev.pointerId); } catch (err) { /* not a live pointer: no capture */ }
  });
  $("view-canvas").addEventListener("pointermove", function (ev) {
    if (!drag) return;
    angles = [drag.az - (ev.clientX - drag.x) / 2, Math.max(-90, Math.min(90, drag.el + (ev.clientY - drag.y) / 2))];
    if (pending) return;
    pending = true;
    requestAnimationFrame(function () {
      pending = false;
      ready.orbit(angles[0], angles[1]);
      ready.draw($("view-canvas").getContext("2d"));
    });
  });
  function endDrag() {
    if (!drag) return;
    drag = null;
    requestAnimationFrame(function () {  /* after the drag's last drawing */
      var ctx = $("view-canvas").getContext("2d");
      $("hash").textContent = dexmill.fnv1aRgb(ctx.getImageData(0, 0, ready.width, ready.height).data);
    });
  }
  $("view-canvas").addEventListener("pointerup", endDrag);
  $("view-canvas").addEventListener("pointercancel", endDrag);

  engine.then(function () { status("ready: open a G-code file and press Run"); },
              function (err) { status("dexmill.wasm did not load: " + err); });
  $("job").addEventListener("submit", function (ev) {
    ev.preventDefault();
    var f = $("file").files[0];
    if (!f) { status("open a G-code file first"); return; }
    status("cutting " + f.name + "…");
    page.running = run(dexmill.blobSource(f));
    page.running.catch(function (err) { status("error: " + err.message); });
  });
  var page = { run: run, engine: engine, running: null,  /* running: the Run button's job, a promise */
               extend: function (h) { hooks.push(h); }, status: status };
  return page;
})();
