/* page_scan.js - the job set up as `dexmill run FILE` sets it up: an empty
 * --stock or --grid means "from the program", the CLI's default, which
 * the engine's first pass chooses (engine_scan.js, web_scan.cpp); the file
 * is read once for it, rewound and cut. The form shows what was chosen
 * (its fields' placeholders and #scan-chosen), and #cut-progress the bytes
 * of the file read, through the first pass and then the cut. */
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

  return {
    prepare: async function (source, o) {
      counted(source);
      var stock = String(o.stock || "").trim(), grid = String(o.grid || "").trim();
      $("scan-chosen").textContent = "";
      if (stock && grid) return;
      if (!source.rewind) throw new Error("this program cannot be read twice: give --stock and --grid");
      dexmillPage.status("reading " + (source.name || "the program") + " for its stock and grid…");
      var r = await (await dexmillPage.engine).scan(source, { tool: o.tool, stock: stock });
      source.rewind();
      var said = [];
      if (!stock) {
        o.stock = r.stock;
        $("stock").placeholder = r.stock;
        said.push("--stock " + r.stock + " (from the " + r.stockFrom + ")");
      }
      if (!grid) {
        o.pitch = r.pitch;
        $("grid").placeholder = stock ? "pitch " + r.pitch : r.grid[0] + "x" + r.grid[1];
        said.push("--pitch " + r.pitch + (stock ? "" : " (" + r.grid[0] + "x" + r.grid[1] + " dexels)"));
      }
      $("scan-chosen").textContent = "from the program: " + said.join(", ") + "; " + r.units + ", " + r.lines +
        " lines, " + r.moves + " moves, " + r.tools + (r.tools === 1 ? " tool" : " tools");
    },
    finished: function (e, result) {
      var bar = $("cut-progress");
      if (result.progress.state === "done" && bar.max) bar.value = bar.max;
    }
  };
})());
