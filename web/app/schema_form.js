// A form built from a JSON Schema (the server's /api/v1/schema/job.json): one field per
// property, its kind from the schema (docs/web.md, "Submit"):
//   enum -> a dropdown;  boolean -> a checkbox;  number / integer -> a number box with the
//   schema's min / max;  string -> a text box;  a number or a named value (oneOf, e.g. a height
//   or "auto") -> a text box;  array of numbers or strings -> a comma list;  array of objects ->
//   a small table of rows (add, remove);  object -> a group (fieldset), nested as deep as the
//   schema;  anything else -> a JSON box.
// Units (x-unit), descriptions and ranges are shown with each field; x-methods says for which
// methods a field is shown, x-when for which choices of other fields ({pointer, values}: mu_s
// only with the law slip_weakening; or a list of such, one of which must hold); x-order gives
// an object's properties in the reader's order (law before its parameters). Every input carries data-pointer (its JSON pointer), so that the
// server's 422 errors find their field.
import { h, fmt } from './dom.js';

// The kind of input a schema gets (see the head of the file).
export function kindOf(schema) {
  if (!schema || typeof schema !== 'object') return 'json';
  if (Array.isArray(schema.enum)) return 'enum';
  if (schema.oneOf || schema.anyOf) return 'choice';
  const type = Array.isArray(schema.type) ? schema.type.find((t) => t !== 'null') : schema.type;
  if (type === 'boolean') return 'boolean';
  if (type === 'number' || type === 'integer') return 'number';
  if (type === 'string') return 'string';
  if (type === 'object' && schema.properties) return 'object';
  if (type === 'array') {
    const item = kindOf(schema.items);
    if (item === 'number') return 'numbers';
    if (item === 'string' || item === 'enum') return 'strings';
    if (item === 'object') return 'rows';
  }
  return 'json';
}

// A bound as written: whole numbers in full (1000000, not 1.00e6), others as fmt.
const bound = (v) => (Number.isInteger(v) && Math.abs(v) < 1e15 ? String(v) : fmt(v));

// "in (0, 0.5)", ">= 1", "at most 200 characters": the allowed values in a few words.
export function rangeText(schema) {
  const kind = kindOf(schema);
  if (kind === 'number') {
    const lo = schema.exclusiveMinimum ?? schema.minimum;
    const hi = schema.exclusiveMaximum ?? schema.maximum;
    const loOpen = schema.exclusiveMinimum !== undefined, hiOpen = schema.exclusiveMaximum !== undefined;
    const int = schema.type === 'integer' ? 'whole number ' : '';
    if (lo !== undefined && hi !== undefined) return `${int}in ${loOpen ? '(' : '['}${bound(lo)}, ${bound(hi)}${hiOpen ? ')' : ']'}`;
    if (lo !== undefined) return `${int}${loOpen ? '>' : '≥'} ${bound(lo)}`;
    if (hi !== undefined) return `${int}${hiOpen ? '<' : '≤'} ${bound(hi)}`;
    return int.trim();
  }
  if (kind === 'choice') return (schema.oneOf || schema.anyOf).map((s) => (s.const !== undefined ? JSON.stringify(s.const) : s.enum ? s.enum.map((v) => JSON.stringify(v)).join(' or ') : rangeText(s) || s.type)).join(', or ');
  if (kind === 'string' && schema.maxLength) return `at most ${schema.maxLength} characters`;
  if (kind === 'numbers' || kind === 'strings') {
    const item = rangeText(schema.items);
    return `comma list${schema.maxItems ? ` of at most ${schema.maxItems}` : ''}${item ? `, each ${item}` : ''}`;
  }
  return '';
}

function idOf(pointer) {
  return `f${pointer.replace(/[^a-zA-Z0-9]/g, '_')}`;
}

function textOf(value) {
  if (value === undefined || value === null) return '';
  if (Array.isArray(value)) return value.map((v) => (typeof v === 'object' ? JSON.stringify(v) : String(v))).join(', ');
  if (typeof value === 'object') return JSON.stringify(value);
  return String(value);
}

// "5, 1e-3, x" -> [5, 0.001, "x"] (text the server will name as not a number).
function numberList(text) {
  return text.split(/[,\s]+/).filter(Boolean).map((s) => (s.trim() !== '' && Number.isFinite(Number(s)) ? Number(s) : s));
}

// The value the schema's choices make of a text: one of their constants, else a number when
// it reads as one, else the text itself (for the server to name).
function choiceValue(schema, text) {
  const constants = (schema.oneOf || schema.anyOf).flatMap((s) => (s.const !== undefined ? [s.const] : s.enum || []));
  if (constants.includes(text)) return text;
  const n = Number(text);
  return Number.isFinite(n) ? n : text;
}

// One input for a value of a scalar or list kind: {input, read(), write(value)}. read()
// returns undefined for an empty box (the field is not sent: the server's default holds).
function scalarInput(pointer, schema, kind) {
  const id = idOf(pointer);
  let input;
  if (kind === 'enum') {
    // Without a default the first choice is "not set" (the field is then not sent).
    const unset = schema.default === undefined ? [h('option', { value: '', text: '— (not set)' })] : [];
    input = h('select', { id }, unset, schema.enum.map((v) => h('option', { value: JSON.stringify(v), text: `${v}${JSON.stringify(v) === JSON.stringify(schema.default) ? ' (default)' : ''}` })));
  } else if (kind === 'boolean') {
    input = h('input', { type: 'checkbox', id });
  } else if (kind === 'number') {
    const lo = schema.minimum ?? schema.exclusiveMinimum, hi = schema.maximum ?? schema.exclusiveMaximum;
    input = h('input', { type: 'number', id, step: schema.type === 'integer' ? 1 : 'any', min: lo, max: hi });
  } else if (kind === 'json') {
    input = h('textarea', { id, rows: 2 });
  } else {
    input = h('input', { type: 'text', id, maxlength: kind === 'string' ? schema.maxLength : undefined, placeholder: kind === 'numbers' || kind === 'strings' ? 'comma list' : kind === 'choice' ? rangeText(schema) : undefined });
  }
  input.dataset.pointer = pointer;
  input.dataset.kind = kind;
  const read = () => {
    if (kind === 'boolean') return input.checked;
    if (kind === 'enum') return input.value === '' ? undefined : JSON.parse(input.value);
    const text = input.value.trim();
    if (text === '') return kind === 'strings' || kind === 'numbers' ? [] : undefined;
    if (kind === 'number') return Number(text);
    if (kind === 'numbers') return numberList(text);
    if (kind === 'strings') return text.split(',').map((s) => s.trim()).filter(Boolean);
    if (kind === 'choice') return choiceValue(schema, text);
    if (kind === 'json') { try { return JSON.parse(text); } catch { return text; } }
    return input.value;
  };
  const write = (value) => {
    if (kind === 'boolean') input.checked = !!value;
    else if (kind === 'enum') input.value = value === undefined ? (schema.default === undefined ? '' : JSON.stringify(schema.default)) : JSON.stringify(value);
    else input.value = textOf(value);
  };
  return { input, read, write };
}

// A schema description as plain text: without its Markdown code marks and escapes (the same
// text feeds docs/api-job-spec.md) and without the trailing "[unit]" the label shows.
export function plainDescription(schema) {
  let text = String(schema.description || '').replace(/`/g, '').replace(/\\([|*_])/g, '$1');
  const unit = schema['x-unit'];
  if (unit && text.endsWith(` [${unit}]`)) text = text.slice(0, -(unit.length + 3));
  return text;
}

// The help under a field: the schema's description, and a line with its range and default
// (rewritten by SchemaForm.write with the default of the chosen method).
function help(schema) {
  const hint = h('span', { class: 'range muted' });
  const text = plainDescription(schema);
  return {
    nodes: [text ? h('span', { class: 'desc', title: text, text }) : null, hint],
    setDefault: (value) => { hint.textContent = [rangeText(schema), value === undefined ? '' : `default ${JSON.stringify(value)}`].filter(Boolean).join(' · '); },
  };
}

// An object schema's properties in its x-order (the server's reader order), the others after.
function orderedProperties(schema) {
  const order = schema['x-order'] || [];
  const rank = (name) => (order.includes(name) ? order.indexOf(name) : order.length);
  return Object.entries(schema.properties || {}).map((e, i) => [...e, i])
    .sort((a, b) => rank(a[0]) - rank(b[0]) || a[2] - b[2]).map(([name, sub]) => [name, sub]);
}

function labelOf(name, schema) {
  return `${name}${schema['x-unit'] ? ` [${schema['x-unit']}]` : ''}`;
}

// The form's fields, as a tree that reads and writes a job spec.
export class SchemaForm {
  // schema: the root object schema; options.skip: top-level property names to leave out;
  // options.order: the groups (object properties) to show first, in that order (the others
  // follow in the schema's order).
  constructor(schema, { skip = [], order = [] } = {}) {
    this.schema = schema;
    this.fields = []; // {pointer, schema, element, read, write, methods, when}
    this.groups = []; // {element, fields: [field...]} for visibility
    this.method = null;
    this.base = {};
    this.element = h('div', { class: 'fieldsets' });
    const loose = h('fieldset', { id: 'group-run' }, h('legend', { text: 'run' }));
    const looseFields = [];
    const wide = []; // arrays of objects: a table needs the page's width
    const rank = (name) => (order.includes(name) ? order.indexOf(name) : order.length);
    const entries = orderedProperties(schema).map((e, i) => [...e, i]).sort((a, b) => rank(a[0]) - rank(b[0]) || a[2] - b[2]);
    for (const [name, sub] of entries) {
      if (skip.includes(name)) continue;
      if (kindOf(sub) === 'object') this.element.append(this.group(`/${name}`, name, sub));
      else if (kindOf(sub) === 'rows') {
        const fs = h('fieldset', { id: `group${idOf(`/${name}`).slice(1)}`, class: 'wide' }, h('legend', { text: name, title: plainDescription(sub) }));
        const fields = [];
        fs.append(this.field(`/${name}`, name, sub, fields));
        this.groups.push({ element: fs, fields });
        wide.push(fs);
      } else { loose.append(this.field(`/${name}`, name, sub, looseFields)); }
    }
    this.element.append(...wide);
    if (looseFields.length) { this.element.prepend(loose); this.groups.push({ element: loose, fields: looseFields }); }
    // A choice that other fields depend on (x-when) shows or hides them when it changes.
    const selectors = new Set(this.fields.flatMap((f) => (f.when || []).map((c) => c.pointer)));
    for (const f of this.fields) if (selectors.has(f.pointer)) f.element.addEventListener('change', () => this.refresh());
  }

  // A fieldset for an object schema, nested objects as nested fieldsets.
  group(pointer, name, schema, parentFields = null) {
    const fs = h('fieldset', { id: `group${idOf(pointer).slice(1)}` }, h('legend', { text: name, title: schema.description || '' }));
    const fields = [];
    for (const [key, sub] of orderedProperties(schema)) {
      const p = `${pointer}/${key}`;
      if (kindOf(sub) === 'object') fs.append(this.group(p, key, sub, fields));
      else fs.append(this.field(p, key, sub, fields));
    }
    if (schema['x-methods']) fs.dataset.methods = schema['x-methods'].join(' ');
    this.groups.push({ element: fs, fields });
    if (parentFields) parentFields.push(...fields);
    return fs;
  }

  // One field: its label (name and unit), input and help; registered for reading.
  field(pointer, name, schema, groupFields) {
    const kind = kindOf(schema);
    const record = { pointer, schema, kind, methods: schema['x-methods'] || null, when: conditionsOf(schema['x-when']) };
    let control;
    if (kind === 'rows') {
      const rows = new RowEditor(pointer, schema);
      Object.assign(record, { read: () => rows.read(), write: (v) => rows.write(v) });
      control = rows.element;
    } else {
      const { input, read, write } = scalarInput(pointer, schema, kind);
      Object.assign(record, { read, write });
      control = input;
    }
    const id = idOf(pointer);
    const { nodes, setDefault } = help(schema);
    record.setDefault = setDefault;
    setDefault(schema.default);
    record.element = kind === 'boolean'
      ? h('div', { class: 'field check' }, h('label', { for: id, title: pointer }, control, ` ${labelOf(name, schema)}`), nodes, h('span', { class: 'ferr' }), h('span', { class: 'fwarn' }))
      : h('div', { class: 'field' }, h('label', { for: id, text: labelOf(name, schema), title: pointer }), control, nodes, h('span', { class: 'ferr' }), h('span', { class: 'fwarn' }));
    record.element.dataset.field = pointer;
    this.fields.push(record);
    groupFields.push(record);
    return record.element;
  }

  // Shows the fields of `method` (x-methods), hides the others and the groups left empty.
  showMethod(method) {
    this.method = method;
    this.refresh();
  }

  // The value of the choice at `pointer` for x-when: what it holds while shown, else what the
  // server takes without it (the base spec's, or the schema's default).
  choice(pointer) {
    const f = this.fields.find((g) => g.pointer === pointer);
    if (!f) return valueAt(this.base, pointer);
    if (!f.element.hidden) return f.read();
    return valueAt(this.base, pointer) ?? f.schema.default;
  }

  // Shows a field when the method uses it (x-methods) and, with x-when, when its choosing
  // field holds one of its values; hides the groups left empty. Fields come in order, and a
  // choosing field before the fields it chooses (law before mu_s), so one pass settles all.
  refresh() {
    for (const f of this.fields) {
      const byMethod = !f.methods || this.method === null || f.methods.includes(this.method);
      f.element.hidden = !byMethod || (!!f.when && !f.when.some((c) => c.values.includes(this.choice(c.pointer))));
    }
    for (const g of this.groups) {
      const own = g.element.dataset.methods;
      g.element.hidden = (own && !own.split(' ').includes(method)) || g.fields.every((f) => f.element.hidden);
    }
  }

  // Writes a spec into the form: `base` (the defaults) overlaid with `spec`. Returns the
  // pointers of `spec` that no field takes.
  write(base, spec = {}) {
    this.base = base;
    this.derived = {};
    for (const f of this.fields) {
      const fallback = valueAt(base, f.pointer) ?? f.schema.default;
      f.setDefault(fallback);
      f.shown = valueAt(spec, f.pointer) ?? fallback;
      f.write(f.shown);
    }
    return leafPointers(spec).filter((p) => !this.fields.some((f) => p === f.pointer || p.startsWith(`${f.pointer}/`)));
  }

  // The spec of the shown fields whose value differs from `base` (the server's defaults):
  // what a submission sends.
  changes(base) {
    const out = {};
    for (const f of this.fields) {
      if (f.element.hidden) continue;
      const v = f.read();
      const d = this.derived?.[f.pointer] ?? valueAt(base, f.pointer) ?? f.schema.default;
      // Nothing typed into a field without a default: not sent.
      if (v === undefined || (d === undefined && ((Array.isArray(v) && !v.length) || v === false))) continue;
      if (JSON.stringify(v) !== JSON.stringify(d)) setAt(out, f.pointer, v);
    }
    return out;
  }
}

// What the server's validation says of the fields (POST /jobs/validate): a value it derived
// from the scene is written into its field unless one typed there (and not sent back: the
// server derives it again), with where it came from; a warning goes beside its field (the
// longest pointer prefix), or to `rest` when no shown field takes it.
export function showValidation(form, { warnings = [], provenance = [] }) {
  const derived = new Map(provenance.filter((v) => String(v.source).startsWith('derived')).map((v) => [v.pointer, v]));
  const rest = [];
  for (const f of form.fields) {
    const slot = f.element.querySelector(':scope > .fwarn');
    if (slot) slot.textContent = '';
    f.element.classList.remove('warned');
    const d = derived.get(f.pointer);
    const untouched = JSON.stringify(f.read()) === JSON.stringify(f.shown);
    if (d) {
      if (untouched) { f.shown = d.value; f.write(d.value); }
      form.derived[f.pointer] = d.value;
      if (slot) slot.textContent = `${d.source} (${fmt(d.value)} ${d.unit})`;
    } else if (f.pointer in form.derived) {
      delete form.derived[f.pointer];
      const fallback = valueAt(form.base, f.pointer) ?? f.schema.default;
      if (untouched) { f.shown = fallback; f.write(fallback); }
    }
  }
  for (const w of warnings) {
    let target = null;
    for (const f of form.fields) {
      if (f.element.hidden) continue;
      if ((w.pointer === f.pointer || w.pointer.startsWith(`${f.pointer}/`)) && (!target || f.pointer.length > target.pointer.length)) target = f;
    }
    const slot = target?.element.querySelector(':scope > .fwarn');
    if (!slot) { rest.push(w); continue; }
    target.element.classList.add('warned');
    slot.textContent = slot.textContent ? `${slot.textContent} · ⚠ ${w.message}` : `⚠ ${w.message}`;
  }
  return rest;
}

// A table of rows for an array of objects: one column per item property, a row per item,
// "add a row" and a remove button per row. Item properties that are objects or arrays of
// objects take a JSON box.
class RowEditor {
  constructor(pointer, schema) {
    this.pointer = pointer;
    this.schema = schema;
    this.columns = orderedProperties(schema.items || {}); // the reader's order (x-order)
    this.values = [];
    this.body = h('tbody');
    const addButton = h('button', { type: 'button', class: 'small', id: `${idOf(pointer)}_add`, text: 'add a row', onclick: () => { this.sync(); this.values.push(this.newItem()); this.render(); } });
    this.element = h('div', { class: 'rows', id: idOf(pointer) },
      h('table', { class: 'rowtable' },
        h('thead', {}, h('tr', {}, this.columns.map(([key, sub]) => h('th', { title: sub.description || '', text: labelOf(key, sub) })), h('th'))),
        this.body),
      addButton);
    this.element.dataset.pointer = pointer; // errors about the whole array land here
  }

  newItem() {
    const item = {};
    for (const [key, sub] of this.columns) if (sub.default !== undefined) item[key] = sub.default;
    return item;
  }

  // Keeps the values typed so far before the rows are re-drawn.
  sync() {
    this.values = this.read();
  }

  render() {
    this.readers = [];
    this.body.replaceChildren(...this.values.map((item, i) => {
      const cells = this.columns.map(([key, sub]) => {
        const kind = kindOf(sub);
        const { input, read, write } = scalarInput(`${this.pointer}/${i}/${key}`, sub, ['object', 'rows'].includes(kind) ? 'json' : kind);
        write(item[key]);
        this.readers.push({ i, key, read });
        return h('td', { class: 'field' }, input, h('span', { class: 'ferr' }));
      });
      return h('tr', {}, cells, h('td', {}, h('button', { type: 'button', class: 'small', title: 'remove this row', text: '×', onclick: () => { this.sync(); this.values.splice(i, 1); this.render(); } })));
    }));
  }

  read() {
    const out = this.values.map(() => ({}));
    for (const { i, key, read } of this.readers || []) {
      const v = read();
      if (v !== undefined) out[i][key] = v;
    }
    return out;
  }

  write(value) {
    this.values = Array.isArray(value) ? value.map((v) => ({ ...v })) : [];
    this.render();
  }
}

// x-when as a list of conditions of which one must hold ({pointer, values} alone is one).
function conditionsOf(when) {
  if (!when) return null;
  return Array.isArray(when) ? when : [when];
}

// The value at a JSON pointer ("/a/b"), undefined when absent.
export function valueAt(obj, pointer) {
  let o = obj;
  for (const k of pointer.split('/').slice(1)) {
    if (o === null || typeof o !== 'object' || !(k in o)) return undefined;
    o = o[k];
  }
  return o;
}

export function setAt(obj, pointer, value) {
  const keys = pointer.split('/').slice(1);
  let o = obj;
  for (const k of keys.slice(0, -1)) o = o[k] ??= {};
  o[keys[keys.length - 1]] = value;
}

// The pointers of the non-object values of a spec (arrays count as values).
function leafPointers(obj, prefix = '') {
  return Object.entries(obj || {}).flatMap(([k, v]) => (v && typeof v === 'object' && !Array.isArray(v) ? leafPointers(v, `${prefix}/${k}`) : [`${prefix}/${k}`]));
}
