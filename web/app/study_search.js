// The L search of a convergence study (docs/studies-api.md "L search"): where it stands, the
// L it tried and each L against the next smaller one by the critical-length rule.
import { h, fmt } from './dom.js';

const STATES = {
  refining: 'refining the meshes of the last L',
  next_L: 'starting the next L',
  found: 'L_c found',
  meets_coulomb: 'L_c found: the runs meet plain Coulomb',
  mesh_cap: 'stopped at the mesh cap',
  floor: 'reached the floor',
  all_agree: 'every L agrees (L_c at least the first L)',
};

function percent(v) {
  return v == null ? '—' : `${fmt(100 * v, 3)} %`;
}

// Each searched L against the unregularised run of the scene (plain Coulomb for a constant
// coefficient: the server's companion_label), where the search compares them.
function coulombPart(coulomb, companion) {
  const name = companion.charAt(0).toUpperCase() + companion.slice(1);
  if (!coulomb) return h('p', { class: 'muted', id: 'search-coulomb', text: `${name}: not compared (ill-posed for this scene, or switched off).` });
  const rows = (coulomb.steps || []).map((s) => h('tr', { class: s.agree ? 'agree' : 'differ' },
    h('td', { text: `${fmt(s.L)} vs ${companion}` }),
    h('td', { class: 'num', text: percent(s.changes?.propagation_distance) }),
    h('td', { class: 'num', text: percent(s.changes?.arrival_time) }),
    h('td', { text: s.agree ? 'agree' : 'differ' }),
    h('td', { class: 'muted', text: s.reason || '' })));
  return h('div', { id: 'search-coulomb' },
    h('p', {}, h('strong', { text: name }), `: ${coulomb.status || ''}`),
    rows.length ? h('table', { class: 'data' },
      h('thead', {}, h('tr', {}, ...[`L against ${companion} [m]`, 'Δ propagation distance (< 0.5 %)', 'Δ arrival time (< 0.1 %)', 'rule', 'why'].map((t) => h('th', { text: t })))),
      h('tbody', {}, ...rows)) : null);
}

export function searchSection(search, companion = 'plain Coulomb') {
  if (!search) return null;
  const rows = (search.steps || []).map((s) => h('tr', { class: s.agree ? 'agree' : 'differ' },
    h('td', { text: `${fmt(s.L)} → ${fmt(s.smaller_L)}` }),
    h('td', { class: 'num', text: percent(s.changes?.propagation_distance) }),
    h('td', { class: 'num', text: percent(s.changes?.arrival_time) }),
    h('td', { text: s.agree ? 'agree' : 'differ' }),
    h('td', { class: 'muted', text: s.reason || '' })));
  return h('div', { id: 'study-search' },
    h('h3', { text: 'L search' }),
    h('p', {}, h('strong', { id: 'search-state', text: STATES[search.state] || search.state }), ': ',
      h('span', { id: 'search-reason', text: search.reason || '' })),
    h('p', { class: 'muted', text: `From L = ${fmt(search.from)} m down by a factor ${fmt(search.factor)} to at most ${fmt(search.floor)} m; ${search.confirm} smallest L must agree. Tried: ${(search.searched_L || []).map((L) => fmt(L)).join(', ')} m.` }),
    rows.length ? h('table', { class: 'data', id: 'search-steps' },
      h('thead', {}, h('tr', {}, ...['L → next smaller L [m]', 'Δ propagation distance (< 0.5 %)', 'Δ arrival time (< 0.1 %)', 'rule', 'why'].map((t) => h('th', { text: t })))),
      h('tbody', {}, ...rows)) : h('p', { class: 'muted', text: 'No two mesh-converged L to compare yet.' }),
    coulombPart(search.coulomb, companion));
}
