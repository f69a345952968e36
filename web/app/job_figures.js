// The paper's Fig. 2 for one run, from JSON slices of its HDF5 file (/fields) and its front
// (/front): (a) |V| in the x1–t plane with the slip front, (c) V_r(x1) directly below it on the
// same x1 axis (zoom one, the other follows), (b) |V|(t) at chosen x1 — by default the job's
// own stations, else its probes. The map opens on the event (the nodes and times that slipped),
// the whole domain and run one click away. Units and colour scales
// are the CLI's (clients/slipfront_client/plots/): |V| in mm/s; the map logarithmic over four
// decades below its largest |V|, or linear clipped at the 90th percentile of the slipping
// nodes' |V|; grey (darker = faster, as the paper) or viridis.
import { h, fill, fmt } from './dom.js';
import { get } from './api.js';
import { axis, chart, chartMessage, linkXAxes, plotly } from './plots.js';

// Colours of the V(t) positions, on the map's light and dark colours and on white.
const MARKS = ['#d62728', '#1f77b4', '#2ca02c', '#9467bd', '#e377c2', '#17becf'];
const FRONT = '#ff7f0e';
const MM = 1e3; // m/s -> mm/s
const LOG_DECADES = 4;
const CLIP_PERCENTILE = 0.9;
const SIGNAL_FRACTION = 0.01;
// The map's plot area: the V_r chart below uses the same margins, the same x domain and the
// same container, so its x1 axis spans the same pixels as the map's. The colour bar is a
// subplot of its own at the right (COLOUR_BAR): Plotly's built-in colour bar sets a style
// attribute, which the page's Content-Security-Policy refuses.
const MARGIN = { l: 80, r: 90, t: 30, b: 50, autoexpand: false };
const X_DOMAIN = [0, 0.9];
const COLOUR_BAR = [0.925, 0.945];
const COLOURS = {
  greys: [[0, '#ffffff'], [1, '#000000']],
  viridis: 'Viridis',
};

// Shear and P wave speeds of a solid (the job's `material`, or its `lower` solid), plane
// strain, in either form of the job (moduli, or wave speeds as given: docs/api-job-spec.md;
// as the CLI's results.wave_speeds); null for a rigid or incomplete one.
export function solidWaveSpeeds(m) {
  if (m?.s_wave_speed > 0 && m?.p_wave_speed > 0) return { cs: m.s_wave_speed, cp: m.p_wave_speed };
  const E = m?.young_modulus, nu = m?.poisson_ratio, rho = m?.density;
  if (!(E > 0 && nu > 0 && nu < 0.5 && rho > 0)) return null;
  const mu = E / (2 * (1 + nu));
  const lambda = (E * nu) / ((1 + nu) * (1 - 2 * nu));
  return { cs: Math.sqrt(mu / rho), cp: Math.sqrt((lambda + 2 * mu) / rho) };
}

// The upper solid's wave speeds (the block of the paper's scene).
export function waveSpeeds(spec) {
  return solidWaveSpeeds(spec?.material);
}

// The lower solid's, when the interface is between two elastic solids; else null.
export function lowerWaveSpeeds(spec) {
  return spec?.lower?.solid === 'elastic' ? solidWaveSpeeds(spec.lower) : null;
}

// The x1 interval of the nucleation, or null when the run has none: the moving ellipse covers
// 0 to sqrt(a^2 + b^2) (solver/interface/nucleation.cpp), the overstressed patch [x1_min, x1_max].
export function nucleationPatch(spec) {
  const n = spec?.nucleation;
  if (!n || n.enabled === false) return null;
  if (n.type === 'overstressed_patch') return Number.isFinite(n.x1_min) && Number.isFinite(n.x1_max) ? [n.x1_min, n.x1_max] : null;
  if (!(n.a > 0) || !(n.b > 0)) return null;
  return [0, Math.hypot(n.a, n.b)];
}

// The default V(t) positions: the job's own stations (at most `most`, spread along them), else
// its probes (spectrum_x1, arrival_x1), each once and inside [xlo, xhi]; else the middle of the
// domain. [{x, what}], what: "station" or the probe's field.
export function jobPositions(spec, xlo, xhi, most = 6) {
  const inside = (x) => Number.isFinite(x) && x >= xlo && x <= xhi;
  const stations = (spec?.stations?.x1 || []).filter(inside).sort((a, b) => a - b);
  let picked = stations.map((x) => ({ x, what: 'station' }));
  if (!picked.length) {
    picked = [['spectrum_x1', spec?.probe?.spectrum_x1], ['arrival_x1', spec?.probe?.arrival_x1]]
      .filter(([, x]) => inside(x)).map(([what, x]) => ({ x, what: `probe.${what}` }))
      .filter((p, i, all) => all.findIndex((q) => q.x === p.x) === i).sort((a, b) => a.x - b.x);
  }
  if (picked.length > most) picked = Array.from({ length: most }, (_, i) => picked[Math.round((i * (picked.length - 1)) / (most - 1))]);
  return picked.length ? picked : [{ x: Number(((xlo + xhi) / 2).toPrecision(3)), what: 'the middle of the domain' }];
}

// The event in the x1–t box: the nodes where |V| ever exceeded 1 % of its peak (and those the
// front reached), padded by 10 % of their span (at least two cells) each side; the times from
// the first sample to the last |V| above 1 % of the peak, padded by 15 %. Null when it fills
// most of the box (nothing to zoom to) or nothing slipped. absV: [n_t][n_x].
export function eventWindow(x, t, absV, front, xRange) {
  let peak = 0;
  for (const row of absV) for (const v of row) if (v > peak) peak = v;
  if (!(peak > 0)) return null;
  const level = SIGNAL_FRACTION * peak;
  let x0 = Infinity, x1 = -Infinity, tLast = -Infinity;
  absV.forEach((row, i) => row.forEach((v, j) => {
    if (!(v > level)) return;
    x0 = Math.min(x0, x[j]); x1 = Math.max(x1, x[j]); tLast = Math.max(tLast, t[i]);
  }));
  (front?.x1 || []).forEach((xi, i) => { if (Number.isFinite(front.arrival_time[i])) { x0 = Math.min(x0, xi); x1 = Math.max(x1, xi); } });
  const dx = x.length > 1 ? (x[x.length - 1] - x[0]) / (x.length - 1) : 1;
  const pad = Math.max(0.1 * (x1 - x0), 2 * dx);
  const xs = [Math.max(xRange[0], x0 - pad), Math.min(xRange[1], x1 + pad)];
  const ts = [t[0], Math.min(t[t.length - 1], tLast + 0.15 * Math.max(tLast - t[0], 1e-12))];
  const fills = (xs[1] - xs[0]) / (xRange[1] - xRange[0]) > 0.8 && (ts[1] - ts[0]) / (t[t.length - 1] - t[0]) > 0.8;
  return fills ? null : { x: xs, t: ts };
}

// The colour normalisation of |V| [mm/s] (the CLI's colour_norm): {zmin, zmax, clipped}, with
// z = log10|V| on the log scale.
function colourRange(values, scale) {
  let peak = 0;
  for (const v of values) if (v > peak) peak = v;
  if (!(peak > 0)) peak = 1;
  if (scale === 'log') return { zmin: Math.log10(peak) - LOG_DECADES, zmax: Math.log10(peak), clipped: false };
  const moving = values.filter((v) => v > peak * 1e-3).sort((a, b) => a - b);
  // The percentile with linear interpolation between the sorted values (numpy's default).
  const at = CLIP_PERCENTILE * (moving.length - 1), lo = Math.floor(at);
  const top = moving.length ? moving[lo] + (at - lo) * ((moving[Math.min(lo + 1, moving.length - 1)]) - moving[lo]) : peak;
  return { zmin: 0, zmax: top, clipped: top < peak };
}

// (t0, t1) covering every series' |V| above 1 % of the largest, padded by 15 % of the width
// (the CLI's signal_window); null without signal. series: [{t, v: |V|}].
export function signalWindow(series) {
  const peak = Math.max(0, ...series.flatMap((s) => s.v.filter(Number.isFinite)));
  if (!(peak > 0)) return null;
  let t0 = Infinity, t1 = -Infinity;
  for (const s of series)
    s.v.forEach((v, i) => { if (v > SIGNAL_FRACTION * peak) { t0 = Math.min(t0, s.t[i]); t1 = Math.max(t1, s.t[i]); } });
  const pad = 0.15 * Math.max(t1 - t0, 1e-9);
  const first = Math.min(...series.map((s) => s.t[0]));
  const last = Math.max(...series.map((s) => s.t[s.t.length - 1]));
  return [Math.max(first, t0 - pad), Math.min(last, t1 + pad)];
}

function select(id, options, value) {
  return h('select', { id }, options.map(([v, text]) => h('option', { value: v, text, selected: v === value })));
}

export async function drawFigures(figs, job) {
  fill(figs, h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: 'The paper’s Fig. 2, drawn from slices of the HDF5 result (GET /api/v1/jobs/{id}/fields/{name}) and its front (/front). Drag to zoom, double-click to reset; hover for values; the camera and disk buttons save PNG and SVG.' }));
  try { await plotly(); } catch (e) { figs.append(h('p', { class: 'error', id: 'figures-error', text: e.message })); return; }
  const mapBox = h('div', { class: 'fig', id: 'fig-map' });
  const vrBox = h('div', { class: 'fig', id: 'fig-vr' });
  const vtBox = h('div', { class: 'fig', id: 'fig-vt' });
  const mapCaption = h('p', { class: 'caption muted' });
  const vrCaption = h('p', { class: 'caption muted' });
  const scale = select('map-scale', [['log', `log, ${LOG_DECADES} decades below the largest |V| (as the CLI)`], ['linear', 'linear, clipped at the 90th percentile of the slipping |V|']], 'log');
  const colours = select('map-colours', [['greys', 'grey: darker = faster (as the CLI and the paper)'], ['viridis', 'viridis']], 'greys');
  const picks = h('input', { id: 'vt-x1', type: 'text', size: 22 });
  const viewButton = h('button', { id: 'map-view', type: 'button' });
  const pickMsg = h('span', { id: 'vt-message', class: 'muted' });
  const stem = `slipfront-${String(job.id).slice(0, 8)}`;
  figs.append(
    h('h3', { text: '(a) Slip velocity |V| in the x1–t plane, with the slip front' }),
    h('div', { class: 'toolbar' }, h('label', { for: 'map-scale', text: 'colour scale: ' }), scale, h('label', { for: 'map-colours', text: 'colours: ' }), colours, viewButton),
    mapBox, mapCaption,
    h('h3', { text: '(c) Rupture speed V_r(x1), on the x1 axis of (a)' }), vrBox, vrCaption,
    h('h3', { text: '(b) Slip velocity history |V|(t) at chosen x1' }),
    h('div', { class: 'toolbar' }, h('label', { for: 'vt-x1', text: 'x1 [m] (comma list, or click the map): ' }), picks, h('button', { id: 'vt-draw', text: 'Draw', onclick: () => drawVt() }), pickMsg),
    vtBox);

  const width = Math.max(320, mapBox.clientWidth || 800);
  const budget = Math.min(400000, Math.round(width * 440));
  const [slice, front] = await Promise.all([
    get(`/api/v1/jobs/${job.id}/fields/slip_velocity?max_points=${budget}`),
    get(`/api/v1/jobs/${job.id}/front`).catch(() => null),
  ]);
  const x = slice.x1, t = slice.time;
  const dx = x.length > 1 ? (x[x.length - 1] - x[0]) / (x.length - 1) : 1;
  const xRange = [x[0] - dx / 2, x[x.length - 1] + dx / 2]; // the cells' outer edges
  const absV = slice.values.map((row) => row.map((v) => (v === null ? null : Math.abs(v) * MM)));
  const flat = absV.flat().filter((v) => v !== null && Number.isFinite(v));
  const frontTrace = [];
  // One threshold for the front and the stations unless the job gives two: each is labelled.
  const frontThreshold = job.metrics?.front_threshold ?? job.spec?.probe?.front_threshold;
  if (front) {
    const pts = front.x1.map((xi, i) => [xi, front.arrival_time[i]]).filter(([, ti]) => Number.isFinite(ti)).sort((a, b) => a[0] - b[0]);
    frontTrace.push({ type: 'scatter', mode: 'lines', x: pts.map((p) => p[0]), y: pts.map((p) => p[1]), name: `slip front (|V| > ${fmt(frontThreshold)} m/s)`, line: { color: FRONT, width: 1.6 }, hovertemplate: 'front: x1 = %{x:.3f} m, t = %{y:.4g} s<extra></extra>' });
  }
  const ruptures = (job.metrics?.stations || []).filter((s) => Number.isFinite(s.rupture_time));
  if (ruptures.length) {
    const threshold = job.spec?.stations?.rupture_threshold;
    frontTrace.push({ type: 'scatter', mode: 'markers', x: ruptures.map((s) => s.x1), y: ruptures.map((s) => s.rupture_time),
      name: `station rupture times (|V| > ${fmt(threshold)} m/s${threshold === frontThreshold ? ', the front\'s threshold' : ''})`,
      marker: { symbol: 'diamond', size: 8, color: '#ffffff', line: { color: FRONT, width: 1.6 } }, hovertemplate: 'station x1 = %{x:.4g} m, rupture t = %{y:.4g} s<extra></extra>' });
  }
  // The map opens on the event; the button shows the whole domain and run, and back.
  const box = { x: xRange, t: [t[0], t[t.length - 1]] };
  const event = eventWindow(x, t, absV, front, xRange);
  let view = event || box;
  const setViewButton = () => {
    viewButton.hidden = !event;
    viewButton.textContent = view === box ? 'zoom to the event' : 'show the whole domain and run';
  };
  setViewButton();
  viewButton.addEventListener('click', async () => {
    view = view === box ? event : box;
    setViewButton();
    await plotly().then((P) => P.relayout(mapBox, { 'xaxis.range': [...view.x], 'xaxis.autorange': false, 'yaxis.range': [...view.t], 'yaxis.autorange': false }));
    mapCaption.textContent = mapText();
  });
  let marks = [];
  let colourText = '';
  const mapText = () => `${colourText} ${view === box ? 'The whole domain and run.' : `Zoomed to the event: x1 from ${fmt(view.x[0])} to ${fmt(view.x[1])} m, t up to ${fmt(view.t[1])} s of ${fmt(t[t.length - 1])} s (where |V| exceeded 1 % of its peak, and the front); “show the whole domain and run” above, or double-click the map to come back here.`}`;

  const drawMap = async () => {
    const log = scale.value === 'log';
    const { zmin, zmax, clipped } = colourRange(flat, scale.value);
    const z = log ? absV.map((row) => row.map((v) => (v > 0 ? Math.log10(v) : null))) : absV;
    const decades = [];
    for (let k = Math.ceil(zmin); k <= Math.floor(zmax); k++) decades.push(k);
    const colourscale = COLOURS[colours.value];
    const heat = {
      type: 'heatmap', x, y: t, z, customdata: absV, zmin, zmax, zauto: false, colorscale: colourscale, showscale: false,
      zsmooth: 'fast', // not false: Plotly would set a style attribute, which the CSP refuses
      hoverongaps: true, hovertemplate: 'x1 = %{x:.3f} m<br>t = %{y:.4g} s<br>|V| = %{customdata:.3g} mm/s<extra></extra>',
    };
    const levels = Array.from({ length: 256 }, (_, i) => zmin + ((zmax - zmin) * i) / 255);
    const bar = {
      type: 'heatmap', xaxis: 'x2', yaxis: 'y2', x: [0], y: levels, z: levels.map((v) => [v]), zmin, zmax, zauto: false,
      colorscale: colourscale, showscale: false, zsmooth: 'fast', hoverinfo: 'skip',
    };
    const probeTraces = marks.map((m) => ({ type: 'scatter', mode: 'lines', x: [m.x, m.x], y: [t[0], t[t.length - 1]], name: `x1 = ${fmt(m.x, 4)} m${m.what ? ` (${m.what})` : ''}`, line: { color: m.color, width: 1.4, dash: 'dash' }, hoverinfo: 'skip' }));
    const barTitle = `|V| [mm/s]${log ? ' (log scale)' : ''}${clipped ? ', clipped at top' : ''}`;
    // More than three entries (stations, both thresholds) would hide the event: the legend
    // goes above the plot, in rows of three, the top margin grown for them (the x axis, and
    // so V_r's below, keeps its pixels: only the left and right margins are shared).
    const entries = frontTrace.length + probeTraces.length;
    const above = entries > 3;
    const rows = Math.ceil(entries / 3);
    await chart(mapBox, {
      data: [heat, bar, ...frontTrace, ...probeTraces], height: 440 + (above ? 20 * rows : 0), filename: `${stem}-map`,
      layout: {
        margin: above ? { ...MARGIN, t: MARGIN.t + 20 * rows } : MARGIN, xaxis: axis('x1 [m]', { range: [...view.x], autorange: false, domain: X_DOMAIN }), yaxis: axis('t [s]', { range: [...view.t], autorange: false }),
        xaxis2: { domain: COLOUR_BAR, anchor: 'y2', visible: false, fixedrange: true },
        yaxis2: axis(barTitle, { anchor: 'x2', side: 'right', range: [zmin, zmax], fixedrange: true, gridcolor: 'rgba(0,0,0,0)', ...(log ? { tickvals: decades, ticktext: decades.map((k) => fmt(10 ** k)) } : {}) }),
        legend: above
          ? { orientation: 'h', x: 0, xanchor: 'left', y: 1.01, yanchor: 'bottom', bgcolor: 'rgba(0,0,0,0)', borderwidth: 0 }
          : { x: 0.01, y: 0.99, bgcolor: 'rgba(255,255,255,0.85)', bordercolor: '#c9d1da', borderwidth: 1 },
      },
    });
    colourText = `${slice.source_shape[0]} samples × ${slice.source_shape[1]} nodes in the file; shown every ${slice.stride.time} sample(s) and ${slice.stride.x1} node(s). ` +
      (log ? `Colours span ${LOG_DECADES} decades below the largest |V| (${fmt(10 ** zmax)} mm/s); white: below that (no slip).` : `Colours from 0 to ${fmt(zmax)} mm/s${clipped ? ', the 90th percentile of the slipping nodes’ |V|: faster nodes have the darkest colour' : ''}.`);
    mapCaption.textContent = mapText();
  };
  scale.addEventListener('change', drawMap);
  colours.addEventListener('change', drawMap);
  await drawMap();
  mapBox.on('plotly_click', (ev) => {
    const xi = ev.points?.[0]?.x;
    if (!Number.isFinite(xi)) return;
    picks.value = parsePicks().concat([Number(xi.toFixed(2))]).slice(-5).join(', ');
    drawVt();
  });

  await drawVr(vrBox, vrCaption, job, front, view.x, stem);
  if (front) linkXAxes(mapBox, vrBox);

  // The job's own stations, else its probes (the map's dashed lines and the curves of (b)).
  const positions = jobPositions(job.spec, x[0], x[x.length - 1], MARKS.length);
  const whatAt = new Map(positions.map((p) => [p.x, p.what]));
  picks.value = positions.map((p) => p.x).join(', ');
  function parsePicks() {
    return picks.value.split(/[,\s]+/).filter(Boolean).map(Number).filter((v) => Number.isFinite(v));
  }
  async function drawVt() {
    const wanted = parsePicks().slice(0, MARKS.length);
    const xs = wanted.filter((xi) => xi >= xRange[0] && xi <= xRange[1]);
    const outside = wanted.filter((xi) => !xs.includes(xi));
    pickMsg.className = 'muted';
    pickMsg.textContent = outside.length ? `outside the domain [${fmt(xRange[0])}, ${fmt(xRange[1])}] m, left out: ${outside.join(', ')}` : '';
    try {
      const slices = await Promise.all(xs.map((xi) => get(`/api/v1/jobs/${job.id}/fields/slip_velocity?x1_min=${xi}&x1_max=${xi}&max_points=4000`)));
      const series = slices.map((s, i) => ({ x: s.x1[0], asked: xs[i], t: s.time, v: s.values.map((r) => (r[0] === null ? null : Math.abs(r[0]) * MM)), color: MARKS[i % MARKS.length] }));
      marks = series.map((s) => ({ x: s.x, color: s.color, what: whatAt.get(s.asked) }));
      await drawMap();
      if (!series.length) { chartMessage(vtBox, 'No position inside the domain.'); return; }
      const signal = signalWindow(series);
      await chart(vtBox, {
        data: series.map((s) => ({ type: 'scatter', mode: 'lines', x: s.t, y: s.v, name: `x1 = ${fmt(s.x, 4)} m${whatAt.get(s.asked) ? ` (${whatAt.get(s.asked)})` : ''}`, line: { color: s.color, width: 1.6 }, hovertemplate: '%{y:.3g} mm/s' })),
        height: 320, filename: `${stem}-velocity`,
        layout: {
          hovermode: 'x unified', margin: { l: 80, r: 24, t: 30, b: 50, autoexpand: false },
          xaxis: axis(signal ? 't [s] (zoomed to the signal; double-click: the whole run)' : 't [s]', signal ? { range: signal, autorange: false } : {}),
          yaxis: axis('|V| [mm/s]', { rangemode: 'tozero' }),
          legend: { x: 0.99, xanchor: 'right', y: 0.99 },
        },
      });
    } catch (e) { pickMsg.textContent = e.message; pickMsg.className = 'error'; }
  }
  await drawVt();
}

// (c) V_r(x1) from the front, with c_s, c_p (of each solid when there are two) and the
// nucleation patch (as the CLI's plot_speed): the y axis stops at 1.1 c_p (of the faster one).
async function drawVr(box, caption, job, front, xRange, stem) {
  if (!front) { chartMessage(box, 'No front stored for this run.'); return; }
  const speeds = waveSpeeds(job.spec);
  const lower = lowerWaveSpeeds(job.spec);
  const patch = nucleationPatch(job.spec);
  const vr = front.rupture_speed.filter((v) => v !== null && Number.isFinite(v));
  const top = Math.max(0, ...vr);
  const fastest = Math.max(speeds?.cp ?? 0, lower?.cp ?? 0); // the axis stops at 1.1 of it
  const shapes = [];
  const notes = [];
  if (patch) shapes.push({ type: 'rect', xref: 'x', yref: 'y domain', x0: patch[0], x1: patch[1], y0: 0, y1: 1, fillcolor: 'rgba(255,127,14,0.15)', line: { width: 0 }, layer: 'below' });
  const lines = speeds ? [['c_s', speeds.cs, 'dash'], ['c_p', speeds.cp, 'dashdot']] : [];
  if (speeds && lower && (lower.cs !== speeds.cs || lower.cp !== speeds.cp)) { // two different solids: each one's
    lines.splice(0, 2, ['c_s upper', speeds.cs, 'dash'], ['c_p upper', speeds.cp, 'dashdot'], ['c_s lower', lower.cs, 'dot'], ['c_p lower', lower.cp, 'longdashdot']);
  }
  for (const [name, v, dash] of lines) {
    shapes.push({ type: 'line', xref: 'x domain', yref: 'y', x0: 0, x1: 1, y0: v, y1: v, line: { color: '#6b7785', width: 1, dash } });
    notes.push({ xref: 'x domain', yref: 'y', x: 1, y: v, xanchor: 'right', yanchor: 'bottom', showarrow: false, text: `${name} = ${fmt(v)} m/s`, font: { color: '#6b7785', size: 11 } });
  }
  await chart(box, {
    data: [{ type: 'scatter', mode: 'lines+markers', x: front.x1, y: front.rupture_speed, name: 'V_r from the front arrival times', marker: { size: 3 }, line: { color: '#1f77b4', width: 1.4 }, hovertemplate: 'x1 = %{x:.3f} m<br>V_r = %{y:.4g} m/s<extra></extra>' },
      ...(patch ? [{ type: 'scatter', mode: 'lines', x: [null], y: [null], name: `nucleation patch (${fmt(patch[0])} to ${fmt(patch[1])} m)`, line: { color: 'rgba(255,127,14,0.5)', width: 8 }, hoverinfo: 'skip' }] : [])],
    height: 260, filename: `${stem}-rupture-speed`,
    layout: {
      margin: MARGIN, shapes, annotations: notes, showlegend: true,
      xaxis: axis('x1 [m]', { range: [...xRange], autorange: false, domain: X_DOMAIN }),
      yaxis: axis('V_r [m/s]', fastest > 0 ? { range: [0, 1.1 * fastest], autorange: false } : { rangemode: 'tozero' }),
      legend: { x: 0.01, xanchor: 'left', y: 0.02, yanchor: 'bottom' },
    },
  });
  caption.textContent = fastest > 0 && top > 1.1 * fastest
    ? `Axis cut at 1.1 c_p${lower ? ' of the faster solid' : ''} (as the CLI); V_r reaches ${fmt(top)} m/s where the front arrives almost at once (inside the nucleation patch).`
    : '';
}
