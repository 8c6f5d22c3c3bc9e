/* page_view.js - the page's view and findings: the wheel zooms
 * about the pointer, two fingers pinch-zoom (one orbits: page.js), the
 * views 1-4, a reset; the toolpath overlay (a checkbox and p); the safety
 * checks (--check) and the findings listed under the view with the input
 * errors, a click marking one in the view and saying it in the status
 * line; a G-code file dropped on the page runs; the keyboard: arrows orbit
 * (as a drag does, through page.js), + and - zoom, 1-4 the views, p the
 * path, r reset. What is drawn and where is the engine's (engine_view.js). */
"use strict";
(function () {
  var $ = function (id) { return document.getElementById(id); };
  var canvas = $("view-canvas"), ready = null, source = null;
  dexmillPage.engine.then(function (e) { ready = e; });
  function live() { return ready && ready.width; }
  function redraw() {
    ready.draw(canvas.getContext("2d"));
    $("hash").textContent = dexmill.fnv1aRgb(canvas.getContext("2d").getImageData(0, 0, ready.width, ready.height).data);
  }
  /* A canvas pixel from a pointer's client position (the canvas may be scaled by CSS). */
  function pixel(cx, cy) {
    var r = canvas.getBoundingClientRect();
    return [Math.max(0, Math.min(ready.width - 1, Math.floor((cx - r.left) * canvas.width / r.width))),
            Math.max(0, Math.min(ready.height - 1, Math.floor((cy - r.top) * canvas.height / r.height)))];
  }
  function zoom(steps, p) {
    if (!live() || !steps) return;
    ready.zoom(steps, p[0], p[1]);
    redraw();
  }

  /* The file's size for the path's room: the source remembers its blob's. */
  var plainSource = dexmill.blobSource;
  dexmill.blobSource = function (blob) {
    var s = plainSource(blob);
    s.size = blob.size;
    return s;
  };
  /* The path's room: a piece for every 2 bytes of the program (a move's
   * line is longer; an arc's chords are more), 4096 at least, at most 2^20
   * pieces (56 MiB): beyond, the status line says it is full. */
  function pathRoom(bytes) { return Math.min(1 << 20, Math.max(4096, Math.ceil((bytes || 0) / 2))); }

  dexmillPage.extend({
    options: function (o) {
      var checks = dexmill.Engine.prototype.checkBits($("check").value);  /* between the job's values and its making */
      if (checks) (o.configure = o.configure || []).push(function (e) { e.check(e.x.web_set_checks(checks), "--check"); });
      o.pathOverlay = $("path-overlay").checked;
    },
    prepare: function (src) { source = src; },
    created: function (e, o) {
      $("findings").textContent = "";
      if (o.pathOverlay) e.path(pathRoom(source && source.size));
    },
    finished: function (e, result) {
      list(e);
      var info = e.pathInfo();
      result.pathSegments = info.segments;
      result.findings = e.findings();
      result.warnings = e.warnings();
      if (info.dropped) dexmillPage.status($("status").textContent + "; the toolpath is full at " + info.segments +
                                           " pieces, " + info.dropped + " more not drawn");
    }
  });

  /* The program's line n (1-based) of a Blob, read again in 1 MiB pieces
   * up to it (a click, not the cut: nothing is kept); null past its end. */
  async function lineOf(blob, n) {
    var at = 0, line = 1, start = 0, parts = [], dec = new TextDecoder();
    while (at < blob.size) {
      var b = new Uint8Array(await blob.slice(at, Math.min(blob.size, at + (1 << 20))).arrayBuffer());
      for (var i = 0; i < b.length; ++i) {
        if (b[i] !== 10) continue;
        if (line === n) return dec.decode(concat(parts, b.subarray(start, i))).replace(/\r$/, "");
        ++line;
        start = i + 1;
      }
      if (line === n) parts.push(b.slice(start));
      at += b.length;
      start = 0;
    }
    return line === n && parts.length ? dec.decode(concat(parts, new Uint8Array(0))) : null;
  }
  function concat(parts, last) {
    var n = last.length, k = 0;
    parts.forEach(function (p) { n += p.length; });
    var out = new Uint8Array(n);
    parts.forEach(function (p) { out.set(p, k); k += p.length; });
    out.set(last, k);
    return out;
  }
  /* Where an item is in the program: its line's text under its message in
   * the status line, a caret under the column of an error or a warning. */
  async function showLine(item) {
    var blob = source && source.blob;
    if (!blob || !(item.line > 0) || item.line === Infinity) return;
    var text = await lineOf(blob, item.line);
    if (text === null || $("status").textContent !== item.text) return;  /* another click since */
    var head = item.line + " | ", caret = item.col > 0 ? "\n" + " ".repeat(head.length + item.col - 1) + "^" : "";
    dexmillPage.status(item.text + "\n" + head + text + caret);
  }

  /* The findings list: the input errors, the warnings and the findings in
   * the program's order, each a button: a finding's marks it in the view. */
  function list(e) {
    var ul = $("findings"), name = (source && source.name) || "program", items = [];
    e.inputErrors().forEach(function (err) {
      items.push({ line: err.line, col: err.col, mark: -1, text: name + ":" + err.line + ":" + err.col + ": error: " + err.message });
    });
    e.warnings().forEach(function (w) {
      items.push({ line: w.line, col: w.col, mark: -1, text: name + ":" + w.line + ":" + w.col + ": warning: " + w.message });
    });
    e.findings().forEach(function (f, k) {
      var lines = f.lastLine > f.line ? f.line + "-" + f.lastLine : "" + f.line;
      items.push({ line: f.line, mark: k, text: name + ":" + lines + ": " + f.name + " at X" + f.atMm[0].toFixed(3) +
                   " Y" + f.atMm[1].toFixed(3) + " Z" + f.atMm[2].toFixed(3) + " mm, " + f.depthMm.toFixed(3) + " mm deep" });
    });
    var p = e.progress(), shown = items.filter(function (i) { return i.mark < 0; }).length - e.inputErrors().length;
    if (p.warnings > shown) items.push({ line: Infinity, mark: -1, text: name + ": " + (p.warnings - shown) + " more warnings not listed" });
    ul.textContent = "";
    items.sort(function (a, b) { return a.line - b.line; }).forEach(function (item) {
      var li = document.createElement("li"), button = document.createElement("button");
      button.type = "button";
      button.textContent = item.text;
      button.dataset.mark = item.mark;
      button.addEventListener("click", function () {
        e.markFinding(item.mark);
        redraw();
        dexmillPage.status(item.text);
        showLine(item);
      });
      li.appendChild(button);
      ul.appendChild(li);
    });
  }

  $("path-overlay").addEventListener("change", function () {
    if (!live()) return;
    if (!ready.pathInfo().segments && this.checked) dexmillPage.status("the toolpath is collected while cutting: press Run with it on");
    ready.showPath(this.checked);
    redraw();
  });
  $("zoom-reset").addEventListener("click", function () {
    if (!live()) return;
    ready.zoomReset();
    ready.preset($("view").value);
    redraw();
  });

  /* The wheel zooms about the pointer, a notch a step. */
  canvas.addEventListener("wheel", function (ev) {
    if (!live()) return;
    ev.preventDefault();
    zoom(ev.deltaY < 0 ? 1 : -1, pixel(ev.clientX, ev.clientY));
  }, { passive: false });

  /* Two pointers pinch: a step each time their distance changes by 10/9,
   * about their midpoint; page.js's orbit does not see their moves. */
  var touches = new Map(), pinch = null;
  function spread() {
    var p = Array.from(touches.values());
    return { d: Math.hypot(p[0][0] - p[1][0], p[0][1] - p[1][1]), mid: [(p[0][0] + p[1][0]) / 2, (p[0][1] + p[1][1]) / 2] };
  }
  window.addEventListener("pointerdown", function (ev) {
    if (ev.target !== canvas) return;
    touches.set(ev.pointerId, [ev.clientX, ev.clientY]);
    if (touches.size === 2) {
      pinch = spread();
      canvas.dispatchEvent(new PointerEvent("pointercancel", { pointerId: -1 }));  /* ends page.js's orbit */
      ev.stopPropagation();
    }
  }, true);
  window.addEventListener("pointermove", function (ev) {
    if (!touches.has(ev.pointerId)) return;
    touches.set(ev.pointerId, [ev.clientX, ev.clientY]);
    if (!pinch || touches.size !== 2) return;
    ev.stopPropagation();
    var s = spread(), steps = Math.trunc(Math.log(s.d / pinch.d) / Math.log(10 / 9));
    if (steps) {
      zoom(steps, pixel(s.mid[0], s.mid[1]));
      pinch.d *= Math.pow(10 / 9, steps);
    }
  }, true);
  function lift(ev) {
    touches.delete(ev.pointerId);
    if (touches.size < 2) pinch = null;
  }
  window.addEventListener("pointerup", lift, true);
  window.addEventListener("pointercancel", lift, true);

  /* An orbit from the keyboard: the drag page.js turns into angles. */
  function orbitBy(dx, dy) {
    var at = function (x, y) { return { bubbles: true, pointerId: 99, clientX: 200 + x, clientY: 200 + y }; };
    canvas.dispatchEvent(new PointerEvent("pointerdown", at(0, 0)));
    canvas.dispatchEvent(new PointerEvent("pointermove", at(dx, dy)));
    canvas.dispatchEvent(new PointerEvent("pointerup", at(dx, dy)));
  }
  document.addEventListener("keydown", function (ev) {
    var t = ev.target && ev.target.tagName;
    if (!live() || t === "INPUT" || t === "SELECT" || t === "TEXTAREA" || ev.ctrlKey || ev.metaKey || ev.altKey) return;
    var views = { "1": "iso", "2": "top", "3": "front", "4": "right" }, centre = [ready.width >> 1, ready.height >> 1];
    var arrows = { ArrowLeft: [-10, 0], ArrowRight: [10, 0], ArrowUp: [0, -10], ArrowDown: [0, 10] };
    if (arrows[ev.key]) orbitBy(arrows[ev.key][0], arrows[ev.key][1]);
    else if (ev.key === "+" || ev.key === "=") zoom(1, centre);
    else if (ev.key === "-") zoom(-1, centre);
    else if (views[ev.key]) { $("view").value = views[ev.key]; ready.preset(views[ev.key]); redraw(); }
    else if (ev.key === "p") { $("path-overlay").checked = !$("path-overlay").checked; $("path-overlay").dispatchEvent(new Event("change")); }
    else if (ev.key === "r") $("zoom-reset").click();
    else return;
    ev.preventDefault();
  });

  /* A G-code file dropped on the page: into the file input, and run. */
  document.addEventListener("dragover", function (ev) { ev.preventDefault(); });
  document.addEventListener("drop", function (ev) {
    ev.preventDefault();
    var files = ev.dataTransfer && ev.dataTransfer.files;
    if (!files || !files.length) return;
    $("file").files = files;
    $("job").requestSubmit();
  });
})();
