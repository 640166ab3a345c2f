// The mission editor (thesis B's user-data GUI): draw regions (drag), place tasks and robots
// (click), give every FSM event its meaning (a robot starting a task, or entering a region), and
// export the mission JSON that `swarmcheck mission plan` reads. The page checks the structure with
// the CLI's messages; `mission plan` (or `serve`) checks the rest against the FSM.
import { el, svgEl, rgbCss, section, downloadText } from './util.js';
import { compactJson } from './editor.js';
import { planeFrame, drawMissionStatic } from './view_mission.js';

const round = (v) => Math.round(v * 2) / 2;

function regionOf(decl) {
  const [a, b] = decl.corners;
  return { name: decl.name, lo: [Math.min(a[0], b[0]), Math.min(a[1], b[1])], hi: [Math.max(a[0], b[0]), Math.max(a[1], b[1])] };
}

// The checks of spec/mission/mission_check.cpp that need no FSM semantics, in its order.
export function checkMissionStructure(m, fsm) {
  const fail = (path, text) => ({ path, message: `${path}: ${text}` });
  if (m.robots.length === 0) return fail('robots', 'expected at least one robot');
  for (const list of ['robots', 'tasks', 'regions']) {
    for (let i = 0; i < m[list].length; ++i) {
      for (let k = 0; k < i; ++k) {
        if (m[list][i].name === m[list][k].name) return fail(`${list}[${i}].name`, `"${m[list][i].name}" is already the name of ${list}[${k}]`);
      }
    }
  }
  for (let i = 0; i < m.regions.length; ++i) {
    const [a, b] = m.regions[i].corners;
    const zero = a[0] === b[0] ? 'width' : a[1] === b[1] ? 'height' : null;
    if (zero) return fail(`regions[${i}].corners`, `the corners [${a[0]}, ${a[1]}] and [${b[0]}, ${b[1]}] give a rectangle of zero ${zero} (expected two opposite corners with different x and different y)`);
  }
  if (!fsm.states.includes(m.initial_state)) return fail('initial_state', `state "${m.initial_state}" is not in ${m.fsm}`);
  if (m.marked_states.length === 0) return fail('marked_states', 'expected at least one marked state');
  for (let i = 0; i < m.marked_states.length; ++i) {
    if (!fsm.states.includes(m.marked_states[i])) return fail(`marked_states[${i}]`, `state "${m.marked_states[i]}" is not in ${m.fsm}`);
  }
  for (const ev of fsm.events) {
    if (!m.events[ev.name]) return fail('events', `event "${ev.name}" of ${m.fsm} has no meaning (expected "${ev.name}": {"robot": ..., "task": ...} or {"robot": ..., "region": ...})`);
  }
  return null;
}

export function showMissionEditor(app, data) {
  const fsm = data.fsm;
  const m = JSON.parse(JSON.stringify(data.mission));
  for (const key of ['robots', 'tasks', 'regions', 'marked_states']) m[key] = m[key] || [];
  m.events = m.events || {};
  const points = [...m.robots.map((r) => r.start), ...m.tasks.map((t) => t.at), ...m.regions.flatMap((g) => g.corners)];
  if (points.length < 2) points.push([-10, -10], [10, 10]);
  const f = planeFrame(points, 520);
  const svg = svgEl('svg', { class: 'plane editing', width: f.w, height: f.h, viewBox: `0 0 ${f.w} ${f.h}` });
  const status = el('p', { class: 'status' });
  const output = el('textarea', { class: 'export', rows: 14, readonly: true, spellcheck: 'false' });
  const lists = el('div', { class: 'lists' });
  const eventsTable = el('tbody');
  let tool = 'robot';
  let drag = null;

  const world = (e) => {
    const box = svg.getBoundingClientRect();
    const [x, y] = f.inverse(e.clientX - box.left, e.clientY - box.top);
    return [round(x), round(y)];
  };
  const fresh = (list, prefix) => { let k = list.length + 1; while (list.some((x) => x.name === `${prefix}${k}`)) ++k; return `${prefix}${k}`; };

  function redraw() {
    svg.replaceChildren(svgEl('rect', { x: 0, y: 0, width: f.w, height: f.h, fill: '#fafafa' }));
    drawMissionStatic(svg, f, { regions: m.regions.map(regionOf), tasks: m.tasks });
    m.robots.forEach((r, q) => {
      svg.append(svgEl('circle', { class: 'robot', cx: f.x(r.start[0]), cy: f.y(r.start[1]), r: 8, fill: rgbCss(data.palette.robots[q % data.palette.robots.length]) }),
        svgEl('text', { class: 'robot-label', x: f.x(r.start[0]) + 10, y: f.y(r.start[1]) - 8, text: r.name }));
    });
    if (drag && drag.to) {
      svg.append(svgEl('rect', { class: 'region drawing', x: f.x(Math.min(drag.from[0], drag.to[0])), y: f.y(Math.max(drag.from[1], drag.to[1])),
        width: Math.abs(drag.to[0] - drag.from[0]) * f.scale, height: Math.abs(drag.to[1] - drag.from[1]) * f.scale }));
    }
  }

  function nameList(title, list, coords) {
    return section(title, ...list.map((item, k) => el('div', { class: 'item' },
      el('input', { value: item.name, 'aria-label': `${title} ${k} name`, onchange: (e) => { item.name = e.target.value; changed(); } }),
      el('span', { text: coords(item) }),
      el('button', { text: '✕', title: 'remove', onclick: () => { list.splice(k, 1); changed(); } }))));
  }

  function eventRows() {
    eventsTable.replaceChildren(...fsm.events.map((ev) => {
      const meaning = m.events[ev.name] || {};
      const targets = ev.controllable ? m.tasks : m.regions;
      const key = ev.controllable ? 'task' : 'region';
      const robot = el('select', { 'aria-label': `${ev.name} robot` }, el('option', { value: '', text: '—' }),
        ...m.robots.map((r) => el('option', { value: r.name, text: r.name, selected: meaning.robot === r.name })));
      const target = el('select', { 'aria-label': `${ev.name} ${key}` }, el('option', { value: '', text: '—' }),
        ...targets.map((t) => el('option', { value: t.name, text: t.name, selected: meaning[key] === t.name })));
      const update = () => {
        if (robot.value && target.value) m.events[ev.name] = { robot: robot.value, [key]: target.value };
        else delete m.events[ev.name];
        changed(false);
      };
      robot.addEventListener('change', update);
      target.addEventListener('change', update);
      return el('tr', { class: ev.controllable ? 'controllable' : 'uncontrollable' }, el('td', { text: ev.name }),
        el('td', { text: ev.controllable ? 'c: a robot starts a task' : 'uc: a robot enters a region' }), el('td', {}, robot), el('td', {}, target));
    }));
  }

  function exported() {
    const out = {};
    if (m.about !== undefined) out.about = m.about;
    Object.assign(out, { fsm: m.fsm, initial_state: m.initial_state, marked_states: m.marked_states, robots: m.robots, tasks: m.tasks, regions: m.regions });
    const events = {};
    for (const ev of fsm.events) if (m.events[ev.name]) events[ev.name] = m.events[ev.name];
    for (const [k, v] of Object.entries(m.events)) if (!events[k]) events[k] = v;
    out.events = events;
    return `${compactJson(out)}\n`;
  }

  function changed(rebuildEvents = true) {
    redraw();
    lists.replaceChildren(
      nameList('Robots', m.robots, (r) => ` start [${r.start[0]}, ${r.start[1]}]`),
      nameList('Tasks', m.tasks, (t) => ` at [${t.at[0]}, ${t.at[1]}]`),
      nameList('Regions', m.regions, (g) => ` corners [${g.corners[0]}] [${g.corners[1]}]`));
    if (rebuildEvents) eventRows();
    const problem = checkMissionStructure(m, fsm);
    status.className = problem ? 'status error' : 'status ok';
    status.textContent = problem ? problem.message : 'structure valid: check it with swarmcheck mission plan';
    output.value = exported();
    document.body.dataset.valid = problem ? 'no' : 'yes';
  }

  svg.addEventListener('mousedown', (e) => {
    const p = world(e);
    if (tool === 'region') { drag = { from: p, to: null }; return; }
    if (tool === 'robot') m.robots.push({ name: fresh(m.robots, 'R'), start: p });
    else if (tool === 'task') m.tasks.push({ name: fresh(m.tasks, 'T'), at: p });
    else if (tool === 'erase') {
      const near = (q) => Math.hypot(q[0] - p[0], q[1] - p[1]) < 12 / f.scale;
      const r = m.robots.findIndex((x) => near(x.start));
      const t = m.tasks.findIndex((x) => near(x.at));
      const g = m.regions.findIndex((x) => { const b = regionOf(x); return p[0] > b.lo[0] && p[0] < b.hi[0] && p[1] > b.lo[1] && p[1] < b.hi[1]; });
      if (r >= 0) m.robots.splice(r, 1); else if (t >= 0) m.tasks.splice(t, 1); else if (g >= 0) m.regions.splice(g, 1);
    }
    changed();
  });
  svg.addEventListener('mousemove', (e) => { if (drag) { drag.to = world(e); redraw(); } });
  svg.addEventListener('mouseup', () => {
    if (drag && drag.to && drag.to[0] !== drag.from[0] && drag.to[1] !== drag.from[1]) {
      m.regions.push({ name: fresh(m.regions, 'reg'), corners: [drag.from, drag.to] });
    }
    drag = null;
    changed();
  });

  const initial = el('select', { 'aria-label': 'initial state', onchange: (e) => { m.initial_state = e.target.value; changed(false); } },
    ...fsm.states.map((q) => el('option', { value: q, text: q, selected: q === m.initial_state })));
  const marked = el('select', { multiple: true, size: 5, 'aria-label': 'marked states', onchange: (e) => { m.marked_states = [...e.target.selectedOptions].map((o) => o.value); changed(false); } },
    ...fsm.states.map((q) => el('option', { value: q, text: q, selected: m.marked_states.includes(q) })));
  const tools = el('div', { class: 'tools' }, ...['robot', 'task', 'region', 'erase'].map((v) =>
    el('label', {}, el('input', { type: 'radio', name: 'mtool', value: v, checked: v === tool, onchange: () => { tool = v; } }), ` ${v}`)));
  app.append(
    el('h1', { text: `Mission editor${data.file ? `: ${data.file}` : ''}` }),
    el('p', { class: 'meta', text: `FSM ${m.fsm}: ${fsm.states.length} states, ${fsm.events.length} events. Click to place robots and tasks, drag to draw a region (metres, snapped to 0.5 m).` }),
    el('div', { class: 'row' }, el('div', {}, tools, svg, lists),
      el('div', { class: 'side' },
        section('Supervisor', el('label', { class: 'field' }, el('span', { class: 'key', text: 'initial_state' }), initial),
          el('label', { class: 'field' }, el('span', { class: 'key', text: 'marked_states' }), marked)),
        status,
        el('div', { class: 'buttons' }, el('button', { class: 'download', text: 'Download mission.json', onclick: () => downloadText('mission.json', exported()) })),
        output)),
    section('What each FSM event means', el('table', { class: 'events' }, el('thead', {}, el('tr', {}, ...['event', 'kind', 'robot', 'task / region'].map((x) => el('th', { text: x })))), eventsTable)));
  changed();
  window.swarmcheckMission = m;
}
