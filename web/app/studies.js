// Studies: the list, and one study with its progress, live convergence map in the L–n_d
// plane, the L_c verdict with its reason, the speed–accuracy chart and the shared map of the
// scene (every run of the group with the same physics but L and n_d).
import { h, fill, fmt, fmtTime, badge, progressBar, kvTable, link, notFound, shortId } from './dom.js';
import { download, get, getJSON, post } from './api.js';
import { convergenceGrid, mapIsFinal, statusBadge } from './convergence_grid.js';
import { METRICS, drawSpeedChart } from './speed_chart.js';
import { searchSection } from './study_search.js';
import { accuracySection } from './study_accuracy.js';
import { defaultMethod, methodHeading, methodLabel } from './methods.js';
import { keepCard } from './job_keep.js';

export function studiesPage(view, page) {
  const table = h('table', { class: 'grid', id: 'studies-table' });
  const message = h('span');
  const archived = h('input', { type: 'checkbox', id: 'study-archived' });
  view.append(
    h('div', { class: 'pagehead' }, h('h1', { text: 'Studies' }), h('a', { class: 'button', href: '#/submit/study', text: 'Start a study' })),
    h('p', { class: 'muted', text: 'A study is a set of runs differing only in L and n_d (the paper’s L × n_d sweeps); the server refines meshes until two successive ones agree and names L_c.' }),
    h('div', { class: 'toolbar' }, h('label', {}, archived, ' show archived')),
    message, h('div', { class: 'tablewrap' }, table));
  let studies = null;
  const render = () => {
    fill(table, h('thead', {}, h('tr', {}, ['Name', 'Method', 'Kind', 'Status', 'Progress', 'L_c [m]', 'By', 'Created'].map((t) => h('th', { text: t })))));
    const body = h('tbody');
    for (const s of studies) {
      const p = s.progress || {};
      body.append(h('tr', { dataset: { id: s.id } },
        h('td', {}, h('a', { href: `#/studies/${s.id}`, text: s.name || `study ${shortId(s.id)}` }),
          s.archived_at ? h('span', { class: 'tag archived', title: `archived ${s.archived_at}`, text: 'archived' }) : null,
          (s.tags || []).slice(0, 4).map((t) => h('span', { class: 'tag', text: t }))),
        h('td', { text: methodLabel(s.method) }),
        h('td', { text: s.kind }),
        h('td', {}, badge(s.status)),
        h('td', { class: 'pcell' }, progressBar(p.fraction, `${p.done ?? 0} / ${p.total ?? 0}`)),
        h('td', { class: 'num', text: fmt(s.L_c) }),
        h('td', { text: s.submitted_by || '—' }),
        h('td', { class: 'when', text: fmtTime(s.created_at) })));
    }
    if (!studies.length) body.append(h('tr', {}, h('td', { colspan: 8, class: 'muted', text: 'No studies yet.' })));
    table.append(body);
  };
  const load = async () => {
    const { body, changed } = await getJSON(`/api/v1/studies?limit=200${archived.checked ? '&archived=include' : ''}`);
    if (!changed && studies) return;
    studies = body.studies || [];
    render();
  };
  const fail = (e) => { message.textContent = e.message; message.className = 'error'; };
  archived.addEventListener('change', () => { studies = null; load().catch(fail); });
  load().catch(fail);
  page.every(3000, () => load().catch(fail));
}

// The headline answer (docs/studies.md "The answer", computed by the server): the verdict, what
// it means, how sure it is, and only then the other numbers, each labelled with what it is.
export function answerBlock(box, answer) {
  if (!answer) { fill(box); box.hidden = true; return; }
  box.hidden = false;
  const others = answer.others || [];
  fill(box, h('h2', { text: 'The answer' }),
    h('p', { class: 'verdict' }, h('strong', { id: 'answer-verdict', text: answer.verdict })),
    h('p', { id: 'answer-meaning' }, h('em', { text: 'What it means: ' }), `${answer.meaning}.`),
    h('p', { id: 'answer-certainty', class: 'muted' }, h('em', { text: 'How sure: ' }), `${answer.certainty}.`),
    others.length ? h('div', {}, h('p', { class: 'muted', text: 'Other numbers, each for what it is:' }),
      kvTable(others.map((o) => [`${fmt(o.value)} ${o.unit}`, o.label]))) : null);
}

export async function studyPage(view, page, id) {
  const head = h('div', { class: 'pagehead' });
  const answerCard = h('section', { class: 'card answer', id: 'study-answer' });
  const summary = h('section', { class: 'card', id: 'study-summary' });
  const mapCard = h('section', { class: 'card', id: 'study-map' });
  const saCard = h('section', { class: 'card', id: 'study-speed' });
  const sceneCard = h('section', { class: 'card', id: 'study-scene' });
  const runsCard = h('section', { class: 'card', id: 'study-runs' });
  const keep = h('section', { class: 'card', id: 'study-keep' });
  let study = null;
  let keepDrawnFor = null; // the study's status when its Keep card was drawn
  let metric = 'max';
  let sa = null;

  const render = () => {
    const p = study.progress || {};
    const cl = study.critical_length || {};
    const out = h('span');
    fill(head, h('h1', {}, study.name || `study ${shortId(study.id)}`, ' ', badge(study.status)),
      h('div', { class: 'sub muted' }, `${study.kind} study · ${methodHeading(study.method)} · id `, h('code', { text: study.id })));
    fill(summary, h('h2', { text: study.kind === 'accuracy' ? 'Progress' : 'Progress and the rule' }),
      progressBar(p.fraction, `${p.done ?? 0} of ${p.total ?? 0} runs final${study.status === 'running' ? ' (a convergence study adds finer meshes as it goes)' : ''}`),
      kvTable(study.kind === 'accuracy' ? [
        ['created / finished', `${fmtTime(study.created_at)} / ${fmtTime(study.finished_at)}`],
        ['submitted by', study.submitted_by],
      ] : [
        ['the rule over every L run', h('span', { id: 'lc-value', text: study.L_c != null ? `L_c = ${fmt(study.L_c)} m` : (study.status === 'running' ? 'not determined yet' : 'not determined (see the reason)') })],
        ['its reason', h('span', { id: 'lc-reason', text: cl.reason || '—' })],
        ['next larger L', cl.next_larger_L != null ? `${fmt(cl.next_larger_L)} m` : '—'],
        ['created / finished', `${fmtTime(study.created_at)} / ${fmtTime(study.finished_at)}`],
        ['submitted by', study.submitted_by],
      ]),
      study.status === 'running' ? h('div', { class: 'actions' }, h('button', { onclick: async () => {
        try { await post(`/api/v1/studies/${study.id}/cancel`); out.textContent = 'cancelled'; out.className = 'ok'; } catch (e) { out.textContent = e.message; out.className = 'error'; }
      }, text: 'Cancel study' }), out) : null,
      searchSection(study.search, study.companion_label),
      accuracySection(study.accuracy, study.id));
    fill(mapCard, h('h2', { text: 'Convergence map (this study)' }),
      h('p', { class: 'muted', text: 'Each cell is a run at (L, n_d): converged when it agrees with the next finer mesh (propagation distance within 0.5 %, arrival time at the probe within 0.1 %). Cells fill in as runs finish; hover a cell for the reason.' }),
      // The map of the study's own L (an L search's plain-Coulomb runs have their own row of
      // the refinement plan; a failure-regimes study's other regimes their own sections).
      convergenceGrid(study.convergence_map, (study.runs || []).filter((r) => !r.regime || r.regime === 'regularised'), 'study-cmap', { tolerances: cl.tolerances, finished: study.status !== 'running' }));
    if (study.refinement && Object.keys(study.refinement).length) {
      mapCard.append(h('details', {}, h('summary', { text: 'Refinement plan per L' }), kvTable(Object.entries(study.refinement).map(([L, r]) => [r.regime === 'coulomb' ? (study.companion_label || 'plain Coulomb') : `L = ${fmt(Number(L))} m`, `${r.state}${r.next_n_d ? ` → n_d = ${r.next_n_d}` : ''}: ${r.reason || ''}`]))));
    }
    fill(runsCard, h('h2', { text: 'Runs' }), h('p', {}, h('a', { id: 'compare-study', href: `#/compare?study=${study.id}`, text: 'Compare these runs side by side' })), runsTable(study.runs || [], study.status !== 'running', study.companion_label));
    if (study.cross_method && (Array.isArray(study.cross_method) ? study.cross_method.length : Object.keys(study.cross_method).length)) {
      runsCard.append(h('details', {}, h('summary', { text: 'The same L by FE and BI (cross-method table)' }), h('pre', { class: 'json', text: JSON.stringify(study.cross_method, null, 2) })));
    }
  };

  // Tags, note, archive and delete (with its runs) of the study, its owner's. Drawn again when
  // its status changes or after a change, not at every poll (it would wipe what one types).
  const renderKeep = () => {
    keepDrawnFor = study.status;
    keepCard(keep, study, (updated) => { study = updated; render(); renderKeep(); }, () => { location.hash = '#/studies'; }, {
      base: `/api/v1/studies/${study.id}`,
      noun: 'study',
      deleteQuestion: `Delete this study with its ${study.runs?.length ?? 0} run(s) and their result files? This cannot be undone.`,
      final: study.status !== 'running',
    });
    // The study with its runs as one archive (GET /studies/{id}/export), for another server's
    // import (POST /imports) or a paper's record.
    if (study.status === 'running') return;
    const out = h('span', { id: 'study-export-message' });
    const exportArchive = async () => {
      out.textContent = 'writing the archive…'; out.className = 'muted';
      try {
        const blob = await download(`/api/v1/studies/${study.id}/export`);
        const name = `slipfront-study-${study.id}.tar`;
        const link = h('a', { id: 'study-export-link', href: URL.createObjectURL(blob), download: name, text: `${name} (${blob.size} bytes)` });
        fill(out, 'saved as ', link);
        out.className = 'ok';
        link.click();
      } catch (e) {
        out.textContent = e.status === 401 ? `${e.message} — enter your token at the top` : e.message;
        out.className = 'error';
      }
    };
    keep.append(h('div', { class: 'actions' },
      h('button', { id: 'study-export', onclick: exportArchive, text: 'Export with its runs (tar)' }), out));
  };

  const renderSpeed = async () => {
    fill(saCard, h('h2', { text: 'Speed and accuracy' }));
    const select = h('select', { id: 'sa-metric', onchange: () => { metric = select.value; renderSpeed(); } },
      METRICS.map(([v, t]) => h('option', { value: v, text: t, selected: v === metric })));
    saCard.append(h('div', { class: 'toolbar' }, h('label', { for: 'sa-metric', text: 'error: ' }), select,
      h('span', { class: 'muted', text: ' relative, against the reference run of the same L (the finest converged one); one curve per method and L along its refinement, points labelled with n_d; click a point for its run' })));
    const box = h('div', { class: 'fig', id: 'fig-speed' });
    saCard.append(box);
    try {
      await drawSpeedChart(box, sa?.across_methods?.runs || sa?.runs || [], metric, study.method || defaultMethod(), `slipfront-study-${shortId(study.id)}-speed`);
    } catch (e) { box.append(h('p', { class: 'error', text: e.message })); }
  };

  // The shared map of the study's scene, and of the same scene by the other method when the
  // group has runs of it (found through speed-accuracy's across_methods entries).
  const renderScene = async () => {
    try {
      const scene = await get(`/api/v1/convergence-map?study=${id}`);
      fill(sceneCard, h('h2', { text: `Shared map of the scene, ${methodHeading(study.method)} (every run of the group)` }),
        h('p', { class: 'muted', text: `${scene.count} run(s) with this physics but L and n_d, from any study or user. L_c on the scene: ${scene.critical_length?.L_c != null ? `${fmt(scene.critical_length.L_c)} m` : 'not determined'}.` }),
        convergenceGrid(scene.convergence_map, [], 'scene-cmap', sceneOptions(scene)));
      const other = (sa?.across_methods?.runs || []).find((e) => e.method && e.method !== (study.method || defaultMethod()));
      if (other) {
        const job = await get(`/api/v1/jobs/${other.id}?fields=scene_hash`);
        const otherScene = await get(`/api/v1/convergence-map?scene=${job.scene_hash}`);
        sceneCard.append(h('h2', { text: `The same scene by ${methodHeading(other.method)}` }),
          h('p', { class: 'muted', text: `${otherScene.count} run(s). L_c: ${otherScene.critical_length?.L_c != null ? `${fmt(otherScene.critical_length.L_c)} m` : 'not determined'}.` }),
          convergenceGrid(otherScene.convergence_map, [], 'scene-cmap-other', sceneOptions(otherScene)));
      }
    } catch (e) { fill(sceneCard, h('p', { class: 'error', text: e.message })); }
  };

  const load = async () => {
    const { body, changed } = await getJSON(`/api/v1/studies/${id}`);
    if (!changed && study) return;
    study = body;
    if (!head.isConnected) view.append(head, answerCard, summary, mapCard, saCard, sceneCard, runsCard, keep); // only for a study that exists
    answerBlock(answerCard, study.answer);
    render();
    if (keepDrawnFor !== study.status) renderKeep();
    sa = await get(`/api/v1/studies/${id}/speed-accuracy`).catch(() => null);
    await renderSpeed();
    await renderScene();
  };
  try { await load(); } catch (e) {
    view.append(notFound(e, 'study', id, '#/studies', 'the studies'));
    return;
  }
  page.every(2000, async () => { if (study.status === 'running' || study.status === 'cancelled') await load(); });
}

// The shared map of a scene takes runs from any study: it is final when none of its cells
// waits for a run.
function sceneOptions(scene) {
  return { tolerances: scene.critical_length?.tolerances, finished: mapIsFinal(scene.convergence_map) };
}

// `companion`: what the study calls an L search's unregularised runs (the server's
// companion_label: 'plain Coulomb', 'rate and state without regularisation').
function runsTable(runs, finished, companion = 'plain Coulomb') {
  const t = h('table', { class: 'grid' });
  t.append(h('thead', {}, h('tr', {}, ['L [m]', 'n_d [1/m]', 'job', 'outcome', 'convergence', 'against', 'cache'].map((x) => h('th', { text: x })))));
  const b = h('tbody');
  for (const r of runs.slice().sort((a, c) => c.L - a.L || a.n_d - c.n_d)) {
    b.append(h('tr', {},
      h('td', { class: 'num', text: r.regime ? `${fmt(r.L)} (${r.regime === 'coulomb' ? `${companion}: L unused` : r.regime})` : fmt(r.L) }), h('td', { class: 'num', text: fmt(r.n_d) }),
      h('td', {}, link(`#/jobs/${r.job_id}`, shortId(r.job_id)), ' ', badge(r.job_status)),
      h('td', { text: r.outcome || '—' }),
      h('td', {}, r.convergence ? statusBadge(r.convergence, finished) : '—'),
      h('td', { class: 'num', text: r.convergence?.partner_n_d ? `n_d = ${fmt(r.convergence.partner_n_d)}` : '—' }),
      h('td', {}, r.cached_from ? h('span', { class: 'hit', text: 'hit' }) : '')));
  }
  t.append(b);
  return h('div', { class: 'tablewrap' }, t);
}
