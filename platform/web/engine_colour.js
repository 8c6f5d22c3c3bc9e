/* engine_colour.js - the loader's colour modes (platform/web/web_colour.cpp):
 * the job's --color, --thin, --material and --design as `dexmill run` takes them, and
 * the material presets' names as the engine lists them. */
"use strict";
(function () {
  var Engine = dexmill.Engine;
  /* display/api/dexmill.h DM_VIEW_*: web_create's preset, for the job made again. */
  var VIEW_NUMBER = { iso: 0, top: 1, front: 2, right: 3 };
  /* After e.job(o): o.color plain|slope|tool|material|thin|error, o.material a
   * preset's name ("" or none: no material), o.thin mm text ("" : 1 mm). */
  Engine.prototype.colour = function (o) {
    var mode = new TextEncoder().encode(o.color || "plain"), material = new TextEncoder().encode(o.material || ""),
        thin = new TextEncoder().encode(o.thin || ""), all = new Uint8Array(mode.length + material.length + thin.length);
    all.set(mode, 0);
    all.set(material, mode.length);
    all.set(thin, mode.length + material.length);
    this.put(all);
    this.check(this.x.web_colour(mode.length, material.length, thin.length, VIEW_NUMBER[o.view || "iso"],
                                 o.antialias ? 1 : 0, o.decorations ? 1 : 0), "--color " + (o.color || "plain"));
  };
  /* A design's STL file (its bytes, a Uint8Array) for the next colour():
   * read into triangles in the module; their count. */
  Engine.prototype.design = function (bytes) {
    var at = this.x.web_design_buffer(bytes.length);
    if (!at) throw new Error("--design: no memory for " + bytes.length + " bytes");
    this.bytes(at, bytes.length).set(bytes);
    var n = this.x.web_design_read();
    if (n < 0) this.check(-n, "--design");
    return n;
  };
  /* The material presets' names, in the engine's order. */
  Engine.prototype.materialNames = function () {
    var out = [];
    for (var k = 0, p; (p = this.x.web_material_name(k)) !== 0; ++k) out.push(this.cstring(p));
    return out;
  };
})();
