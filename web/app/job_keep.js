// Keep, annotate, share on the run page and the study page (docs/server.md): the tags and note, edited
// after submission, archive and restore, and delete (after a confirmation). On a shared
// server only the run's owner may: the server's 401 or 403 is shown beside the buttons.
import { h, fill, fmtTime } from './dom.js';
import { send } from './api.js';

// "fig-2, keep ,," -> ['fig-2', 'keep']
export function parseTags(text) {
  return text.split(',').map((t) => t.trim()).filter(Boolean);
}

// The PATCH members that turn the tags shown when the page was drawn into those typed: only
// the tags added and removed, so a tag another client added meanwhile stays.
export function tagChange(shown, typed) {
  return {
    tags_add: typed.filter((t) => !shown.includes(t)),
    tags_remove: shown.filter((t) => !typed.includes(t)),
  };
}

// Fills `card` for `job` (or a study: `what` gives its URL and words); onChange(record) after a
// change the server took, onDeleted() after a delete.
export function keepCard(card, job, onChange, onDeleted, what = {}) {
  const base = what.base || `/api/v1/jobs/${job.id}`;
  const noun = what.noun || 'run';
  const deleteQuestion = what.deleteQuestion || 'Delete this run and its result file? This cannot be undone.';
  const final = what.final ?? ['succeeded', 'failed', 'cancelled'].includes(job.status);
  const tags = h('input', { id: 'keep-tags', type: 'text', size: 40, value: (job.tags || []).join(', '), placeholder: 'comma-separated, e.g. fig-2, keep' });
  const note = h('textarea', { id: 'keep-note', rows: 3, cols: 60, placeholder: 'a note for yourself and your group' });
  note.value = job.note || '';
  const out = h('span', { id: 'keep-message' });
  const show = (e) => {
    const fields = (e.errors || []).map((x) => `${x.pointer}: ${x.reason}`).join('; ');
    out.textContent = e.status === 401 ? `${e.message} — enter your token at the top` : (fields || e.message);
    out.className = 'error';
  };
  const act = async (method, url, payload, done) => {
    try {
      const answer = await send(method, url, payload);
      done(answer);
    } catch (e) { show(e); }
  };
  const save = () => act('PATCH', base, { ...tagChange(job.tags || [], parseTags(tags.value)), note: note.value }, (updated) => {
    onChange(updated);
    const saved = document.getElementById('keep-message');
    if (saved) { saved.textContent = 'saved'; saved.className = 'ok'; }
  });
  const archived = Boolean(job.archived_at);
  const toggle = () => act('POST', `${base}/${archived ? 'restore' : 'archive'}`, undefined, onChange);
  const remove = () => {
    if (!window.confirm(deleteQuestion)) return;
    act('DELETE', base, undefined, onDeleted);
  };
  fill(card,
    h('h2', { text: 'Keep' }),
    archived ? h('p', { class: 'muted', id: 'keep-archived', text: `Archived ${fmtTime(job.archived_at)}: hidden from the ${noun === 'run' ? 'jobs list and exports' : 'studies list'}, never deleted.` }) : null,
    job.imported_from ? h('p', { class: 'muted', text: `Imported from ${job.imported_from.server?.host || 'another server'} (id ${job.imported_from.id}).` }) : null,
    h('label', {}, 'Tags ', tags),
    h('label', { class: 'block' }, 'Note', note),
    h('div', { class: 'actions' },
      h('button', { id: 'keep-save', onclick: save, text: 'Save tags and note' }),
      h('button', { id: 'keep-archive', onclick: toggle, text: archived ? 'Restore' : 'Archive' }),
      final ? h('button', { id: 'keep-delete', class: 'danger', onclick: remove, text: 'Delete…' }) : null,
      out));
}
