// Small canvas charts drawn by hand (no library): a heat map with colour bar (the x1-t map),
// line/scatter plots with linear or log axes. Axes are labelled with units by the caller.
import { h, fmt } from './dom.js';

const FONT = '12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const INK = '#1d2733';
const GRID = '#e3e8ee';
export const PALETTE = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f', '#bcbd22'];

// Viridis, 9 anchors, linearly interpolated.
const VIRIDIS = [[68, 1, 84], [71, 44, 122], [59, 81, 139], [44, 113, 142], [33, 144, 141],
  [39, 173, 129], [92, 200, 99], [170, 220, 50], [253, 231, 37]];
export function viridis(t) {
  if (!Number.isFinite(t)) return [235, 235, 235];
  t = Math.max(0, Math.min(1, t)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(t));
  const f = t - i;
  const a = VIRIDIS[i], b = VIRIDIS[i + 1];
  return [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])];
}

function niceStep(span, count) {
  const raw = span / Math.max(1, count);
  const mag = Math.pow(10, Math.floor(Math.log10(raw)));
  const n = raw / mag;
  return (n < 1.5 ? 1 : n < 3 ? 2 : n < 7 ? 5 : 10) * mag;
}

export function ticks(min, max, log, count = 6) {
  if (!(max > min)) return [min];
  if (log) {
    const out = [];
    for (let e = Math.floor(Math.log10(min)); e <= Math.ceil(Math.log10(max)); e++) {
      const v = Math.pow(10, e);
      if (v >= min * 0.999 && v <= max * 1.001) out.push(v);
    }
    if (out.length >= 2) return out;
    // Less than two decades: 1-2-5 marks.
    for (let e = Math.floor(Math.log10(min)); e <= Math.ceil(Math.log10(max)); e++)
      for (const m of [2, 5]) {
        const v = m * Math.pow(10, e);
        if (v >= min && v <= max) out.push(v);
      }
    return out.sort((a, b) => a - b);
  }
  const step = niceStep(max - min, count);
  const out = [];
  for (let v = Math.ceil(min / step) * step; v <= max + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  return out;
}

function tickLabel(v, log) {
  if (log) {
    const e = Math.log10(v);
    if (Math.abs(e - Math.round(e)) < 1e-9) return Math.abs(e) <= 2 ? String(Number(v.toPrecision(3))) : `1e${Math.round(e)}`;
  }
  return fmt(v, 3);
}

// A canvas sized to its container (CSS pixels × devicePixelRatio).
function makeCanvas(container, height) {
  const width = Math.max(320, Math.floor(container.clientWidth || 640));
  const dpr = window.devicePixelRatio || 1;
  const canvas = h('canvas', { class: 'chart', width: Math.round(width * dpr), height: Math.round(height * dpr) });
  canvas.style.width = `${width}px`;
  canvas.style.height = `${height}px`;
  const ctx = canvas.getContext('2d');
  ctx.scale(dpr, dpr);
  ctx.font = FONT;
  return { canvas, ctx, width, height };
}

class Axes {
  constructor(box, xr, yr, xlog, ylog) {
    Object.assign(this, { box, xr, yr, xlog, ylog });
  }
  fx(v) {
    const { box, xr, xlog } = this;
    const t = xlog ? (Math.log10(v) - Math.log10(xr[0])) / (Math.log10(xr[1]) - Math.log10(xr[0])) : (v - xr[0]) / (xr[1] - xr[0]);
    return box.x + t * box.w;
  }
  fy(v) {
    const { box, yr, ylog } = this;
    const t = ylog ? (Math.log10(v) - Math.log10(yr[0])) / (Math.log10(yr[1]) - Math.log10(yr[0])) : (v - yr[0]) / (yr[1] - yr[0]);
    return box.y + box.h - t * box.h;
  }
  ix(px) {
    const { box, xr, xlog } = this;
    const t = (px - box.x) / box.w;
    return xlog ? Math.pow(10, Math.log10(xr[0]) + t * (Math.log10(xr[1]) - Math.log10(xr[0]))) : xr[0] + t * (xr[1] - xr[0]);
  }
  iy(py) {
    const { box, yr, ylog } = this;
    const t = (box.y + box.h - py) / box.h;
    return ylog ? Math.pow(10, Math.log10(yr[0]) + t * (Math.log10(yr[1]) - Math.log10(yr[0]))) : yr[0] + t * (yr[1] - yr[0]);
  }
}

function drawAxes(ctx, ax, { xlabel, ylabel, title, grid = true }) {
  const { box } = ax;
  ctx.save();
  ctx.strokeStyle = GRID;
  ctx.fillStyle = INK;
  ctx.lineWidth = 1;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  for (const v of ticks(ax.xr[0], ax.xr[1], ax.xlog, Math.max(3, Math.floor(box.w / 90)))) {
    const x = Math.round(ax.fx(v)) + 0.5;
    if (grid) { ctx.beginPath(); ctx.moveTo(x, box.y); ctx.lineTo(x, box.y + box.h); ctx.stroke(); }
    ctx.beginPath(); ctx.strokeStyle = INK; ctx.moveTo(x, box.y + box.h); ctx.lineTo(x, box.y + box.h + 4); ctx.stroke(); ctx.strokeStyle = GRID;
    ctx.fillText(tickLabel(v, ax.xlog), x, box.y + box.h + 6);
  }
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const v of ticks(ax.yr[0], ax.yr[1], ax.ylog, Math.max(3, Math.floor(box.h / 50)))) {
    const y = Math.round(ax.fy(v)) + 0.5;
    if (grid) { ctx.beginPath(); ctx.moveTo(box.x, y); ctx.lineTo(box.x + box.w, y); ctx.stroke(); }
    ctx.beginPath(); ctx.strokeStyle = INK; ctx.moveTo(box.x - 4, y); ctx.lineTo(box.x, y); ctx.stroke(); ctx.strokeStyle = GRID;
    ctx.fillText(tickLabel(v, ax.ylog), box.x - 6, y);
  }
  ctx.strokeStyle = INK;
  ctx.strokeRect(box.x + 0.5, box.y + 0.5, box.w, box.h);
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  if (xlabel) ctx.fillText(xlabel, box.x + box.w / 2, box.y + box.h + 38);
  if (title) { ctx.font = `600 ${FONT}`; ctx.textBaseline = 'top'; ctx.fillText(title, box.x + box.w / 2, 6); ctx.font = FONT; }
  if (ylabel) {
    ctx.translate(14, box.y + box.h / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.textBaseline = 'middle';
    ctx.fillText(ylabel, 0, 0);
  }
  ctx.restore();
}

function extent(values, log) {
  let lo = Infinity, hi = -Infinity;
  for (const v of values) {
    if (v === null || !Number.isFinite(v) || (log && v <= 0)) continue;
    lo = Math.min(lo, v); hi = Math.max(hi, v);
  }
  if (!Number.isFinite(lo)) return log ? [1, 10] : [0, 1];
  if (lo === hi) return log ? [lo / 2, hi * 2] : [lo - (Math.abs(lo) || 1) * 0.1, hi + (Math.abs(hi) || 1) * 0.1];
  if (log) return [lo / 1.3, hi * 1.3];
  const pad = (hi - lo) * 0.05;
  return [lo - pad, hi + pad];
}

// Heat map of values[row][col] over x (columns) and y (rows, increasing upwards), with a
// colour bar. opts: {x, y, values, xlabel, ylabel, clabel, title, vmin, vmax, lines:[{x, y,
// color, label}], onPick(x, y), height}
export function heatmap(container, opts) {
  const { x, y, values } = opts;
  const height = opts.height || 420;
  const { canvas, ctx, width } = makeCanvas(container, height);
  const box = { x: 70, y: 28, w: width - 70 - 110, h: height - 28 - 52 };
  const dx = x.length > 1 ? (x[x.length - 1] - x[0]) / (x.length - 1) : 1;
  const dy = y.length > 1 ? (y[y.length - 1] - y[0]) / (y.length - 1) : 1;
  const ax = new Axes(box, [x[0] - dx / 2, x[x.length - 1] + dx / 2], [y[0] - dy / 2, y[y.length - 1] + dy / 2], false, false);
  let vmin = opts.vmin, vmax = opts.vmax;
  if (vmin === undefined || vmax === undefined) {
    const [lo, hi] = extent(values.flat(), false);
    vmin = vmin ?? lo; vmax = vmax ?? hi;
  }
  const img = ctx.createImageData(x.length, y.length);
  for (let r = 0; r < y.length; r++) {
    const row = values[r];
    const pr = y.length - 1 - r;
    for (let c = 0; c < x.length; c++) {
      const v = row[c];
      const [R, G, B] = viridis(v === null ? NaN : (v - vmin) / (vmax - vmin || 1));
      const k = 4 * (pr * x.length + c);
      img.data[k] = R; img.data[k + 1] = G; img.data[k + 2] = B; img.data[k + 3] = 255;
    }
  }
  const off = document.createElement('canvas');
  off.width = x.length; off.height = y.length;
  off.getContext('2d').putImageData(img, 0, 0);
  ctx.imageSmoothingEnabled = x.length * 2 < box.w; // smooth only when enlarging a lot
  ctx.drawImage(off, box.x, box.y, box.w, box.h);
  ctx.imageSmoothingEnabled = true;
  for (const line of opts.lines || []) drawSeries(ctx, ax, line, box);
  drawAxes(ctx, ax, { xlabel: opts.xlabel, ylabel: opts.ylabel, title: opts.title, grid: false });
  // Colour bar.
  const cb = { x: box.x + box.w + 22, y: box.y, w: 16, h: box.h };
  for (let i = 0; i < cb.h; i++) {
    const [R, G, B] = viridis(1 - i / (cb.h - 1));
    ctx.fillStyle = `rgb(${R | 0},${G | 0},${B | 0})`;
    ctx.fillRect(cb.x, cb.y + i, cb.w, 1);
  }
  ctx.strokeStyle = INK;
  ctx.strokeRect(cb.x + 0.5, cb.y + 0.5, cb.w, cb.h);
  const cax = new Axes(cb, [0, 1], [vmin, vmax], false, false);
  ctx.fillStyle = INK; ctx.textAlign = 'left'; ctx.textBaseline = 'middle';
  for (const v of ticks(vmin, vmax, false, 6)) {
    const yy = Math.round(cax.fy(v)) + 0.5;
    ctx.beginPath(); ctx.moveTo(cb.x + cb.w, yy); ctx.lineTo(cb.x + cb.w + 4, yy); ctx.stroke();
    ctx.fillText(fmt(v, 3), cb.x + cb.w + 6, yy);
  }
  if (opts.clabel) {
    ctx.save(); ctx.translate(cb.x + cb.w + 58, cb.y + cb.h / 2); ctx.rotate(Math.PI / 2);
    ctx.textAlign = 'center'; ctx.fillText(opts.clabel, 0, 0); ctx.restore();
  }
  legend(ctx, box, (opts.lines || []).filter((l) => l.label), 'light');
  if (opts.onPick) {
    canvas.classList.add('pickable');
    canvas.addEventListener('click', (ev) => {
      const rect = canvas.getBoundingClientRect();
      const px = ev.clientX - rect.left, py = ev.clientY - rect.top;
      if (px < box.x || px > box.x + box.w || py < box.y || py > box.y + box.h) return;
      opts.onPick(ax.ix(px), ax.iy(py));
    });
  }
  container.append(canvas);
  return canvas;
}

function drawSeries(ctx, ax, s, box) {
  ctx.save();
  ctx.beginPath(); ctx.rect(box.x, box.y, box.w, box.h); ctx.clip();
  ctx.strokeStyle = s.color || PALETTE[0];
  ctx.fillStyle = s.color || PALETTE[0];
  ctx.lineWidth = s.width || 1.6;
  if (s.dash) ctx.setLineDash(s.dash);
  const ok = (v, log) => v !== null && Number.isFinite(v) && (!log || v > 0);
  if (!s.points || s.line) {
    ctx.beginPath();
    let pen = false;
    for (let i = 0; i < s.x.length; i++) {
      if (!ok(s.x[i], ax.xlog) || !ok(s.y[i], ax.ylog)) { pen = false; continue; }
      const px = ax.fx(s.x[i]), py = ax.fy(s.y[i]);
      if (pen) ctx.lineTo(px, py); else ctx.moveTo(px, py);
      pen = true;
    }
    ctx.stroke();
  }
  if (s.points) {
    ctx.setLineDash([]);
    for (let i = 0; i < s.x.length; i++) {
      if (!ok(s.x[i], ax.xlog) || !ok(s.y[i], ax.ylog)) continue;
      const px = ax.fx(s.x[i]), py = ax.fy(s.y[i]);
      ctx.beginPath();
      if (s.marker === 'square') ctx.rect(px - 4, py - 4, 8, 8);
      else ctx.arc(px, py, 4, 0, 2 * Math.PI);
      ctx.fill();
      ctx.strokeStyle = '#fff'; ctx.lineWidth = 1; ctx.stroke();
    }
  }
  ctx.restore();
}

function legend(ctx, box, series, style) {
  if (!series.length) return;
  ctx.save();
  ctx.font = FONT;
  const w = Math.max(...series.map((s) => ctx.measureText(s.label).width)) + 34;
  const hgt = series.length * 17 + 8;
  const x0 = box.x + box.w - w - 8, y0 = box.y + 8;
  ctx.fillStyle = style === 'light' ? 'rgba(255,255,255,0.85)' : 'rgba(255,255,255,0.9)';
  ctx.fillRect(x0, y0, w, hgt);
  ctx.strokeStyle = '#c9d1da'; ctx.strokeRect(x0 + 0.5, y0 + 0.5, w, hgt);
  series.forEach((s, i) => {
    const yy = y0 + 12 + i * 17;
    ctx.strokeStyle = s.color; ctx.fillStyle = s.color; ctx.lineWidth = 2;
    if (s.dash) ctx.setLineDash(s.dash);
    if (!s.points || s.line) { ctx.beginPath(); ctx.moveTo(x0 + 4, yy); ctx.lineTo(x0 + 24, yy); ctx.stroke(); }
    ctx.setLineDash([]);
    if (s.points) {
      ctx.beginPath();
      if (s.marker === 'square') ctx.rect(x0 + 10, yy - 4, 8, 8); else ctx.arc(x0 + 14, yy, 4, 0, 2 * Math.PI);
      ctx.fill();
    }
    ctx.setLineDash([]);
    ctx.fillStyle = INK; ctx.textBaseline = 'middle'; ctx.textAlign = 'left';
    ctx.fillText(s.label, x0 + 28, yy);
  });
  ctx.restore();
}

// Lines and/or points. opts: {series:[{x, y, label, color, points, line, dash, marker}],
// xlabel, ylabel, title, xlog, ylog, xrange, yrange, height, hlines:[{y, label, color}]}
export function plot(container, opts) {
  const height = opts.height || 300;
  const { canvas, ctx, width } = makeCanvas(container, height);
  const box = { x: 74, y: 28, w: width - 74 - 20, h: height - 28 - 52 };
  const allx = opts.series.flatMap((s) => s.x);
  const ally = opts.series.flatMap((s) => s.y).concat((opts.hlines || []).map((l) => l.y));
  const ax = new Axes(box, opts.xrange || extent(allx, opts.xlog), opts.yrange || extent(ally, opts.ylog), !!opts.xlog, !!opts.ylog);
  ctx.fillStyle = '#fff'; ctx.fillRect(box.x, box.y, box.w, box.h);
  drawAxes(ctx, ax, opts);
  for (const l of opts.hlines || []) {
    if (!Number.isFinite(l.y)) continue;
    drawSeries(ctx, ax, { x: ax.xr, y: [l.y, l.y], color: l.color || '#888', dash: [5, 4], width: 1.2 }, box);
    ctx.save(); ctx.fillStyle = l.color || '#666'; ctx.textAlign = 'left'; ctx.textBaseline = 'bottom';
    ctx.fillText(l.label || '', box.x + 6, ax.fy(l.y) - 2); ctx.restore();
  }
  opts.series.forEach((s, i) => drawSeries(ctx, ax, { color: PALETTE[i % PALETTE.length], ...s }, box));
  legend(ctx, box, opts.series.map((s, i) => ({ color: PALETTE[i % PALETTE.length], ...s })).filter((s) => s.label));
  if (opts.empty && !opts.series.some((s) => s.x.length)) {
    ctx.fillStyle = '#8894a0'; ctx.textAlign = 'center'; ctx.fillText(opts.empty, box.x + box.w / 2, box.y + box.h / 2);
  }
  container.append(canvas);
  return canvas;
}
