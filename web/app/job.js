// A run: status and progress (live), spec, metrics, cost, convergence status, provenance,
// the HDF5 download, and the paper's figures drawn from /fields and /front slices.
import { h, clear, fill, fmt, fmtDuration, fmtBytes, fmtTime, badge, progressBar, kvTable, link, shortId } from './dom.js';
import { get, getJSON } from './api.js';
import { heatmap, plot, PALETTE } from './charts.js';
import { cancelJob, jobL, jobNd } from './jobs.js';

const FINAL = new Set(['succeeded', 'failed', 'cancelled']);
// Colours of the V(t) positions: visible on the map's dark background and on white.
const MARKS = ['#00b4d8', '#ff9f1c', '#e040fb', '#7cb342', '#ffd166', '#f4f4f4'];

// Shear and P wave speeds of the block (plane strain) from the spec's material.
function waveSpeeds(spec) {
  const m = spec?.material || {};
  const E = m.young_modulus, nu = m.poisson_ratio, rho = m.density;
  if (!(E > 0 && nu > 0 && rho > 0)) return null;
  const G = E / (2 * (1 + nu));
  const cs = Math.sqrt(G / rho);
  const cd = Math.sqrt((E * (1 - nu)) / ((1 + nu) * (1 - 2 * nu) * rho));
  return { cs, cp: cd };
}

export async function jobPage(view, page, id) {
  const head = h('div', { class: 'pagehead' });
  const live = h('section', { class: 'card', id: 'job-live' });
  const cols = h('div', { class: 'cols' });
  const figs = h('section', { class: 'card figures', id: 'job-figures' });
  view.append(head, live, cols, figs);
  let job = null;
  let drawn = false;

  const renderHead = () => {
    fill(head, 
      h('h1', {}, job.name || `job ${shortId(job.id)}`, ' ', badge(job.status)),
      h('div', { class: 'sub muted' }, `${job.method === 'spectral_bi' ? 'spectral BI' : 'FE'} · L = ${fmt(jobL(job))} m · n_d = ${fmt(jobNd(job))} /m · id `, h('code', { text: job.id }),
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
        active ? h('button', { id: 'cancel', onclick: () => cancelJob(job.id, out), text: 'Cancel' }) : null, out));
  };

  const renderDetails = async () => {
    const m = job.metrics || {};
    const spec = job.spec || {};
    // Convergence: from the run's study, else from the shared map of its scene (every run
    // of the group with the same physics but L and n_d).
    let convergence = null;
    let source = null;
    try {
      if (job.study_id) {
        const study = await get(`/api/v1/studies/${job.study_id}`);
        convergence = (study.runs || []).find((r) => r.job_id === job.id)?.convergence || null;
        source = 'its study';
      }
      if (!convergence && job.scene_hash && FINAL.has(job.status)) {
        const scene = await get(`/api/v1/convergence-map?scene=${job.scene_hash}`);
        convergence = (scene.runs || []).find((r) => r.job_id === job.id)?.convergence || null;
        source = `the scene's shared map (${scene.count} run${scene.count === 1 ? '' : 's'})`;
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
        ['steps', m.steps ?? job.progress?.steps],
        ['time step', m.dt != null ? `${fmt(m.dt)} s (stable ${fmt(m.stable_dt)} s)` : '—'],
        ['mesh', m.mesh ? Object.entries(m.mesh).map(([k, v]) => `${k} = ${v}`).join(', ') : '—'],
        ['memory estimate', fmtBytes(job.memory_estimate_bytes)],
        ['result file', job.result ? fmtBytes(job.result.size) : '—'],
      ]), h('h2', { text: 'Convergence' }), convergence
        ? kvTable([['status', badge(convergence.status)], ['against', convergence.partner_n_d ? `n_d = ${convergence.partner_n_d}` : '—'], ['reason', convergence.reason], ['judged in', source]])
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
      h('section', { class: 'card wide' }, h('details', {}, h('summary', { text: 'Job spec (canonical JSON, defaults filled)' }),
        h('pre', { class: 'json', text: JSON.stringify(spec, null, 2) }))));
  };

  const load = async () => {
    const { body, changed } = await getJSON(`/api/v1/jobs/${id}`);
    if (!changed && job) return;
    const wasFinal = job && FINAL.has(job.status);
    job = body;
    renderHead();
    renderLive();
    if (!wasFinal) await renderDetails();
    if (job.status === 'succeeded' && !drawn) {
      drawn = true;
      await drawFigures(figs, job);
    } else if (!FINAL.has(job.status)) {
      fill(figs, h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: 'The figures appear when the run has succeeded.' }));
    } else if (job.status !== 'succeeded') {
      fill(figs, h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: `No result file: the run ${job.status}.` }));
    }
  };
  try {
    await load();
  } catch (e) {
    view.append(h('p', { class: 'error', text: e.status === 404 ? `No job ${id}.` : e.message }));
    return;
  }
  page.every(1000, async () => { if (!FINAL.has(job.status)) await load(); });
}

async function drawFigures(figs, job) {
  fill(figs, h('h2', { text: 'Figures' }), h('p', { class: 'muted', text: 'Drawn from slices of the HDF5 result (GET /api/v1/jobs/{id}/fields/{name}) and the front (/front), as the paper’s Fig. 2.' }));
  const mapBox = h('div', { class: 'fig', id: 'fig-map' });
  const vtBox = h('div', { class: 'fig', id: 'fig-vt' });
  const vrBox = h('div', { class: 'fig', id: 'fig-vr' });
  const picks = h('input', { id: 'vt-x1', type: 'text', size: 22 });
  const pickMsg = h('span', { class: 'muted' });
  figs.append(
    h('h3', { text: 'Slip velocity in the x1–t plane, with the slip front' }), mapBox,
    h('h3', { text: 'Slip velocity history V(t) at chosen x1' }),
    h('div', { class: 'toolbar' }, h('label', { for: 'vt-x1', text: 'x1 [m] (comma list, or click the map): ' }), picks, h('button', { id: 'vt-draw', text: 'Draw', onclick: () => drawVt() }), pickMsg),
    vtBox,
    h('h3', { text: 'Rupture speed V_r(x1)' }), vrBox);

  const width = Math.max(320, mapBox.clientWidth || 800);
  const budget = Math.min(400000, Math.round(width * 420));
  const [slice, front] = await Promise.all([
    get(`/api/v1/jobs/${job.id}/fields/slip_velocity?max_points=${budget}`),
    get(`/api/v1/jobs/${job.id}/front`).catch(() => null),
  ]);
  const frontLine = front ? { x: front.x1, y: front.arrival_time, color: '#ff3b30', width: 2, label: 'slip front (arrival time)' } : null;
  const values = slice.values;
  // Colour range: 0 to the 99.9th percentile of V, so that the nucleation peak does not wash
  // out the propagating pulse.
  const flat = values.flat().filter((v) => v !== null && Number.isFinite(v)).sort((a, b) => a - b);
  const vmax = flat.length ? flat[Math.min(flat.length - 1, Math.floor(flat.length * 0.999))] : 1;
  const vmin = Math.min(0, flat.length ? flat[0] : 0);
  // The map is redrawn when the V(t) positions change: they are marked on it as vertical
  // lines in the colours of their curves, as in the paper's Fig. 2a-b.
  const mapHolder = h('div');
  mapBox.append(mapHolder);
  const drawMap = (marks = []) => {
    clear(mapHolder);
    heatmap(mapHolder, {
      x: slice.x1, y: slice.time, values, vmin, vmax: vmax > vmin ? vmax : vmin + 1,
      xlabel: 'x1 [m]', ylabel: 't [s]', clabel: 'slip velocity V [m/s]',
      lines: (frontLine ? [frontLine] : []).concat(marks.map((m) => ({ x: [m.x, m.x], y: [slice.time[0], slice.time[slice.time.length - 1]], color: m.color, dash: [6, 4], width: 1.5 }))),
      onPick: (x1) => { const list = parsePicks().concat([Number(x1.toFixed(2))]).slice(-5); picks.value = list.join(', '); drawVt(); },
    });
  };
  drawMap();
  figs.querySelector('#fig-map').append(h('p', { class: 'caption muted', text: `${slice.source_shape[0]} samples × ${slice.source_shape[1]} nodes in the file; shown every ${slice.stride.time} sample(s) and ${slice.stride.x1} node(s). Colours saturate at the 99.9th percentile (${fmt(vmax)} m/s).` }));

  // Default positions: a quarter, half and three quarters of the way from the nucleation
  // (x1 = 0) to the arrest (or to the probes when the run did not arrest).
  const x0 = slice.x1[0], x1end = slice.x1[slice.x1.length - 1];
  const arrest = job.metrics?.arrest_position;
  const reach = Number.isFinite(arrest) && arrest > 0 ? arrest : (job.spec?.probe?.arrival_x1 ?? x0 + 0.5 * (x1end - x0));
  const defaults = [0.25, 0.5, 0.75].map((f) => Number((f * reach).toFixed(2)));
  picks.value = defaults.join(', ');
  function parsePicks() {
    return picks.value.split(/[,\s]+/).map(Number).filter((v) => Number.isFinite(v));
  }
  async function drawVt() {
    const xs = parsePicks().slice(0, 6);
    pickMsg.textContent = '';
    try {
      const series = await Promise.all(xs.map((x) => get(`/api/v1/jobs/${job.id}/fields/slip_velocity?x1_min=${x}&x1_max=${x}&max_points=4000`)));
      clear(vtBox);
      drawMap(series.map((s, i) => ({ x: s.x1[0], color: MARKS[i % MARKS.length] })));
      plot(vtBox, {
        series: series.map((s, i) => ({ x: s.time, y: s.values.map((r) => r[0]), label: `x1 = ${fmt(s.x1[0], 4)} m`, color: MARKS[i % MARKS.length] })),
        xlabel: 't [s]', ylabel: 'slip velocity V [m/s]', height: 300,
      });
    } catch (e) { pickMsg.textContent = e.message; pickMsg.className = 'error'; }
  }
  await drawVt();

  if (front) {
    const speeds = waveSpeeds(job.spec);
    const hl = speeds ? [{ y: speeds.cs, label: `c_s = ${fmt(speeds.cs)} m/s`, color: '#6b7785' }, { y: speeds.cp, label: `c_p = ${fmt(speeds.cp)} m/s`, color: '#6b7785' }] : [];
    // Near the nucleation the front arrives almost at once (V_r -> infinity): the axis stops at
    // 1.5 c_p so that the propagation stays readable.
    const vr = front.rupture_speed.filter((v) => v !== null && Number.isFinite(v));
    const top = Math.max(...vr, 0);
    const yrange = speeds && top > 1.5 * speeds.cp ? [0, 1.5 * speeds.cp] : undefined;
    plot(vrBox, {
      series: [{ x: front.x1, y: front.rupture_speed, label: 'V_r (from the front arrival times)', color: PALETTE[0] }],
      xlabel: 'x1 [m]', ylabel: 'rupture speed V_r [m/s]', height: 300, hlines: hl, yrange,
      empty: 'no rupture speed (no front)',
    });
    if (yrange) vrBox.append(h('p', { class: 'caption muted', text: `Axis cut at 1.5 c_p; V_r reaches ${fmt(top)} m/s near the nucleation, where the front arrives almost at once.` }));
  } else {
    vrBox.append(h('p', { class: 'muted', text: 'No front stored for this run.' }));
  }
}
