// The conformance counterexample view: the reference model and the library side by side at the
// first step where they differ (both re-run by `swarmcheck view` from the trace's header), the
// differing field highlighted, then the model's run up to there.
import { el, section } from './util.js';
import { decodeField } from './field.js';
import { MapView } from './map.js';
import { showExploration } from './view_exploration.js';

// Leaves of a record with the paths of spec/util/hana_diff.hpp ("robots[2].cell").
function flatten(value, path, out) {
  const leafArray = Array.isArray(value) && value.every((x) => typeof x !== 'object') && value.length <= 3;
  if (value !== null && typeof value === 'object' && !leafArray) {
    if (Array.isArray(value)) value.forEach((x, i) => flatten(x, `${path}[${i}]`, out));
    else for (const [k, v] of Object.entries(value)) flatten(v, path ? `${path}.${k}` : k, out);
  } else {
    out.set(path, JSON.stringify(value));
  }
  return out;
}

function sideMap(data, side, name, highlight) {
  const s = data.scenario;
  const map = new MapView({ mapSize: s.map_size, cellSize: s.cell_size, palette: data.palette, obstacles: s.obstacles, sidePx: 380 });
  const field = decodeField(side.field, s.map_size);
  map.highlight = highlight;
  const vmax = Math.max(data.sides.model.field.pheromone_max, data.sides.impl.field.pheromone_max);
  map.drawCells(field, vmax, null);
  const robots = side.record.robots.map((r) => ({
    x: s.mode === 'abstract' ? (r.cell[0] + 0.5) * s.cell_size : r.body.x_m,
    y: s.mode === 'abstract' ? (r.cell[1] + 0.5) * s.cell_size : r.body.y_m,
    theta: r.body.theta_rad, wx: r.waypoint[0], wy: r.waypoint[1] }));
  map.drawRobots(robots, s.mode === 'cosim');
  return el('div', { class: `side-map ${name}` }, el('h3', { text: `${name} at step ${side.record.step}` }), map.root);
}

export function showCounterexample(app, data) {
  const d = data.divergence;
  const s = data.scenario;
  const model = flatten(data.sides.model.record, '', new Map());
  const impl = flatten(data.sides.impl.record, '', new Map());
  // Cells that differ between the two grids, and the cell a "cells[i][j]" divergence names.
  const n = s.map_size;
  const fm = decodeField(data.sides.model.field, n), fi = decodeField(data.sides.impl.field, n);
  const highlight = new Set();
  for (let k = 0; k < n * n; ++k) if (fm.pheromone[k] !== fi.pheromone[k] || fm.visited[k] !== fi.visited[k]) highlight.add(k);
  const named = /^cells\[(\d+)\]\[(\d+)\]/.exec(d.path || '');
  if (named) highlight.add(Number(named[1]) * n + Number(named[2]));
  const differs = (path) => model.get(path) !== impl.get(path);
  const first = (path) => path === d.path || path.startsWith(`${d.path}.`) || path.startsWith(`${d.path}[`);
  const rows = [...model.keys()].map((path) => el('tr', { class: [differs(path) ? 'diff' : '', first(path) ? 'first-diff' : ''].join(' ').trim() || null, 'data-path': path },
    el('td', { text: path }), el('td', { text: model.get(path) }), el('td', { text: impl.get(path) ?? '—' })));
  const same = data.sides.model.record.pheromone_digest === data.sides.impl.record.pheromone_digest && model.size === impl.size && rows.every((r) => !r.classList.contains('diff'));
  app.append(...[
    el('h1', { text: `Conformance counterexample: ${data.file}` }),
    el('p', { class: 'divergence', text: d.text || `step ${d.step}: ${d.path}` }),
    same ? el('p', { class: 'note', text: 'Re-run now, the model and the library agree at this step: the difference this trace recorded is gone (fixed, or a different build).' }) : null,
    el('p', { class: 'meta', text: `map ${n}×${n}, ${s.robots.length} robots, rule ${s.rule}, mode ${s.mode}, seed ${s.seed}; cells outlined in red differ between the two grids (${highlight.size})` }),
    el('div', { class: 'row' }, sideMap(data, data.sides.model, 'model', highlight), sideMap(data, data.sides.impl, 'impl', highlight)),
    section('The step record, field by field (differences highlighted; the first in bold)',
      el('table', { class: 'diff-table' }, el('thead', {}, el('tr', {}, el('th', { text: 'field' }), el('th', { text: 'model' }), el('th', { text: 'impl' }))), el('tbody', {}, ...rows)))].filter(Boolean));
  const firstRow = app.querySelector('tr.first-diff');
  if (firstRow) firstRow.scrollIntoView({ block: 'center' });
  const below = el('section', { class: 'panel' });
  app.append(below);
  showExploration(below, data, { title: 'The model’s run up to the divergence (the trace)' });
}
