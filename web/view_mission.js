// The mission trace view: regions, tasks and the robots' paths on the plane; a time slider; the
// events on a timeline with the supervisor's state after each; a robot that waits at a region
// whose entry the supervisor does not allow now is ringed and labelled as waiting.
import { el, svgEl, rgbCss, fixed, section } from './util.js';
import { Timeline } from './timeline.js';

export function planeFrame(points, widthPx = 560) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of points) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
  if (!Number.isFinite(x0)) { x0 = 0; y0 = 0; x1 = 10; y1 = 10; }
  const span = Math.max(x1 - x0, y1 - y0, 1e-9);
  const pad = 0.06 * span;
  const scale = widthPx / (span + 2 * pad);
  return { x: (x) => (x - x0 + pad) * scale, y: (y) => (y1 + pad - y) * scale, w: (x1 - x0 + 2 * pad) * scale, h: (y1 - y0 + 2 * pad) * scale, scale,
    inverse: (px, py) => [px / scale + x0 - pad, y1 + pad - py / scale] };
}

export function drawMissionStatic(svg, f, mission) {
  for (const g of mission.regions) {
    const w = (g.hi[0] - g.lo[0]) * f.scale, h = (g.hi[1] - g.lo[1]) * f.scale;
    svg.append(svgEl('rect', { class: 'region', x: f.x(g.lo[0]), y: f.y(g.hi[1]), width: w, height: h }, svgEl('title', { text: g.name })));
    // Small regions keep their name in the tooltip: a label would cover the task inside.
    if (w >= 60 && h >= 30) svg.append(svgEl('text', { class: 'region-label', x: f.x(g.lo[0]) + 3, y: f.y(g.hi[1]) + 12, text: g.name }));
  }
  for (const t of mission.tasks) {
    const x = f.x(t.at[0]), y = f.y(t.at[1]);
    svg.append(svgEl('path', { class: 'task', d: `M${x} ${y - 6}l6 6l-6 6l-6 -6z` }), svgEl('text', { class: 'task-label', x: x + 8, y: y - 6, text: t.name }));
  }
}

export function showMission(app, data) {
  const m = data.mission;
  const st = data.steps;
  const count = st.t.length;
  const points = [...m.regions.flatMap((g) => [g.lo, g.hi]), ...m.tasks.map((t) => t.at), ...m.robots.map((r) => r.start)];
  st.x.forEach((xs, r) => xs.forEach((x, k) => points.push([x, st.y[r][k]])));
  const f = planeFrame(points);
  const svg = svgEl('svg', { class: 'plane', width: f.w, height: f.h, viewBox: `0 0 ${f.w} ${f.h}` });
  const dynamic = svgEl('g', { class: 'dynamic' });
  drawMissionStatic(svg, f, m);
  svg.append(dynamic);
  const state = el('p', { class: 'info' });
  const rows = data.events.map((e, k) => el('tr', { 'data-index': k, class: e.kind === 'c' ? 'controllable' : 'uncontrollable' },
    el('td', { text: fixed(e.t) }), el('td', { text: e.event }), el('td', { text: e.robot }),
    el('td', { text: e.kind === 'c' ? 'controllable (task start)' : 'uncontrollable (region entry)' }), el('td', { text: e.state })));
  const draw = (index) => {
    dynamic.replaceChildren();
    const t = st.t[index];
    m.robots.forEach((r, q) => {
      const colour = rgbCss(data.palette.robots[q % data.palette.robots.length]);
      const pts = [];
      for (let k = 0; k <= index; ++k) pts.push(`${f.x(st.x[q][k]).toFixed(1)},${f.y(st.y[q][k]).toFixed(1)}`);
      dynamic.append(svgEl('polyline', { class: 'path', points: pts.join(' '), fill: 'none', stroke: colour, 'stroke-width': 2.5, 'stroke-opacity': 0.8 }));
      const x = f.x(st.x[q][index]), y = f.y(st.y[q][index]);
      const waiting = st.blocked[q][index];
      if (waiting) {
        dynamic.append(svgEl('circle', { class: 'waiting', cx: x, cy: y, r: 13, fill: 'none', stroke: '#f59e0b', 'stroke-width': 3, 'stroke-dasharray': '4 2' }),
          svgEl('text', { class: 'waiting-label', x: x + 14, y: y + 16, text: 'waiting' }));
      }
      dynamic.append(svgEl('circle', { class: 'robot', 'data-robot': q, cx: x, cy: y, r: 8, fill: colour, stroke: 'white', 'stroke-width': 1.5 }),
        svgEl('text', { class: 'robot-label', x: x + 10, y: y - 8, text: r.name }));
    });
    let last = -1;
    rows.forEach((row, k) => {
      const past = data.events[k].t <= t;
      row.classList.toggle('past', past);
      if (past) last = k;
      row.classList.remove('current');
    });
    if (last >= 0) rows[last].classList.add('current');
    const waiting = m.robots.filter((r, q) => st.blocked[q][index]).map((r) => r.name);
    state.textContent = `t = ${fixed(t)} s · supervisor state ${st.state[index]}` + (waiting.length ? ` · waiting: ${waiting.join(', ')}` : '');
    document.body.dataset.step = String(index);
  };
  const timeline = new Timeline(count, draw, (k) => `t = ${fixed(st.t[k])} s`);
  const h = data.header;
  app.append(
    el('h1', { text: `Mission trace: ${data.file}` }),
    el('p', { class: 'meta', text: `mission ${h.mission} · FSM ${m.fsm} · initial state ${m.initial_state} · body ${h.body} · dt ${h.dt} s · ${m.robots.length} robots, ${m.tasks.length} tasks, ${m.regions.length} regions · ${count} of ${data.steps_total} steps shown` }),
    el('div', { class: 'row' }, el('div', {}, svg, timeline.root, state),
      el('div', { class: 'side' }, el('div', { class: 'legend' }, el('span', { class: 'swatch region' }), ' region ', el('span', { class: 'swatch task' }), ' task ',
        el('span', { class: 'swatch waiting' }), ' waiting at a disabled region'))),
    section('Events (controllable: task starts the supervisor chose; uncontrollable: region entries), with the supervisor state after each',
      el('table', { class: 'events mission-events' }, el('thead', {}, el('tr', {}, ...['t (s)', 'event', 'robot', 'kind', 'state after'].map((x) => el('th', { text: x })))), el('tbody', {}, ...rows))));
  timeline.set(0);
  window.swarmcheckTimeline = timeline;
}
