// DOM building without innerHTML: every text goes in through textContent, so user strings
// (job names, tags, errors) can never become markup.
export function h(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) {
    if (v === undefined || v === null || v === false) continue;
    if (k === 'class') el.className = v;
    else if (k === 'text') el.textContent = String(v);
    else if (k.startsWith('on') && typeof v === 'function') el.addEventListener(k.slice(2), v);
    else if (k === 'dataset') Object.assign(el.dataset, v);
    else if (k === 'value') el.value = v;
    else if (k === 'checked') el.checked = !!v;
    else if (k === 'style') {
      for (const [p, val] of Object.entries(v)) el.style.setProperty(p, val);
    } else el.setAttribute(k, v === true ? '' : String(v));
  }
  append(el, children);
  return el;
}

export function append(el, children) {
  for (const c of children.flat(Infinity)) {
    if (c === undefined || c === null || c === false) continue;
    el.append(c instanceof Node ? c : document.createTextNode(String(c)));
  }
  return el;
}

export function clear(el) {
  while (el.firstChild) el.removeChild(el.firstChild);
  return el;
}

// Numbers as a researcher reads them.
export function fmt(v, digits = 3) {
  if (v === null || v === undefined || Number.isNaN(v)) return '—';
  if (typeof v !== 'number') return String(v);
  if (v === 0) return '0';
  const a = Math.abs(v);
  if (a >= 1e5 || a < 1e-3) return v.toExponential(digits - 1).replace('e+', 'e');
  return Number(v.toPrecision(digits)).toString();
}

export function fmtDuration(s) {
  if (s === null || s === undefined || !Number.isFinite(s)) return '—';
  if (s < 1) return `${(s * 1000).toFixed(0)} ms`;
  if (s < 90) return `${s.toFixed(s < 10 ? 1 : 0)} s`;
  if (s < 5400) return `${Math.floor(s / 60)} min ${Math.round(s % 60)} s`;
  return `${Math.floor(s / 3600)} h ${Math.round((s % 3600) / 60)} min`;
}

export function fmtBytes(b) {
  if (!Number.isFinite(b)) return '—';
  const u = ['B', 'kB', 'MB', 'GB', 'TB'];
  let i = 0;
  while (b >= 1000 && i < u.length - 1) { b /= 1000; i++; }
  return `${b.toFixed(b < 10 && i > 0 ? 1 : 0)} ${u[i]}`;
}

export function fmtTime(iso) {
  if (!iso) return '—';
  const d = new Date(iso);
  if (Number.isNaN(d.getTime())) return String(iso);
  return d.toISOString().replace('T', ' ').replace(/\.\d+Z$/, 'Z');
}

export function badge(status) {
  return h('span', { class: `badge st-${String(status).replace(/[^a-z_]/g, '')}`, text: status });
}

export function progressBar(fraction, label) {
  const f = Math.max(0, Math.min(1, Number(fraction) || 0));
  const bar = h('div', { class: 'bar' }, h('div', { class: 'fill' }));
  bar.firstChild.style.width = `${(f * 100).toFixed(1)}%`;
  return h('div', { class: 'progress' }, bar, h('span', { class: 'ptext', text: label ?? `${(f * 100).toFixed(0)} %` }));
}

// A definition table: [[label, value-or-node], ...]
export function kvTable(rows) {
  return h('table', { class: 'kv' },
    h('tbody', {}, rows.filter(Boolean).map(([k, v, title]) =>
      h('tr', { title }, h('th', { text: k }), h('td', {}, v instanceof Node ? v : (v ?? '—'))))));
}

export function link(href, text) {
  return h('a', { href, text });
}

export function shortId(id) {
  return id ? String(id).slice(0, 8) : '—';
}

// Replaces the children of `el` (null, undefined and false children are skipped; the DOM's
// own append would write them as text).
export function fill(el, ...children) {
  return append(clear(el), children);
}

// The page of a job or study that does not exist (or could not be read): one message and a
// way back, nothing else.
export function notFound(error, what, id, back, backText) {
  return h('section', { class: 'card', id: 'not-found' },
    h('h1', { text: error.status === 404 ? `No ${what} ${id}` : `Could not load ${what} ${id}` }),
    h('p', { class: 'error', text: error.status === 404 ? `This server has no ${what} with that id (it may be on another server).` : error.message }),
    h('p', {}, h('a', { href: back, text: `Back to ${backText}` })));
}
