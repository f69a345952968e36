// Compare runs (docs/web.md "Compare runs"): runs picked by id (the jobs list's check boxes),
// by the server's search (`where`) or by study, side by side — a table of their run fields,
// spec and metrics with the fields that differ highlighted, then their figures overlaid
// (compare_figures.js), each run in its colour and its method's line style, named by what
// tells it from the others (run_labels.js).
import { h, clear, fill, fmt, badge, link, shortId } from './dom.js';
import { get, qs } from './api.js';
import { PALETTE } from './plots.js';
import { cellText, compareLabels, compareRows } from './run_labels.js';
import { defaultMethod, methodStyle } from './methods.js';
import { drawCompareFigures } from './compare_figures.js';

export const MAX_RUNS = 12; // overlaid curves beyond this read as noise
export const POLL_MS = 3000; // while a compared run is queued or running
const FINAL = new Set(['succeeded', 'failed', 'cancelled']);
const JOB_ID = /^[0-9a-f]{32}$/;
// The rows shown even when every run has the same value (the others: a check box away).
const KEY_ROWS = new Set(['run.name', 'run.status', 'spec.method', 'spec.friction.L', 'spec.geometry.nodes_per_meter',
  'metrics.outcome', 'metrics.arrest_position', 'metrics.propagation_distance', 'metrics.rupture_speed.max',
  'metrics.rupture_speed.mean', 'metrics.arrival_time_at_probe', 'metrics.max_slip_velocity', 'metrics.wall_time_s']);
const GROUPS = { run: 'Run', spec: 'Parameters (the job spec, defaults filled)', metrics: 'Metrics (docs/metrics.md)' };

// The order of a study's or a search's runs: by method, L from large to small, n_d up.
function byScene(a, b) {
  const key = (j) => [j.method || defaultMethod(), -(j.spec?.friction?.L ?? 0), j.spec?.geometry?.nodes_per_meter ?? 0];
  const [x, y] = [key(a), key(b)];
  for (let i = 0; i < x.length; i++) if (x[i] !== y[i]) return x[i] < y[i] ? -1 : 1;
  return 0;
}

// {jobs, source, notes}: the runs the address names (?ids=a,b | ?study=S | ?where=...).
async function pickRuns(params) {
  const notes = [];
  if (params.get('ids')) {
    const ids = [...new Set(params.get('ids').split(',').map((s) => s.trim()).filter(Boolean))];
    const bad = ids.filter((id) => !JOB_ID.test(id));
    if (bad.length) notes.push(`Not a job id (32 hex characters), left out: ${bad.join(', ')}`);
    const found = await Promise.all(ids.filter((id) => JOB_ID.test(id)).map((id) => get(`/api/v1/jobs/${id}`).catch((e) => ({ missing: id, error: e }))));
    for (const f of found.filter((x) => x.missing)) notes.push(`Job ${f.missing}: ${f.error.status === 404 ? 'no such job on this server' : f.error.message}`);
    return { jobs: found.filter((x) => !x.missing), source: 'the runs you picked', notes };
  }
  const study = params.get('study'), where = params.get('where');
  if (!study && !where) return { jobs: [], source: '', notes };
  const listing = await get(`/api/v1/jobs${qs({ study_id: study || '', where: where || '', limit: 200 })}`);
  const jobs = (listing.jobs || []).slice().sort(byScene);
  const source = study ? `the runs of study ${shortId(study)}` : `the search “${where}”`;
  return { jobs, source, notes, study };
}

function picker(params) {
  const ids = h('input', { type: 'text', id: 'compare-ids', size: 50, placeholder: 'job ids, comma-separated', value: params.get('ids') || '' });
  const where = h('input', { type: 'text', id: 'compare-where', size: 44, placeholder: 'or a search: method=spectral_bi and friction.L<1e-4', value: params.get('where') || '' });
  const go = (ev) => {
    ev.preventDefault();
    const q = ids.value.trim() ? { ids: ids.value.replace(/\s+/g, '') } : { where: where.value.trim() };
    location.hash = `#/compare${qs(q)}`;
  };
  return h('form', { class: 'toolbar', id: 'compare-pick', onsubmit: go }, h('label', { for: 'compare-ids', text: 'runs: ' }), ids, where,
    h('button', { type: 'submit', text: 'Compare' }),
    h('span', { class: 'muted', text: 'search fields: docs/server.md “Searching and exporting runs”' }));
}

// A short line in the run's colour and its method's dash, as in the charts.
function swatch(run) {
  const s = h('span', { class: `swatch ${run.style.dash}` });
  s.style.setProperty('border-top-color', run.color);
  return s;
}

function valueCell(row, v) {
  if ((row.key === 'study_id' || row.key === 'cached_from') && v) return h('td', {}, link(row.key === 'study_id' ? `#/studies/${v}` : `#/jobs/${v}`, shortId(v)));
  if (row.key === 'scene_hash' && v) return h('td', { title: v }, h('code', { text: shortId(v) }));
  if (row.key === 'status' && v) return h('td', {}, badge(v));
  const text = cellText(v);
  return h('td', { class: typeof v === 'number' ? 'num' : null, title: text.length > 40 ? text : null, text: text.length > 40 ? `${text.slice(0, 38)}…` : text });
}

function compareTable(runs, rows, showAll) {
  const head = h('tr', {}, h('th', { text: 'field' }), runs.map((r) => h('th', { class: 'run' },
    swatch(r), ' ', link(`#/jobs/${r.job.id}`, r.job.name || shortId(r.job.id)), h('div', { class: 'muted label', text: r.label }))),
  h('th', { class: 'num', title: '(max − min) / max |value| of the runs', text: 'spread' }));
  const body = h('tbody');
  for (const group of Object.keys(GROUPS)) {
    const shown = rows.filter((r) => r.group === group && (showAll || r.differs || KEY_ROWS.has(`${group}.${r.key}`)));
    const hidden = rows.filter((r) => r.group === group).length - shown.length;
    body.append(h('tr', { class: 'group' }, h('th', { colspan: runs.length + 2, text: `${GROUPS[group]}${hidden ? ` — ${hidden} identical field${hidden === 1 ? '' : 's'} hidden` : ''}` })));
    for (const row of shown) {
      const note = row.partial ? 'only some of the runs have this field' : 'differs between the runs';
      body.append(h('tr', { class: row.differs ? `differs${row.partial ? ' partial' : ''}` : null, dataset: { field: `${group}.${row.key}` }, title: row.differs ? note : null },
        h('th', {}, row.differs ? h('span', { class: 'ne', text: '≠ ' }) : null, h('code', { text: row.key })),
        row.values.map((v) => valueCell(row, v)),
        h('td', { class: 'num spread', text: row.differs && row.spread !== null && group !== 'run' ? `${fmt(100 * row.spread, 3)} %` : '' })));
    }
  }
  return h('div', { class: 'tablewrap' }, h('table', { class: 'grid compare', id: 'compare-table' }, h('thead', {}, head), body));
}

// The page; while some of the runs are queued or running it asks again every POLL_MS and
// draws the page anew when one of them changes state (the figures need the finished runs).
export async function comparePage(view, page, params) {
  let picked = await pickRuns(params);
  await drawComparison(view, params, picked);
  const state = (p) => p.jobs.map((j) => `${j.id}:${j.status}`).join(',');
  if (picked.jobs.every((j) => FINAL.has(j.status))) return;
  page.every(POLL_MS, async () => {
    const next = await pickRuns(params);
    if (state(next) === state(picked)) return;
    picked = next;
    clear(view);
    await drawComparison(view, params, picked);
    if (picked.jobs.every((j) => FINAL.has(j.status))) page.stop();
  });
}

async function drawComparison(view, params, { jobs, source, notes, study }) {
  view.append(h('div', { class: 'pagehead' }, h('h1', { text: 'Compare runs' })), picker(params));
  for (const n of notes) view.append(h('p', { class: 'error', text: n }));
  if (!jobs.length) {
    view.append(h('section', { class: 'card', id: 'compare-empty' }, h('p', { text: source ? `No runs in ${source}.` : 'Pick the runs to compare: tick them in the jobs list and press “Compare selected”, follow “Compare these runs” on a study page, or give job ids or a search above.' }),
      h('p', {}, link('#/jobs', 'Back to the jobs'))));
    return;
  }
  const shown = jobs.slice(0, MAX_RUNS);
  const active = shown.filter((j) => !FINAL.has(j.status));
  if (active.length) {
    view.append(h('p', { class: 'muted', id: 'compare-running',
      text: `${active.length} of the runs ${active.length === 1 ? 'is' : 'are'} still ${active.map((j) => j.status).includes('running') ? 'running' : 'queued'} (${active.map((j) => j.name || shortId(j.id)).join(', ')}): their metrics and curves appear when they finish; this page refreshes by itself.` }));
  }
  const rows = compareRows(shown);
  const labels = compareLabels(shown, rows);
  const runs = shown.map((job, i) => ({ job, label: labels[i], color: PALETTE[i % PALETTE.length], style: methodStyle(job.method || job.spec?.method) }));
  const differing = rows.filter((r) => r.differs && !r.partial).length;
  const partial = rows.filter((r) => r.partial).length;
  view.querySelector('.pagehead').append(h('div', { class: 'sub muted', id: 'compare-source' },
    `${shown.length} run${shown.length === 1 ? '' : 's'}: ${source}${jobs.length > shown.length ? ` (the first ${MAX_RUNS} of ${jobs.length}; narrow the search to see others)` : ''}`,
    study ? h('span', {}, ' · ', link(`#/studies/${study}`, 'the study')) : null));

  const tableBox = h('div');
  const all = h('input', { type: 'checkbox', id: 'compare-all' });
  const renderTable = () => fill(tableBox, compareTable(runs, rows, all.checked));
  all.addEventListener('change', renderTable);
  view.append(h('section', { class: 'card', id: 'compare-fields' }, h('h2', { text: 'Parameters and metrics' }),
    h('div', { class: 'toolbar' }, h('span', { class: 'differs-key', id: 'compare-count', text: `${differing} field${differing === 1 ? '' : 's'} differ (highlighted, ≠)${partial ? `, ${partial} only some runs have (lighter)` : ''}` }),
      h('label', {}, all, ' show the identical fields too'),
      h('span', { class: 'muted', text: 'Legends name each run by its method, law, n_d and every other parameter that differs; FE solid lines and circles, BI dashed lines and squares.' })),
    tableBox));
  renderTable();
  const figs = h('section', { class: 'card figures', id: 'compare-figures' });
  view.append(figs);
  await drawCompareFigures(figs, runs, rows);
}
