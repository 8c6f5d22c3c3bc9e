/* page_colour.js - the page's colour modes: the form's --color, --thin and
 * --material (its list the engine's presets, engine_colour.js) handed to
 * the job once it is made (the created hook), as `dexmill run` takes them. */
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
    created: function (e, o) { e.colour(o); }
  });
})();
