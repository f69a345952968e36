// Named job templates for the submit form. The server's list when it serves one
// (GET /api/v1/presets: {"presets": [{name, title, description, spec}]} or the bare array);
// when that answers 404 (servers without the endpoint), the list built into the web view
// (app/presets.json: the job files of examples/, written by the build, web/presets.cmake).
// The first entry is always the paper's scene: the server's defaults, nothing changed.
import { get } from './api.js';

export const PAPER_SCENE = {
  name: 'paper', title: 'The paper’s scene (Kammer et al. 2014, Fig. 2: every field at the server’s default)',
  spec: {}, source: 'defaults',
};

// {name, title, description, spec, source} from an entry of either list.
function normalise(entry, source) {
  const file = entry.file ? String(entry.file).replace(/\.json$/, '') : null;
  const spec = entry.spec && typeof entry.spec === 'object' ? entry.spec : {};
  const name = String(entry.name ?? file ?? spec.name ?? 'preset');
  return { name, title: String(entry.title ?? spec.name ?? name), description: entry.description ? String(entry.description) : '', spec, source };
}

// The presets and where they came from ('server' or 'built-in'); the server's errors other
// than 404 are reported, and the built-in list is used.
export async function loadPresets() {
  let entries = null;
  let source = 'server';
  let note = '';
  try {
    const body = await get('/api/v1/presets');
    entries = Array.isArray(body) ? body : body?.presets;
    if (!Array.isArray(entries)) throw new Error('GET /api/v1/presets: no "presets" list in the answer');
  } catch (e) {
    if (e.status !== 404) note = `The server's presets could not be read (${e.message}): the built-in list is shown.`;
    source = 'built-in';
    try { entries = await get('/app/presets.json'); } catch (e2) { entries = []; note = `${note} The built-in list is missing (${e2.message}).`.trim(); }
  }
  const presets = [PAPER_SCENE, ...entries.filter((e) => e && typeof e === 'object').map((e) => normalise(e, source))];
  return { presets, source, note };
}
