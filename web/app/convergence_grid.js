// The L × n_d convergence map (paper Fig. 3c) as a table: rows L (large to small), columns
// n_d. A cell is the run at that point, coloured by its status against the next finer mesh,
// and shows the SPEC §2 criterion that decided it: the change of the propagation distance and
// of the arrival time at the probe, each against its tolerance (docs/studies.md).
import { h, fmt } from './dom.js';

const STATUS_TEXT = {
  converged: 'converged', not_converged: 'not converged', unknown: 'no finer mesh yet',
  diverged: 'diverged', pending: 'pending', failed: 'failed',
};
const ACTIVE = ['queued', 'running'];

const percent = (fraction) => `${fmt(100 * fraction, 2)} %`;

// One line of the criterion: "d 0.12 % < 0.5 %" (class crit-ok) or "t 0.3 % ≥ 0.1 %" (crit-bad:
// it decided against convergence). Without a tolerance only the change.
function criterion(symbol, what, change, tolerance) {
  if (!Number.isFinite(tolerance)) return h('div', { class: 'crit', title: what, text: `${symbol} ${percent(change)}` });
  const ok = change < tolerance;
  return h('div', { class: `crit ${ok ? 'crit-ok' : 'crit-bad'}`, title: `${what}: ${percent(change)} ${ok ? 'within' : 'not within'} the tolerance ${percent(tolerance)}` },
    `${symbol} ${percent(change)} ${ok ? '<' : '≥'} ${percent(tolerance)}`);
}

// What a cell of the map says: {label, title, lines}. `finished`: no run will be added any
// more (the study has ended), so a run without a finer mesh is the finest of its L, not one
// waiting for a finer mesh.
export function cellText(cell, tolerances, finished) {
  const ch = cell.changes || {};
  let label = STATUS_TEXT[cell.status] || cell.status;
  let title = cell.reason || '';
  const lines = [];
  if (cell.status === 'unknown' && cell.partner_n_d == null) {
    if (finished) {
      label = 'finest mesh';
      title = 'The finest mesh of this L: no finer run to compare it with (the coarser meshes, if any, are judged against it).';
    }
  } else if (cell.status === 'unknown') {
    label = `waiting for n_d = ${fmt(cell.partner_n_d)}`;
  }
  if (cell.status === 'converged' || cell.status === 'not_converged') {
    lines.push(h('div', { class: 'against', text: `vs n_d = ${fmt(cell.partner_n_d)}` }));
    const d = ch.propagation_distance, t = ch.arrival_time;
    if (Number.isFinite(d)) lines.push(criterion('d', 'change of the propagation distance', d, tolerances?.propagation_distance));
    if (Number.isFinite(t)) lines.push(criterion('t', 'change of the arrival time at the probe', t, tolerances?.arrival_time));
    else if (Number.isFinite(d)) lines.push(h('div', { class: 'crit', title: 'the front reached the probe in neither run: judged on the distance alone', text: 't: not reached' }));
    if (!Number.isFinite(d)) lines.push(h('div', { class: 'crit', text: String(cell.reason || '').replace(/^against n_d = [^:]*: /, '') }));
  }
  return { label, title, lines };
}

// A run's convergence status as a badge, in the words of the map's cells.
export function statusBadge(convergence, finished) {
  const { label, title } = cellText(convergence, null, finished);
  return h('span', { class: `badge st-${String(convergence.status).replace(/[^a-z_]/g, '')}`, title, text: label });
}

// Whether a shared map (runs from any study) is final: none of its cells waits for a run.
export function mapIsFinal(map) {
  return !(map?.cells || []).some((c) => c.status === 'pending' || (c.status === 'unknown' && c.partner_n_d != null));
}

// map: a convergence_map JSON ({L, n_d, cells, converged_n_d}); runs: the study's runs (for
// the ones still queued or running); tolerances: {propagation_distance, arrival_time};
// finished: see cellText.
export function convergenceGrid(map, runs, id, { tolerances = null, finished = false } = {}) {
  const Ls = new Set((map?.L) || []);
  const nds = new Set((map?.n_d) || []);
  for (const r of runs || []) { Ls.add(r.L); nds.add(r.n_d); }
  const Llist = [...Ls].sort((a, b) => b - a);
  const ndlist = [...nds].sort((a, b) => a - b);
  const key = (L, n) => `${L}|${n}`;
  const cells = new Map((map?.cells || []).map((c) => [key(c.L, c.n_d), c]));
  const running = new Map();
  for (const r of runs || []) if (!cells.has(key(r.L, r.n_d)) || ACTIVE.includes(r.job_status)) running.set(key(r.L, r.n_d), r);
  const table = h('table', { class: 'cmap', id });
  table.append(h('thead', {}, h('tr', {}, h('th', { class: 'corner', text: 'L [m] \\ n_d [1/m]' }), ndlist.map((n) => h('th', { text: fmt(n) })), h('th', { text: 'converged at' }))));
  const body = h('tbody');
  for (const L of Llist) {
    const tr = h('tr', {}, h('th', { text: fmt(L) }));
    for (const n of ndlist) {
      const c = cells.get(key(L, n));
      const r = running.get(key(L, n));
      if (r && (!c || ACTIVE.includes(r.job_status))) {
        tr.append(h('td', { class: `cell st-${r.job_status}`, title: `job ${r.job_status}` }, h('a', { href: `#/jobs/${r.job_id}`, text: r.job_status })));
      } else if (c) {
        const { label, title, lines } = cellText(c, tolerances, finished);
        tr.append(h('td', { class: `cell cs-${c.status}`, title }, h('a', { href: `#/jobs/${c.run_id}`, text: label }), lines));
      } else tr.append(h('td', { class: 'cell empty', text: '' }));
    }
    const conv = map?.converged_n_d ? map.converged_n_d[JSON.stringify(L)] ?? findConverged(map.converged_n_d, L) : null;
    tr.append(h('td', { class: 'num', text: conv != null ? `n_d = ${fmt(conv)}` : '—' }));
    body.append(tr);
  }
  if (!Llist.length) body.append(h('tr', {}, h('td', { class: 'muted', text: 'no runs yet' })));
  table.append(body);
  return h('div', { class: 'cmapwrap' }, table, legendRow(tolerances, finished));
}

function findConverged(obj, L) {
  for (const [k, v] of Object.entries(obj)) if (Math.abs(Number(k) - L) <= 1e-12 * Math.abs(L)) return v;
  return null;
}

function legendRow(tolerances, finished) {
  const unknown = finished ? 'finest mesh' : STATUS_TEXT.unknown;
  const tol = tolerances ? ` (tolerances: d ${percent(tolerances.propagation_distance)}, t ${percent(tolerances.arrival_time)})` : '';
  return h('div', { class: 'cmaplegend' },
    ['converged', 'not_converged', 'unknown', 'diverged', 'failed'].map((s) => h('span', { class: `cell cs-${s}`, text: s === 'unknown' ? unknown : STATUS_TEXT[s] })),
    h('span', { class: 'cell st-running', text: 'running / queued' }),
    h('span', { class: 'muted', text: ` Against the next finer mesh: d, the change of the propagation distance; t, of the arrival time at the probe${tol}. Converged when both are below their tolerance.` }));
}
