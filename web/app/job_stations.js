// The on-fault stations of a run (the job's `stations`; docs/hdf5-layout.md "/stations"), as
// dynamic-rupture benchmarks show them: (d) the rupture time against x1 — each station's first
// time |V| exceeds the job's rupture threshold — with the slip front of every node (/front);
// (e) the stations' time series — slip rate, slip, shear and normal traction — one panel each
// on one time axis, one colour per station, dark to light along x1. Drawn
// from GET /api/v1/jobs/{id}/stations (every step within a budget; the CSV has every step).
import { h, fill, fmt } from './dom.js';
import { get } from './api.js';
import { axis, chart, chartMessage, plotly } from './plots.js';
import { nucleationPatch, signalWindow } from './job_figures.js';

const FRONT = '#3b4756'; // dark grey: the stations' colours run to orange, the patch is orange
const SAMPLE_BUDGET = 100000; // time samples × stations asked for (about 8 MB of JSON): every
// step of the presets (a stride could step over the peak of a slip-rate spike a few steps wide)
const PANEL = 150; // px: the height of one time-series panel
const GAP = 34; // px between panels
const SERIES_MARGIN = { l: 80, r: 150, t: 20, b: 50, autoexpand: false }; // r: the legend

// The four series, in the order benchmark exchanges list them, with the SI prefixes each may
// take (docs/hdf5-layout.md: m/s, m, Pa, Pa; the normal traction is negative in compression).
const QUANTITIES = [
  { key: 'slip_rate', title: 'slip rate V', unit: 'm/s', prefixes: ['', 'm', 'µ'] },
  { key: 'slip', title: 'slip δ', unit: 'm', prefixes: ['', 'm', 'µ'] },
  { key: 'shear_traction', title: 'shear traction τ', unit: 'Pa', prefixes: ['G', 'M', 'k', ''] },
  { key: 'normal_traction', title: 'normal traction σ', unit: 'Pa', prefixes: ['G', 'M', 'k', ''] },
];
const PREFIX = { G: 1e9, M: 1e6, k: 1e3, '': 1, m: 1e-3, 'µ': 1e-6 };

// Whether the job records stations (its spec lists at least one).
export function hasStations(job) {
  return (job?.spec?.stations?.x1 || []).length > 0;
}

// {scale, unit}: the unit among `prefixes` of `unit` in which `peak` reads 1 to 999 (the
// smallest one below that; the plain unit for 0): values are multiplied by `scale`.
export function siUnit(peak, unit, prefixes) {
  if (!(peak > 0)) return { scale: 1, unit };
  const sorted = [...prefixes].sort((a, b) => PREFIX[b] - PREFIX[a]);
  const p = sorted.find((q) => peak >= PREFIX[q]) ?? sorted[sorted.length - 1];
  return { scale: 1 / PREFIX[p], unit: `${p}${unit}` };
}

// n colours dark to light along x1: matplotlib's plasma from 0 to 0.85 (perceptually ordered,
// and with more change of hue than viridis between neighbouring stations; its light end
// stays readable on white).
const PLASMA = [[13, 8, 135], [83, 2, 163], [139, 10, 165], [184, 50, 137], [219, 92, 104], [244, 136, 73], [254, 189, 42], [240, 249, 33]];
export function stationColours(n) {
  return Array.from({ length: n }, (_, i) => {
    const f = ((0.85 * i) / Math.max(n - 1, 1)) * (PLASMA.length - 1);
    const k = Math.min(Math.floor(f), PLASMA.length - 2), w = f - k;
    const c = PLASMA[k].map((a, j) => Math.round(a + w * (PLASMA[k + 1][j] - a)));
    return `rgb(${c.join(',')})`;
  });
}

function peakOf(rows) {
  let peak = 0;
  for (const row of rows) for (const v of row) if (v !== null && Math.abs(v) > peak) peak = Math.abs(v);
  return peak;
}

// Draws the stations of a succeeded run into `box` (a card the caller adds only for a run
// with stations).
export async function drawStations(box, job) {
  const n = job.spec.stations.x1.length;
  const csv = `/api/v1/jobs/${job.id}/stations.csv`;
  const rtBox = h('div', { class: 'fig', id: 'fig-rupture-time' });
  const seriesBox = h('div', { class: 'fig', id: 'fig-stations' });
  const rtCaption = h('p', { class: 'caption muted', id: 'rupture-time-caption' });
  const seriesCaption = h('p', { class: 'caption muted', id: 'stations-caption' });
  const table = h('div', { class: 'tablewrap stations-table' });
  fill(box, h('h2', { text: 'On-fault stations' }),
    h('p', { class: 'muted', id: 'stations-intro' }, `${n} station${n === 1 ? '' : 's'} on the interface, recorded every time step (GET /api/v1/jobs/{id}/stations). `,
      h('a', { class: 'button', id: 'stations-csv', href: csv, download: `${job.id}-stations.csv`, text: 'Download the stations as CSV (every step)' })));
  try { await plotly(); } catch (e) { box.append(h('p', { class: 'error', text: e.message })); return; }
  const threshold = h('p', { id: 'rupture-threshold' });
  box.append(
    h('h3', { text: '(d) Rupture time against x1' }), threshold, rtBox, rtCaption, table,
    h('h3', { text: '(e) Station time series: slip rate, slip, shear and normal traction' }),
    h('p', { class: 'muted', text: 'One colour per station (the legend, dark to light along x1): click a station to hide it in every panel, double-click to show it alone. Drag to zoom (the panels share the time axis), double-click the plot for the whole run.' }),
    seriesBox, seriesCaption);

  const samples = Math.max(500, Math.floor(SAMPLE_BUDGET / n));
  const [st, front] = await Promise.all([
    get(`/api/v1/jobs/${job.id}/stations?max_samples=${samples}`),
    get(`/api/v1/jobs/${job.id}/front`).catch(() => null),
  ]);
  const colours = stationColours(st.x1.length);
  // One time unit for both figures, from the run's duration (0.1 s reads in ms, 16 s in s).
  const time = siUnit(st.time[st.time.length - 1], 's', ['', 'm', 'µ']);
  const frontThreshold = job.metrics?.front_threshold ?? job.spec.probe?.front_threshold;
  // The thresholds as the job gives them (String: 0.001, 0.0001, 1e-7), not rounded.
  threshold.textContent = `Rupture time: the first time the slip rate |V| at a station exceeds ${String(st.rupture_threshold)} m/s (the job's stations.rupture_threshold), interpolated linearly between time steps.`;
  await drawRuptureTime(rtBox, rtCaption, job, st, front, frontThreshold, time, colours);
  fill(table, rupturesTable(st, time));
  await drawSeries(seriesBox, seriesCaption, job, st, time, colours);
}

// x1 and rupture time of each station, as a two-row table.
function rupturesTable(st, time) {
  return h('table', { class: 'grid' }, h('tbody', {},
    h('tr', {}, h('th', { text: 'station x1 [m]' }), st.x1.map((x) => h('td', { class: 'num', text: fmt(x, 6) }))),
    h('tr', {}, h('th', { text: `rupture time [${time.unit}]` }), st.rupture_time.map((t) => h('td', { class: 'num', text: t === null ? 'never' : fmt(t * time.scale, 6) })))));
}

// (d): the stations' rupture times as markers, the front of every node as a line, the
// nucleation patch shaded.
async function drawRuptureTime(box, caption, job, st, front, frontThreshold, time, colours) {
  const ruptured = st.x1.map((x, i) => [x, st.rupture_time[i], colours[i]]).filter(([, t]) => t !== null);
  const never = st.x1.filter((_, i) => st.rupture_time[i] === null);
  const traces = [];
  const xs = ruptured.map(([x]) => x);
  let tTop = Math.max(0, ...ruptured.map(([, t]) => t));
  if (front) {
    const pts = front.x1.map((x, i) => [x, front.arrival_time[i]]).sort((a, b) => a[0] - b[0]);
    const reached = pts.filter(([, t]) => t !== null && Number.isFinite(t));
    if (reached.length) {
      xs.push(reached[0][0], reached[reached.length - 1][0]);
      tTop = Math.max(tTop, ...reached.map(([, t]) => t));
      traces.push({ type: 'scatter', mode: 'lines', x: pts.map((p) => p[0]), y: pts.map((p) => (p[1] === null ? null : p[1] * time.scale)), connectgaps: false,
        name: `slip front, every node (|V| > ${String(frontThreshold)} m/s)`, line: { color: FRONT, width: 1.6 },
        hovertemplate: `front: x1 = %{x:.4g} m, t = %{y:.5g} ${time.unit}<extra></extra>` });
    }
  }
  traces.push({ type: 'scatter', mode: 'markers', x: ruptured.map(([x]) => x), y: ruptured.map(([, t]) => t * time.scale),
    name: `stations (|V| > ${String(st.rupture_threshold)} m/s)`, marker: { size: 10, color: ruptured.map(([, , c]) => c), line: { color: '#1d2733', width: 1 } },
    hovertemplate: `station x1 = %{x:.4g} m<br>rupture time = %{y:.5g} ${time.unit}<extra></extra>` });
  const patch = nucleationPatch(job.spec);
  const shapes = [];
  if (patch) {
    shapes.push({ type: 'rect', xref: 'x', yref: 'y domain', x0: patch[0], x1: patch[1], y0: 0, y1: 1, fillcolor: 'rgba(255,127,14,0.15)', line: { width: 0 }, layer: 'below' });
    traces.push({ type: 'scatter', mode: 'lines', x: [null], y: [null], name: `nucleation patch (${fmt(patch[0])} to ${fmt(patch[1])} m)`, line: { color: 'rgba(255,127,14,0.5)', width: 8 }, hoverinfo: 'skip' });
  }
  if (!xs.length) xs.push(...st.x1);
  const lo = Math.min(...xs, ...st.x1), hi = Math.max(...xs, ...st.x1);
  const pad = 0.05 * Math.max(hi - lo, 1e-9);
  await chart(box, {
    data: traces, height: 350, filename: `slipfront-${String(job.id).slice(0, 8)}-rupture-time`,
    layout: {
      showlegend: true, shapes,
      xaxis: axis('x1 [m]', { range: [lo - pad, hi + pad], autorange: false }),
      // from a little below 0: the markers of stations that slipped at once stay whole
      yaxis: axis(`rupture time [${time.unit}]`, { range: [-0.03 * tTop * time.scale, 1.08 * tTop * time.scale || 1], autorange: false }),
      margin: { l: 80, r: 24, t: 40, b: 50, autoexpand: false },
      legend: { orientation: 'h', x: 0, xanchor: 'left', y: 1.01, yanchor: 'bottom', bgcolor: 'rgba(0,0,0,0)', borderwidth: 0 }, // above the plot: never on the data
    },
  });
  caption.textContent = (front ? `The front line: each interface node's first time |V| > ${String(frontThreshold)} m/s (the job's probe.front_threshold; GET /api/v1/jobs/{id}/front), checked every step. ` : 'No front stored for this run. ') +
    (never.length ? `Never ruptured (|V| stayed at or below the threshold): x1 = ${never.map((x) => fmt(x, 6)).join(', ')} m.` : '');
}

// (e): four panels on one time axis, the stations as traces grouped across the panels.
async function drawSeries(box, caption, job, st, time, colours) {
  if (!st.time.length) { chartMessage(box, 'No time step recorded.'); return; }
  const t = st.time.map((v) => v * time.scale);
  const count = QUANTITIES.length;
  const plotHeight = count * PANEL + (count - 1) * GAP;
  const height = plotHeight + SERIES_MARGIN.t + SERIES_MARGIN.b;
  const layout = {
    margin: SERIES_MARGIN, hovermode: 'closest', showlegend: true,
    legend: { x: 1.01, xanchor: 'left', y: 1, yanchor: 'top', title: { text: 'station' } },
  };
  const data = [];
  QUANTITIES.forEach((q, k) => {
    const rows = st[q.key];
    const u = siUnit(peakOf(rows), q.unit, q.prefixes);
    const suffix = k ? String(k + 1) : '';
    const top = 1 - (k * (PANEL + GAP)) / plotHeight;
    layout[`yaxis${suffix}`] = axis(`${q.title} [${u.unit}]`, { domain: [top - PANEL / plotHeight, top], anchor: `x${suffix}`, automargin: false });
    layout[`xaxis${suffix}`] = axis(k === count - 1 ? `t [${time.unit}]` : '', { anchor: `y${suffix}`, showticklabels: k === count - 1, ...(k ? { matches: 'x' } : {}) });
    st.x1.forEach((x, i) => data.push({
      type: 'scatter', mode: 'lines', x: t, y: rows.map((r) => (r[i] === null ? null : r[i] * u.scale)),
      xaxis: `x${suffix}`, yaxis: `y${suffix}`, name: `x1 = ${fmt(x, 4)} m`, legendgroup: `station-${i}`, showlegend: k === 0,
      line: { color: colours[i], width: 1.5 },
      hovertemplate: `x1 = ${fmt(x, 4)} m<br>t = %{x:.5g} ${time.unit}<br>${q.title} = %{y:.4g} ${u.unit}<extra></extra>`,
    }));
  });
  // The time axis zoomed to the slip (|V| above 1 % of its peak at any station, as (b)).
  const signal = signalWindow(st.x1.map((_, i) => ({ t: st.time, v: st.slip_rate.map((r) => (r[i] === null ? 0 : Math.abs(r[i]))) })));
  const zoomed = signal && (signal[0] > st.time[0] || signal[1] < st.time[st.time.length - 1]);
  if (zoomed) Object.assign(layout.xaxis, { range: signal.map((v) => v * time.scale), autorange: false });
  await chart(box, { data, layout, height, filename: `slipfront-${String(job.id).slice(0, 8)}-stations` });
  caption.textContent = `${st.stride === 1 ? `Every time step of the run (${st.steps})` : `One time step in ${st.stride} of the run's ${st.steps} (the CSV has every step)`} at each station; ` +
    `σ is negative in compression; slip and slip rate are the upper solid's relative to what is below it.${zoomed ? ' Time axis zoomed to the slip (|V| above 1 % of its peak); double-click for the whole run.' : ''}`;
}
