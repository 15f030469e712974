// The live part of a scene's page: the engine replays the construction as the student drags a
// given point or moves a slider; the step shown stays, the checks follow, a refused position
// shows its one-line error over the last good figure, and the scene as edited can be saved.
(function () {
'use strict';
var NS = 'http://www.w3.org/2000/svg';
var data = JSON.parse(document.getElementById('gs-data').textContent);
var name = data.name, scene = data.scene, good = clone(scene), handles = data.handles;
var engine = null, queued = false, drag = null, lastText = JSON.stringify(scene);
var times = [], last = null;
var figure = document.getElementById('wt-figure');
function clone(v) { return JSON.parse(JSON.stringify(v)); }
function svg() { return figure.querySelector('svg'); }
function el(id) { return document.getElementById(id); }

// A JSON pointer's value, and its setting (missing objects and arrays made on the way).
function setField(obj, ptr, v) {
  var parts = ptr.split('/').slice(1).map(function (p) { return p.replace(/~1/g, '/').replace(/~0/g, '~'); });
  var o = obj;
  for (var i = 0; i < parts.length - 1; i++) {
    var key = parts[i];
    if (o[key] === null || typeof o[key] !== 'object') o[key] = /^\d+$/.test(parts[i + 1]) ? [] : {};
    o = o[key];
  }
  o[parts[parts.length - 1]] = v;
}
// The round step (1, 2 or 5 times a power of ten) at or above `x`: a drag moves a value on
// the grid of the step worth two screen pixels, so that a student's variant has round
// numbers and a point can be put exactly on another one given on that grid.
function nice(x) {
  var p = Math.pow(10, Math.floor(Math.log10(x)));
  return [1, 2, 5, 10].map(function (m) { return m * p; }).filter(function (v) { return v >= x; })[0];
}
function snap(v, step) {
  var d = Math.max(0, Math.min(12, Math.ceil(-Math.log10(step) - 1e-9)));
  return Number((Math.round(v / step) * step).toFixed(d));
}

function showError(text) {
  var e = el('wt-error');
  if (!e) {
    e = document.createElement('p');
    e.id = 'wt-error';
    e.setAttribute('role', 'alert');
    document.body.insertBefore(e, document.querySelector('main'));
  }
  e.textContent = text;
  e.setAttribute('data-live', '1');
}
// Only the page's own error goes when a replay succeeds (serve's line about the file stays
// until the file is mended).
function clearError() { var e = el('wt-error'); if (e && e.getAttribute('data-live')) e.remove(); }

function drawHandles() {
  var s = svg();
  var old = s.querySelector('g.gs-handles');
  if (old) old.remove();
  var g = document.createElementNS(NS, 'g');
  g.setAttribute('class', 'gs-handles');
  handles.forEach(function (h, i) {
    var c = document.createElementNS(NS, 'circle');
    c.setAttribute('cx', h.at[0]);
    c.setAttribute('cy', h.at[1]);
    c.setAttribute('r', 2.2);
    c.setAttribute('class', 'gs-handle gs-' + h.drag.kind);
    c.setAttribute('data-handle', i);
    var t = document.createElementNS(NS, 'title');
    t.textContent = h.name + ': drag to move it';
    c.appendChild(t);
    g.appendChild(c);
  });
  s.appendChild(g);
}

function summary(a) {
  var n = a.checks.length;
  el('gs-summary').textContent = a.step_count + ' steps, ' + n + ' checks: ' +
    (a.failed === 0 ? 'all pass' : a.failed + ' fail');
  el('gs-summary').className = a.failed === 0 ? 'gs-pass' : 'gs-fail';
}

// Where a handle is held on the sheet: a point by itself, an angle by its centre.
function anchor(h) { return h.drag.kind === 'angle' ? h.center : h.at; }
function sameHandle(a, i) {
  var h = a.handles[i];
  if (h && h.name === drag.h.name && h.drag.field === drag.h.drag.field) return h;
  for (var j = 0; j < a.handles.length; j++) {
    h = a.handles[j];
    if (h.name === drag.h.name && h.drag.field === drag.h.drag.field) return h;
  }
  return null;
}

// Puts a built answer in place: figure, step list, handles, sliders' values, summary.
var phases = {};
function mark(name, t) { var n = performance.now(); phases[name] = (phases[name] || 0) + n - t; return n; }
// While the pointer moves (`light`), the engine answers with the current step's item alone
// and only the figure and that step's details are put in place; the step list follows when
// the pointer rests (`settle`).
var stale = false;
function apply(a, light) {
  var t = performance.now();
  var holder = document.createElement('div');
  holder.innerHTML = a.svg;
  var next = holder.querySelector('svg');
  t = mark('parse', t);
  svg().replaceWith(next);
  t = mark('swap', t);
  var walk = window.graphostatikWalk;
  if (a.page !== undefined && a.step_count === walk.pages) {
    walk.swapFigure(a.items[0]);
    stale = true;
    t = mark('step', t);
  } else {
    el('wt-steps').innerHTML = a.items.join('');
    stale = false;
    t = mark('items', t);
    walk.rebind();
    t = mark('rebind', t);
  }
  handles = a.handles;
  if (drag) {
    // The sheet stays where it was under the pointer: the held point (or centre) is kept at
    // the same place on the screen while the figure around it is drawn anew.
    var h = sameHandle(a, drag.index);
    if (h) {
      var an = anchor(h), target = drag.h.drag.kind === 'angle' ? drag.a0
        : [drag.p.x - drag.p0.x + drag.a0[0], drag.p.y - drag.p0.y + drag.a0[1]];
      next.dataset.viewBox = next.getAttribute('viewBox');
      next.dataset.width = next.getAttribute('width');
      next.dataset.height = next.getAttribute('height');
      next.setAttribute('viewBox', [drag.vb[0] + an[0] - target[0], drag.vb[1] + an[1] - target[1],
        drag.vb[2], drag.vb[3]].join(' '));
      next.setAttribute('width', drag.width);
      next.setAttribute('height', drag.height);
    }
  }
  drawHandles();
  t = mark('handles', t);
  a.sliders.forEach(function (sl, i) {
    var input = document.querySelector('#wt-sliders input[name=s' + i + ']');
    if (input && document.activeElement !== input) { input.value = sl.value; input.nextElementSibling.textContent = sl.value; }
  });
  summary(a);
  document.body.offsetHeight;
  mark('layout', t);
}

// The full answer once the pointer rests: the step list with every step's checks.
function settle() {
  if (stale) replay(true, false);
}

// Replays the scene as it stands now; a refused scene keeps the last good figure.
function replay(force, light) {
  var text = JSON.stringify(scene);
  if (!engine || (!force && text === lastText)) return null;
  lastText = text;
  var t0 = performance.now(), a;
  try {
    a = light ? engine.replay(name + '.json', text, window.graphostatikWalk.step())
      : engine.replay(name + '.json', text);
  } catch (e) {
    showError(String(e.message || e).split('\n')[0]);
    if (e.trapped) { engine = null; window.graphostatikEngine().then(function (x) { engine = x; }); }
    return null;
  }
  var t1 = performance.now();
  if (!a.ok) {
    showError(a.error);
  } else {
    clearError();
    good = clone(scene);
    last = a;
    apply(a, light);
  }
  var t2 = performance.now();
  var t = { engine: t1 - t0, total: t2 - t0, ok: a.ok };
  times.push(t);
  el('gs-time').textContent = a.ok ? 'replayed in ' + t.total.toFixed(1) + ' ms' : '';
  return t;
}
function request() {
  if (queued) return;
  queued = true;
  window.requestAnimationFrame(function () { queued = false; replay(false, true); });
}

function toSheet(e, inv) { return new DOMPoint(e.clientX, e.clientY).matrixTransform(inv); }
figure.addEventListener('pointerdown', function (e) {
  var c = e.target.closest && e.target.closest('.gs-handle');
  if (!c || !engine || e.button !== 0) return;
  var s = svg(), i = Number(c.getAttribute('data-handle')), h = handles[i];
  var inv = s.getScreenCTM().inverse(), p0 = toSheet(e, inv);
  // Sheet units (mm) per screen pixel, from the figure's scale on the screen now.
  var perPx = Math.sqrt(Math.abs(inv.a * inv.d - inv.b * inv.c));
  drag = { h: h, index: i, inv: inv, perPx: perPx, p0: p0, p: p0, a0: anchor(h).slice(),
    vb: s.getAttribute('viewBox').split(/[ ,]+/).map(Number),
    width: s.getAttribute('width'), height: s.getAttribute('height'),
    value: h.drag.value ? h.drag.value.slice() : null };
  figure.setPointerCapture(e.pointerId);
  figure.classList.add('gs-dragging');
  e.preventDefault();
});
figure.addEventListener('pointermove', function (e) {
  if (!drag) return;
  var p = toSheet(e, drag.inv), d = drag.h.drag;
  drag.p = p;
  if (d.kind === 'point') {
    var u = nice(2 * drag.perPx * d.per_mm);
    setField(scene, d.field, [snap(drag.value[0] + (p.x - drag.p0.x) * d.per_mm, u),
      snap(drag.value[1] - (p.y - drag.p0.y) * d.per_mm, u)]);
  } else {
    var rx = p.x - drag.a0[0], ry = -(p.y - drag.a0[1]);
    var phi = Math.atan2(ry, rx) * 180 / Math.PI;
    var r = Math.max(Math.sqrt(rx * rx + ry * ry), drag.perPx);
    var theta = ((d.zero_deg + d.sense * phi) % 360 + 360) % 360;
    setField(scene, d.field, snap(theta, Math.min(nice(2 * drag.perPx / r * 180 / Math.PI), 5)) % 360);
  }
  request();
});
function endDrag() {
  if (!drag) return;
  drag = null;
  figure.classList.remove('gs-dragging');
  var s = svg();
  ['viewBox', 'width', 'height'].forEach(function (k) {
    if (s.dataset[k]) { s.setAttribute(k, s.dataset[k]); delete s.dataset[k]; }
  });
  if (!replay(false, false)) {
    if (stale) settle(); else { window.graphostatikWalk.rebind(); drawHandles(); }
  }
}
figure.addEventListener('pointerup', endDrag);
figure.addEventListener('pointercancel', endDrag);

var form = el('wt-sliders');
if (form) {
  form.addEventListener('submit', function (e) { e.preventDefault(); });
  form.addEventListener('change', function () { if (!replay(false, false)) settle(); });
  form.addEventListener('input', function (e) {
    var input = e.target;
    if (!input.dataset.field) return;
    input.nextElementSibling.textContent = input.value;
    setField(scene, input.dataset.field, Number(input.value));
    request();
  });
}
el('gs-download').addEventListener('click', function () {
  var blob = new Blob([JSON.stringify(good, null, 2) + '\n'], { type: 'application/json' });
  var a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name + '.json';
  document.body.appendChild(a);
  a.click();
  a.remove();
});

window.graphostatikSite = {
  ready: false,
  times: times,
  phases: phases,
  scene: function () { return clone(scene); },
  good: function () { return clone(good); },
  // The last construction put in place: its steps, checks (with bounds) and handles.
  answer: function () { return last && { steps: last.step_count, checks: last.checks,
    failed: last.failed, handles: last.handles }; },
  // Replays the scene `n` times as it stands, as a drag does (engine and page update, ms
  // each); `full` also puts the step list in place each time, as the end of a drag does.
  bench: function (n, full) {
    var out = [];
    for (var i = 0; i < n; i++) { var t = replay(true, !full); if (t) out.push(t); }
    settle();
    return out;
  }
};
window.graphostatikEngine().then(function (x) {
  engine = x;
  // The first replay in the page: the figure, steps and handles from here on are the
  // engine's own.
  replay(true);
  el('gs-time').textContent = 'drag a point, or move a slider';
  window.graphostatikSite.ready = true;
}, function (e) { showError('the engine did not load: ' + e); });
})();
