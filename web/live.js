// The live page of `swarmcheck serve`: the scenario editor, and "Run", which starts the run in
// the server and draws its steps as they arrive (Server-Sent Events), with pause and speed.
// Closing the page closes the stream, and the server stops the run.
import { el, svgEl, section, fixed } from './util.js';
import { decodeField } from './field.js';
import { MapView } from './map.js';
import { ScenarioEditor } from './editor.js';

class LiveChart {
  constructor() {
    this.points = [];
    this.line = svgEl('polyline', { fill: 'none', stroke: '#2563eb', 'stroke-width': 2 });
    this.root = svgEl('svg', { class: 'chart', width: 560, height: 120, viewBox: '0 0 560 120' },
      svgEl('text', { x: 4, y: 14, class: 'label', text: 'eP (%) over steps' }), this.line);
  }
  add(step, eP) {
    this.points.push([step, eP]);
    const xMax = Math.max(1, step);
    this.line.setAttribute('points', this.points.map(([x, y]) => `${(30 + (x / xMax) * 520).toFixed(1)},${(110 - y).toFixed(1)}`).join(' '));
  }
}

export function showLive(app, data) {
  const status = el('p', { class: 'status live-status', text: 'Edit the scenario, then Run.' });
  const view = el('div', { class: 'live-map' });
  const info = el('p', { class: 'info' });
  let run = null;
  let source = null;
  const runButton = el('button', { class: 'run', text: 'Run', onclick: () => start() });
  const editor = new ScenarioEditor(data, (s, problem) => { runButton.disabled = Boolean(problem); });
  const pauseButton = el('button', { class: 'pause', text: 'Pause', disabled: true, onclick: () => control({ paused: pauseButton.textContent === 'Pause' }) });
  const speed = el('select', { class: 'speed', 'aria-label': 'steps per frame', onchange: () => control({ steps_per_frame: Number(speed.value) }) },
    ...[1, 10, 100, 1000].map((v) => el('option', { value: v, text: `${v} steps / frame`, selected: v === 100 })));

  async function control(body) {
    if (!run) return;
    const r = await fetch(`/api/runs/${run.id}/control`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body) });
    if (r.ok && body.paused !== undefined) pauseButton.textContent = body.paused ? 'Resume' : 'Pause';
  }

  async function start() {
    if (source) source.close();
    const r = await fetch(`/api/runs?steps_per_frame=${speed.value}`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: editor.json() });
    const text = await r.text();
    if (!r.ok) { status.className = 'status live-status error'; status.textContent = `HTTP ${r.status}: ${text}`; return; }
    run = JSON.parse(text);
    const s = run.scenario;
    const map = new MapView({ mapSize: s.map_size, cellSize: s.cell_size, palette: data.palette, obstacles: s.obstacles });
    const chart = new LiveChart();
    const paths = s.robots.map((p) => [p]);
    let field = null;
    let received = 0;
    view.replaceChildren(map.root, info, chart.root);
    pauseButton.disabled = false;
    pauseButton.textContent = 'Pause';
    status.className = 'status live-status ok';
    status.textContent = `running ${run.id}`;
    source = new EventSource(`/api/runs/${run.id}/events`);
    source.addEventListener('step', (e) => {
      const m = JSON.parse(e.data);
      received += 1;
      if (m.field) field = decodeField(m.field, s.map_size);
      m.robots.forEach((r, q) => { if (q < 64) paths[q].push([r[0], r[1]]); });
      map.drawCells(field, field ? field.max : 0, null);
      map.drawRobots(m.robots.map((r, q) => ({ x: r[0], y: r[1], theta: r[2], wx: r[5], wy: r[6], path: paths[q] })), s.mode === 'cosim');
      chart.add(m.step, m.eP);
      info.textContent = `step ${m.step} · sTime ${fixed(m.sTime, 1)} s · eP ${fixed(m.eP)} % · visited ${m.visited} / ${m.free_cells}`;
      document.body.dataset.liveStep = String(m.step);
      document.body.dataset.received = String(received);
    });
    source.addEventListener('done', (e) => {
      const m = JSON.parse(e.data);
      status.textContent = m.completed ? `completed at step ${m.completion_step} (sTime ${fixed(m.sTime, 1)} s): eP ${fixed(m.eP)} %` : `stopped after ${m.steps} steps: eP ${fixed(m.eP)} %`;
      document.body.dataset.done = m.completed ? 'completed' : 'stopped';
      pauseButton.disabled = true;
      source.close();
    });
    source.onerror = () => { if (document.body.dataset.done === undefined) { status.className = 'status live-status error'; status.textContent = 'the stream closed'; } source.close(); };
  }

  // Any trace or .fsm file: the server returns the page `swarmcheck view` would write.
  const viewStatus = el('p', { class: 'status view-status' });
  const picker = el('input', { type: 'file', class: 'view-file', 'aria-label': 'trace or .fsm file', onchange: async () => {
    const file = picker.files[0];
    if (!file) return;
    // API bodies are JSON (a page of another origin cannot send that without asking first); the
    // name is only shown in messages and the page's title.
    const r = await fetch('/api/view', { method: 'POST', headers: { 'Content-Type': 'application/json' },
                                         body: JSON.stringify({ name: file.name, text: await file.text() }) });
    const text = await r.text();
    if (!r.ok) { viewStatus.className = 'status view-status error'; viewStatus.textContent = `HTTP ${r.status}: ${text}`; return; }
    viewStatus.className = 'status view-status ok';
    viewStatus.textContent = `view of ${file.name} opened in a new tab`;
    window.open(URL.createObjectURL(new Blob([text], { type: 'text/html' })), '_blank');
  } });

  app.append(el('h1', { text: 'swarmcheck live' }),
    el('p', { class: 'meta', text: 'Runs happen in the server, one per page; each page sees its own.' }),
    editor.root,
    section('Run', el('div', { class: 'buttons' }, runButton, pauseButton, speed), status, view),
    section('View a trace or an .fsm file (run --trace, conform, prove --trace-dir)', picker, viewStatus));
  window.swarmcheckLive = { editor };
}
