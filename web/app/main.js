// The web view's entry: a hash router over the pages, the token box, and one poll timer
// per page (stopped when the page changes).
import { h, clear } from './dom.js';
import { token, setToken, get } from './api.js';
import { jobsPage } from './jobs.js';
import { jobPage } from './job.js';
import { studiesPage, studyPage } from './studies.js';
import { submitPage } from './submit.js';
import { lengthFitPage } from './length_fit.js';
import { comparePage } from './compare.js';
import { loadFrictionLabels } from './friction_labels.js';
import { loadMethods } from './methods.js';

const view = document.getElementById('view');
let current = null; // {stop()}

function route() {
  const hash = location.hash || '#/jobs';
  const [, path, query] = hash.replace(/^#\/?/, '').match(/^([^?]*)\??(.*)$/); // #/compare?ids=...
  const parts = path.split('/').map(decodeURIComponent);
  if (current?.stop) current.stop();
  current = null;
  clear(view);
  document.querySelectorAll('[data-nav]').forEach((a) => a.classList.toggle('active', a.dataset.nav === parts[0]));
  const page = { poll: null, stopped: false };
  page.every = (ms, fn) => {
    const tick = async () => {
      if (page.stopped) return;
      try { await fn(); } catch (e) { console.warn(e); }
      if (!page.stopped) page.poll = setTimeout(tick, ms);
    };
    page.poll = setTimeout(tick, ms);
  };
  page.stop = () => { page.stopped = true; clearTimeout(page.poll); };
  current = page;
  const id = parts[1];
  const render = {
    jobs: () => (id ? jobPage(view, page, id) : jobsPage(view, page)),
    studies: () => (id ? studyPage(view, page, id) : studiesPage(view, page)),
    submit: () => submitPage(view, page, id),
    'length-fit': () => lengthFitPage(view),
    compare: () => comparePage(view, page, new URLSearchParams(query)),
  }[parts[0]];
  if (!render) {
    view.append(h('p', { text: 'No such page. ' }, h('a', { href: '#/jobs', text: 'Jobs' })));
    return;
  }
  Promise.resolve(render()).catch((e) => {
    view.append(h('p', { class: 'error', text: `Could not load this page: ${e.message}` }));
  });
}

function tokenBox() {
  const input = document.getElementById('token-input');
  const state = document.getElementById('token-state');
  const show = () => { state.textContent = token() ? 'token set (this tab only)' : 'no token: read-only on a shared server'; };
  document.getElementById('token-form').addEventListener('submit', (ev) => {
    ev.preventDefault();
    setToken(input.value.trim());
    input.value = '';
    show();
  });
  document.getElementById('token-clear').addEventListener('click', () => { setToken(''); input.value = ''; show(); });
  show();
}

async function version() {
  try {
    const health = await get('/healthz');
    const v = health.code_version || health.version;
    if (v) document.getElementById('server-version').textContent = `slipfront ${v}`;
  } catch (e) { /* healthz may be degraded; the footer keeps its text */ }
}

tokenBox();
window.addEventListener('hashchange', route);
// The methods' and the friction laws' labels come from the job schema: the pages' first
// drawing waits for them (methods.js, friction_labels.js).
Promise.all([loadMethods(), loadFrictionLabels()]).finally(route);
version();
