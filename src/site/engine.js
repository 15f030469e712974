// The graphostatik engine in the page: the WebAssembly module (inlined above as base64, so
// that the page works from file:// with no server) behind a small object with one method,
// replay(name, sceneText) → the answer of graphostatik::web::replay as an object.
(function () {
'use strict';
var compiled = null;
function bytes(b64) {
  var s = atob(b64), a = new Uint8Array(s.length);
  for (var i = 0; i < s.length; i++) a[i] = s.charCodeAt(i);
  return a;
}
function Engine(instance) { this.x = instance.exports; }
Engine.prototype.put = function (text) {
  var b = new TextEncoder().encode(text), p = this.x.gs_alloc(b.length);
  new Uint8Array(this.x.memory.buffer, p, b.length).set(b);
  return [p, b.length];
};
Engine.prototype.read = function (ptr, len) {
  return new TextDecoder().decode(new Uint8Array(this.x.memory.buffer, ptr, len));
};
// A panic inside the engine traps (WebAssembly.RuntimeError); its message is kept by the
// engine's hook and thrown here as one line. The instance is not used again after a trap.
// `page` (optional): the answer of a drag on that page (its step item alone, no step list).
// `shown` (optional): the number of the figure the page shows (an answer's `figureId`); where
// it is the engine's last figure, the answer's `patch` holds what changed from it (the lines
// and the root's children that changed; null: none), and its `svg` is read only if asked
// for (the crane bridge's figure is 2 MB of text to decode).
Engine.prototype.replay = function (name, text, page, shown) {
  var n = this.put(name), t = this.put(text), len, x = this.x;
  try {
    len = x.gs_replay(n[0], n[1], t[0], t[1], page === undefined ? -1 : page,
      shown === undefined || shown === null ? -1 : shown);
  } catch (e) {
    var why = this.x.gs_panic_len() > 0 ? this.read(this.x.gs_panic_ptr(), this.x.gs_panic_len()) : String(e);
    var err = new Error('the engine stopped: ' + why);
    err.trapped = true;
    throw err;
  }
  var a = JSON.parse(this.read(x.gs_out_ptr(), len)), self = this;
  if (!a.ok) return a;
  // The figure comes apart from the JSON (its quotes unescaped), read when it is first asked
  // for, while it is still the engine's last.
  var id = x.gs_figure_id(), svg = null;
  a.figureId = id;
  Object.defineProperty(a, 'svg', { enumerable: true, get: function () {
    if (svg === null) {
      if (x.gs_figure_id() !== id) throw new Error('the figure of an earlier answer is gone');
      svg = self.read(x.gs_svg_ptr(), x.gs_svg_len());
    }
    return svg;
  } });
  a.patch = x.gs_patch_len() > 0 ? JSON.parse(this.read(x.gs_patch_ptr(), x.gs_patch_len())) : null;
  return a;
};
// What page `k` of the last scene built shows beside the figure (HTML; the answer when the
// pointer rests carries no page's details, the engine keeps the construction); null where
// there is no such page, or the engine stopped.
Engine.prototype.details = function (k) {
  var len;
  try { len = this.x.gs_details(k); } catch (e) { return null; }
  return len > 0 ? this.read(this.x.gs_details_ptr(), len) : null;
};
// A fresh engine: the module is compiled once per page, instantiated per call.
window.graphostatikEngine = function () {
  var m = compiled ? Promise.resolve(compiled)
    : WebAssembly.compile(bytes(window.graphostatikWasm)).then(function (c) { compiled = c; return c; });
  return m.then(function (c) { return WebAssembly.instantiate(c, {}); })
    .then(function (inst) { return new Engine(inst); });
};
})();
