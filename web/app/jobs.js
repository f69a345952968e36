// Jobs: the group's runs, newest first, filtered and sorted in the page, refreshed every
// 2 s (If-None-Match: an unchanged listing costs a 304), with cancel for active jobs.
import { h, clear, fmt, fmtDuration, badge, progressBar, shortId } from './dom.js';
import { getJSON, post, qs } from './api.js';
import { defaultMethod, methodLabel } from './methods.js';

const FIELDS = 'id,name,tags,method,spec,status,progress,metrics,wall_time_s,cached_from,submitted_by,created_at,study_id,error,archived_at';

export function jobL(job) { return job.spec?.friction?.L ?? null; }
export function jobNd(job) { return job.spec?.geometry?.nodes_per_meter ?? null; }

// The friction in words (friction_labels.js), where the pages have always imported it.
export { frictionText } from './friction_labels.js';

const COLUMNS = [
  { key: 'name', label: 'Name', value: (j) => j.name || '', cell: (j) => h('td', { title: j.name || '' }, h('a', { href: `#/jobs/${j.id}`, class: 'jobname', text: j.name || `(${shortId(j.id)})` }), j.study_id ? h('a', { class: 'tag', href: `#/studies/${j.study_id}`, title: 'run of a study', text: 'study' }) : null, j.archived_at ? h('span', { class: 'tag archived', title: `archived ${j.archived_at}`, text: 'archived' }) : null, (j.tags || []).filter((t) => !String(t).startsWith('study:')).slice(0, 4).map((t) => h('span', { class: 'tag', text: t }))) },
  { key: 'method', label: 'Method', value: (j) => j.method || defaultMethod(), cell: (j) => h('td', { text: methodLabel(j.method), title: j.method }) },
  { key: 'L', label: 'L [m]', num: true, value: jobL, cell: (j) => h('td', { class: 'num', text: fmt(jobL(j)) }) },
  { key: 'n_d', label: 'n_d [1/m]', num: true, value: jobNd, cell: (j) => h('td', { class: 'num', text: fmt(jobNd(j)) }) },
  { key: 'status', label: 'Status', value: (j) => j.status, cell: (j) => h('td', {}, badge(j.status)) },
  { key: 'progress', label: 'Progress', num: true, value: (j) => j.progress?.fraction ?? 0, cell: (j) => h('td', { class: 'pcell' }, progressCell(j)) },
  { key: 'outcome', label: 'Outcome', value: (j) => j.metrics?.outcome || '', cell: (j) => h('td', { text: j.metrics?.outcome || (j.error ? 'error' : '—'), title: j.error || '' }) },
  { key: 'arrest', label: 'Arrest x1 [m]', num: true, value: (j) => j.metrics?.arrest_position ?? null, cell: (j) => h('td', { class: 'num', text: fmt(j.metrics?.arrest_position) }) },
  { key: 'wall', label: 'Wall time', num: true, value: (j) => j.wall_time_s ?? null, cell: (j) => (j.cached_from ? h('td', { class: 'num muted', title: `reused: no run; the original run (${j.cached_from}) took this long`, text: j.metrics?.wall_time_s != null ? `${fmtDuration(j.metrics.wall_time_s)} cached` : 'cached' }) : h('td', { class: 'num', text: fmtDuration(j.wall_time_s) })) },
  { key: 'cache', label: 'Cache', value: (j) => (j.cached_from ? 1 : 0), cell: (j) => h('td', {}, j.cached_from ? h('a', { class: 'hit', href: `#/jobs/${j.cached_from}`, title: `result reused from job ${j.cached_from}`, text: 'hit' }) : '') },
  { key: 'by', label: 'By', value: (j) => j.submitted_by || '', cell: (j) => h('td', { text: j.submitted_by || '—' }) },
  { key: 'created', label: 'Submitted (UTC)', value: (j) => j.created_at || '', cell: (j) => h('td', { class: 'when', title: j.created_at || '', text: (j.created_at || '').replace(/^\d{4}-/, '').replace('T', ' ').replace(/:\d\d(\.\d+)?Z$/, '') }) },
];

function progressCell(j) {
  const p = j.progress || {};
  if (j.status === 'running') {
    const eta = Number.isFinite(p.eta_s) ? ` · ETA ${fmtDuration(p.eta_s)}` : '';
    return progressBar(p.fraction, `${((p.fraction || 0) * 100).toFixed(0)} %${eta}`);
  }
  if (j.status === 'succeeded') return progressBar(1, '100 %');
  if (j.status === 'queued') return h('span', { class: 'muted', text: 'queued' });
  return progressBar(p.fraction || 0, `${((p.fraction || 0) * 100).toFixed(0)} %`);
}

export async function cancelJob(id, out) {
  try {
    const r = await post(`/api/v1/jobs/${id}/cancel`);
    out.textContent = r.status === 'cancelled' ? 'cancelled' : 'cancel requested: stops at its next step';
    out.className = 'ok';
  } catch (e) {
    out.textContent = e.status === 401 ? `${e.message} — enter your token at the top` : e.message;
    out.className = 'error';
  }
}

export function jobsPage(view, page) {
  const state = { sort: 'created', dir: -1, filter: '', status: '', archived: false, jobs: [], picked: new Set() }; // picked: ids to compare
  const messages = new Map();
  const filter = h('input', { type: 'search', id: 'job-filter', placeholder: 'filter: name, tag, id, user…', size: 30 });
  const status = h('select', { id: 'job-status' },
    ['', 'queued', 'running', 'succeeded', 'failed', 'cancelled'].map((s) => h('option', { value: s, text: s || 'any status' })));
  const archived = h('input', { type: 'checkbox', id: 'job-archived' });
  const counter = h('span', { class: 'muted' });
  const message = h('span', { id: 'jobs-message' });
  const table = h('table', { class: 'grid', id: 'jobs-table' });
  const compare = h('button', { id: 'compare-selected', onclick: () => { location.hash = `#/compare?ids=${[...state.picked].join(',')}`; } });
  view.append(
    h('div', { class: 'pagehead' }, h('h1', { text: 'Jobs' }), h('a', { class: 'button', href: '#/submit', text: 'Submit a job' })),
    h('div', { class: 'toolbar' }, filter, status, h('label', {}, archived, ' show archived'), counter, compare, message),
    h('div', { class: 'tablewrap' }, table));

  const render = () => {
    const q = state.filter.toLowerCase();
    let rows = state.jobs.filter((j) => !q || [j.name, j.id, j.submitted_by, j.method, ...(j.tags || [])].some((s) => String(s || '').toLowerCase().includes(q)));
    const col = COLUMNS.find((c) => c.key === state.sort);
    rows = rows.slice().sort((a, b) => {
      const va = col.value(a), vb = col.value(b);
      if (va === vb) return 0;
      if (va === null || va === undefined) return 1;
      if (vb === null || vb === undefined) return -1;
      return (va < vb ? -1 : 1) * state.dir;
    });
    clear(table);
    const pick = (id, on) => { if (on) state.picked.add(id); else state.picked.delete(id); };
    const all = h('input', { type: 'checkbox', id: 'pick-all', title: 'pick every run shown (to compare)', checked: rows.length > 0 && rows.every((j) => state.picked.has(j.id)),
      onchange: (ev) => { rows.forEach((j) => pick(j.id, ev.target.checked)); render(); } });
    table.append(h('thead', {}, h('tr', {}, h('th', {}, all), COLUMNS.map((c) => h('th', {
      class: `${c.num ? 'num ' : ''}sortable${state.sort === c.key ? ' sorted' : ''}`,
      title: 'sort', onclick: () => { state.dir = state.sort === c.key ? -state.dir : (c.key === 'created' ? -1 : 1); state.sort = c.key; render(); },
    }, c.label, state.sort === c.key ? (state.dir > 0 ? ' ▲' : ' ▼') : '')), h('th', { text: '' }))));
    const body = h('tbody');
    for (const j of rows) {
      if (!messages.has(j.id)) messages.set(j.id, h('span'));
      const out = messages.get(j.id); // a cancel's answer stays through the refreshes
      const active = j.status === 'queued' || j.status === 'running';
      body.append(h('tr', { dataset: { id: j.id, status: j.status } },
        h('td', {}, h('input', { type: 'checkbox', class: 'pick', title: 'pick to compare', checked: state.picked.has(j.id), onchange: (ev) => { pick(j.id, ev.target.checked); render(); } })),
        COLUMNS.map((c) => c.cell(j)),
        h('td', {}, active ? h('button', { class: 'small', onclick: () => cancelJob(j.id, out), text: 'Cancel' }) : null, out)));
    }
    if (!rows.length) body.append(h('tr', {}, h('td', { colspan: COLUMNS.length + 2, class: 'muted', text: state.jobs.length ? 'No job matches the filter.' : 'No jobs yet: submit one.' })));
    table.append(body);
    counter.textContent = `${rows.length} of ${state.jobs.length} shown`;
    compare.textContent = `Compare selected (${state.picked.size})`;
    compare.disabled = state.picked.size < 2;
    compare.title = compare.disabled ? 'tick two runs or more (the boxes at the left) to compare them' : 'open the picked runs side by side';
  };

  const load = async () => {
    const { body, changed } = await getJSON(`/api/v1/jobs${qs({ limit: 500, fields: FIELDS, status: state.status, archived: state.archived ? 'include' : '' })}`);
    message.textContent = '';
    if (!changed && state.jobs.length) return;
    state.jobs = body.jobs || [];
    render();
  };
  filter.addEventListener('input', () => { state.filter = filter.value; render(); });
  status.addEventListener('change', () => { state.status = status.value; load().catch(showError); });
  archived.addEventListener('change', () => { state.archived = archived.checked; load().catch(showError); });
  const showError = (e) => { message.textContent = `listing failed: ${e.message}`; message.className = 'error'; };
  render();
  load().catch(showError);
  page.every(2000, () => load().catch(showError));
}
