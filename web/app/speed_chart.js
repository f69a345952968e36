// The speed–accuracy chart of a study: wall time against the relative error, log-log, one
// curve per (method, L) along its refinement (increasing n_d), as the CLI's cost chart
// (clients/slipfront_client/plots/cost.py): colour = L, FE ● solid, BI □ dashed, each point
// labelled with its n_d. A curve never joins two runs of the same mesh: when a mesh was run
// more than once (a repeated or fresh run, a run of another study of the same scene) the curve
// goes through one of them (the smallest id, as the convergence map's pick) and the others are
// shown as crosses.
import { fmt } from './dom.js';
import { axis, chart, chartMessage, PALETTE } from './plots.js';
import { defaultMethod, methodLabel, methodStyle } from './methods.js';

// [key, the menu's text, the chart title's text]
export const METRICS = [
  ['max', 'larger of the distance and arrival-time errors (as the CLI)', 'Relative error (the larger of distance and arrival time)'],
  ['propagation_distance', 'error of the propagation distance', 'Relative error of the propagation distance'],
  ['arrival_time', 'error of the arrival time at the probe', 'Relative error of the arrival time at the probe'],
  ['slip_velocity_l2', 'L2 error of V at the spectrum probe', 'Relative L2 error of V(t) at the spectrum probe'],
];

// The error of an entry of GET /studies/{id}/speed-accuracy under `metric`; null when none.
export function entryError(entry, metric) {
  const e = entry.errors || {};
  const ok = (v) => (Number.isFinite(v) && v > 0 ? v : null);
  if (metric !== 'max') return ok(e[metric]);
  const both = [ok(e.propagation_distance), ok(e.arrival_time)].filter((v) => v !== null);
  return both.length ? Math.max(...both) : null;
}

// The curves of the chart: [{method, L, runs: [entry...] (increasing n_d, one per mesh),
// repeats: [entry...] (the other runs of a mesh already on the curve)}], sorted by method
// then L (large to small). Entries without a positive error or wall time are left out.
export function refinementCurves(entries, metric, fallbackMethod = defaultMethod()) {
  const groups = new Map();
  for (const entry of entries) {
    if (entryError(entry, metric) === null || !(entry.wall_time_s > 0)) continue;
    const method = entry.method || fallbackMethod;
    const key = `${method}|${entry.L}`;
    if (!groups.has(key)) groups.set(key, { method, L: entry.L, byMesh: new Map() });
    const meshes = groups.get(key).byMesh;
    if (!meshes.has(entry.n_d)) meshes.set(entry.n_d, []);
    meshes.get(entry.n_d).push(entry);
  }
  const curves = [];
  for (const g of groups.values()) {
    const runs = [];
    const repeats = [];
    for (const n_d of [...g.byMesh.keys()].sort((a, b) => a - b)) {
      const same = g.byMesh.get(n_d).slice().sort((a, b) => String(a.id).localeCompare(String(b.id)));
      runs.push(same[0]);
      repeats.push(...same.slice(1));
    }
    curves.push({ method: g.method, L: g.L, runs, repeats });
  }
  return curves.sort((a, b) => a.method.localeCompare(b.method) || b.L - a.L);
}

// Draws the chart into `box`; a click on a point opens its run.
export async function drawSpeedChart(box, entries, metric, fallbackMethod, filename) {
  const curves = refinementCurves(entries, metric, fallbackMethod);
  if (!curves.length) { chartMessage(box, 'No run has both a reference and an error yet.'); return; }
  const Ls = [...new Set(curves.map((c) => c.L))].sort((a, b) => b - a);
  const traces = [];
  const hover = 'run %{customdata[0]}<br>n_d = %{customdata[1]} /m<br>wall time %{x:.3g} s<br>error %{y:.3g}<extra>%{fullData.name}</extra>';
  for (const c of curves) {
    const colour = PALETTE[Ls.indexOf(c.L) % PALETTE.length];
    const style = methodStyle(c.method);
    const name = `${methodLabel(c.method)}, L = ${fmt(c.L)} m`;
    const point = (e) => [e.id, e.n_d];
    traces.push({
      type: 'scatter', mode: 'lines+markers+text', name, legendgroup: name,
      x: c.runs.map((e) => e.wall_time_s), y: c.runs.map((e) => entryError(e, metric)),
      text: c.runs.map((e) => fmt(e.n_d)), textposition: style.text, textfont: { size: 10, color: colour },
      customdata: c.runs.map(point), hovertemplate: hover,
      line: { color: colour, width: 1.4, dash: style.dash },
      marker: { color: colour, size: 8, symbol: style.marker, line: { color: colour, width: 1.5 } },
    });
    if (c.repeats.length) {
      traces.push({
        type: 'scatter', mode: 'markers', name: `${name}: repeated runs of a mesh`, legendgroup: name, showlegend: false,
        x: c.repeats.map((e) => e.wall_time_s), y: c.repeats.map((e) => entryError(e, metric)),
        customdata: c.repeats.map(point), hovertemplate: hover,
        marker: { color: colour, size: 8, symbol: 'x-thin-open', line: { color: colour, width: 1.5 } },
      });
    }
  }
  const label = METRICS.find(([k]) => k === metric)?.[2] || metric;
  await chart(box, {
    data: traces, height: 360, filename,
    layout: {
      margin: { l: 80, r: 190, t: 40, b: 50, autoexpand: false }, hovermode: 'closest',
      title: { text: `${label} against wall time (point labels: n_d)`, font: { size: 13 }, x: 0, xref: 'paper', xanchor: 'left' },
      xaxis: axis('wall time [s]', { type: 'log', dtick: 'D2' }), yaxis: axis('relative error', { type: 'log', dtick: 'D2' }),
      legend: { x: 1.02, xanchor: 'left', y: 1 },
    },
  });
  box.on('plotly_click', (ev) => {
    const id = ev.points?.[0]?.customdata?.[0];
    if (id) location.hash = `#/jobs/${id}`;
  });
}
