// A run's friction in words, from the labels the friction laws give themselves (the job
// schema's x-labels of friction.law and friction.regularization, docs/api-job-spec.md):
// 'L = 5e-5 m' (slip scale: the paper's Prakash–Clifton), 't* = 3.5e-4 s' (time scale),
// 'Coulomb' (constant mu, none), 'slip weakening D_c = 7.44e-4 m' and its regularisation's.
// The same rule as the client's results.friction_label.
import { fmt } from './dom.js';
import { get } from './api.js';

let labels = null; // {law: {name: {label, alone}}, regularization: {...}, fixed: {law: reg}, defaults}

// Reads the labels from the server's job schema once (the pages call frictionText after it).
export async function loadFrictionLabels() {
  try {
    labels = frictionLabelsOf(await get('/api/v1/schema/job.json'));
  } catch (e) {
    console.warn('friction labels: no job schema', e);
  }
}

export function frictionLabelsOf(schema) {
  const f = schema?.properties?.friction?.properties || {};
  const defaults = {};
  for (const [name, sub] of Object.entries(f)) if ('default' in sub) defaults[name] = sub.default;
  return {
    law: f.law?.['x-labels'] || {},
    regularization: f.regularization?.['x-labels'] || {},
    fixed: f.law?.['x-fixed-regularization'] || {},
    defaults,
  };
}

// {name} of a label filled with the friction's value (fmt's dash when the spec lacks it).
function fill(template, friction) {
  return (template || '').replace(/\{(\w+)\}/g, (_, name) => {
    const v = friction[name];
    return typeof v === 'string' ? v : fmt(v);
  });
}

export function frictionText(spec, given = labels) {
  const f = spec?.friction || {};
  if (!given) return f.law || '';
  const law = f.law || given.defaults.law;
  const regularization = given.fixed[law] || f.regularization || given.defaults.regularization || 'none';
  const own = given.law[law] || {};
  const its = given.regularization[regularization] || {};
  const parts = [fill(own.label, f), fill(its.label, f)].filter(Boolean);
  if (!parts.length) parts.push(own.alone || its.alone || law);
  return parts.join(', ');
}
