// The figures of runs compared (compare.js), each run in its colour, its method's dash and
// marker (methods.js methodStyle) and named by its legend text: |V|(t) at chosen x1 (the
// paper's 6 and 10 m by default) in stacked panels, V_r(x1) and the slip front overlaid, and a
// scatter of any parameter against any metric. Drawn from the endpoints the run page uses
// (/fields/slip_velocity at one node, /front); units as the run page's (job_figures.js).
import { h, fmt } from './dom.js';
import { get } from './api.js';
import { axis, chart, chartMessage, plotly } from './plots.js';
import { jobPositions, nucleationPatch, signalWindow, waveSpeeds } from './job_figures.js';

const MM = 1e3; // m/s -> mm/s
const MAX_POSITIONS = 4;
const PANEL = 190; // px: one V(t) panel
const GAP = 46; // px between panels (room for each panel's title)
// Room above the plot for the legend (one line per run: the texts are long).
const legendTop = { orientation: 'h', x: 0, xanchor: 'left', y: 1.02, yanchor: 'bottom', bgcolor: 'rgba(0,0,0,0)', borderwidth: 0 };
const margin = (runs) => ({ l: 80, r: 24, t: 30 + 22 * runs.length, b: 50, autoexpand: false });

function line(run, extra = {}) {
  return { color: run.color, width: 1.6, dash: run.style.dash, ...extra };
}

export async function drawCompareFigures(box, runs, rows) {
  box.append(h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: 'Drawn from slices of each run’s HDF5 result (GET /api/v1/jobs/{id}/fields/slip_velocity at one node) and its front (/front). Click a legend entry to hide a run, double-click to show it alone; drag to zoom; the camera and disk buttons save PNG and SVG.' }));
  try { await plotly(); } catch (e) { box.append(h('p', { class: 'error', text: e.message })); return; }
  const done = runs.filter((r) => r.job.status === 'succeeded' && r.job.result);
  const left = runs.filter((r) => !done.includes(r));
  if (left.length) box.append(h('p', { class: 'muted', id: 'compare-no-result', text: `No result file, so no curves, for: ${left.map((r) => r.label).join('; ')}.` }));
  const fronts = await Promise.all(done.map((r) => get(`/api/v1/jobs/${r.job.id}/front`).catch(() => null)));
  const withFront = done.map((r, i) => ({ ...r, front: fronts[i] })).filter((r) => r.front);

  const picks = h('input', { id: 'cmp-x1', type: 'text', size: 18 });
  const pickMsg = h('span', { id: 'cmp-vt-message', class: 'muted' });
  const vtBox = h('div', { class: 'fig', id: 'cmp-vt' });
  const vrBox = h('div', { class: 'fig', id: 'cmp-vr' });
  const frontBox = h('div', { class: 'fig', id: 'cmp-front' });
  const scatterBox = h('div', { class: 'fig', id: 'cmp-scatter' });
  const scatterTools = h('div', { class: 'toolbar' });
  box.append(
    h('h3', { text: '(b) Slip velocity history |V|(t) at chosen x1' }),
    h('div', { class: 'toolbar' }, h('label', { for: 'cmp-x1', text: `x1 [m] (comma list, up to ${MAX_POSITIONS}): ` }), picks,
      h('button', { id: 'cmp-vt-draw', text: 'Draw', onclick: () => drawVt() }), pickMsg),
    vtBox,
    h('h3', { text: '(c) Rupture speed V_r(x1)' }), vrBox,
    h('h3', { text: 'Slip front: arrival time against x1' }), frontBox,
    h('h3', { text: 'Any parameter against any metric' }), scatterTools, scatterBox);

  // The first run's own stations or probes inside every run's domain (the front lists every
  // node), as the run page.
  const lo = Math.max(...withFront.map((r) => Math.min(...r.front.x1)));
  const hi = Math.min(...withFront.map((r) => Math.max(...r.front.x1)));
  picks.value = Number.isFinite(lo + hi) ? jobPositions(withFront[0].job.spec, lo, hi, MAX_POSITIONS).map((p) => p.x).join(', ') : '';

  async function drawVt() {
    const wanted = picks.value.split(/[,\s]+/).filter(Boolean).map(Number).filter(Number.isFinite).slice(0, MAX_POSITIONS);
    pickMsg.textContent = '';
    pickMsg.className = 'muted';
    if (!withFront.length || !wanted.length) { chartMessage(vtBox, withFront.length ? 'Give at least one x1.' : 'No run with a result.'); return; }
    try {
      await drawVelocity(vtBox, withFront, wanted, pickMsg);
    } catch (e) { pickMsg.textContent = e.message; pickMsg.className = 'error'; }
  }
  await drawVt();
  if (withFront.length) {
    await drawSpeed(vrBox, withFront);
    await drawFront(frontBox, withFront);
  } else {
    chartMessage(vrBox, 'No run with a front.');
    chartMessage(frontBox, 'No run with a front.');
  }
  scatterControls(scatterTools, scatterBox, runs, rows);
}

// One panel per position, stacked; one trace per run in every panel, one
// legend entry per run (legendgroup: a click hides the run in every panel).
async function drawVelocity(box, runs, positions, message) {
  const series = await Promise.all(runs.map((r) => Promise.all(positions.map(async (x) => {
    if (x < Math.min(...r.front.x1) || x > Math.max(...r.front.x1)) return null;
    const s = await get(`/api/v1/jobs/${r.job.id}/fields/slip_velocity?x1_min=${x}&x1_max=${x}&max_points=4000`);
    return { node: s.x1[0], t: s.time, v: s.values.map((row) => (row[0] === null ? null : Math.abs(row[0]) * MM)) };
  }))));
  const missing = positions.filter((_, k) => series.some((perRun) => !perRun[k]));
  if (missing.length) message.textContent = `outside the domain of some runs (no curve there): x1 = ${missing.join(', ')} m`;
  const count = positions.length;
  const top = margin(runs);
  const plotHeight = count * PANEL + (count - 1) * GAP;
  const layout = { margin: top, showlegend: true, legend: legendTop, hovermode: 'closest', annotations: [] };
  const data = [];
  positions.forEach((x, k) => {
    const suffix = k ? String(k + 1) : '';
    const upper = 1 - (k * (PANEL + GAP)) / plotHeight;
    layout[`yaxis${suffix}`] = axis('|V| [mm/s]', { domain: [upper - PANEL / plotHeight, upper], anchor: `x${suffix}`, rangemode: 'tozero' });
    // Each panel zoomed to its own signal (the front reaches each x1 at another time).
    const signal = signalWindow(series.map((perRun) => perRun[k]).filter(Boolean));
    layout[`xaxis${suffix}`] = axis(k === count - 1 ? 't [s] (each panel zoomed to its signal; double-click: the whole runs)' : '', { anchor: `y${suffix}`, ...(signal ? { range: signal, autorange: false } : {}) });
    layout.annotations.push({ xref: `x${suffix} domain`, yref: `y${suffix} domain`, x: 0, y: 1, xanchor: 'left', yanchor: 'bottom', showarrow: false, text: `x1 = ${fmt(x, 4)} m`, font: { size: 12 } });
    runs.forEach((r, i) => {
      const s = series[i][k];
      data.push({
        type: 'scatter', mode: 'lines', x: s ? s.t : [], y: s ? s.v : [], xaxis: `x${suffix}`, yaxis: `y${suffix}`,
        name: r.label, legendgroup: r.job.id, showlegend: k === 0, line: line(r),
        hovertemplate: `${r.label}<br>node x1 = ${s ? fmt(s.node, 4) : '—'} m<br>t = %{x:.4g} s<br>|V| = %{y:.3g} mm/s<extra></extra>`,
      });
    });
  });
  await chart(box, { data, layout, height: plotHeight + top.t + top.b, filename: 'slipfront-compare-velocity' });
}

// The wave speeds and the nucleation patch when every run has the same (else none: whose?).
function sharedScene(runs) {
  const speeds = runs.map((r) => waveSpeeds(r.job.spec));
  const patches = runs.map((r) => nucleationPatch(r.job.spec));
  const one = (list) => (list.every((v) => JSON.stringify(v) === JSON.stringify(list[0])) ? list[0] : null);
  return { speeds: one(speeds), patch: one(patches) };
}

// The x1 range where any run's values are known (V_r, the front's arrival), padded: the
// rupture's extent, not the whole domain.
function knownRange(runs, valuesOf) {
  const xs = runs.flatMap((r) => r.front.x1.filter((_, i) => Number.isFinite(valuesOf(r.front)[i])));
  if (!xs.length) return {};
  const lo = Math.min(...xs), hi = Math.max(...xs), pad = 0.04 * Math.max(hi - lo, 1e-9);
  return { range: [lo - pad, hi + pad], autorange: false };
}

async function drawSpeed(box, runs) {
  const { speeds, patch } = sharedScene(runs);
  const shapes = [], notes = [];
  if (patch) shapes.push({ type: 'rect', xref: 'x', yref: 'y domain', x0: patch[0], x1: patch[1], y0: 0, y1: 1, fillcolor: 'rgba(255,127,14,0.15)', line: { width: 0 }, layer: 'below' });
  if (speeds) {
    for (const [name, v, dash] of [['c_s', speeds.cs, 'dash'], ['c_p', speeds.cp, 'dashdot']]) {
      shapes.push({ type: 'line', xref: 'x domain', yref: 'y', x0: 0, x1: 1, y0: v, y1: v, line: { color: '#6b7785', width: 1, dash } });
      notes.push({ xref: 'x domain', yref: 'y', x: 1, y: v, xanchor: 'right', yanchor: 'bottom', showarrow: false, text: `${name} = ${fmt(v)} m/s`, font: { color: '#6b7785', size: 11 } });
    }
  }
  const data = runs.map((r) => ({
    type: 'scatter', mode: 'lines+markers', x: r.front.x1, y: r.front.rupture_speed, name: r.label,
    line: line(r, { width: 1.3 }), marker: { symbol: r.style.symbol, size: 5, color: r.color },
    hovertemplate: `${r.label}<br>x1 = %{x:.3f} m<br>V_r = %{y:.4g} m/s<extra></extra>`,
  }));
  const top = margin(runs);
  await chart(box, {
    data, height: 300 + top.t, filename: 'slipfront-compare-rupture-speed',
    layout: {
      margin: top, shapes, annotations: notes, showlegend: true, legend: legendTop,
      xaxis: axis('x1 [m]', knownRange(runs, (f) => f.rupture_speed)), yaxis: axis('V_r [m/s]', speeds ? { range: [0, 1.1 * speeds.cp], autorange: false } : { rangemode: 'tozero' }),
    },
  });
}

async function drawFront(box, runs) {
  const data = runs.map((r) => {
    const pts = r.front.x1.map((x, i) => [x, r.front.arrival_time[i]]).sort((a, b) => a[0] - b[0]);
    return {
      type: 'scatter', mode: 'lines', x: pts.map((p) => p[0]), y: pts.map((p) => p[1]), connectgaps: false, name: r.label, line: line(r),
      hovertemplate: `${r.label}<br>x1 = %{x:.3f} m<br>t = %{y:.4g} s<extra></extra>`,
    };
  });
  const top = margin(runs);
  await chart(box, {
    data, height: 300 + top.t, filename: 'slipfront-compare-front',
    layout: { margin: top, showlegend: true, legend: legendTop, xaxis: axis('x1 [m]', knownRange(runs, (f) => f.arrival_time)), yaxis: axis('arrival time of the front [s]', { rangemode: 'tozero' }) },
  });
}

// The fields of one kind of value (numbers, or with `text` also text such as the method) with
// a value for at least one run: the parameters (spec) for x, the metrics (numbers) for y.
function plottableRows(rows, group, text = false) {
  const kinds = text ? ['number', 'string'] : ['number'];
  return rows.filter((r) => r.group === group).filter((r) => {
    const types = new Set(r.values.filter((v) => v !== undefined && v !== null).map((v) => typeof v));
    return types.size === 1 && kinds.includes([...types][0]);
  });
}

function scatterControls(tools, box, runs, rows) {
  const params = plottableRows(rows, 'spec', true);
  const metrics = plottableRows(rows, 'metrics');
  if (!params.length || !metrics.length) { chartMessage(box, 'No parameter or numeric metric to plot.'); return; }
  // Defaults: the parameter that differs and every run has (L, n_d, the method first), the
  // propagation distance.
  const common = params.filter((r) => r.differs && r.values.every((v) => v !== undefined && v !== null));
  const firstDiffering = ['friction.L', 'geometry.nodes_per_meter', 'method'].find((k) => common.some((r) => r.key === k)) || common[0]?.key || 'friction.L';
  const yDefault = metrics.some((r) => r.key === 'propagation_distance') ? 'propagation_distance' : metrics[0].key;
  const menu = (id, list, value) => h('select', { id }, list.map((r) => h('option', { value: r.key, text: `${r.key}${r.differs ? ' (differs)' : ''}`, selected: r.key === value })));
  const xs = menu('cmp-scatter-x', params, firstDiffering), ys = menu('cmp-scatter-y', metrics, yDefault);
  const note = h('span', { class: 'muted', id: 'cmp-scatter-note' });
  tools.append(h('label', { for: 'cmp-scatter-x', text: 'parameter (x): ' }), xs, h('label', { for: 'cmp-scatter-y', text: 'metric (y): ' }), ys, note);
  const draw = () => drawScatter(box, note, runs, params.find((r) => r.key === xs.value), metrics.find((r) => r.key === ys.value));
  xs.addEventListener('change', draw);
  ys.addEventListener('change', draw);
  return draw();
}

// A category axis for text, a log axis when the values are positive and span more than a
// decade and a half.
function axisType(values) {
  if (values.some((x) => typeof x === 'string')) return 'category';
  const v = values.filter(Number.isFinite);
  return v.length > 1 && v.every((x) => x > 0) && Math.max(...v) / Math.min(...v) > 30 ? 'log' : 'linear';
}

async function drawScatter(box, note, runs, xRow, yRow) {
  const points = runs.map((r, i) => ({ r, x: xRow.values[i], y: yRow.values[i] })).filter((p) => p.x !== undefined && p.x !== null && typeof p.y === 'number');
  const without = runs.length - points.length;
  note.textContent = without ? `${without} run${without === 1 ? ' has' : 's have'} no value of one of them (not drawn)` : '';
  const data = points.map(({ r, x, y }) => ({
    type: 'scatter', mode: 'markers', x: [x], y: [y], name: r.label,
    marker: { symbol: r.style.symbol, size: 12, color: r.color, line: { color: '#1d2733', width: 1 } },
    hovertemplate: `${r.label}<br>${xRow.key} = %{x}<br>${yRow.key} = %{y:.4g}<extra></extra>`,
  }));
  const top = margin(points.map((p) => p.r));
  await chart(box, {
    data, height: 320 + top.t, filename: 'slipfront-compare-scatter',
    layout: {
      margin: top, showlegend: true, legend: legendTop,
      xaxis: axis(xRow.key, { type: axisType(points.map((p) => p.x)) }), yaxis: axis(`metrics.${yRow.key}`, { type: axisType(points.map((p) => p.y)) }),
    },
  });
}
