// The job form: built from the server's job schema (GET /api/v1/schema/job.json, see
// schema_form.js), filled from a preset (presets.js) and the server's defaults of the chosen
// method (GET /api/v1/job-defaults?method=); a submission sends only the fields that differ
// from those defaults, so the paper's scene submitted untouched is the paper's run. The
// server's 422 puts each error beside its field.
import { h, fill, fmt, clear } from './dom.js';
import { get, post, token } from './api.js';
import { SchemaForm, showValidation, valueAt } from './schema_form.js';
import { loadPresets } from './presets.js';
import { showErrors } from './form_errors.js';
import { defaultMethod, jobSchema, methodNames } from './methods.js';

// The order of the groups on the page (the physics first, as docs/api-job-spec.md, then each
// method's options, a section named after its method); groups the schema adds later follow
// these in the schema's order.
const GROUP_ORDER = ['material', 'geometry', 'loading', 'friction', 'nucleation', 'time', 'output', 'probe'];

// The validation's cost estimate in a line: steps, time step, memory and wall time.
function estimateText(answer) {
  const e = answer.estimate;
  const memory = `${fmt(answer.memory_estimate_bytes / 1e6)} MB`;
  if (!e) return `memory estimate ${memory}`;
  const wall = e.wall_time_s === null || e.wall_time_s === undefined ? '' : `, about ${fmt(e.wall_time_s)} s on this server${e.stops_on_arrest ? ' (at most: the run ends earlier once the rupture arrests)' : ''}`;
  return `${fmt(e.steps)} steps of dt = ${fmt(e.dt)} s, memory ${memory}${wall}`;
}

export async function jobForm(view) {
  const holder = h('div', { id: 'job-fields' });
  const presetBox = h('select', { id: 'job-preset' });
  const presetNote = h('p', { id: 'preset-note', class: 'muted' });
  const fresh = h('input', { type: 'checkbox', id: 'job-fresh' });
  const general = h('div', { id: 'form-errors' });
  const warned = h('div', { id: 'form-warnings' });
  const estimate = h('span', { id: 'memory-estimate', class: 'muted' });
  const sendBtn = h('button', { type: 'submit', id: 'job-submit', class: 'primary', text: 'Submit' });
  const form = h('form', { id: 'job-form', class: 'specform', novalidate: true },
    h('p', { class: 'muted', text: 'Every field, its unit, range and meaning come from the server’s job schema. Pick a preset or change any field: only the fields that differ from the server’s defaults are sent, so the paper’s scene submitted untouched is the paper’s run.' }),
    h('div', { class: 'row' },
      h('div', { class: 'field preset' }, h('label', { for: 'job-preset', text: 'preset' }), presetBox, presetNote),
      h('div', { class: 'field check' }, h('label', { for: 'job-fresh' }, fresh, ' fresh (run even if an identical result exists)'))),
    holder, warned, general,
    h('div', { class: 'actions' }, sendBtn, estimate, h('span', { class: 'muted', text: token() ? '' : ' (no token set: fine on a server without tokens)' })));
  view.append(form);
  fill(holder, h('p', { class: 'muted', text: 'Loading the job schema…' }));

  const [schema, { presets, source, note }] = await Promise.all([jobSchema(), loadPresets()]);
  // "preset" is chosen in the preset box above, which fills the form from the preset's spec.
  const fields = new SchemaForm(schema, { order: [...GROUP_ORDER, ...methodNames()], skip: ['preset'] });
  fill(holder, fields.element);
  const methodInput = form.querySelector('[data-pointer="/method"]');
  let defaults = {};

  presetBox.append(...presets.map((p, i) => h('option', { value: String(i), text: p.title })));
  const describe = (p, unknown = []) => {
    const where = p.source === 'defaults' ? '' : p.source === 'server' ? ' (from the server’s presets)' : ' (built into the web view, from examples/)';
    presetNote.textContent = `${p.description || ''}${where}${unknown.length ? ` This preset sets fields the server’s schema does not have, left out: ${unknown.join(', ')}.` : ''}`.trim();
    if (note) presetNote.textContent = `${presetNote.textContent} ${note}`.trim();
  };

  // The server's defaults of a method (the schema's defaults when that endpoint fails).
  const loadDefaults = async (method) => {
    try {
      const d = await get(`/api/v1/job-defaults?method=${encodeURIComponent(method)}`);
      estimate.textContent = `memory estimate of the defaults: ${fmt(d.memory_estimate_bytes / 1e6)} MB`;
      return d.spec || {};
    } catch { estimate.textContent = ''; return {}; }
  };

  const applyPreset = async () => {
    const preset = presets[Number(presetBox.value)] || presets[0];
    const method = valueAt(preset.spec, '/method') ?? schema.properties?.method?.default ?? defaultMethod();
    defaults = await loadDefaults(method);
    const unknown = fields.write(defaults, preset.spec);
    fields.showMethod(method);
    describe(preset, unknown);
  };
  presetBox.addEventListener('change', () => applyPreset().then(() => check()).catch((e) => { general.textContent = e.message; }));
  if (methodInput) {
    methodInput.addEventListener('change', async () => {
      const method = JSON.parse(methodInput.value);
      defaults = await loadDefaults(method);
      fields.showMethod(method);
    });
  }
  // The server checks the job while one types (POST /jobs/validate, at most one request in
  // flight, the last answer wins): errors and warnings beside their fields, derived values
  // written into theirs, the cost estimate beside the submit button.
  let asked = 0;
  let timer = null;
  const body = () => {
    const b = fields.changes(defaults);
    if (methodInput && !methodInput.closest('[hidden]')) b.method = JSON.parse(methodInput.value);
    return b;
  };
  const check = async () => {
    const mine = ++asked;
    try {
      const answer = await post('/api/v1/jobs/validate', body());
      if (mine !== asked) return;
      if (answer.valid === false) { // beside the fields, as a 422 of a submission
        showErrors(form, general, { message: `the job is invalid (${answer.errors.length} error${answer.errors.length === 1 ? '' : 's'})`, errors: answer.errors });
        estimate.textContent = '';
        return;
      }
      form.querySelectorAll('.ferr').forEach((e) => { e.textContent = ''; });
      form.querySelectorAll('.invalid').forEach((e) => e.classList.remove('invalid'));
      clear(general);
      const rest = showValidation(fields, answer);
      clear(warned);
      warned.className = rest.length ? 'warn' : '';
      if (rest.length) warned.append(h('ul', {}, rest.map((w) => h('li', { text: `⚠ ${w.pointer}: ${w.message}` }))));
      estimate.textContent = estimateText(answer);
    } catch (e) {
      if (mine !== asked) return;
      if (e.errors?.length) showErrors(form, general, e); else general.textContent = e.message;
      estimate.textContent = '';
    }
  };
  const later = () => { clearTimeout(timer); timer = setTimeout(check, 350); };
  form.addEventListener('input', later);
  form.addEventListener('change', later);

  await applyPreset();
  if (source === 'built-in' && note) describe(presets[0]);
  await check();

  form.addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const body = fields.changes(defaults);
    if (methodInput && !methodInput.closest('[hidden]')) body.method = JSON.parse(methodInput.value); // always explicit
    if (fresh.checked) body.fresh = true;
    sendBtn.disabled = true;
    try {
      const job = await post('/api/v1/jobs', body);
      location.hash = `#/jobs/${job.id}`;
    } catch (e) {
      showErrors(form, general, e);
    } finally { sendBtn.disabled = false; }
  });
}
