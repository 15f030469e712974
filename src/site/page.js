// The live part of a scene's page: the engine replays the construction as the student drags a
// given point or moves a slider; the step shown stays, the checks follow, a refused position
// shows its one-line error over the last good figure, and the scene as edited can be saved.
(function () {
'use strict';
var NS = 'http://www.w3.org/2000/svg';
var data = JSON.parse(document.getElementById('gs-data').textContent);
var name = data.name, scene = data.scene, good = clone(scene), handles = data.handles;
var engine = null, queued = false, drag = null, lastText = JSON.stringify(scene);
var times = [], last = null, counts = { splice: 0, parsed: 0, list: 0, lines: 0 };
var figure = document.getElementById('wt-figure');
function clone(v) { return JSON.parse(JSON.stringify(v)); }
function svg() { return figure.querySelector('svg'); }
// The sheet's stage: a drag keeps the sheet under the pointer by a CSS translation of the
// stage (of the figure's root it would lay out every text anew: 7 ms a replay for the shed
// roof's 451, 30 ms for the crane bridge's 5,299; of the stage, none).
var stage = document.createElement('div');
stage.className = 'gs-sheet';
figure.insertBefore(stage, svg());
stage.appendChild(svg());
function el(id) { return document.getElementById(id); }

// A JSON pointer's value, and its setting (missing objects and arrays made on the way).
function getField(obj, ptr) {
  return ptr.split('/').slice(1).reduce(function (o, p) {
    return o === null || o === undefined ? o : o[p.replace(/~1/g, '/').replace(/~0/g, '~')];
  }, obj);
}
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
  var s = svg(), old = s.lastElementChild;
  if (!old || old.getAttribute('class') !== 'gs-handles') old = null;
  // A drag's replay moves the handles: where they are the same handles, they are moved.
  var same = old && old.children.length === handles.length && handles.every(function (h, i) {
    var c = old.children[i];
    return c.getAttribute('class') === 'gs-handle gs-' + h.drag.kind &&
      c.textContent === h.name + ': drag to move it';
  });
  if (same) {
    handles.forEach(function (h, i) {
      var c = old.children[i], x = String(h.at[0]), y = String(h.at[1]);
      if (c.getAttribute('cx') !== x) c.setAttribute('cx', x);
      if (c.getAttribute('cy') !== y) c.setAttribute('cy', y);
    });
    return;
  }
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

// The figure in place as text and nodes, so that a replay whose figure has the same elements
// in the same order (a drag moves points; it seldom adds or drops one) sets the attributes
// and texts that changed instead of parsing a new SVG and laying it out anew. The figure is
// written one tag or one text per line. It is kept by the root's children (the title, the
// style, the definitions, the sheet and one layer per step): a child whose elements changed
// (a label that took a leader) is parsed alone and put in place of the old one. A child is
// kept as `lines` (its text by line), `els[i]` (the element line i opens; null for an end
// tag or a text), `root[i]` (the line of the outermost `text`, `style` or `title` around
// line i, -1 outside one) and `end[i]` (the line that closes the element of line i).
var shown = null;
function kindOf(line) {
  if (line.charCodeAt(0) !== 60) return '#';
  if (line.charCodeAt(1) === 47) return '/';
  var m = /^<([^\s/>]+)/.exec(line);
  return m ? m[1] : '?';
}
function opens(line) { return line.slice(-2) !== '/>' && line.indexOf('</') < 0; }
// The root's children as line ranges [first, last]; null where the text is not one root
// element written a tag or a text per line.
function children(lines) {
  var out = [], depth = 0, first = -1;
  for (var i = 1; i < lines.length; i++) {
    var l = lines[i], k = kindOf(l);
    if (k === '/') {
      depth--;
      if (depth < 0) {
        for (var j = i + 1; j < lines.length; j++) if (lines[j] !== '') return null;
        return out;
      }
      if (depth === 0) out.push([first, i]);
    } else if (k === '#') {
      if (depth === 0 && l !== '') return null;
    } else if (opens(l)) {
      if (depth === 0) first = i;
      depth++;
    } else if (depth === 0) {
      out.push([i, i]);
    }
  }
  return null;
}
// A child of the root as the page keeps it, or null where its element and its lines differ.
// Inside a text, style or title, `txt[i]` is the text node of text line i (the element's
// child between the tags around it).
function keep(el, lines) {
  var all = [el].concat(Array.prototype.slice.call(el.getElementsByTagName('*')));
  var n = lines.length, els = new Array(n), roots = new Array(n), end = new Array(n), txt = new Array(n);
  var open = [], cur = {}, j = 0, outer = -1;
  // Moves the cursor of the element opened on line p past its next child of node type t
  // (or past node `to`), and gives that child.
  var next = function (p, t, to) {
    var kids = els[p].childNodes, c = cur[p] || 0;
    while (c < kids.length && (to ? kids[c] !== to : kids[c].nodeType !== t)) c++;
    cur[p] = c + 1;
    return kids[c];
  };
  for (var i = 0; i < n; i++) {
    var l = lines[i], k = kindOf(l), p = open[open.length - 1];
    roots[i] = outer;
    els[i] = null;
    if (k === '/') {
      var s = open.pop();
      if (s === undefined) return null;
      end[s] = i;
      if (s === outer) outer = -1;
    } else if (k !== '#') {
      var e = all[j++];
      if (!e || e.localName !== k) return null;
      els[i] = e;
      if (outer >= 0 && next(p, 1, e) !== e) return null;
      if (opens(l)) {
        open.push(i);
        if (outer < 0 && (k === 'text' || k === 'style' || k === 'title')) outer = i;
      } else {
        // A text on one line holds its spans: they are set with it.
        j += e.getElementsByTagName('*').length;
      }
    } else if (outer < 0) {
      return null;
    } else {
      // A text of several lines (a style sheet) is one node.
      txt[i] = i > 0 && kindOf(lines[i - 1]) === '#' ? txt[i - 1] : next(p, 3);
    }
  }
  return j === all.length && open.length === 0
    ? { el: el, lines: lines, els: els, root: roots, end: end, txt: txt } : null;
}
function remember(svgEl, text) {
  var lines = text.split('\n'), ranges = children(lines), kids = svgEl.children, out = [];
  shown = null;
  if (!ranges || ranges.length !== kids.length) return;
  for (var i = 0; i < ranges.length; i++) {
    var c = keep(kids[i], lines.slice(ranges[i][0], ranges[i][1] + 1));
    if (!c) return;
    out.push(c);
  }
  shown = { svg: svgEl, kids: out };
}
function decode(v) {
  return v.indexOf('&') < 0 ? v : v.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"')
    .replace(/&#39;/g, "'").replace(/&amp;/g, '&');
}
// The start tag's attributes (a text on one line holds its spans' tags after it; a '>' in a
// value is escaped, so the first one ends the tag).
function attributes(line) {
  var gt = line.indexOf('>');
  if (gt >= 0) line = line.slice(0, gt + 1);
  var out = {}, re = /\s([^\s=]+)="([^"]*)"/g, m;
  while ((m = re.exec(line))) out[m[1]] = m[2];
  return out;
}
// The sheet's size and view box stay as they were while a drag holds the sheet: the answer's
// wait in the element's data set until the pointer is released, and the sheet is moved under
// the pointer by a CSS translation, which the browser composes without laying the figure out
// again. A root attribute is set only where it changed: setting the view box, even to the
// value it has, lays out every text anew (~120 ms for the crane bridge's 5,299).
var HELD = ['viewBox', 'width', 'height'];
function setRoot(s, line) {
  var a = attributes(line);
  for (var k in a) {
    var v = decode(a[k]);
    if (drag && HELD.indexOf(k) >= 0) s.dataset[k] = v;
    else if (s.getAttribute(k) !== v) s.setAttribute(k, v);
  }
}
// A figure parsed anew during a drag: its size and view box as the drag holds them.
function hold(s) {
  HELD.forEach(function (k) { s.dataset[k] = s.getAttribute(k); s.setAttribute(k, drag.held[k]); });
}
function setAttributes(e, was, now) {
  var a = attributes(was), b = attributes(now), k;
  for (k in b) if (a[k] !== b[k]) e.setAttribute(k, decode(b[k]));
  for (k in a) if (!(k in b)) e.removeAttribute(k);
}
// The lines of child c that changed, or null where an element changed (its name, or an
// element or end tag for a text).
function changes(c, lines) {
  if (lines.length !== c.lines.length) return null;
  var out = [];
  for (var i = 0; i < lines.length; i++) {
    if (lines[i] === c.lines[i]) continue;
    var k = kindOf(lines[i]);
    if (k !== kindOf(c.lines[i]) || k === '/' || (k === '#' && c.root[i] < 0)) return null;
    out.push(i);
  }
  return out;
}
// Puts the figure `text` in place of the one shown by changing what changed; false where the
// root's children differ from those shown (then it is parsed anew).
function patch(text) {
  if (!shown || shown.svg !== svg()) return false;
  var lines = text.split('\n'), ranges = children(lines);
  if (!ranges || ranges.length !== shown.kids.length) return false;
  setRoot(shown.svg, lines[0]);
  for (var i = 0; i < ranges.length; i++) {
    var c = shown.kids[i], now = lines.slice(ranges[i][0], ranges[i][1] + 1), changed = changes(c, now);
    if (changed) {
      if (!update(c, now, changed)) { shown = null; return false; }
    } else if (!replaceChild(i, now)) {
      return false;
    }
  }
  return true;
}
// Puts root child i anew from its lines: parsed alone, taken in, put in place of the one
// shown and marked fresh (its layers are set up anew). False, and nothing kept of the figure
// shown, where the lines do not give one element.
function replaceChild(i, lines) {
  var holder = document.createElementNS(NS, 'svg');
  holder.innerHTML = lines.join('\n');
  var el = holder.firstElementChild, kept = el && shown.kids[i] && keep(el, lines);
  if (!kept) { shown = null; return false; }
  shown.kids[i].el.replaceWith(el);
  shown.kids[i] = kept;
  fresh.push(el);
  return true;
}
// Puts the figure in place from the engine's patch `p` against the figure shown (what changed,
// found by the engine: web::figure_patch): the root's tag, the lines that changed by child,
// the children whose elements changed whole. False where it cannot (the figure is then
// taken whole).
function applyPatch(p) {
  if (!shown || shown.svg !== svg()) return false;
  if (p.root) setRoot(shown.svg, p.root);
  if (p.splice && !splice(p.splice)) return false;
  var by = {};
  p.lines.forEach(function (x) { (by[x[0]] = by[x[0]] || []).push(x); });
  for (var k in by) {
    var c = shown.kids[k];
    if (!c) { shown = null; return false; }
    var now = c.lines.slice(), sets = {};
    var changed = by[k].map(function (x) { now[x[1]] = x[2]; if (x[3]) sets[x[1]] = x[3]; return x[1]; });
    if (!update(c, now, changed, sets)) { shown = null; return false; }
  }
  for (var i = 0; i < p.children.length; i++) {
    if (!replaceChild(p.children[i][0], p.children[i][1].split('\n'))) return false;
  }
  return true;
}
// Takes out `removed` children of the root from child `at` on and puts the `added` ones (each
// its text) in their place: a step more or fewer. False, and nothing kept of the figure
// shown, where the children are not those shown or the texts are not one element each.
function splice(sp) {
  var kids = shown.kids;
  if (sp.at + sp.removed > kids.length) { shown = null; return false; }
  var holder = document.createElementNS(NS, 'svg');
  holder.innerHTML = sp.added.join('\n');
  var els = Array.prototype.slice.call(holder.children), put = [];
  if (els.length !== sp.added.length) { shown = null; return false; }
  for (var i = 0; i < els.length; i++) {
    var kept = keep(els[i], sp.added[i].split('\n'));
    if (!kept) { shown = null; return false; }
    put.push(kept);
  }
  // (Past the last child: before what the page put after it, the handles.)
  var after = sp.at + sp.removed < kids.length ? kids[sp.at + sp.removed].el
    : kids.length ? kids[kids.length - 1].el.nextSibling : null;
  // Each child is written on lines of its own: the line break after it goes and comes with it.
  kids.slice(sp.at, sp.at + sp.removed).forEach(function (c) {
    var n = c.el.nextSibling;
    if (n && n.nodeType === 3 && n.data === '\n') n.remove();
    c.el.remove();
  });
  els.forEach(function (e) {
    shown.svg.insertBefore(e, after);
    shown.svg.insertBefore(document.createTextNode('\n'), after);
    fresh.push(e);
  });
  Array.prototype.splice.apply(kids, [sp.at, sp.removed].concat(put));
  counts.splice++;
  return true;
}
// Sets the changed lines of child c in place: a tag's attributes, a text's node; a text
// whose node does not hold the old line alone (a style sheet's) has its text, style or title
// written anew. `sets` (from the engine's patch) gives, by line, a tag's attributes that
// changed as name, value, … (null for one gone), so that neither tag need be read.
function update(c, lines, changed, sets) {
  var redone = {};
  changed.forEach(function (i) {
    var r = c.root[i];
    if (redone[r]) return;
    if (kindOf(lines[i]) === '#') {
      var t = c.txt[i];
      if (t && t.data === '\n' + decode(c.lines[i]) + '\n') t.data = '\n' + decode(lines[i]) + '\n';
      else { redone[r] = true; rewrite(c, r, lines); }
    } else {
      var e = c.els[i], set = sets && sets[i];
      if (set) {
        for (var j = 0; j < set.length; j += 2) {
          if (set[j + 1] === null) e.removeAttribute(set[j]);
          else e.setAttribute(set[j], decode(set[j + 1]));
        }
      } else setAttributes(e, c.lines[i], lines[i]);
      var inline = lines[i].indexOf('</') > 0 && /^<[^>]*>(.*)<\/[^>]*>$/.exec(lines[i]);
      // A text with its spans on one line: its content as markup (in the text's namespace).
      if (inline) {
        if (inline[1].indexOf('<') >= 0) e.innerHTML = inline[1];
        else e.textContent = decode(inline[1]);
      }
    }
  });
  c.lines = lines;
  // A text written anew holds new nodes: the child is taken in again.
  if (Object.keys(redone).length) {
    var kept = keep(c.el, lines);
    if (kept) for (var k in kept) c[k] = kept[k];
    else return false;
  }
  return true;
}
// Writes the content of the text, style or title element opened on line r of child c anew,
// from the new lines.
function rewrite(c, r, lines) {
  c.els[r].innerHTML = '\n' + lines.slice(r + 1, c.end[r]).join('\n') + '\n';
}
// Whether the figure on the page is what a fresh parse of the last answer gives: every
// element's name, attributes and text, in order; the page's own marks (the handles, the
// current step, shown and hidden layers, the sheet held under the pointer) aside. '' when
// it is, else the first difference (for the browser tests).
function figureIsAnswer() {
  var holder = document.createElement('div');
  holder.innerHTML = last.svg;
  var list = function (root) {
    return [root].concat(Array.prototype.slice.call(root.getElementsByTagName('*')))
      .filter(function (e) { return !e.closest('.gs-handles'); });
  };
  var a = list(holder.querySelector('svg')), b = list(svg());
  if (a.length !== b.length) return 'elements: ' + a.length + ' in the answer, ' + b.length + ' shown';
  // The page's own: a layer's display (its style), the sheet's size kept during a drag.
  var own = function (e, n) {
    return (n === 'style' && (e.localName === 'g' || e.localName === 'svg')) || /^data-(view-box|width|height)$/.test(n);
  };
  var cls = function (e) {
    return (e.getAttribute('class') || '').split(' ').filter(function (c) {
      return c && c !== 'current' && c !== 'wt-hover';
    }).join(' ');
  };
  var text = function (e) {
    return Array.prototype.filter.call(e.childNodes, function (n) { return n.nodeType === 3; })
      .map(function (n) { return n.data; }).join('|');
  };
  for (var i = 0; i < a.length; i++) {
    var x = a[i], y = b[i], where = i + ' (' + x.localName + ')';
    if (x.localName !== y.localName) return 'element ' + where + ' shown as ' + y.localName;
    var names = {};
    Array.prototype.forEach.call(x.attributes, function (at) { names[at.name] = 1; });
    Array.prototype.forEach.call(y.attributes, function (at) { names[at.name] = 1; });
    for (var n in names) {
      if (own(x, n) || (i === 0 && drag && HELD.indexOf(n) >= 0)) continue;
      var u = n === 'class' ? cls(x) : x.getAttribute(n), v = n === 'class' ? cls(y) : y.getAttribute(n);
      if (u !== v) return 'element ' + where + ', ' + n + ': ' + u + ' in the answer, ' + v + ' shown';
    }
    if (text(x) !== text(y)) return 'element ' + where + ': text ' + text(x) + ' in the answer, ' + text(y) + ' shown';
  }
  return '';
}

// Puts a built answer in place: figure, step list, handles, sliders' values, summary.
var phases = {};
function mark(name, t) { var n = performance.now(); phases[name] = (phases[name] || 0) + n - t; return n; }
// Whether a replay's figure is set in place where it can be (else always parsed anew; the
// latency bench compares the two).
var inPlace = true, patched = false;
// While the pointer moves (`light`), the engine answers with the current step's item alone
// and only the figure and that step's details are put in place; the step list follows when
// the pointer rests (`settle`).
var stale = false;
// The step list's lines as the page holds them (null: as the page came, written with it).
var listed = null;
// Whether list item `a` says what `b` does (the current page's mark aside).
function sameItem(a, b) {
  return a.innerHTML === b.innerHTML && a.getAttribute('data-first') === b.getAttribute('data-first') &&
    a.getAttribute('data-last') === b.getAttribute('data-last');
}
// Puts the list's `lines` in place: where as many pages are listed as before, only the items
// whose line changed (a drag changes few: the crane bridge's list is 2,080 items, whose
// layout alone takes a tenth of a second); else the whole list anew. The list the page came
// with is compared item by item, parsed apart from the page (no layout).
function setList(lines) {
  var ul = el('wt-steps'), kids = ul.children, i;
  if (kids.length !== lines.length) {
    ul.innerHTML = lines.join('');
    counts.list++;
  } else if (listed) {
    for (i = 0; i < lines.length; i++) {
      if (lines[i] === listed[i]) continue;
      kids[i].outerHTML = lines[i].trim();
      counts.lines++;
    }
  } else {
    var t = document.createElement('template');
    t.innerHTML = lines.join('');
    var fresh = Array.prototype.slice.call(t.content.children), old = Array.prototype.slice.call(kids);
    for (i = 0; i < fresh.length; i++) {
      if (sameItem(fresh[i], old[i])) continue;
      old[i].replaceWith(fresh[i]);
      counts.lines++;
    }
  }
  listed = lines;
}

// The number of the engine's figure on the page (the engine answers a replay with what
// changed from it), and the step layers the last replay put anew (null: the whole figure).
var figureId = null, fresh = null;
// `moved`: whether `a` has a step more or fewer than the answer put in place before it (its
// layers are numbered anew).
function apply(a, moved) {
  var t = performance.now(), next;
  fresh = [];
  patched = inPlace && (a.patch ? applyPatch(a.patch) : patch(a.svg));
  if (patched) {
    next = svg();
    t = mark('patch', t);
  } else {
    fresh = null;
    counts.parsed++;
    var holder = document.createElement('div');
    holder.innerHTML = a.svg;
    next = holder.querySelector('svg');
    t = mark('parse', t);
    svg().replaceWith(next);
    t = mark('swap', t);
    // The new figure's lines and nodes, for the next replay to patch.
    if (inPlace) {
      remember(next, a.svg);
      t = mark('keep', t);
    }
  }
  figureId = a.figureId;
  var walk = window.graphostatikWalk;
  if (a.page !== undefined) {
    // A step more or fewer (a crank off its dead centre, a diagonal gone slack) leaves the
    // list behind until the pointer rests: the figure and the current page follow now.
    walk.swapFigure(a.items[0], fresh, moved, a.page_count);
    stale = true;
    t = mark('step', t);
  } else {
    setList(a.items);
    stale = false;
    t = mark('items', t);
    // Each page's details as the page shows it, from the construction the engine keeps.
    walk.rebind(a.details || pageDetails);
    t = mark('rebind', t);
  }
  handles = a.handles;
  if (drag) {
    // The sheet stays where it was under the pointer: the held point (or centre) is kept at
    // the same place on the screen while the figure around it is drawn anew.
    if (!patched) hold(next);
    // (The walk-through's zoom may have set the view box; the drag holds it.)
    else if (next.getAttribute('viewBox') !== drag.held.viewBox) next.setAttribute('viewBox', drag.held.viewBox);
    var h = drag.h && sameHandle(a, drag.index);
    if (h) {
      var an = anchor(h), target = drag.h.drag.kind === 'angle' ? drag.a0
        : [drag.p.x - drag.p0.x + drag.a0[0], drag.p.y - drag.p0.y + drag.a0[1]];
      stage.style.transform = 'translate(' + (target[0] - an[0]) / drag.perPx + 'px,' +
        (target[1] - an[1]) / drag.perPx + 'px)';
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

// What page `j` shows beside the figure, from the engine's last construction ('' where the
// engine has none: it stopped, and its successor has built nothing yet).
function pageDetails(j) { return (engine && engine.details(j)) || ''; }

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
    var base = inPlace && shown ? figureId : null;
    a = light ? engine.replay(name + '.json', text, window.graphostatikWalk.step(), base)
      : engine.replay(name + '.json', text, undefined, base);
  } catch (e) {
    showError(String(e.message || e).split('\n')[0]);
    if (e.trapped) {
      // A fresh engine, given the last good scene: it keeps the construction shown.
      engine = null;
      window.graphostatikEngine().then(function (x) {
        x.replay(name + '.json', JSON.stringify(good));
        engine = x;
      });
    }
    return null;
  }
  var t1 = performance.now();
  if (!a.ok) {
    showError(a.error);
  } else {
    clearError();
    good = clone(scene);
    var moved = !last || a.step_count !== last.step_count;
    last = a;
    apply(a, moved);
  }
  var t2 = performance.now();
  var t = { engine: t1 - t0, total: t2 - t0, ok: a.ok, inPlace: a.ok && patched,
    steps: a.ok ? a.step_count : null };
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
// Takes hold of handle i where the pointer is (`p0`, sheet units; its own anchor if none):
// the sheet's size and view box are held from here on until `letGo`.
function grab(i, p0, inv) {
  var s = svg(), h = handles[i];
  inv = inv || s.getScreenCTM().inverse();
  p0 = p0 || { x: anchor(h)[0], y: anchor(h)[1] };
  // Sheet units (mm) per screen pixel, from the figure's scale on the screen now.
  var perPx = Math.sqrt(Math.abs(inv.a * inv.d - inv.b * inv.c));
  drag = { h: h, index: i, inv: inv, perPx: perPx, p0: p0, p: p0, a0: anchor(h).slice(),
    held: { viewBox: s.getAttribute('viewBox'), width: s.getAttribute('width'), height: s.getAttribute('height') },
    value: h.drag.value ? h.drag.value.slice() : null };
  figure.classList.add('gs-dragging');
}
// Holds the sheet as it stands while a slider moves (no handle held: `drag.h` is null):
// the figure keeps its size and scale on the screen until the slider is let go, as during
// a drag.
function holdSheet() {
  if (drag) return;
  var s = svg();
  drag = { h: null, held: { viewBox: s.getAttribute('viewBox'), width: s.getAttribute('width'),
    height: s.getAttribute('height') } };
}
// Lets go of the sheet: its own size and view box, as the last answer gave them.
function letGo() {
  drag = null;
  figure.classList.remove('gs-dragging');
  var s = svg();
  stage.style.removeProperty('transform');
  HELD.forEach(function (k) {
    if (!s.dataset[k]) return;
    if (s.getAttribute(k) !== s.dataset[k]) s.setAttribute(k, s.dataset[k]);
    delete s.dataset[k];
  });
}
figure.addEventListener('pointerdown', function (e) {
  var c = e.target.closest && e.target.closest('.gs-handle');
  if (!c || !engine || e.button !== 0) return;
  var inv = svg().getScreenCTM().inverse();
  grab(Number(c.getAttribute('data-handle')), toSheet(e, inv), inv);
  figure.setPointerCapture(e.pointerId);
  e.preventDefault();
});
figure.addEventListener('pointermove', function (e) {
  if (!drag || !drag.h) return;
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
  if (!drag || !drag.h) return;
  letGo();
  if (!replay(false, false)) {
    if (stale) settle(); else { window.graphostatikWalk.rebind(); drawHandles(); }
  }
}
figure.addEventListener('pointerup', endDrag);
figure.addEventListener('pointercancel', endDrag);

var form = el('wt-sliders');
if (form) {
  form.addEventListener('submit', function (e) { e.preventDefault(); });
  form.addEventListener('change', function () {
    if (drag && !drag.h) letGo();
    if (!replay(false, false)) settle();
  });
  form.addEventListener('input', function (e) {
    var input = e.target;
    if (!input.dataset.field) return;
    holdSheet();
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
  figureIsAnswer: figureIsAnswer,
  // Sets whether replays set the figure in place where they can (true when the page opens).
  setInPlace: function (on) { inPlace = !!on; shown = null; },
  scene: function () { return clone(scene); },
  good: function () { return clone(good); },
  // The last construction put in place: its steps, checks (with bounds) and handles.
  answer: function () { return last && { steps: last.step_count, pages: last.page_count,
    checks: last.checks, failed: last.failed, handles: last.handles,
    item: last.page !== undefined ? last.items[0] : null }; },
  // Where the step list or the current page's details differ from the last full answer's
  // ('' where they do not): the browser test holds the list kept in place to the answer.
  listDiffers: function () {
    var kids = el('wt-steps').children;
    if (!listed || kids.length !== listed.length) return 'the list has ' + kids.length + ' items';
    for (var i = 0; i < kids.length; i++) {
      var t = document.createElement('template'), li = kids[i].cloneNode(true);
      t.innerHTML = listed[i].trim();
      li.classList.remove('wt-on');
      if (!li.getAttribute('class')) li.removeAttribute('class');
      if (!t.content.firstElementChild.isEqualNode(li)) return 'item ' + (i + 1);
    }
    // The current page's details beside the figure, as the answer gives them.
    var now = document.createElement('div'), k = window.graphostatikWalk.step();
    now.innerHTML = !last ? '' : last.details ? last.details[k] : pageDetails(k);
    if (now.innerHTML !== el('wt-now').innerHTML) return 'the details of page ' + (k + 1);
    return '';
  },
  // How often a replay put steps in or took some out of the figure shown (splice), parsed
  // the figure anew (parsed), put the whole step list in place (list), and how many of the
  // list's items it put anew where the list was kept (lines).
  counts: counts,
  // Replays the scene `n` times as a drag makes it, each replay drawing a figure other than
  // the one shown: the first handle moved by 0.5 to 2 mm (a crank turned by 2 to 8 degrees)
  // from where it was, in turn, or where the scene has no handle its first slider by 1 to 4
  // steps (`moved` names what moved; null: nothing, each replay the same scene); the scene
  // is put back after. Engine and page update, ms
  // each, of the replays the engine took (`steps`: the step count of each; `before`: that
  // of the figure shown before them), and as `release` the full answer put in place after
  // them, as when the pointer is released; `full` also puts the step list in place each
  // time. `held`: the handle is held as a pointer holds it (the sheet's size and view box
  // kept until the release, the sheet moved under the handle), as a drag's replays are.
  bench: function (n, full, held) {
    var out = [], h = handles[0], sl = !h && last && last.sliders[0], was = clone(scene);
    out.before = last && last.step_count;
    out.moved = h ? h.name : sl ? sl.label : null;
    if (held && h) grab(0);
    else if (held && sl) holdSheet();
    for (var i = 0; i < n; i++) {
      if (h) nudge(h, was, i);
      else if (sl) slide(sl, was, i);
      var t = replay(true, !full);
      if (t && t.ok) out.push(t);
    }
    scene = was;
    // The release: the sheet let go, the full answer, the step list put in place.
    // (Letting go sets the sheet's size: the layout it costs falls in the replay's.)
    if (drag) letGo();
    var r = replay(true, false);
    settle();
    out.release = r && r.ok ? r.total : null;
    return out;
  }
};
// The i-th of the bench's moves of slider `sl` where the scene has no handle: 1 to 4 of its
// steps from its value in `base` (down where up would pass its end).
function slide(sl, base, i) {
  var v = getField(base, sl.field), m = (i % 4 + 1) * sl.step;
  setField(scene, sl.field, Number((v + m <= sl.max ? v + m : v - m).toPrecision(12)));
}
// The i-th of the bench's moves of handle h, from its value in `base` (an angle the scene
// leaves to its default: from where the handle stands).
function nudge(h, base, i) {
  var d = h.drag, v = getField(base, d.field), m = 0.5 * (i % 4 + 1);
  if (d.kind === 'point' && v && v.length === 2) {
    setField(scene, d.field, [v[0] + m * d.per_mm, v[1] + m * d.per_mm]);
  } else if (d.kind === 'angle') {
    if (typeof v !== 'number') {
      v = d.zero_deg + d.sense * Math.atan2(h.center[1] - h.at[1], h.at[0] - h.center[0]) * 180 / Math.PI;
    }
    setField(scene, d.field, ((v + 4 * m) % 360 + 360) % 360);
  }
}
window.graphostatikEngine().then(function (x) {
  engine = x;
  // The first replay in the page: the figure, steps and handles from here on are the
  // engine's own.
  replay(true);
  el('gs-time').textContent = 'drag a point, or move a slider';
  window.graphostatikSite.ready = true;
}, function (e) { showError('the engine did not load: ' + e); });
})();
