// The rupture methods and their labels, in one place for every page: the server's list (its
// job schema's `method`: the enum, the default and `x-labels`; GET /api/v1/schema/job.json),
// read once by loadMethods() before the first page is drawn; when the server cannot say, the
// two built-in methods. A method's line style goes by its place in the list (the first solid
// lines and circles, the second dashed lines and squares, ...).
import { get } from './api.js';

export const BUILT_IN_METHODS = {
  names: ['fe', 'spectral_bi'],
  default: 'fe',
  labels: {
    fe: { label: 'FE', heading: 'FE', title: 'finite elements', run_cost: 'minutes per run at fine meshes', cost_rank: 1 },
    spectral_bi: { label: 'BI', heading: 'spectral BI', title: 'spectral boundary integral', run_cost: 'seconds per run', cost_rank: 0 },
  },
};
let known = BUILT_IN_METHODS;
let schema = null; // the promise of the job schema, fetched once

// The server's job schema (the job form is built from it too).
export function jobSchema() {
  if (!schema) schema = get('/api/v1/schema/job.json').catch((e) => { schema = null; throw e; });
  return schema;
}

// The methods of a job schema ({names, default, labels}), or null if it lists none.
export function methodsOf(jobSchemaDoc) {
  const m = jobSchemaDoc?.properties?.method;
  if (!Array.isArray(m?.enum) || !m.enum.length) return null;
  return { names: m.enum, default: m.default ?? m.enum[0], labels: m['x-labels'] || {} };
}

// Reads the server's methods; keeps the built-in ones when it cannot.
export async function loadMethods() {
  try { known = methodsOf(await jobSchema()) || known; } catch { /* the built-in methods */ }
  return known;
}

export const methodNames = () => known.names;
export const defaultMethod = () => known.default;
const labelsOf = (method) => known.labels[method || known.default] || {};

// 'FE', 'BI': table cells and legends (a method without labels: its name).
export function methodLabel(method) {
  return labelsOf(method).label ?? method;
}
// 'FE', 'spectral BI': a page's heading.
export function methodHeading(method) {
  return labelsOf(method).heading ?? method;
}
// 'spectral_bi (seconds per run)': a choice between methods.
export function methodChoiceText(method) {
  const cost = labelsOf(method).run_cost;
  return cost ? `${method} (${cost})` : method;
}
// The methods, the cheapest per run first (the server's cost_rank; then in its order).
export function methodsByCost() {
  const rank = (m) => labelsOf(m).cost_rank ?? Infinity;
  return [...known.names].sort((a, b) => rank(a) - rank(b));
}

// Line and marker of a method's runs in the charts: `symbol` for the compare figures, `marker`
// and `text` (the position of point labels) for the speed chart.
const STYLES = [
  { dash: 'solid', symbol: 'circle', marker: 'circle', text: 'top right' },
  { dash: 'dash', symbol: 'square', marker: 'square-open', text: 'bottom right' },
  { dash: 'dot', symbol: 'diamond', marker: 'diamond-open', text: 'bottom left' },
  { dash: 'dashdot', symbol: 'triangle-up', marker: 'triangle-up-open', text: 'top left' },
];
export function methodStyle(method) {
  return STYLES[known.names.indexOf(method || known.default)] || STYLES[0];
}
