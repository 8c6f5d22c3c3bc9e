/* dexmill.js - the page's side of dexmill.wasm: loads the module (its bytes
 * are DEXMILL_WASM_BASE64, put in front of this file by
 * tools/scripts/web_embed.sh), sets a job up with the CLI's option texts,
 * feeds the program in pieces, steps it a slice at a time so the page stays
 * live, and copies the XRGB8888 frame into a canvas. The exports it calls
 * are platform/web/web_api.cpp's; the states and statuses are
 * display/api/dexmill.h's. No framework, no request: plain script.
 */
"use strict";
var dexmill = (function () {
  var READY = 0, NEED_INPUT = 1, DONE = 2, STOPPED = 3;
  var VIEWS = { iso: 0, top: 1, front: 2, right: 3 };
  /* The presets' eye directions, [azimuth, elevation] in degrees: where an orbit starts. */
  var PRESET_ANGLES = { iso: [-45, 35.264], top: [-90, 90], front: [-90, 0], right: [0, 0] };
  var STATES = ["ready", "need input", "done", "stopped", "input error"];

  function wasmBytes() {
    var s = atob(DEXMILL_WASM_BASE64), b = new Uint8Array(s.length);
    for (var i = 0; i < s.length; ++i) b[i] = s.charCodeAt(i);
    return b;
  }

  /* "AxB" as two positive integers (the CLI's --grid and --size). */
  function pair(text, what) {
    var m = /^\s*(\d+)\s*x\s*(\d+)\s*$/.exec(text || "");
    if (!m) throw new Error(what + ": not WxH: '" + text + "'");
    return [parseInt(m[1], 10), parseInt(m[2], 10)];
  }

  /* Lets the page run (events, painting) and comes back at once: a message
   * to itself, as setTimeout(0) waits 4 ms or more once nested. */
  var channel = new MessageChannel(), resumes = [];
  channel.port1.onmessage = function () { resumes.shift()(); };
  function yieldToPage() {
    return new Promise(function (r) { resumes.push(r); channel.port2.postMessage(0); });
  }

  function Engine(exports) {
    this.x = exports;
    this.width = 0;
    this.height = 0;
    this.generation = 0;  /* jobs made: one job at a time lives in the module */
  }
  Engine.prototype.bytes = function (ptr, n) { return new Uint8Array(this.x.memory.buffer, ptr, n); };
  Engine.prototype.cstring = function (ptr) {
    var b = new Uint8Array(this.x.memory.buffer), end = ptr;
    while (b[end]) ++end;
    return new TextDecoder().decode(b.subarray(ptr, end));
  };
  /* Text into web_text()'s buffer; its length in bytes. */
  Engine.prototype.put = function (text) {
    var b = typeof text === "string" ? new TextEncoder().encode(text) : text;
    if (b.length > this.x.web_text_bytes()) throw new Error("text too long");
    this.bytes(this.x.web_text(), b.length).set(b);
    return b.length;
  };
  Engine.prototype.check = function (status, what) {
    if (status !== 0) throw new Error(what + ": " + this.cstring(this.x.web_status_message(status)));
  };

  /* A job from the CLI's texts: o.stock "X0,Y0,Z0,X1,Y1,Z1" (mm), o.tool
   * "flat:6", o.grid "NXxNY", o.size "WxH", o.view iso|top|front|right,
   * o.antialias and o.decorations as `dexmill run` draws its images. */
  Engine.prototype.job = function (o) {
    var x = this.x, v = String(o.stock || "").split(",");
    ++this.generation;  /* a run of the job before stops at its next await */
    this.check(x.web_job(), "job");
    if (v.length !== 6) throw new Error("stock: six comma-separated numbers (mm)");
    for (var k = 0; k < 6; ++k) this.check(x.web_set_stock(k, this.put(v[k])), "stock");
    this.check(x.web_set_tool(this.put(o.tool || "flat:6")), "tool");
    var g = o.grid ? pair(o.grid, "grid") : [0, 0], s = pair(o.size || "640x480", "size");
    this.check(x.web_set_grid(g[0], g[1]), "grid");
    /* Topics' settings of the job, before it is made (page_scan.js: --pitch, --tools; page_view.js: --check). */
    (o.configure || []).forEach(function (f) { f(this); }, this);
    var view = VIEWS[o.view || "iso"];
    if (view === undefined) throw new Error("view: iso, top, front or right");
    this.check(x.web_create(s[0], s[1], view, o.antialias ? 1 : 0, o.decorations ? 1 : 0), "the job");
    this.width = s[0];
    this.height = s[1];
  };

  Engine.prototype.progress = function () {
    var x = this.x;
    this.check(x.web_progress(), "progress");
    return {
      state: STATES[x.web_state()] || "?", stopReason: x.web_stop_reason(), line: x.web_line(),
      linesRead: x.web_lines_read(), moves: Number(x.web_moves()), errors: x.web_errors(),
      warnings: x.web_warnings(), removedMm3: Number(x.web_removed_um3()) / 1e9,
      machineSeconds: Number(x.web_machine_time_us()) / 1e6
    };
  };
  /* The input errors kept: {line, col, message}. */
  Engine.prototype.inputErrors = function () {
    var out = [], x = this.x;
    for (var k = 0; x.web_error_message(k) > 0; ++k)
      out.push({ line: x.web_error_line(k), col: x.web_error_col(k), message: this.cstring(x.web_message()) });
    return out;
  };

  /* Cuts the program of `source` (next(max) -> Promise of a Uint8Array, empty
   * at its end). Every o.sliceMs (default 30) it calls o.onSlice(progress,
   * drawn) and lets the page run; it draws the frame first (drawn true)
   * unless the last drawing took more than a quarter of the time since it: a
   * fine grid's redraw can cost more than the cut (drawn every slice,
   * KB-850's at 1012 x 1024 dexels took 5x as long). o.moves is a step's
   * budget (default 256). A pace (o.pace or this.pace, engine_replay.js:
   * wait(engine) -> ms ahead of the wall clock or paused, 0 due, -1 not
   * pacing) holds the cut
   * to machine time: a move a step, and while it is ahead (to the last
   * move's end) the frame is drawn and the page runs; none, or one at full
   * speed, cuts as before. */
  Engine.prototype.run = async function (source, o) {
    o = o || {};
    var pace = o.pace || this.pace || null;
    var x = this.x, moves = o.moves || 256, sliceMs = o.sliceMs || 30, state = READY, ended = false;
    var last = performance.now(), drawn = -Infinity, drawCost = 0, generation = this.generation, self = this;
    /* After each await: the module may hold another job now (Run again). */
    function mine() { if (self.generation !== generation) throw new Error("replaced by a new job"); }
    /* Ahead of machine time, or paused: the frame shown, the page runs a while. */
    async function hold(ms) {
      self.render();
      if (o.onSlice) o.onSlice(self.progress(), true);
      await new Promise(function (r) { setTimeout(r, Math.min(ms, sliceMs)); });
      mine();
      last = performance.now();
    }
    while (state === READY || state === NEED_INPUT) {
      var ahead = pace ? pace.wait(this) : -1;
      if (ahead > 0) {
        await hold(ahead);
        continue;
      }
      state = x.web_step(ahead < 0 ? moves : 1);
      if (state < 0) this.check(-state, "step");
      if (state === NEED_INPUT) {
        var piece = ended ? null : await source.next(x.web_text_bytes());
        mine();
        if (piece && piece.length) this.check(x.web_feed(this.put(piece)), "feed");
        else { ended = true; this.check(x.web_end_input(), "end of input"); }
      } else if (performance.now() - last > sliceMs) {
        var t = performance.now(), draw = t - drawn > 4 * drawCost;
        if (draw) this.render();
        if (o.onSlice) o.onSlice(this.progress(), draw);
        if (draw) {
          drawn = performance.now();
          drawCost = drawn - t;
        }
        await yieldToPage();
        mine();
        last = performance.now();
      }
    }
    for (var wait; pace && (wait = pace.wait(this)) > 0;) await hold(wait);  /* the last move's time */
    this.render();
    return this.progress();
  };

  /* The eye's azimuth (around +z from +x) and elevation in degrees, as the
   * CLI's --azimuth and --elevation, redrawn whole; a preset's are PRESET_ANGLES
   * (display/raster/camera.h). */
  Engine.prototype.orbit = function (azimuthDeg, elevationDeg) {
    var el = Math.max(-90, Math.min(90, elevationDeg)), az = ((azimuthDeg % 360) + 540) % 360 - 180;  /* -180..180 */
    this.check(this.x.web_set_camera(0, 1, Math.round(az * 1000), Math.round(el * 1000)), "camera");
    this.render();
  };

  Engine.prototype.render = function () {
    var n = this.x.web_render();
    if (n < 0) this.check(-n, "render");
  };
  /* The frame (XRGB8888, 0xFFRRGGBB little-endian: B, G, R, X) into a
   * canvas's 2D context as RGBA. */
  Engine.prototype.draw = function (ctx) {
    var n = this.width * this.height, src = this.bytes(this.x.web_pixels(), n * 4);
    if (!this.img || this.img.width !== this.width || this.img.height !== this.height)
      this.img = ctx.createImageData(this.width, this.height);  /* one a job: no garbage a frame */
    var img = this.img, d = img.data;
    for (var i = 0; i < n * 4; i += 4) {
      d[i] = src[i + 2];
      d[i + 1] = src[i + 1];
      d[i + 2] = src[i];
      d[i + 3] = 255;
    }
    ctx.putImageData(img, 0, 0);
  };

  /* A File or Blob read in pieces: only a piece is held. Into one buffer
   * where the browser reads blobs as byte streams (a BYOB reader hands the
   * buffer back), so that a long file leaves no garbage behind (a new
   * buffer a piece, 64 KiB each, cost a 35 MB program's tab 50 MB more at
   * its peak, tools/scripts/web-stream-test.sh); else, and after a stream
   * read that stalled, by Blob.slice. */
  function blobSource(blob) {
    var at = 0, reader = null, buf = null, source;
    function open() {
      at = 0;
      try { reader = blob.stream().getReader({ mode: "byob" }); } catch (e) { reader = null; }
    }
    /* A read of the stream that has not come in STALL_MS is given up, and
     * the rest read by Blob.slice from where the stream left: Chromium now
     * and then never settles a Blob stream's read after the same Blob's
     * stream was read to its end (make test-web in CI, a first pass then
     * the second: the page waited for ever). */
    var STALL_MS = 2000;
    async function streamed(max) {
      if (!buf || buf.byteLength < max) buf = new ArrayBuffer(max);
      var timer = null, pending = reader.read(new Uint8Array(buf, 0, max));
      var r = await Promise.race([pending, new Promise(function (done) { timer = setTimeout(done, STALL_MS, null); })]);
      clearTimeout(timer);
      if (r === null) {
        pending.catch(function () { /* given up: its answer is not wanted */ });
        reader.cancel().catch(function () { /* the same */ });
        reader = null;
        buf = null;  /* lent to the read given up */
        ++source.stalls;
        return sliced(max);
      }
      if (r.done) return new Uint8Array(0);
      buf = r.value.buffer;
      at += r.value.length;
      return r.value;
    }
    async function sliced(max) {
      var piece = blob.slice(at, Math.min(blob.size, at + max));
      at += piece.size;
      return new Uint8Array(await piece.arrayBuffer());
    }
    open();
    source = {
      name: blob.name || "program",  /* a File's name, for FILE:LINE:COL */
      size: blob.size,               /* bytes, for a progress bar */
      blob: blob,                    /* the program itself: a finding's line read again (page_view.js) */
      stalls: 0,                     /* stream reads given up (then read by Blob.slice) */
      /* From the start again (a first pass read it: page_scan.js). */
      rewind: function () {
        if (reader) reader.cancel().catch(function () { /* a finished stream: nothing to cancel */ });
        open();
      },
      next: function (max) { return reader ? streamed(max) : sliced(max); }
    };
    return source;
  }


  /* FNV-1a (32 bits) of the R, G, B bytes of RGBA pixels, as hex: the pixel
   * hash tools/scripts/web-test.sh computes of `dexmill run --image`'s. */
  function fnv1aRgb(rgba) {
    var h = 0x811c9dc5;
    for (var i = 0; i < rgba.length; ++i) {
      if ((i & 3) === 3) continue;
      h = Math.imul(h ^ rgba[i], 16777619) >>> 0;
    }
    return ("0000000" + h.toString(16)).slice(-8);
  }

  function load() {
    return WebAssembly.instantiate(wasmBytes(), {}).then(function (r) { return new Engine(r.instance.exports); });
  }

  /* Engine: a topic of the loader (engine_*.js, after this file in the
   * built dexmill.js) adds its methods to Engine.prototype. */
  return { load: load, blobSource: blobSource, fnv1aRgb: fnv1aRgb, PRESET_ANGLES: PRESET_ANGLES, DONE: DONE,
           STOPPED: STOPPED, Engine: Engine };
})();
