// The OpenAPI document rendered by Swagger UI (vendored from npm, served locally), or, when
// the build had no Swagger UI, by the small renderer below.
import { h, append, clear, fill } from './dom.js';

const URL = '/api/v1/openapi.json';

function endpoint(path, method, op) {
  const params = (op.parameters || []).map((p) => (p.$ref ? p.$ref.split('/').pop() : `${p.name} (${p.in})`));
  return h('section', { class: 'card endpoint' },
    h('h3', {}, h('span', { class: `verb verb-${method}`, text: method.toUpperCase() }), ' ', h('code', { text: path })),
    h('p', { text: op.summary || '' }), op.description ? h('p', { class: 'muted', text: op.description }) : null,
    params.length ? h('p', {}, h('strong', { text: 'parameters: ' }), params.join(', ')) : null,
    h('p', {}, h('strong', { text: 'responses: ' }), Object.keys(op.responses || {}).join(', ')));
}

// The operations under their tags, in the document's order of tags (as Swagger UI shows them).
async function fallback(root) {
  const doc = await (await fetch(URL)).json();
  fill(root, h('h1', { text: `${doc.info?.title || 'API'} ${doc.info?.version || ''}` }), h('p', { text: doc.info?.description || '' }));
  const tags = (doc.tags || []).map((t) => ({ name: t.name, description: t.description || '', ops: [] }));
  const other = { name: 'other', description: '', ops: [] };
  for (const [path, ops] of Object.entries(doc.paths || {})) {
    for (const [method, op] of Object.entries(ops)) {
      (tags.find((t) => t.name === op.tags?.[0]) || other).ops.push(endpoint(path, method, op));
    }
  }
  for (const tag of [...tags, other].filter((t) => t.ops.length)) {
    append(root, [h('h2', { text: tag.name }), tag.description ? h('p', { class: 'muted', text: tag.description }) : null, tag.ops]);
  }
}

// Swagger UI when the build vendored it (vendor.json says so), else the fallback.
async function start() {
  const root = document.getElementById('swagger');
  let vendored = false;
  try { vendored = (await (await fetch('/app/vendor.json', { cache: 'no-store' })).json()).swagger_ui === true; } catch { vendored = false; }
  if (!vendored) {
    await fallback(root).catch((e) => root.append(h('p', { class: 'error', text: e.message })));
    return;
  }
  document.head.append(h('link', { rel: 'stylesheet', href: '/vendor/swagger-ui/swagger-ui.css' }));
  const script = h('script', { src: '/vendor/swagger-ui/swagger-ui-bundle.js' });
  script.addEventListener('load', () => {
    window.SwaggerUIBundle({ url: URL, dom_id: '#swagger', deepLinking: true, validatorUrl: null, tryItOutEnabled: false, supportedSubmitMethods: ['get', 'head'] });
  });
  document.head.append(script);
}

start();
