// Submit: the job form (job_form.js: built from the server's job schema, with presets) and
// the study form (grid or convergence). Errors of the server's problem+json are shown beside
// the field their JSON pointer names (form_errors.js).
import { h } from './dom.js';
import { post } from './api.js';
import { showErrors } from './form_errors.js';
import { jobForm } from './job_form.js';
import { defaultMethod, methodChoiceText, methodsByCost } from './methods.js';

export async function submitPage(view, page, which) {
  const tabs = h('div', { class: 'tabs' },
    h('a', { href: '#/submit', class: which === 'study' ? '' : 'active', text: 'A job' }),
    h('a', { href: '#/submit/study', class: which === 'study' ? 'active' : '', text: 'A study' }));
  view.append(h('div', { class: 'pagehead' }, h('h1', { text: which === 'study' ? 'Start a study' : 'Submit a job' })), tabs);
  if (which === 'study') return studyForm(view);
  return jobForm(view);
}

function field(id, label, input, pointer) {
  input.dataset.pointer = pointer;
  return h('div', { class: 'field' }, h('label', { for: id, text: label }), input, h('span', { class: 'ferr' }));
}

function numbers(text) {
  return text.split(/[,\s]+/).filter(Boolean).map((s) => (Number.isFinite(Number(s)) ? Number(s) : s));
}

function studyForm(view) {
  const name = h('input', { type: 'text', id: 'study-name', size: 36, placeholder: 'e.g. L_c sweep' });
  const method = h('select', { id: 'study-method' }, methodsByCost().map((m) => h('option', { value: m, text: methodChoiceText(m) }))); // the cheapest first
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
    if (method.value !== defaultMethod()) baseSpec.method = method.value;
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
