// Submit: a job form generated from the server's defaults (GET /api/v1/job-defaults), sending
// only what differs from them; a study form (grid or convergence). Errors of the server's
// problem+json are shown beside the field their JSON pointer names.
import { h, clear, fill, fmt } from './dom.js';
import { get, post, token } from './api.js';

const HIDDEN = new Set(['/name', '/tags', '/method']);

function leaves(obj, prefix = '') {
  const out = [];
  for (const [k, v] of Object.entries(obj)) {
    const p = `${prefix}/${k}`;
    if (v && typeof v === 'object' && !Array.isArray(v)) out.push({ group: p, children: leaves(v, p) });
    else out.push({ pointer: p, value: v });
  }
  return out;
}

function inputFor(leaf) {
  const id = `f${leaf.pointer.replace(/[^a-zA-Z0-9]/g, '_')}`;
  const v = leaf.value;
  let input;
  if (typeof v === 'boolean') input = h('input', { type: 'checkbox', id, checked: v });
  else if (Array.isArray(v)) input = h('input', { type: 'text', id, value: JSON.stringify(v) });
  else input = h('input', { type: 'text', id, value: v === null ? '' : String(v), inputmode: typeof v === 'number' ? 'decimal' : undefined });
  input.dataset.pointer = leaf.pointer;
  input.dataset.kind = Array.isArray(v) ? 'json' : v === null ? 'null' : typeof v;
  input.dataset.default = JSON.stringify(v);
  return { id, input };
}

function readInput(input) {
  const kind = input.dataset.kind;
  if (kind === 'boolean') return input.checked;
  const text = input.value.trim();
  if (kind === 'json') { try { return JSON.parse(text); } catch { return text; } }
  if (kind === 'number') { const n = Number(text); return text !== '' && Number.isFinite(n) ? n : text; }
  if (kind === 'null') {
    if (text === '') return null;
    const n = Number(text);
    return Number.isFinite(n) ? n : text;
  }
  return text;
}

function setAt(obj, pointer, value) {
  const keys = pointer.split('/').slice(1);
  let o = obj;
  for (const k of keys.slice(0, -1)) o = o[k] ??= {};
  o[keys[keys.length - 1]] = value;
}

// Error messages placed beside the field whose pointer is the longest prefix of the error's.
function showErrors(form, general, err, mapPointer = (p) => p) {
  form.querySelectorAll('.ferr').forEach((e) => { e.textContent = ''; });
  form.querySelectorAll('.invalid').forEach((e) => e.classList.remove('invalid'));
  clear(general);
  general.className = 'error';
  general.append(h('strong', { text: err.message }));
  const rest = [];
  for (const e of err.errors) {
    const pointer = mapPointer(e.pointer || '');
    let target = null;
    for (const el of form.querySelectorAll('[data-pointer]')) {
      const p = el.dataset.pointer;
      if ((pointer === p || pointer.startsWith(`${p}/`)) && (!target || p.length > target.dataset.pointer.length)) target = el;
    }
    if (target) {
      target.classList.add('invalid');
      const slot = target.closest('.field')?.querySelector('.ferr');
      if (slot) slot.textContent = slot.textContent ? `${slot.textContent}; ${e.reason}` : e.reason;
      else rest.push(e);
    } else rest.push(e);
  }
  if (rest.length) general.append(h('ul', {}, rest.map((e) => h('li', { text: `${e.pointer || '(body)'}: ${e.reason}` }))));
  if (err.status === 401) general.append(h('p', { text: 'This server needs a token to submit: enter it at the top of the page.' }));
}

export async function submitPage(view, page, which) {
  const tabs = h('div', { class: 'tabs' },
    h('a', { href: '#/submit', class: which === 'study' ? '' : 'active', text: 'A job' }),
    h('a', { href: '#/submit/study', class: which === 'study' ? 'active' : '', text: 'A study' }));
  view.append(h('div', { class: 'pagehead' }, h('h1', { text: which === 'study' ? 'Start a study' : 'Submit a job' })), tabs);
  if (which === 'study') return studyForm(view);
  return jobForm(view);
}

async function jobForm(view) {
  const holder = h('div');
  const method = h('select', { id: 'job-method' }, h('option', { value: 'fe', text: 'fe — explicit finite elements of the block' }), h('option', { value: 'spectral_bi', text: 'spectral_bi — boundary integral, half-space (fast)' }));
  const name = h('input', { type: 'text', id: 'job-name', size: 40, placeholder: 'e.g. paper run L=5e-5' });
  const tags = h('input', { type: 'text', id: 'job-tags', size: 40, placeholder: 'comma separated' });
  const fresh = h('input', { type: 'checkbox', id: 'job-fresh' });
  const general = h('div', { id: 'form-errors' });
  const sendBtn = h('button', { type: 'submit', id: 'job-submit', class: 'primary', text: 'Submit' });
  const form = h('form', { id: 'job-form', class: 'specform', novalidate: true },
    h('p', { class: 'muted', text: 'Every field starts at the server’s default: submitted unchanged, it is the paper’s run (Kammer et al. 2014, Fig. 2). Only the fields you change are sent.' }),
    h('div', { class: 'row' },
      h('div', { class: 'field', dataset: {} }, h('label', { for: 'job-method', text: 'method' }), method, h('span', { class: 'ferr' })),
      field('job-name', 'name', name, '/name'), field('job-tags', 'tags', tags, '/tags'),
      h('div', { class: 'field' }, h('label', { for: 'job-fresh', text: 'fresh (run even if an identical result exists)' }), fresh)),
    holder, general, h('div', { class: 'actions' }, sendBtn, h('span', { class: 'muted', text: token() ? '' : ' (no token set: fine on a server without tokens)' })));
  method.dataset.pointer = '/method';
  view.append(form);

  const build = async () => {
    fill(holder, h('p', { class: 'muted', text: 'Loading the defaults…' }));
    const d = await get(`/api/v1/job-defaults?method=${method.value}`);
    clear(holder);
    const grid = h('div', { class: 'fieldsets' });
    const loose = [];
    for (const item of leaves(d.spec)) {
      if (item.group) {
        const fs = h('fieldset', {}, h('legend', { text: item.group.slice(1) }));
        for (const leaf of flatten(item.children)) fs.append(leafField(leaf, item.group));
        grid.append(fs);
      } else if (!HIDDEN.has(item.pointer)) loose.push(item);
    }
    if (loose.length) {
      const fs = h('fieldset', {}, h('legend', { text: 'run' }));
      for (const leaf of loose) fs.append(leafField(leaf, ''));
      grid.prepend(fs);
    }
    holder.append(grid, h('p', { class: 'muted', text: `Memory estimate of the defaults: ${fmt(d.memory_estimate_bytes / 1e6)} MB.` }));
  };
  method.addEventListener('change', () => build().catch((e) => { general.textContent = e.message; }));
  await build();

  form.addEventListener('submit', async (ev) => {
    ev.preventDefault();
    const body = {};
    if (method.value !== 'fe') body.method = method.value;
    if (name.value.trim()) body.name = name.value.trim();
    const t = tags.value.split(',').map((s) => s.trim()).filter(Boolean);
    if (t.length) body.tags = t;
    if (fresh.checked) body.fresh = true;
    for (const input of holder.querySelectorAll('[data-pointer]')) {
      const v = readInput(input);
      if (JSON.stringify(v) !== input.dataset.default) setAt(body, input.dataset.pointer, v);
    }
    sendBtn.disabled = true;
    try {
      const job = await post('/api/v1/jobs', body);
      location.hash = `#/jobs/${job.id}`;
    } catch (e) {
      showErrors(form, general, e);
    } finally { sendBtn.disabled = false; }
  });
}

function flatten(items) {
  return items.flatMap((i) => (i.group ? flatten(i.children) : [i]));
}

function field(id, label, input, pointer) {
  input.dataset.pointer = pointer;
  return h('div', { class: 'field' }, h('label', { for: id, text: label }), input, h('span', { class: 'ferr' }));
}

function leafField(leaf, group) {
  const { id, input } = inputFor(leaf);
  const label = leaf.pointer.slice(group.length + 1).replace(/\//g, '.');
  return h('div', { class: 'field' }, h('label', { for: id, text: label, title: leaf.pointer }), input,
    h('span', { class: 'default muted', text: `default ${JSON.stringify(leaf.value)}` }), h('span', { class: 'ferr' }));
}

function numbers(text) {
  return text.split(/[,\s]+/).filter(Boolean).map((s) => (Number.isFinite(Number(s)) ? Number(s) : s));
}

function studyForm(view) {
  const name = h('input', { type: 'text', id: 'study-name', size: 36, placeholder: 'e.g. L_c sweep' });
  const method = h('select', { id: 'study-method' }, h('option', { value: 'spectral_bi', text: 'spectral_bi (seconds per run)' }), h('option', { value: 'fe', text: 'fe (minutes per run at fine meshes)' }));
  const kind = h('select', { id: 'study-kind' }, h('option', { value: 'convergence', text: 'convergence: refine n_d per L until two meshes agree' }), h('option', { value: 'grid', text: 'grid: every L × n_d at once' }));
  const Ls = h('input', { type: 'text', id: 'study-L', size: 40, value: '1e-3, 1e-4, 5e-5, 1e-5, 5e-6' });
  const nds = h('input', { type: 'text', id: 'study-nd', size: 30, value: '10, 20, 40' });
  const ndmax = h('input', { type: 'text', id: 'study-ndmax', size: 8, value: '40' });
  const base = h('textarea', { id: 'study-base', rows: 4, cols: 60, placeholder: '{"time": {"duration": 12}}  (optional: the job spec shared by every run, without friction.L and geometry.nodes_per_meter)' });
  const fresh = h('input', { type: 'checkbox', id: 'study-fresh' });
  const general = h('div', { id: 'form-errors' });
  const sendBtn = h('button', { type: 'submit', id: 'study-submit', class: 'primary', text: 'Start the study' });
  const ndmaxField = field('study-ndmax', 'n_d_max (cap of the ladder)', ndmax, '/convergence/n_d_max');
  const form = h('form', { id: 'study-form', class: 'specform', novalidate: true },
    h('p', { class: 'muted', text: 'The paper’s five L on the spectral BI method converge within n_d ≤ 40 in seconds; the FE method takes minutes per fine run.' }),
    h('div', { class: 'fieldsets' }, h('fieldset', {}, h('legend', { text: 'study' }),
      field('study-name', 'name', name, '/name'),
      field('study-method', 'method', method, '/base/method'),
      field('study-kind', 'kind', kind, '/kind'),
      field('study-L', 'L values [m]', Ls, '/L'),
      field('study-nd', 'n_d values [nodes per m] (the ladder)', nds, '/n_d'),
      ndmaxField,
      field('study-base', 'base spec (JSON)', base, '/base'),
      h('div', { class: 'field' }, h('label', { for: 'study-fresh', text: 'fresh (recompute reused runs)' }), fresh))),
    general, h('div', { class: 'actions' }, sendBtn));
  kind.addEventListener('change', () => { ndmaxField.hidden = kind.value !== 'convergence'; });
  view.append(form);
  form.addEventListener('submit', async (ev) => {
    ev.preventDefault();
    let baseSpec = {};
    if (base.value.trim()) {
      try { baseSpec = JSON.parse(base.value); } catch (e) {
        showErrors(form, general, { message: 'the base spec is not valid JSON', errors: [{ pointer: '/base', reason: e.message }] });
        return;
      }
    }
    if (method.value !== 'fe') baseSpec.method = method.value;
    const body = { base: baseSpec };
    if (name.value.trim()) body.name = name.value.trim();
    if (fresh.checked) body.fresh = true;
    const spec = { L: numbers(Ls.value), n_d: numbers(nds.value) };
    if (kind.value === 'convergence' && ndmax.value.trim()) spec.n_d_max = Number(ndmax.value);
    body[kind.value] = spec;
    sendBtn.disabled = true;
    try {
      const study = await post('/api/v1/studies', body);
      location.hash = `#/studies/${study.id}`;
    } catch (e) {
      // /grid/L/2 and /convergence/n_d name the L and n_d boxes; n_d_max its own.
      showErrors(form, general, e, (p) => p.replace(/^\/(grid|convergence)\/(L|n_d)(\/|$)/, '/$2$3').replace(/^\/convergence\/n_d_max/, '/convergence/n_d_max'));
    } finally { sendBtn.disabled = false; }
  });
}
