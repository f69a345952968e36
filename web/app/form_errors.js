// The server's problem+json errors in a form: each beside the field its JSON pointer names
// (the input whose data-pointer is the longest prefix of the error's), the rest above the
// submit button.
import { h, clear } from './dom.js';

// Error messages placed beside the field whose pointer is the longest prefix of the error's.
export function showErrors(form, general, err, mapPointer = (p) => p) {
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
      const slot = target.closest('.field')?.querySelector(':scope > .ferr');
      if (slot) slot.textContent = slot.textContent ? `${slot.textContent}; ${e.reason}` : e.reason;
      else rest.push(e);
    } else rest.push(e);
  }
  if (rest.length) general.append(h('ul', {}, rest.map((e) => h('li', { text: `${e.pointer || '(body)'}: ${e.reason}` }))));
  if (err.status === 401) general.append(h('p', { text: 'This server needs a token to submit: enter it at the top of the page.' }));
}
