// The scenario editor: click cells to place obstacles and robots, a form for every parameter
// (generated from the schema the binary derives from its own declarations, with the same domains),
// the CLI's message for the first problem, and the scenario JSON that `swarmcheck run` accepts.
import { el, section, downloadText } from './util.js';
import { MapView } from './map.js';
import { validateScenario } from './validate.js';

// Key order of scenario files (the Hana declaration's order).
export function orderedScenario(schema, s) {
  const out = {};
  for (const key of schema['x-order']) if (s[key] !== undefined) out[key] = s[key];
  return out;
}

// Indented JSON with short lists of numbers on one line ("[0.5, 0.5]").
export function compactJson(value) {
  return JSON.stringify(value, null, 2).replace(/\[\s*([-0-9.e+]+(?:,\s*[-0-9.e+]+)*)\s*\]/g, (m, body) => `[${body.split(/,\s*/).join(', ')}]`);
}

function inputFor(schema, path, value, onValue) {
  const d = schema;
  let input;
  if ((d.type === 'string' || d.type === 'x-body') && d.enum) {
    input = el('select', { name: path }, ...d.enum.map((v) => el('option', { value: v, text: v, selected: v === value })));
  } else {
    input = el('input', { name: path, type: 'text', inputmode: 'decimal', value: String(value) });
  }
  const read = () => {
    if (d.type === 'string' || d.type === 'x-body') return input.value;
    const t = input.value.trim();
    // A number that parses is a number; anything else stays text, which the validator reports
    // as the CLI would ("expected a number, got a string").
    return t !== '' && Number.isFinite(Number(t)) ? Number(t) : t;
  };
  // 'change' also fires when the field loses focus: act only on a new value (a rebuilt map
  // under a click in progress would swallow the click).
  let last = value;
  const update = () => {
    const v = read();
    if (v === last) return;
    last = v;
    onValue(v);
  };
  input.addEventListener('input', update);
  input.addEventListener('change', update);
  const hint = d['x-expected'] || (d.enum ? d.enum.join(' | ') : d.type === 'integer' ? 'an integer' : 'a number');
  return el('label', { class: 'field' }, el('span', { class: 'key', text: path }), input, el('span', { class: 'hint', text: hint }));
}

export class ScenarioEditor {
  // data: {schema, scenario, file, palette}; onChange(scenario, problem)
  constructor(data, onChange = () => {}) {
    this.schema = data.schema;
    this.palette = data.palette;
    this.s = JSON.parse(JSON.stringify(data.scenario));
    if (!this.s.obstacles) this.s.obstacles = [];
    this.onChange = onChange;
    this.tool = 'robot';
    this.mapHolder = el('div', { class: 'map-holder' });
    this.status = el('p', { class: 'status' });
    this.output = el('textarea', { class: 'export', rows: 14, readonly: true, spellcheck: 'false' });
    this.robotList = el('div', { class: 'robot-list' });
    const tools = el('div', { class: 'tools', role: 'radiogroup' },
      ...[['robot', 'robot'], ['obstacle', 'obstacle'], ['erase', 'erase']].map(([v, label]) =>
        el('label', {}, el('input', { type: 'radio', name: 'tool', value: v, checked: v === this.tool, onchange: () => { this.tool = v; } }), ` ${label}`)));
    const form = el('div', { class: 'form' });
    const props = this.schema.properties;
    for (const key of this.schema['x-order']) {
      if (key === 'robots' || key === 'obstacles') continue;
      if (props[key].type === 'object') {
        for (const sub of props[key]['x-order']) {
          form.append(inputFor(props[key].properties[sub], `${key}.${sub}`, this.s[key][sub], (v) => { this.s[key][sub] = v; this.changed(); }));
        }
      } else if (props[key].type === 'x-body') {
        // The body's kind is chosen here; an intocps body's parameters, if the file set any, are
        // kept (they are edited in the JSON: 45 of them would drown the form).
        const kindOf = (b) => (b === undefined ? props[key].enum[0] : typeof b === 'string' ? b : b.kind);
        form.append(inputFor(props[key], key, kindOf(this.s[key]), (v) => {
          this.s[key] = typeof this.s[key] !== 'object' || v !== 'intocps' ? v : { ...this.s[key], kind: v };
          this.changed();
        }));
      } else {
        form.append(inputFor(props[key], key, this.s[key], (v) => {
          this.s[key] = v;
          this.changed(key === 'map_size' || key === 'cell_size');
        }));
      }
    }
    this.root = el('div', { class: 'editor' },
      el('div', { class: 'row' },
        el('div', {}, el('p', { class: 'note', text: 'Click a cell: the chosen tool places a robot (at the cell centre) or an obstacle; click again, or erase, to remove.' }), tools, this.mapHolder, this.robotList),
        el('div', { class: 'side' }, section('Parameters', form), this.status,
          el('div', { class: 'buttons' }, el('button', { class: 'download', text: 'Download scenario.json', onclick: () => downloadText('scenario.json', this.json()) })),
          this.output)));
    this.buildMap();
    this.changed();
  }

  json() { return `${compactJson(orderedScenario(this.schema, this.s))}\n`; }

  buildMap() {
    const n = Number(this.s.map_size), cell = Number(this.s.cell_size);
    this.mapHolder.replaceChildren();
    this.map = null;
    if (!(Number.isInteger(n) && n >= 1 && n <= 256 && cell > 0)) {
      this.mapHolder.append(el('p', { class: 'note', text: 'The map is drawn for map_size 1..256 and cell_size > 0.' }));
      return;
    }
    this.map = new MapView({ mapSize: n, cellSize: cell, palette: this.palette, obstacles: [], sidePx: 480 });
    this.map.canvas.addEventListener('click', (e) => this.click(this.map.cellAt(e)));
    this.map.svg.addEventListener('click', (e) => this.click(this.map.cellAt(e)));
    this.mapHolder.append(this.map.root);
  }

  click(c) {
    if (!c) return;
    const cell = Number(this.s.cell_size);
    const [i, j] = c;
    const robotAt = this.s.robots.findIndex((p) => Math.floor(p[0] / cell) === i && Math.floor(p[1] / cell) === j);
    const obstacleAt = this.s.obstacles.findIndex((o) => o[0] === i && o[1] === j);
    if (robotAt >= 0) this.s.robots.splice(robotAt, 1);
    else if (obstacleAt >= 0) this.s.obstacles.splice(obstacleAt, 1);
    else if (this.tool === 'robot') this.s.robots.push([(i + 0.5) * cell, (j + 0.5) * cell]);
    else if (this.tool === 'obstacle') this.s.obstacles.push([i, j]);
    this.changed();
  }

  changed(rebuild = false) {
    if (rebuild) this.buildMap();
    if (this.map) {
      this.map.setObstacles(this.s.obstacles.filter((o) => o[0] < this.map.n && o[1] < this.map.n));
      this.map.drawCells(null, 0, new Uint8Array(this.map.n * this.map.n).fill(1));
      this.map.drawRobots(this.s.robots.map((p, k) => ({ x: p[0], y: p[1], label: String(k) })), false);
    }
    this.robotList.textContent = `${this.s.robots.length} robots: ${this.s.robots.map((p) => `[${p[0]}, ${p[1]}]`).join(' ')} · ${this.s.obstacles.length} obstacles`;
    const problem = validateScenario(this.schema, this.s);
    this.status.className = problem ? 'status error' : 'status ok';
    this.status.textContent = problem ? problem.message : 'valid: swarmcheck run accepts this scenario';
    this.output.value = this.json();
    document.body.dataset.valid = problem ? 'no' : 'yes';
    this.onChange(this.s, problem);
  }
}

export function showEditor(app, data) {
  app.append(el('h1', { text: `Scenario editor${data.file ? `: ${data.file}` : ''}` }),
    el('p', { class: 'meta', text: 'Export, then: swarmcheck run scenario.json' }));
  const editor = new ScenarioEditor(data);
  app.append(editor.root);
  window.swarmcheckEditor = editor;
  return editor;
}
