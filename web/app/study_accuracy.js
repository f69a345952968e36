// An accuracy study (docs/studies-api.md "Accuracy target"): the answer with its error estimate,
// how it was estimated, the method and first mesh the service chose, and the value of every
// mesh with its estimate as a chart (error bars) and a table.
import { h, fmt } from './dom.js';
import { methodHeading } from './methods.js';
import { axis, chart } from './plots.js';

const STATES = {
  waiting: 'refining (a mesh is running)',
  run_next: 'refining',
  met: 'target met',
  mesh_cap: 'stopped at the mesh cap (best estimate below)',
  failed: 'cannot be met',
};

function percent(v) {
  return v == null ? '—' : `${fmt(100 * v, 3)} %`;
}

export function accuracySection(answer, studyId) {
  if (!answer) return null;
  const target = answer.target || {};
  const steps = answer.steps || [];
  const box = h('div', { class: 'fig', id: 'fig-accuracy' });
  const rows = steps.map((s) => h('tr', {},
    h('td', { class: 'num', text: fmt(s.n_d) }),
    h('td', { class: 'num', text: fmt(s.value, 6) }),
    h('td', { class: 'num', text: s.error != null ? `± ${fmt(s.error, 3)}` : '—' }),
    h('td', { class: 'num', text: percent(s.relative_error) }),
    h('td', { text: s.estimate || 'one mesh: no estimate' }),
    h('td', { class: 'num', text: `${fmt(s.wall_time_s, 3)} s` }),
    h('td', {}, h('a', { href: `#/jobs/${s.job_id}`, text: 'run' }))));
  const section = h('div', { id: 'study-accuracy' },
    h('h3', { text: `Accuracy target: ${target.metric} within ${percent(target.tolerance)}` }),
    h('p', {}, h('strong', { id: 'accuracy-state', text: STATES[answer.state] || answer.state }), ': ',
      h('span', { id: 'accuracy-answer', text: answer.value != null ? `${fmt(answer.value, 6)} ± ${fmt(answer.error, 3)} (${percent(answer.relative_error)}, ${answer.estimate || '—'}) at n_d = ${fmt(answer.n_d)}` : '—' })),
    answer.extrapolated != null ? h('p', { class: 'muted', text: `Richardson: observed order ${fmt(answer.observed_order, 3)}, extrapolated value ${fmt(answer.extrapolated, 6)}.` }) : null,
    h('p', { class: 'muted', id: 'accuracy-reason', text: answer.reason || '' }),
    h('p', { class: 'muted', text: `Method ${methodHeading(answer.method?.name)}: ${answer.method?.reason || ''}. First mesh n_d = ${fmt(answer.start?.n_d)}: ${answer.start?.reason || ''}. Cost: ${answer.cost?.runs ?? '?'} run(s), ${fmt(answer.cost?.wall_time_s, 3)} s of run wall time.` }),
    box,
    rows.length ? h('table', { class: 'data', id: 'accuracy-steps' },
      h('thead', {}, h('tr', {}, ...['n_d', target.metric, 'estimated error', 'relative', 'estimate', 'wall', ''].map((t) => h('th', { text: t })))),
      h('tbody', {}, ...rows)) : null);
  if (steps.length) {
    const withError = steps.filter((s) => s.error != null);
    const data = [{
      x: steps.map((s) => s.n_d), y: steps.map((s) => s.value), mode: 'lines+markers', name: target.metric,
      error_y: { type: 'data', array: steps.map((s) => s.error ?? 0), visible: true, thickness: 1.2, width: 6 },
      hovertemplate: 'n_d = %{x}<br>%{y}<extra></extra>', line: { color: '#1f77b4' },
    }];
    if (answer.extrapolated != null && withError.length) {
      data.push({ x: [steps[0].n_d, steps[steps.length - 1].n_d], y: [answer.extrapolated, answer.extrapolated], mode: 'lines', name: 'Richardson extrapolation', line: { dash: 'dot', color: '#7f7f7f' } });
    }
    chart(box, {
      data,
      layout: {
        xaxis: axis('n_d [nodes/m]', { type: 'log', tickvals: steps.map((s) => s.n_d) }),
        yaxis: axis(target.metric),
        legend: { x: 0.01, y: 0.99 },
      },
      filename: `slipfront-study-${(studyId || '').slice(0, 8)}-accuracy`, height: 280,
    }).catch((e) => box.append(h('p', { class: 'error', text: e.message })));
  }
  return section;
}
