/* page_scan.js - the job set up as `dexmill run FILE` sets it up: an empty
 * --stock or --grid means "from the program", the CLI's default, which
 * the engine's first pass chooses (engine_scan.js, web_scan.cpp); the file
 * is read once for it, rewound and cut. A --tools table (#tools-file, a
 * LinuxCNC .tbl) is read in the module (web_tools.cpp) in the units the
 * CLI reads it in, its errors as FILE:LINE:COL: error: .... The form shows
 * what was chosen (its fields' placeholders and #scan-chosen), and
 * #cut-progress the bytes of the file read, through the passes and the cut.
 * #demo cuts the built-in demo (web_demo.cpp) the same way. */
"use strict";
dexmillPage.extend((function () {
  var $ = function (id) { return document.getElementById(id); };

  /* The source's next() counted into the progress bar; the count restarts when it is rewound. */
  function counted(source) {
    var bar = $("cut-progress"), read = 0, next = source.next, rewind = source.rewind;
    if (source.size > 0) { bar.max = source.size; bar.value = 0; } else bar.removeAttribute("value");
    source.next = async function (max) {
      var piece = await next.call(source, max);
      read += piece.length;
      if (source.size > 0) bar.value = Math.min(read, source.size);
      return piece;
    };
    if (rewind) source.rewind = function () { read = 0; rewind.call(source); };
  }

  /* A --tools table's error as `dexmill run` prints it, in the page's error list. */
  function tableError(name, err) {
    var li = document.createElement("li");
    li.textContent = name + ":" + err.line + ":" + err.col + ": error: " + err.message;
    $("errors").textContent = "";
    $("errors").appendChild(li);
    return new Error("the tool table '" + name + "' does not read");
  }

  /* The job's --pitch or --tools, set between the form's options and the job made (dexmill.js). */
  function configure(o, f) { (o.configure = o.configure || []).push(f); }

  /* The built-in demo, as `dexmill run --demo pocket` cuts it (web_demo.cpp):
   * its program as a file, its stock, an empty grid (the program's), its
   * tool table and its material in the form, coloured by the material as the
   * CLI colours it when no --color is given, then the Run path. */
  async function demo() {
    var e = await dexmillPage.engine, n = e.x.web_demo_program();
    if (n < 0) e.check(-n, "demo");
    var program = e.bytes(e.x.web_demo_text_at(), n).slice(), dt = new DataTransfer();
    $("stock").value = e.cstring(e.x.web_demo_text(0));
    $("grid").value = "";
    dt.items.add(new File([e.cstring(e.x.web_demo_text(1))], "demo.tbl"));
    $("tools-file").files = dt.files;
    $("material").value = e.cstring(e.x.web_demo_text(2));
    $("color").value = "material";
    dexmillPage.status("cutting the demo…");
    return dexmillPage.run(dexmill.blobSource(new File([program], "demo.ngc")));
  }
  dexmillPage.demo = demo;  /* the Demo button's, and tools/scripts/web-test.sh's */
  $("demo").addEventListener("click", function () {
    dexmillPage.running = demo();
    dexmillPage.running.catch(function (err) { dexmillPage.status("error: " + err.message); });
  });

  return {
    /* The first passes: one for the units a --tools table is read in
     * (core/sim/tool_units.h's rule), one with its tools for the stock and
     * grid left empty; the file rewound after each. */
    prepare: async function (source, o) {
      counted(source);
      var e = await dexmillPage.engine, table = $("tools-file").files[0] || null;
      var stock = String(o.stock || "").trim(), grid = String(o.grid || "").trim(), said = [];
      $("scan-chosen").textContent = "";
      if ((table || !stock || !grid) && !source.rewind)
        throw new Error("this program cannot be read twice: give --stock and --grid, and no --tools");
      if (table) {
        dexmillPage.status("reading " + (source.name || "the program") + " for its tool table's units…");
        var units = await e.scan(source, { tool: o.tool, stock: stock });
        source.rewind();
        var err = e.tools(new Uint8Array(await table.arrayBuffer()), units.tableInch);
        if (err) throw tableError(table.name, err);
        configure(o, function (eng) { eng.check(eng.x.web_set_tools(), "tools"); });
        said.push("--tools " + table.name + " read in " + (units.tableInch ? "inch" : "mm") + " (" + e.x.web_tools_count() + " tools that cut)");
      } else e.tools(new Uint8Array(0), false);
      if (!stock || !grid) {
        dexmillPage.status("reading " + (source.name || "the program") + " for its stock and grid…");
        var r = await e.scan(source, { tool: o.tool, stock: stock, table: !!table });
        source.rewind();
        if (!stock) {
          o.stock = r.stock;
          $("stock").placeholder = r.stock;
          said.push("--stock " + r.stock + " (from the " + r.stockFrom + ")");
        }
        if (!grid) {
          configure(o, function (eng) { eng.check(eng.x.web_set_pitch(eng.put(r.pitch)), "pitch"); });
          $("grid").placeholder = stock ? "pitch " + r.pitch : r.grid[0] + "x" + r.grid[1];
          said.push("--pitch " + r.pitch + (stock ? "" : " (" + r.grid[0] + "x" + r.grid[1] + " dexels)"));
        }
        said.push(r.units + ", " + r.lines + " lines, " + r.moves + " moves, " + r.tools + (r.tools === 1 ? " tool" : " tools"));
      }
      $("scan-chosen").textContent = said.length ? "as dexmill run chooses: " + said.join("; ") : "";
    },
    finished: function (e, result) {
      var bar = $("cut-progress");
      if (result.progress.state === "done" && bar.max) bar.value = bar.max;
    }
  };
})());
