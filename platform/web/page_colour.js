/* page_colour.js - the page's colour modes: the form's --color, --thin,
 * --material (its list the engine's presets, engine_colour.js) and
 * --design (an STL file, read whole before the job) handed to the job once
 * it is made (the created hook), as `dexmill run` takes them. */
"use strict";
(function () {
  var $ = function (id) { return document.getElementById(id); };
  dexmillPage.engine.then(function (e) {
    e.materialNames().forEach(function (name) {
      var opt = document.createElement("option");
      opt.textContent = name;
      $("material").appendChild(opt);
    });
  });
  dexmillPage.extend({
    options: function (o) {
      o.color = $("color").value;
      o.thin = $("thin").value;
      o.material = $("material").value;
    },
    prepare: async function (source, o) {
      var f = $("design").files[0];
      o.designBytes = f ? new Uint8Array(await f.arrayBuffer()) : null;
    },
    created: function (e, o) {
      if (o.designBytes) e.design(o.designBytes);
      e.colour(o);
    }
  });
})();
