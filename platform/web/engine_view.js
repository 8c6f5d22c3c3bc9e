/* engine_view.js - the Engine's view controls and findings
 * (platform/web/web_view.cpp's exports over display/api/dexmill.h): zoom
 * about a pixel, the toolpath overlay, the safety checks, the findings and
 * a marker at one of them. */
"use strict";
(function (P) {
  /* The CLI's --check names (tools/CLI.md) as dexmill.h's DM_CHECK_* bits. */
  var CHECKS = { rapid: 1, spindle: 2, below: 4, shank: 8, holder: 16, plunge: 32, all: 63 };
  P.checkBits = function (text) {
    var bits = 0;
    String(text || "").split(",").forEach(function (w) {
      w = w.trim();
      if (!w) return;
      if (!(w in CHECKS)) throw new Error("--check takes rapid, spindle, below, shank, holder, plunge or all, not '" + w + "'");
      bits |= CHECKS[w];
    });
    return bits;
  };
  /* steps (> 0 towards the scene) about the canvas pixel (x, y); redrawn. */
  P.zoom = function (steps, x, y) {
    this.check(this.x.web_zoom(steps, x, y), "zoom");
    this.render();
  };
  P.zoomReset = function () {
    this.check(this.x.web_zoom_reset(), "zoom");
    this.render();
  };
  /* A preset view (iso, top, front, right), its zoom kept; redrawn. */
  P.preset = function (name) {
    this.check(this.x.web_set_camera({ iso: 0, top: 1, front: 2, right: 3 }[name] || 0, 0, 0, 0), "camera");
    this.render();
  };
  /* Room for `segments` pieces of the toolpath, after the job is made and before the cut. */
  P.path = function (segments) { this.check(this.x.web_path(segments), "the path's memory"); };
  P.showPath = function (on) {
    this.check(this.x.web_path_show(on ? 1 : 0), "path");
    this.render();
  };
  P.pathInfo = function () {
    return { segments: this.x.web_path_count(), dropped: Number(this.x.web_path_dropped()) };
  };
  /* The findings kept: {kind, name, line, lastLine, atMm: [x, y, z], depthMm}. */
  P.findings = function () {
    var x = this.x, out = [];
    for (var k = 0, n = x.web_finding_count(); k < n; ++k) {
      this.check(x.web_finding(k), "finding");
      var kind = x.web_finding_kind();
      out.push({ kind: kind, name: this.cstring(x.web_finding_name(kind)), line: x.web_finding_line(),
                 lastLine: x.web_finding_last_line(),
                 atMm: [0, 1, 2].map(function (a) { return Number(x.web_finding_at_nm(a)) / 1e6; }),
                 depthMm: Number(x.web_finding_depth_nm()) / 1e6 });
    }
    return out;
  };
  /* The warnings kept (the first 16): {line, col, message}. */
  P.warnings = function () {
    var out = [], x = this.x;
    for (var k = 0; x.web_warning(k) > 0; ++k)
      out.push({ line: x.web_warning_line(), col: x.web_warning_col(), message: this.cstring(x.web_warning_text()) });
    return out;
  };
  /* A marker at finding k (k < 0: none); redrawn. */
  P.markFinding = function (k) {
    this.check(this.x.web_mark_finding(k), "mark");
    this.render();
  };
})(dexmill.Engine.prototype);
