// What tells runs apart, in one place for every page: the run's name as the CLI's run labels
// (clients/slipfront_client/results.py run_label: method, what is below the interface, the
// friction law by its scale parameter, n_d), and for a set of runs side by side their fields
// flattened, which of them differ, and legend texts that add every other spec field that
// differs (docs/web.md "Compare runs").
import { fmt } from './dom.js';
import { frictionText, jobNd } from './jobs.js';
import { lowerWaveSpeeds, waveSpeeds } from './job_figures.js';
import { methodLabel } from './methods.js';

// What is below the interface when it is not the rigid plane (as the CLI's run labels):
// 'bimaterial' for two different elastic solids, 'full space' for two identical ones.
export function belowText(spec) {
  const lower = lowerWaveSpeeds(spec), upper = waveSpeeds(spec);
  if (!lower) return '';
  const same = upper && lower.cs === upper.cs && lower.cp === upper.cp && (spec.lower.density ?? 1) === (spec.material?.density ?? 1);
  return same ? 'full space' : 'bimaterial';
}

// The parts of a run's label: ['FE', 'L = 1.00e-4 m', 'n_d = 10'] (with 'bimaterial' after
// the method when there is a lower solid).
export function runLabelParts(job) {
  return [methodLabel(job.method || job.spec?.method), belowText(job.spec), frictionText(job.spec), `n_d = ${fmt(jobNd(job))}`].filter(Boolean);
}

// {'friction.L': 1e-4, 'geometry.nodes_per_meter': 10, ...}: a nested object's leaves by
// their dotted path; arrays are leaves (compared and shown as JSON).
export function flatten(value, prefix = '', out = {}) {
  if (value && typeof value === 'object' && !Array.isArray(value)) {
    for (const [k, v] of Object.entries(value)) flatten(v, prefix ? `${prefix}.${k}` : k, out);
  } else if (prefix) {
    out[prefix] = value;
  }
  return out;
}

// The job columns shown beside the spec and the metrics (a cell may be a link: see compare.js).
const RUN_FIELDS = ['name', 'status', 'study_id', 'submitted_by', 'code_version', 'scene_hash', 'cached_from', 'wall_time_s'];
// Spec fields that are not the physics (the job's own name and tags are run fields).
const NOT_PHYSICS = new Set(['name', 'tags']);

function same(a, b) {
  return JSON.stringify(a ?? null) === JSON.stringify(b ?? null);
}

// The relative spread of a row's numbers, (max − min) / max |v|, when every run has a number
// and they are not all zero; else null.
export function spread(values) {
  if (!values.length || !values.every((v) => typeof v === 'number' && Number.isFinite(v))) return null;
  const top = Math.max(...values.map(Math.abs));
  return top > 0 ? (Math.max(...values) - Math.min(...values)) / top : null;
}

// The rows of the comparison table: [{group: 'run'|'spec'|'metrics', key, values (one per job,
// undefined where a job has no such field), differs, partial (some job has no such field),
// spread}]. In each group the fields every job has and that differ come first, then those
// only some jobs have (a method's own settings), then the identical ones, each in the order
// of the first job that has them.
export function compareRows(jobs) {
  const rows = [];
  const add = (group, keys, valueOf) => {
    const made = keys.map((key) => {
      const values = jobs.map((j) => valueOf(j, key));
      const partial = values.some((v) => v === undefined);
      return { group, key, values, differs: values.some((v) => !same(v, values[0])), partial, spread: spread(values) };
    });
    const rank = (r) => (r.differs ? (r.partial ? 1 : 0) : 2);
    rows.push(...made.map((r, i) => [r, i]).sort((a, b) => rank(a[0]) - rank(b[0]) || a[1] - b[1]).map(([r]) => r));
  };
  add('run', RUN_FIELDS, (j, k) => j[k] ?? undefined);
  const specs = jobs.map((j) => flatten(j.spec || {}));
  const metrics = jobs.map((j) => flatten(j.metrics || {}));
  const keysOf = (maps) => [...new Set(maps.flatMap((m) => Object.keys(m)))];
  add('spec', keysOf(specs).filter((k) => !NOT_PHYSICS.has(k)), (j, k) => specs[jobs.indexOf(j)][k]);
  add('metrics', keysOf(metrics), (j, k) => metrics[jobs.indexOf(j)][k]);
  return rows;
}

// The spec fields the base label already says (the method, the friction law's scale, n_d).
const IN_BASE_LABEL = new Set(['method', 'geometry.nodes_per_meter', 'friction.law', 'friction.regularization', 'friction.L', 'friction.t_star', 'friction.D_c']);

// Legend texts of runs side by side: each run's label parts, then every other spec field that
// every run has and that differs between them ('time.duration = 3'); a run whose text is
// still another's gets its short id, so that no two legend entries read the same.
export function compareLabels(jobs, rows = compareRows(jobs)) {
  const extra = rows.filter((r) => r.group === 'spec' && r.differs && !r.partial && !IN_BASE_LABEL.has(r.key));
  const labels = jobs.map((j, i) => [...runLabelParts(j), ...extra.map((r) => `${r.key} = ${cellText(r.values[i])}`)].join(', '));
  return labels.map((text, i) => (labels.indexOf(text) !== i || labels.lastIndexOf(text) !== i ? `${text} (${String(jobs[i].id).slice(0, 8)})` : text));
}

// A value of the table as text: numbers as a researcher reads them (six digits), arrays and
// objects as JSON, booleans as true/false, a missing value as '—'.
export function cellText(v) {
  if (v === undefined || v === null) return '—';
  if (typeof v === 'number') return Number.isInteger(v) ? String(v) : String(Number(v.toPrecision(6)));
  if (typeof v === 'object') return JSON.stringify(v);
  return String(v);
}
