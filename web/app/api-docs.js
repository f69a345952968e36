// The OpenAPI document rendered by Swagger UI (vendored from npm, served locally), or, when
// the build had no Swagger UI, by the small renderer below.
import { h, clear, fill } from './dom.js';

const URL = '/api/v1/openapi.json';

async function fallback(root) {
  const doc = await (await fetch(URL)).json();
  fill(root, h('h1', { text: `${doc.info?.title || 'API'} ${doc.info?.version || ''}` }), h('p', { text: doc.info?.description || '' }));
  for (const [path, ops] of Object.entries(doc.paths || {})) {
    for (const [method, op] of Object.entries(ops)) {
      const params = (op.parameters || []).map((p) => (p.$ref ? p.$ref.split('/').pop() : `${p.name} (${p.in})`));
      root.append(h('section', { class: 'card endpoint' },
        h('h3', {}, h('span', { class: `verb verb-${method}`, text: method.toUpperCase() }), ' ', h('code', { text: path })),
        h('p', { text: op.summary || '' }), op.description ? h('p', { class: 'muted', text: op.description }) : null,
        params.length ? h('p', {}, h('strong', { text: 'parameters: ' }), params.join(', ')) : null,
        h('p', {}, h('strong', { text: 'responses: ' }), Object.keys(op.responses || {}).join(', '))));
    }
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
