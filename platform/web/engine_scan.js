/* engine_scan.js - the first pass over a program (platform/web/web_scan.cpp,
 * display/api/dexmill.h dm_scan_*): what `dexmill run FILE` chooses when it
 * is given no --stock and no --grid, read from the engine, never decided
 * here. */
"use strict";
(function () {
  var READY = 0, NEED_INPUT = 1, DONE = 2;
  var FROM = ["program", "workpiece comment", "workpiece comment's box", "BLK FORM comments"];
  var UNITS = { "-1": "none", 0: "mm", 1: "inch", 2: "mixed" };

  /* nm (a BigInt) as the shortest exact mm text ("-12.5", "33.000087"). */
  function mmText(nm) {
    var neg = nm < 0n, a = neg ? -nm : nm, frac = String(a % 1000000n).padStart(6, "0").replace(/0+$/, "");
    return (neg ? "-" : "") + String(a / 1000000n) + (frac ? "." + frac : "");
  }

  /* Reads `source` (next(max) -> Promise of a Uint8Array, empty at its end)
   * through the scan with o.tool (the --tool text) and o.stock (the --stock
   * text, or none): {stock: the --stock text (o.stock's, or the program's),
   * pitch: the --pitch text for it, grid: [nx, ny] of the program's stock,
   * stockFrom, units, tableInch (a tool table's units for it), lines, moves,
   * tools}. o.table: with the tool table read (tools()). o.lines: lines a
   * step (default 4096). */
  dexmill.Engine.prototype.scan = async function (source, o) {
    var x = this.x, self = this, generation = ++this.generation, lines = o.lines || 4096, ended = false, state, k;
    function mine() { if (self.generation !== generation) throw new Error("replaced by a new job"); }
    this.check(x.web_scan_begin(this.put(o.tool || "flat:6"), o.table ? 1 : 0), "scan");
    if (o.stock) {
      var v = String(o.stock).split(",");
      if (v.length !== 6) throw new Error("stock: six comma-separated numbers (mm)");
      for (k = 0; k < 6; ++k) this.check(x.web_scan_set_stock(k, this.put(v[k])), "stock");
    }
    for (;;) {
      state = x.web_scan_step(lines);
      if (state < 0) this.check(-state, "scan");
      if (state === NEED_INPUT) {
        var piece = ended ? null : await source.next(x.web_text_bytes());
        mine();
        if (piece && piece.length) this.check(x.web_scan_feed(this.put(piece)), "scan");
        else { ended = true; this.check(x.web_scan_end_input(), "scan"); }
      } else if (state !== READY) break;
    }
    if (state !== DONE) throw new Error("scan: the program could not be read again");
    var status = x.web_scan_result(), stock = [];
    for (k = 0; k < 6; ++k) stock.push(mmText(x.web_scan_stock_nm(k)));
    var r = { stock: stock.join(","), pitch: mmText(x.web_scan_pitch_nm()), grid: [x.web_scan_grid_nx(), x.web_scan_grid_ny()],
              stockFrom: FROM[x.web_scan_stock_from()], units: UNITS[x.web_scan_units()], lines: x.web_scan_lines(),
              moves: Number(x.web_scan_moves()), tools: x.web_scan_tools(), tableInch: x.web_scan_table_units() === 1 };
    this.check(status, "the program's stock");
    return r;
  };

  /* A LinuxCNC tool table's bytes (the CLI's --tools), lengths in inch when
   * `inch`, read in the module for the scan and the job: null, or the
   * error {line, col, message} as the CLI says it. */
  dexmill.Engine.prototype.tools = function (bytes, inch) {
    var x = this.x, s = x.web_tools_parse(this.put(bytes), inch ? 1 : 0);
    if (s === 0) return null;
    return { line: x.web_tools_line(), col: x.web_tools_col(), message: this.cstring(x.web_tools_message()) };
  };
})();
