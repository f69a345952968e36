// The length fit of paper Sec. 6 (docs/length-fit.md): a record pasted, uploaded or taken
// from a job's stations is sent to POST /api/v1/length-fits; the page shows the verdict with
// the numbers that decided, the measured stress with the fitted strength against time, and
// the contact pressure's spectrum with f_m. Of a stations CSV holding several stations only
// the chosen one's rows are sent (the others as empty lines, so that an error's line number
// is the file's), as slipfront-client does.
import { h, fill, fmt, kvTable } from './dom.js';
import { get, post } from './api.js';
import { showErrors } from './form_errors.js';
import { axis, chart, chartMessage } from './plots.js';

const MEASURED = '#7f7f7f';
const FITTED = '#d62728';
const COULOMB = '#1f77b4';
const F_M = '#d62728';
const F_99 = '#4d4d4d';

// The station_x1 values of a stations CSV (in order of first appearance), or [] for another
// record.
export function stationsOf(text) {
  const lines = text.split('\n');
  const header = lines.findIndex((l) => l.trim() && !l.trimStart().startsWith('#'));
  if (header < 0 || !lines[header].trim().startsWith('station_x1')) return [];
  const seen = [];
  for (const line of lines.slice(header + 1)) {
    if (!line.trim() || line.trimStart().startsWith('#')) continue;
    const x = Number(line.split(',', 1)[0]);
    if (Number.isFinite(x) && !seen.includes(x)) seen.push(x);
  }
  return seen;
}

// `text` with the data rows of every station but `station` blanked (line count kept).
export function oneStation(text, station) {
  const lines = text.split('\n');
  const header = lines.findIndex((l) => l.trim() && !l.trimStart().startsWith('#'));
  return lines.map((line, i) => {
    if (i <= header || !line.trim() || line.trimStart().startsWith('#')) return line;
    const x = Number(line.split(',', 1)[0]);
    return Number.isFinite(x) && x !== station ? '' : line;
  }).join('\n');
}

function field(id, label, input, pointer, hint) {
  if (pointer) input.dataset.pointer = pointer;
  return h('div', { class: 'field' }, h('label', { for: id, text: label }), input,
    hint ? h('span', { class: 'range muted', text: hint }) : null, h('span', { class: 'ferr' }));
}

// The request's body from the form; a message instead when a number box holds no number.
function requestBody(inputs, record, stations) {
  const body = {};
  const text = record.trim();
  if (text.startsWith('{')) {
    try { body.record = JSON.parse(text); } catch (e) { return { error: { pointer: '/record', reason: `not valid JSON: ${e.message}` } }; }
  } else body.record = record;
  for (const [name, input] of Object.entries(inputs.numbers)) {
    const value = input.value.trim();
    if (!value) continue;
    const number = Number(value);
    if (!Number.isFinite(number)) return { error: { pointer: `/${name}`, reason: `must be a number, got "${value}"` } };
    body[name] = number;
  }
  if (inputs.fitVStar.checked) body.fit_v_star = true;
  if (stations.length > 1) {
    const station = Number(inputs.station.value);
    body.station_x1 = station;
    body.record = oneStation(record, station);
  }
  return { body };
}

function verdictCard(box, answer) {
  const v = answer.verdict;
  const f = answer.fit;
  const fm = answer.critical_frequency;
  const interval = (pair, unit) => `[${fmt(pair[0])}, ${pair[1] === null ? '∞' : fmt(pair[1])}] ${unit}`;
  fill(box,
    h('h2', { text: 'Verdict' }),
    h('p', { id: 'fit-verdict', class: `verdict ${v.rich_enough ? 'rich' : 'bound'}`, text: v.text }),
    h('p', { id: 'fit-reason', class: 'muted', text: v.reason }),
    kvTable([
      [v.rich_enough ? 'measured length L_m' : 'fitted L_m (below the bound: not a measurement)', h('span', { id: 'fit-L', text: `${fmt(f.L, 4)} m` })],
      ['95 % interval of L_m', interval(f.L_interval_95, 'm'), 'statistical error (Jacobian, widened for the misfit’s correlation) and sampling error (refits on every second sample) in quadrature'],
      ['V*', f.v_star_fitted ? `${fmt(f.v_star, 4)} m/s, 95 % ${interval(f.v_star_interval_95, 'm/s')}` : `${fmt(f.v_star, 4)} m/s (given)`],
      ['μ', f.mu_fitted ? `${fmt(f.mu, 5)} ± ${fmt(f.mu_standard_error, 2)}` : `${fmt(f.mu, 5)} (given)`],
      ['measured critical frequency f_m', h('span', { id: 'fit-fm', text: `${fmt(fm.f_m, 4)} Hz` }), `L_c(f_m) = L_m: A/A0 = ${fm.attenuation_ratio} at |V| = ${fmt(fm.slip_rate)} m/s`],
      ['power above f_m', `${fmt(100 * v.power_above_f_m)} % (threshold ${fmt(100 * v.power_threshold)} %)`],
      ['the event’s critical length', `${fmt(v.event_critical_length)} m (the rule at its 99 % power frequency ${fmt(answer.spectrum.frequency_99)} Hz)`],
      v.rich_enough ? null : ['the physical length is at most', `${fmt(v.upper_bound)} m`],
      ['record', `${answer.record.samples} samples over ${fmt(answer.record.duration)} s${answer.record.station_x1 != null ? ` (station x1 = ${fmt(answer.record.station_x1)} m)` : ''}; ${answer.record.slipping_samples} slip (|V| ≥ ${fmt(answer.record.slip_threshold)} m/s)`],
      ['misfit', `rms ${fmt(f.rms_misfit)} Pa over ${f.fitted_samples} samples, correlated over ${fmt(f.misfit_correlation_time)}`],
    ]));
}

async function drawStress(box, answer) {
  const s = answer.series;
  const slipT = s.time.filter((_, i) => s.slipping[i]);
  const slipY = s.frictional_stress.filter((_, i) => s.slipping[i]);
  await chart(box, {
    filename: 'slipfront-length-fit',
    height: 360,
    data: [
      { x: s.time, y: s.frictional_stress, name: 'measured', mode: 'lines', line: { color: MEASURED, width: 1.2 } },
      { x: slipT, y: slipY, name: 'measured, slipping (fitted)', mode: 'markers', marker: { color: '#333', size: 4 } },
      { x: s.time, y: s.coulomb_strength, name: 'μ p (Coulomb)', mode: 'lines', line: { color: COULOMB, width: 1, dash: 'dash' } },
      { x: s.time, y: s.fitted_stress, name: `fitted strength, L = ${fmt(answer.fit.L)} m`, mode: 'lines', line: { color: FITTED, width: 2 } },
    ],
    layout: {
      xaxis: axis('t [s]'), yaxis: axis('frictional stress [Pa]'),
      legend: { x: 1, xanchor: 'right', y: 1, bgcolor: 'rgba(255,255,255,0.85)', bordercolor: '#c9d1da', borderwidth: 1 },
    },
  });
}

async function drawSpectrum(box, answer) {
  const sp = answer.spectrum;
  const f = [], p = [];
  sp.frequency.forEach((x, i) => { if (sp.power[i] > 0) { f.push(x); p.push(sp.power[i]); } });
  if (!f.length) { chartMessage(box, 'The contact pressure carries no power to draw.'); return; }
  const fm = answer.critical_frequency.f_m;
  const lo = Math.min(...p), hi = Math.max(...p);
  const vertical = (x, name, color, dash) => ({ x: [x, x], y: [lo, hi], name, mode: 'lines', line: { color, width: 1.6, dash }, hoverinfo: 'name' });
  await chart(box, {
    filename: 'slipfront-length-fit-spectrum',
    height: 360,
    data: [
      { x: f, y: p, name: 'contact pressure', mode: 'lines', line: { color: COULOMB, width: 1.2 } },
      vertical(fm, `f_m = ${fmt(fm)} Hz`, F_M, 'dash'),
      sp.frequency_99 != null ? vertical(sp.frequency_99, `99 % of the power below ${fmt(sp.frequency_99)} Hz`, F_99, 'dot') : null,
    ].filter(Boolean),
    layout: {
      xaxis: axis('f [Hz]', { type: 'log', dtick: 1 }), yaxis: axis('fraction of the power', { type: 'log', dtick: 2 }),
      legend: { x: 0, xanchor: 'left', y: 0, yanchor: 'bottom', bgcolor: 'rgba(255,255,255,0.85)', bordercolor: '#c9d1da', borderwidth: 1 },
    },
  });
}

export function lengthFitPage(view) {
  const record = h('textarea', { id: 'fit-record', rows: 8, cols: 90, spellcheck: 'false', placeholder: 'time,slip_rate,contact_pressure,frictional_stress\n0,0,1.5e-2,1.05e-2\n…  (or a stations CSV, or {"time": [...], ...})' });
  const file = h('input', { type: 'file', id: 'fit-file', accept: '.csv,.json,.txt,text/csv,application/json' });
  const jobId = h('input', { type: 'text', id: 'fit-job', size: 34, placeholder: 'job id' });
  const jobLoad = h('button', { type: 'button', id: 'fit-job-load', text: 'Load its stations' });
  const station = h('select', { id: 'fit-station' });
  const stationField = field('fit-station', 'station x1 [m]', station, '/station_x1');
  stationField.hidden = true;
  const numbers = {
    v_star: h('input', { type: 'text', id: 'fit-v-star', size: 10, placeholder: '1e-4' }),
    mu: h('input', { type: 'text', id: 'fit-mu', size: 10, placeholder: 'fitted' }),
    slip_threshold: h('input', { type: 'text', id: 'fit-threshold', size: 10, placeholder: '1 % of peak' }),
  };
  const fitVStar = h('input', { type: 'checkbox', id: 'fit-fit-v-star' });
  const general = h('div', { id: 'form-errors' });
  const fitButton = h('button', { type: 'submit', id: 'fit-submit', class: 'primary', text: 'Fit' });
  const loadNote = h('span', { id: 'fit-load-note', class: 'muted' });
  let stations = [];

  const recordChanged = () => {
    stations = stationsOf(record.value);
    stationField.hidden = stations.length < 2;
    const keep = Number(station.value);
    fill(station, stations.map((x) => h('option', { value: String(x), text: fmt(x, 6) })));
    if (stations.includes(keep)) station.value = String(keep);
  };
  record.addEventListener('input', recordChanged);
  file.addEventListener('change', async () => {
    const f = file.files[0];
    if (!f) return;
    record.value = await f.text();
    loadNote.textContent = `${f.name}: ${record.value.split('\n').length} lines`;
    recordChanged();
  });
  jobLoad.addEventListener('click', async () => {
    const id = jobId.value.trim();
    if (!id) return;
    loadNote.textContent = 'loading…';
    try {
      record.value = await get(`/api/v1/jobs/${encodeURIComponent(id)}/stations.csv`);
      loadNote.textContent = `the stations of job ${id}`;
      recordChanged();
    } catch (e) { loadNote.textContent = e.message; }
  });

  const form = h('form', { id: 'fit-form', class: 'specform', novalidate: true },
    h('div', { class: 'fieldsets' },
      h('fieldset', { class: 'wide' }, h('legend', { text: 'record of one interface point' }),
        h('p', { class: 'muted', text: 'CSV with a header naming time [s], slip_rate [m/s], contact_pressure [Pa, > 0 in compression] and frictional_stress [Pa]; a stations CSV (slipfront stations --csv, or a job’s stations below) as it is; or JSON {"time": [...], "slip_rate": [...], ...}. At most 200 000 samples, and the server’s body limit (1 MiB by default).' }),
        field('fit-record', 'paste the record', record, '/record'),
        h('div', { class: 'row' },
          h('div', { class: 'field' }, h('label', { for: 'fit-file', text: 'or upload a file' }), file),
          h('div', { class: 'field' }, h('label', { for: 'fit-job', text: 'or a job’s stations' }), h('span', {}, jobId, ' ', jobLoad))),
        loadNote),
      h('fieldset', {}, h('legend', { text: 'the law (paper eq. 1)' }),
        stationField,
        field('fit-v-star', 'V* [m/s]', numbers.v_star, '/v_star', 'default 1e-4, the paper’s'),
        h('div', { class: 'field check' }, h('label', { for: 'fit-fit-v-star' }, fitVStar, 'fit V* too')),
        field('fit-mu', 'μ', numbers.mu, '/mu', 'fitted when empty'),
        field('fit-threshold', 'slip threshold [m/s]', numbers.slip_threshold, '/slip_threshold', 'a sample slips from this |V| on'))),
    general, h('div', { class: 'actions' }, fitButton));

  const verdict = h('section', { class: 'card', id: 'fit-result' });
  const stressBox = h('div', { id: 'fig-fit-stress', class: 'chart' });
  const spectrumBox = h('div', { id: 'fig-fit-spectrum', class: 'chart' });
  const figures = h('section', { class: 'card', id: 'fit-figures' },
    h('h2', { text: 'Measured stress and the fitted strength' }), stressBox,
    h('h2', { text: 'Power spectrum of the contact pressure (the law’s input)' }), spectrumBox);
  verdict.hidden = true;
  figures.hidden = true;

  view.append(
    h('div', { class: 'pagehead' }, h('h1', { text: 'Length fit (paper §6)' })),
    h('p', { class: 'muted', text: 'The experimentalist’s procedure: fit the simplified Prakash–Clifton law to the record of a slip event (the measured length L_m), compute the measured critical frequency f_m from L_c(f_m) = L_m, and look at the power the event carries above f_m. More than 1 %: the event is rich enough and L_m is the interface’s physical length; otherwise the event only bounds the length, by its own critical length (at least L_m).' }),
    form, verdict, figures);

  form.addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const { body, error } = requestBody({ numbers, fitVStar, station }, record.value, stations);
    if (error) { showErrors(form, general, { message: 'the form is not complete', errors: [error] }); return; }
    fitButton.disabled = true;
    try {
      const answer = await post('/api/v1/length-fits', body);
      form.querySelectorAll('.ferr').forEach((e) => { e.textContent = ''; });
      form.querySelectorAll('.invalid').forEach((e) => e.classList.remove('invalid'));
      fill(general);
      general.className = '';
      verdict.hidden = false;
      figures.hidden = false;
      verdictCard(verdict, answer);
      await drawStress(stressBox, answer).catch((e) => chartMessage(stressBox, e.message, 'error'));
      await drawSpectrum(spectrumBox, answer).catch((e) => chartMessage(spectrumBox, e.message, 'error'));
    } catch (e) {
      showErrors(form, general, e);
    } finally { fitButton.disabled = false; }
  });
}
