// The charts of the web view, drawn by Plotly (the npm package plotly.js-cartesian-dist-min,
// pinned in web/package.json and vendored by the build into /vendor/plotly/; docs/web.md says
// why this library). One look for every chart: the page's font, white plot area, zoom and pan,
// hover read-out, and two export buttons (PNG and SVG) always shown in the chart's tool bar.
import { h } from './dom.js';

export const PALETTE = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f', '#bcbd22'];
const FONT = { family: 'system-ui, -apple-system, "Segoe UI", Roboto, sans-serif', size: 12, color: '#1d2733' };
const GRID = '#e3e8ee';
const LIBRARY = '/vendor/plotly/plotly-cartesian.min.js';

let loading = null;

// window.Plotly, loading the vendored bundle on first use (the pages without charts never
// fetch it). Rejects with a message naming the set-up step when the build did not vendor it.
export function plotly() {
  if (window.Plotly) return Promise.resolve(window.Plotly);
  loading ??= (async () => {
    let vendored = false;
    try { vendored = (await (await fetch('/app/vendor.json', { cache: 'no-store' })).json()).plotly === true; } catch { vendored = false; }
    if (!vendored) throw new Error('The charting library (Plotly) was not vendored into this build: run scripts/setup.sh (npm ci in web/) and rebuild.');
    await new Promise((resolve, reject) => {
      const script = h('script', { src: LIBRARY });
      script.addEventListener('load', resolve);
      script.addEventListener('error', () => reject(new Error(`could not load ${LIBRARY}`)));
      document.head.append(script);
    });
    return window.Plotly;
  })();
  loading.catch(() => { loading = null; });
  return loading;
}

// An axis of the common look: title with its unit, grid, no zero line, log when asked.
export function axis(title, extra = {}) {
  return { title: { text: title, standoff: 8 }, gridcolor: GRID, zeroline: false, linecolor: '#8894a0', mirror: true, ticks: 'outside', exponentformat: 'e', ...extra };
}

function exportButton(Plotly, format, filename) {
  return {
    name: `download-${format}`,
    title: `Download plot as ${format.toUpperCase()}`,
    icon: format === 'png' ? Plotly.Icons.camera : Plotly.Icons.disk,
    click: (gd) => Plotly.downloadImage(gd, { format, filename, scale: format === 'png' ? 2 : 1 }),
  };
}

// Draws (or redraws) a chart into `box`. layout.margin is kept as given (no automatic growth)
// so that charts meant to share an x axis keep the same plot area. Returns the chart element.
export async function chart(box, { data, layout = {}, filename = 'slipfront-chart', height = 320 }) {
  const Plotly = await plotly();
  const full = {
    font: FONT, height, paper_bgcolor: '#fff', plot_bgcolor: '#fff',
    margin: { l: 80, r: 24, t: 30, b: 50, autoexpand: false },
    hoverlabel: { font: { family: FONT.family, size: 12 } },
    legend: { bgcolor: 'rgba(255,255,255,0.85)', bordercolor: '#c9d1da', borderwidth: 1 },
    uirevision: filename, // a redraw (another colour scale, more V(t) positions) keeps the zoom
    ...layout,
  };
  const config = {
    responsive: true, displaylogo: false, displayModeBar: true, scrollZoom: false,
    modeBarButtons: [['zoom2d', 'pan2d', 'zoomIn2d', 'zoomOut2d', 'resetScale2d'],
      [exportButton(Plotly, 'png', filename), exportButton(Plotly, 'svg', filename)]],
  };
  await Plotly.react(box, data, full, config);
  return box;
}

// Keeps the x axes of charts `a` and `b` on the same range: a zoom or pan in one is applied
// to the other (their plot areas are the same width: same margins, same container).
export function linkXAxes(a, b) {
  let busy = false;
  const follow = (from, to) => from.on('plotly_relayout', async (ev) => {
    const moved = Object.keys(ev).some((k) => k.startsWith('xaxis.range') || k === 'xaxis.autorange');
    if (busy || !moved) return;
    busy = true;
    try {
      await window.Plotly.relayout(to, { 'xaxis.range': [...from._fullLayout.xaxis.range] });
    } finally { busy = false; }
  });
  follow(a, b);
  follow(b, a);
}

// A message where a chart would be (no data, or no library).
export function chartMessage(box, text, cls = 'muted') {
  box.replaceChildren(h('p', { class: cls, text }));
}
