// The exploration trace view: map (heat map, obstacles, visited, robots with paths, waypoints and
// headings), a time slider, the eP curve and the handshake timeline.
import { el, section, fixed } from './util.js';
import { decodeField, fieldAt } from './field.js';
import { MapView } from './map.js';
import { Timeline } from './timeline.js';
import { LineChart, SignalChart } from './charts.js';

const PATH_ROBOTS_MAX = 64;   // paths of more robots would only cover the map

// The first record index at which each cell was stood on (from the robots' cells).
function firstVisits(data) {
  const n = data.scenario.map_size;
  const first = new Int32Array(n * n).fill(2147483647);
  const rec = data.records;
  rec.robots.forEach((r) => {
    for (let k = 0; k < rec.step.length; ++k) {
      const c = r.ci[k] * n + r.cj[k];
      if (first[c] > k) first[c] = k;
    }
  });
  return first;
}

export function robotsAt(data, index, withPaths) {
  const rec = data.records;
  const cell = data.scenario.cell_size;
  return rec.robots.map((r, q) => {
    const abstract = data.scenario.mode === 'abstract';
    const pose = abstract ? [(r.ci[index] + 0.5) * cell, (r.cj[index] + 0.5) * cell] : [r.x[index], r.y[index]];
    let path = null;
    if (withPaths && q < PATH_ROBOTS_MAX) {
      path = [];
      for (let k = 0; k <= index; ++k) path.push(abstract ? [(r.ci[k] + 0.5) * cell, (r.cj[k] + 0.5) * cell] : [r.x[k], r.y[k]]);
    }
    const robot = { x: pose[0], y: pose[1], theta: r.theta[index], wx: r.wx[index], wy: r.wy[index], path };
    // The intocps body's reported point is axle_offset ahead of the axle (forward (-sin, cos)).
    if (data.axle_offset !== undefined && !abstract) {
      const a = data.axle_offset, th = r.theta[index];
      robot.axle = [pose[0] + a * Math.sin(th), pose[1] - a * Math.cos(th)];
    }
    return robot;
  });
}

function robotTable(data, index) {
  const rec = data.records;
  const rows = rec.robots.slice(0, 50).map((r, q) => el('tr', {},
    el('td', { text: String(q) }),
    el('td', { text: `(${r.ci[index]}, ${r.cj[index]})` }),
    el('td', { text: `(${fixed(r.wx[index])}, ${fixed(r.wy[index])})` }),
    el('td', { text: `(${fixed(r.x[index], 3)}, ${fixed(r.y[index], 3)}, ${fixed(r.theta[index], 3)})` }),
    el('td', { text: `m${r.maneuver[index]} od=${r.onDest[index]}` })));
  return el('table', { class: 'robots' },
    el('thead', {}, el('tr', {}, ...['robot', 'cell', 'waypoint', 'pose x, y, θ', 'controller'].map((h) => el('th', { text: h })))),
    el('tbody', {}, ...rows));
}

export function showExploration(app, data, { title } = {}) {
  const s = data.scenario;
  const rec = data.records;
  const count = rec.step.length;
  const fields = data.fields.map((f) => decodeField(f, s.map_size));
  const vmax = data.fields.reduce((m, f) => Math.max(m, f.pheromone_max), 0);
  const first = fields.length ? null : firstVisits(data);
  const map = new MapView({ mapSize: s.map_size, cellSize: s.cell_size, palette: data.palette, obstacles: s.obstacles });
  const info = el('p', { class: 'info' });
  const table = el('div', { class: 'robot-table' });
  const cosim = s.mode === 'cosim';
  const eP = new LineChart({ xs: rec.step, ys: rec.eP, yMax: 100, label: 'eP (%)' });
  const signals = new SignalChart({
    xs: rec.step,
    title: 'handshake (high = 1)',
    rows: [{ label: 'Environment flag', values: rec.flag, colour: '#7c3aed' },
      { label: 'Environment onDest', values: rec.envOnDest, colour: '#7c3aed' },
      ...rec.robots.slice(0, 16).map((r, q) => ({ label: `controller ${q} onDest`, values: r.onDest }))],
  });
  const draw = (index) => {
    const step = rec.step[index];
    const f = fieldAt(fields, step);
    let visited = null;
    if (f < 0 && first) {
      visited = new Uint8Array(first.length);
      for (let k = 0; k < first.length; ++k) visited[k] = first[k] <= index ? 1 : 0;
    }
    map.drawCells(f >= 0 ? fields[f] : null, vmax, visited);
    map.drawRobots(robotsAt(data, index, true), cosim);
    eP.cursor(step);
    signals.cursor(step);
    info.textContent = `step ${step} · sTime ${fixed(rec.sTime[index], 1)} s · eP ${fixed(rec.eP[index])} % · visited ${rec.visited[index]} · planning steps ${rec.planning[index]}` +
      (fields.length ? ` · pheromone field of step ${f >= 0 ? fields[f].step : '–'}` : ' · this trace has no field records (run with --trace-field K)');
    table.replaceChildren(robotTable(data, index));
    document.body.dataset.step = String(step);
    document.body.dataset.fieldStep = f >= 0 ? String(fields[f].step) : '';
  };
  const timeline = new Timeline(count, draw, (k) => `step ${rec.step[k]}`);
  const h = data.header;
  app.append(
    el('h1', { text: title || `Exploration trace: ${data.file}` }),
    el('p', { class: 'meta', text: `map ${s.map_size}×${s.map_size} (cell ${s.cell_size} m), ${s.robots.length} robots, ${s.obstacles.length} obstacles · rule ${s.rule} · mode ${s.mode} · seed ${s.seed} · ${count} of ${data.records_total} records shown` + (h.field_every ? ` · field every ${h.field_every} steps` : '') }),
    el('div', { class: 'row' }, el('div', {}, map.root, timeline.root, info), el('div', { class: 'side' }, legend(), table)),
    section('Exploration percentage', eP.root),
    section('Handshake', signals.root));
  timeline.set(0);
  window.swarmcheckTimeline = timeline;
  return timeline;
}

export function legend() {
  return el('div', { class: 'legend' },
    el('span', { class: 'swatch heat' }), ' pheromone (√ scale, 0 → max of the trace) ',
    el('span', { class: 'swatch obstacle' }), ' obstacle ',
    el('span', { class: 'dot' }), ' unvisited ',
    el('span', { class: 'swatch waypoint' }), ' waypoint');
}
