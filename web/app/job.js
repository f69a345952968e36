// A run: status and progress (live), spec, metrics, cost, convergence status, provenance,
// the HDF5 download, the paper's figures drawn from /fields and /front slices, and the
// on-fault stations of a run that has them (job_stations.js).
import { h, fill, fmt, fmtDuration, fmtBytes, fmtTime, badge, progressBar, kvTable, link, notFound, shortId } from './dom.js';
import { get, getJSON } from './api.js';
import { drawFigures } from './job_figures.js';
import { belowText } from './run_labels.js';
import { methodHeading } from './methods.js';
import { drawStations, hasStations } from './job_stations.js';
import { cancelJob, frictionText, jobNd } from './jobs.js';
import { cellText, mapIsFinal, statusBadge } from './convergence_grid.js';
import { keepCard } from './job_keep.js';

const FINAL = new Set(['succeeded', 'failed', 'cancelled']);

// "dx = 0.025 m, height = 20 m, nx = 800, ny = 101": the mesh entries a method has (the BI
// method has no height), lengths with their unit.
const MESH_UNITS = { dx: ' m', height: ' m' };
function meshText(mesh) {
  const known = Object.entries(mesh || {}).filter(([, v]) => v !== null && v !== undefined);
  return known.length ? known.map(([k, v]) => `${k} = ${typeof v === 'number' && !Number.isInteger(v) ? fmt(v, 6) : v}${MESH_UNITS[k] || ''}`).join(', ') : '—';
}

// What the validation said when the job was accepted: its warnings, and the values with a unit
// it did not give (derived from its scene, or the paper's defaults), with where they came from.
function checksCard(job) {
  const warnings = job.warnings || [];
  const taken = (job.provenance || []).filter((v) => v.source !== 'given' && !String(v.source).startsWith('preset'));
  if (!warnings.length && !taken.length) return null;
  return h('section', { class: 'card wide', id: 'job-checks' }, h('h2', { text: 'Checks before the run' }),
    warnings.length ? h('ul', { class: 'warnings' }, warnings.map((w) => h('li', {}, '⚠ ', h('code', { text: w.pointer }), `: ${w.message}`))) : h('p', { class: 'muted', text: 'No warning.' }),
    taken.length ? h('details', {}, h('summary', { text: `Values the job did not give (${taken.length})` }),
      kvTable(taken.map((v) => [v.pointer, `${fmt(v.value, 6)} ${v.unit} — ${v.source}`]))) : null);
}

export async function jobPage(view, page, id) {
  const head = h('div', { class: 'pagehead' });
  const live = h('section', { class: 'card', id: 'job-live' });
  const cols = h('div', { class: 'cols' });
  const figs = h('section', { class: 'card figures', id: 'job-figures' });
  const keep = h('section', { class: 'card', id: 'job-keep' });
  let job = null;
  let drawn = false;

  const renderHead = () => {
    fill(head, 
      h('h1', {}, job.name || `job ${shortId(job.id)}`, ' ', badge(job.status)),
      h('div', { class: 'sub muted' }, [methodHeading(job.method), belowText(job.spec), frictionText(job.spec), `n_d = ${fmt(jobNd(job))} /m`, 'id '].filter(Boolean).join(' · '), h('code', { text: job.id }),
        job.study_id ? h('span', {}, ' · ', link(`#/studies/${job.study_id}`, 'its study')) : null));
  };

  const out = h('span', { id: 'cancel-message' }); // kept across re-renders
  const renderLive = () => {
    const p = job.progress || {};
    const active = !FINAL.has(job.status);
    fill(live, 
      h('h2', { text: 'Progress' }),
      progressBar(job.status === 'succeeded' ? 1 : p.fraction,
        job.status === 'running' ? `${((p.fraction || 0) * 100).toFixed(1)} % · t = ${fmt(p.time)} of ${fmt(p.duration)} s · ${p.steps ?? 0} steps · ETA ${fmtDuration(p.eta_s)}` : job.status),
      job.error ? h('p', { class: 'error', text: job.error }) : null,
      h('div', { class: 'actions' },
        job.result ? h('a', { class: 'button', id: 'download', href: job.result.url, download: `${job.id}.h5`, text: `Download HDF5 (${fmtBytes(job.result.size)})` }) : null,
        job.result ? h('a', { class: 'button', id: 'download-xdmf', href: `/api/v1/jobs/${job.id}/result.xdmf`, download: `${job.id}.xdmf`, text: 'XDMF for ParaView', title: `The time series of the interface for ParaView or VisIt: save it beside ${job.id}.h5 (it reads the data from that file)` }) : null,
        active ? h('button', { id: 'cancel', onclick: () => cancelJob(job.id, out), text: 'Cancel' }) : null, out));
  };

  const renderDetails = async () => {
    const m = job.metrics || {};
    const spec = job.spec || {};
    // Convergence: from the run's study, else from the shared map of its scene (every run
    // of the group with the same physics but L and n_d).
    let convergence = null;
    let source = null;
    let finished = false; // no run will be added to what the status was judged against
    try {
      if (job.study_id) {
        const study = await get(`/api/v1/studies/${job.study_id}`);
        convergence = (study.runs || []).find((r) => r.job_id === job.id)?.convergence || null;
        source = 'its study';
        finished = study.status !== 'running';
      }
      if (!convergence && job.scene_hash && FINAL.has(job.status)) {
        const scene = await get(`/api/v1/convergence-map?scene=${job.scene_hash}`);
        convergence = (scene.runs || []).find((r) => r.job_id === job.id)?.convergence || null;
        source = `the scene's shared map (${scene.count} run${scene.count === 1 ? '' : 's'})`;
        finished = mapIsFinal(scene.convergence_map); // as the study page's shared map says
      }
    } catch (e) { convergence = { status: 'unknown', reason: e.message }; }
    fill(cols, 
      h('section', { class: 'card' }, h('h2', { text: 'Metrics' }), kvTable([
        ['outcome', m.outcome],
        ['arrest position', m.arrest_position != null ? `${fmt(m.arrest_position, 4)} m` : '—'],
        ['propagation distance', m.propagation_distance != null ? `${fmt(m.propagation_distance, 4)} m` : '—'],
        ['rupture speed max / mean', m.rupture_speed ? `${fmt(m.rupture_speed.max)} / ${fmt(m.rupture_speed.mean)} m/s` : '—'],
        ['max slip velocity', m.max_slip_velocity != null ? `${fmt(m.max_slip_velocity)} m/s` : '—'],
        ['arrival time at probe', m.arrival_time_at_probe != null ? `${fmt(m.arrival_time_at_probe, 4)} s (x1 = ${fmt(m.probe_x1)} m)` : '—'],
        ['spectral L_c estimate', m.spectral_critical_length != null ? `${fmt(m.spectral_critical_length)} m` : '—'],
        ['energy balance error', m.energy_error != null ? fmt(m.energy_error) : '—'],
        ['simulated time', m.simulated_time != null ? `${fmt(m.simulated_time)} s` : '—'],
        m.warnings?.length ? ['warnings', m.warnings.join('; ')] : null,
      ])),
      h('section', { class: 'card' }, h('h2', { text: 'Cost' }), kvTable([
        ['wall time', job.status === 'running' && job.started_at ? `${fmtDuration((Date.now() - Date.parse(job.started_at)) / 1000)} so far` : (job.cached_from ? 'none: reused' : fmtDuration(job.wall_time_s))],
        job.estimate ? ['estimated before the run', `${fmtDuration(job.estimate.wall_time_s)}${job.estimate.stops_on_arrest ? ' at most (the whole duration)' : ''}, ${fmt(job.estimate.steps)} steps of ${fmt(job.estimate.dt)} s`] : null,
        ['steps', m.steps ?? job.progress?.steps],
        ['time step', m.dt != null ? `${fmt(m.dt)} s${m.stable_dt != null ? ` (stable ${fmt(m.stable_dt)} s)` : ''}` : '—'],
        ['mesh', meshText(m.mesh)],
        ['memory estimate', fmtBytes(job.memory_estimate_bytes)],
        ['result file', job.result ? fmtBytes(job.result.size) : '—'],
      ]), h('h2', { text: 'Convergence' }), convergence
        ? kvTable([['status', statusBadge(convergence, finished)], ['against', convergence.partner_n_d ? `n_d = ${convergence.partner_n_d}` : '—'], ['reason', cellText(convergence, null, finished).title], ['judged in', source]])
        : h('p', { class: 'muted', text: FINAL.has(job.status) ? 'No convergence status (the run has no result to compare).' : 'Judged when the run has finished, against the other meshes of its scene.' })),
      h('section', { class: 'card' }, h('h2', { text: 'Provenance' }), kvTable([
        ['code version', job.code_version],
        ['method', m.method_description || job.method],
        ['physics hash', h('code', { text: job.spec_sha256 || '—' })],
        ['scene hash', h('code', { text: job.scene_hash ? shortId(job.scene_hash) : '—', title: job.scene_hash })],
        ['cached from', job.cached_from ? link(`#/jobs/${job.cached_from}`, shortId(job.cached_from)) : 'computed (not reused)'],
        ['result sha256', job.result ? h('code', { text: shortId(job.result.sha256), title: job.result.sha256 }) : '—'],
        ['submitted by', job.submitted_by],
        ['submitted / started / finished', `${fmtTime(job.created_at)} / ${fmtTime(job.started_at)} / ${fmtTime(job.finished_at)}`],
        ['host, attempts', `${job.host || '—'}, ${job.attempts ?? '—'}`],
        ['tags', (job.tags || []).join(', ') || '—'],
      ])),
      checksCard(job),
      h('section', { class: 'card wide' }, h('details', {}, h('summary', { text: 'Job spec (canonical JSON, defaults filled)' }),
        h('pre', { class: 'json', text: JSON.stringify(spec, null, 2) }))));
  };

  const load = async () => {
    const { body, changed } = await getJSON(`/api/v1/jobs/${id}`);
    if (!changed && job) return;
    const wasFinal = job && FINAL.has(job.status);
    job = body;
    if (!head.isConnected) view.append(head, live, keep, cols, figs); // only for a job that exists
    renderHead();
    renderLive();
    // Drawn once (a refresh would wipe what is being typed), and again after each change.
    const renderKeep = () => keepCard(keep, job, (updated) => { job = updated; renderHead(); renderKeep(); renderDetails(); }, () => { location.hash = '#/jobs'; });
    if (!keep.hasChildNodes()) renderKeep();
    if (!wasFinal) await renderDetails();
    if (job.status === 'succeeded' && !drawn) {
      drawn = true;
      await drawFigures(figs, job).catch((e) => figs.append(h('p', { class: 'error', text: `The figures could not be drawn: ${e.message}` })));
      if (hasStations(job)) { // a run without stations has no card for them
        const stations = h('section', { class: 'card figures', id: 'job-stations' });
        figs.after(stations);
        await drawStations(stations, job).catch((e) => stations.append(h('p', { class: 'error', text: `The stations could not be drawn: ${e.message}` })));
      }
    } else if (!FINAL.has(job.status)) {
      fill(figs, h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: 'The figures appear when the run has succeeded.' }));
    } else if (job.status !== 'succeeded') {
      fill(figs, h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: `No result file: the run ${job.status}.` }));
    }
  };
  try {
    await load();
  } catch (e) {
    view.append(notFound(e, 'job', id, '#/jobs', 'the jobs'));
    return;
  }
  page.every(1000, async () => { if (!FINAL.has(job.status)) await load(); });
}
