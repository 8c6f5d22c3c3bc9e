/* web_probe.js - for the browser tests (web-test.sh, web-stream-test.sh):
 * a result of index.html's dexmillPage.run with what the page shows added,
 * the canvas's R, G, B bytes (base64) and the hash in its text, for
 * tools/scripts/web_compare.py. */
function dexmillProbe(r) {
  var px = document.getElementById("view-canvas").getContext("2d").getImageData(0, 0, r.width, r.height).data;
  var rgb = "";
  for (var k = 0; k < px.length; k += 4) rgb += String.fromCharCode(px[k], px[k + 1], px[k + 2]);
  r.rgb = btoa(rgb);
  r.shownHash = document.getElementById("hash").textContent;
  return r;
}
