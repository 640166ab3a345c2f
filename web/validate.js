// Scenario validation in the page, with the CLI's messages. The schema comes from the binary
// (views/schema.cpp: generated from the Hana declarations and spec/exploration/domains.hpp); this
// module interprets it the way spec/exploration/scenario.cpp and spec/util/hana_json.hpp read a
// file, in the same order, so the first problem and its words are the CLI's.
// tests/browser/validate_test.mjs runs both on the same files and compares the messages.

// std::to_chars(double): the shortest text that reads back, fixed or scientific, whichever is
// shorter (fixed on a tie), exponent with a sign and at least two digits.
export function toChars(v) {
  if (Number.isNaN(v)) return 'nan';
  if (!Number.isFinite(v)) return v < 0 ? '-inf' : 'inf';
  if (v === 0) return Object.is(v, -0) ? '-0' : '0';
  const sign = v < 0 ? '-' : '';
  const [mant, expText] = Math.abs(v).toExponential().split('e');
  const digits = mant.replace('.', '');
  const e = Number(expText);
  const n = digits.length;
  let fixed;
  if (e >= n - 1) fixed = digits + '0'.repeat(e - (n - 1));
  else if (e >= 0) fixed = digits.slice(0, e + 1) + '.' + digits.slice(e + 1);
  else fixed = '0.' + '0'.repeat(-e - 1) + digits;
  const sci = digits[0] + (n > 1 ? '.' + digits.slice(1) : '') + 'e' + (e < 0 ? '-' : '+') +
    String(Math.abs(e)).padStart(2, '0');
  return sign + (fixed.length <= sci.length ? fixed : sci);
}

class ScenarioError extends Error {
  constructor(path, expected) {
    super(`${path}: ${expected}`);
    this.path = path;
  }
}

function typeName(v) {
  if (typeof v === 'number') return Number.isInteger(v) ? 'an integer' : 'a number';
  if (typeof v === 'string') return 'a string';
  if (typeof v === 'boolean') return 'a boolean';
  if (Array.isArray(v)) return 'a list';
  if (v !== null && typeof v === 'object') return 'an object';
  return 'null';
}

const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const joinKey = (path, key) => (path ? `${path}.${key}` : key);

// hana_json.hpp's from_json, driven by the schema: returns the typed value.
function read(schema, v, path, current) {
  switch (schema.type) {
    case 'object': {
      if (!isObject(v)) throw new ScenarioError(path || '(top level)', `expected an object, got ${typeName(v)}`);
      const out = { ...current };
      for (const [key, value] of Object.entries(v)) {
        const sub = schema.properties[key];
        if (!sub) {
          throw new ScenarioError(joinKey(path, key), `unknown key (expected one of: ${schema['x-order'].join(', ')})`);
        }
        out[key] = read(sub, value, joinKey(path, key), current ? current[key] : undefined);
      }
      return out;
    }
    case 'string': {
      const choices = schema.enum.join('|');
      if (typeof v !== 'string') throw new ScenarioError(path, `expected one of ${choices}, got ${typeName(v)}`);
      if (!schema.enum.includes(v)) throw new ScenarioError(path, `expected one of ${choices}, got "${v}"`);
      return v;
    }
    case 'integer': {
      if (typeof v !== 'number' || !Number.isInteger(v)) throw new ScenarioError(path, `expected an integer, got ${typeName(v)}`);
      const [lo, hi] = schema['x-range'];
      if (schema['x-integer'] === 'unsigned' && v < 0) throw new ScenarioError(path, `expected a non-negative integer, got ${v}`);
      if (v < lo || v > hi) throw new ScenarioError(path, `integer ${v} is out of range`);
      return v;
    }
    case 'number':
      if (typeof v !== 'number') throw new ScenarioError(path, `expected a number, got ${typeName(v)}`);
      return v;
    case 'boolean':
      if (typeof v !== 'boolean') throw new ScenarioError(path, `expected a boolean, got ${typeName(v)}`);
      return v;
    case 'array': {
      const n = schema.minItems;
      if (n !== undefined && (!Array.isArray(v) || v.length !== n)) {
        throw new ScenarioError(path, `expected a list of ${n} values, got ${Array.isArray(v) ? `${v.length} values` : typeName(v)}`);
      }
      if (!Array.isArray(v)) throw new ScenarioError(path, `expected a list, got ${typeName(v)}`);
      return v.map((x, i) => read(schema.items, x, `${path}[${i}]`, undefined));
    }
    case 'x-body':
      return readBody(schema, v, path);
    default:
      throw new Error(`schema type ${schema.type} not handled`);
  }
}

// JsonCodec<BodyChoice>::read of spec/exploration/body_choice.cpp: a body's name, or
// {"kind": name, "parameters": {Body_Block name: number}}; returns {kind, parameters} with every
// parameter (the defaults where the file names none).
function readBody(schema, v, path) {
  const kinds = schema.enum.join('|');
  const body = { kind: undefined, parameters: { ...schema['x-parameter-defaults'] } };
  const kindOf = (k, at) => {
    if (typeof k !== 'string') throw new ScenarioError(at, `expected one of ${kinds}, got ${typeName(k)}`);
    if (!schema.enum.includes(k)) throw new ScenarioError(at, `expected one of ${kinds}, got "${k}"`);
    return k;
  };
  if (typeof v === 'string') return { ...body, kind: kindOf(v, path) };
  if (!isObject(v)) throw new ScenarioError(path, `expected ${kinds} or {"kind": ..., "parameters": {...}}, got ${typeName(v)}`);
  for (const key of Object.keys(v)) {
    if (key !== 'kind' && key !== 'parameters') throw new ScenarioError(joinKey(path, key), 'unknown key (expected one of: kind, parameters)');
  }
  if (!('kind' in v)) throw new ScenarioError(joinKey(path, 'kind'), `missing (${kinds})`);
  body.kind = kindOf(v.kind, joinKey(path, 'kind'));
  if ('parameters' in v) {
    const at = joinKey(path, 'parameters');
    const ps = v.parameters;
    if (!isObject(ps)) throw new ScenarioError(at, `expected an object of the Body_Block's parameters, got ${typeName(ps)}`);
    if (body.kind !== 'intocps' && Object.keys(ps).length > 0) {
      throw new ScenarioError(at, `the ${body.kind} body has no parameters (the intocps body has)`);
    }
    for (const [name, value] of Object.entries(ps)) {
      const key = joinKey(at, name);
      if (!schema['x-parameters'].includes(name)) {
        throw new ScenarioError(key, 'unknown parameter of the intocps body (its names are the Body_Block FMU\'s: ' +
          'battery_initial_energy, axle_offset, mu, servo_left.resistance.r, ...; `swarmcheck run --help` lists them all)');
      }
      if (name === 'initial_position[0]' || name === 'initial_position[1]') {
        throw new ScenarioError(key, 'a robot\'s position is its entry in robots; only initial_position[2] (the heading) is a body parameter');
      }
      if (typeof value !== 'number') throw new ScenarioError(key, `expected a number, got ${typeName(value)}`);
      body.parameters[name] = value;
    }
  }
  return body;
}

// validate_intocps_params of body_choice.cpp, in its order and with its arithmetic (the mass,
// inertia and ground friction of intocps_body_model, operation for operation).
function checkBody(schema, s) {
  // Absent (the default) or a name: the default parameters.
  const body = s.body === undefined || typeof s.body === 'string'
    ? { parameters: schema.properties.body['x-parameter-defaults'] } : s.body;
  const p = body.parameters;
  const need = (ok, name, expected, got) => {
    if (!ok) throw new ScenarioError(`body.parameters.${name}`, `expected ${expected}, got ${toChars(got)}`);
  };
  for (const name of schema.properties.body['x-parameters']) need(Number.isFinite(p[name]), name, 'a finite number', p[name]);
  need(p.battery_initial_energy >= 0, 'battery_initial_energy', 'a number >= 0 (J)', p.battery_initial_energy);
  need(p.axle_half_width > 0, 'axle_half_width', 'a number > 0 (m)', p.axle_half_width);
  need(p.wheel_radius > 0, 'wheel_radius', 'a number > 0 (m)', p.wheel_radius);
  need(p['body.R.bladePosition'] > 0, 'body.R.bladePosition', 'a number > 0 (m)', p['body.R.bladePosition']);
  need(p.robot_mass_without_battery + p.battery_mass > 0, 'robot_mass_without_battery',
    'a mass that with battery_mass is > 0 (kg)', p.robot_mass_without_battery);
  need(p['encoder_left.Quantisize.lsb'] > 0, 'encoder_left.Quantisize.lsb', 'a number > 0', p['encoder_left.Quantisize.lsb']);
  need(p['encoder_right.Quantisize.lsb'] > 0, 'encoder_right.Quantisize.lsb', 'a number > 0', p['encoder_right.Quantisize.lsb']);
  need(p.mu >= 0, 'mu', 'a number >= 0', p.mu);
  need(p['wheel_left.R.r'] >= 0, 'wheel_left.R.r', 'a number >= 0 (N s/m)', p['wheel_left.R.r']);
  need(p['wheel_right.R2.r'] >= 0, 'wheel_right.R2.r', 'a number >= 0 (N s/m)', p['wheel_right.R2.r']);
  const bm = p.battery_mass;
  const inertia = p.robot_inertia_without_battery +
    ((((bm / 12) * (p.battery_length * p.battery_length)) * (p.battery_width * p.battery_width)) +
     bm * (p.battery_cog_offset * p.battery_cog_offset));
  need(inertia > 0, 'robot_inertia_without_battery', 'an inertia that with the battery\'s is > 0', p.robot_inertia_without_battery);
  const blade = p['body.R.bladePosition'];
  const friction = ((p.robot_mass_without_battery * p.axle_offset) / blade) * p.mu + ((bm * p.battery_cog_offset) / blade) * p.mu;
  const mass = 1.0 / (1.0 / (p.robot_mass_without_battery + bm));
  const fastest = 0.5e-3;   // RK4 at 1 ms is stable for time constants above half a step
  need(friction === 0 || mass / friction >= fastest, 'mu', 'a ground friction whose time constant mass / c is at least 0.5 ms (RK4 at 1 ms)', p.mu);
  const damping = Math.max(p['wheel_left.R.r'], p['wheel_right.R2.r']);
  need(damping === 0 || mass / (2 * damping) >= fastest, 'wheel_left.R.r', 'a lateral damping d with mass / (2 d) at least 0.5 ms (RK4 at 1 ms)', damping);
  for (const side of ['servo_left', 'servo_right']) {
    const q = (n) => p[`${side}.${n}`];
    need(q('inductance.i') > 0, `${side}.inductance.i`, 'a number > 0 (H)', q('inductance.i'));
    need(q('internal_controller.tauI') > 0, `${side}.internal_controller.tauI`, 'a number > 0 (s)', q('internal_controller.tauI'));
    const r = q('resistance.r');
    need(r >= 0 && (r === 0 || q('inductance.i') / r >= fastest), `${side}.resistance.r`, 'a resistance >= 0 with inductance / resistance at least 0.5 ms', r);
    need(q('voltage_limit.minimum') <= q('voltage_limit.maximum'), `${side}.voltage_limit.minimum`, 'at most voltage_limit.maximum', q('voltage_limit.minimum'));
  }
}

function domains(schema, prefix = '') {
  const out = [];
  for (const [key, sub] of Object.entries(schema.properties || {})) {
    const path = joinKey(prefix, key);
    if (sub['x-expected']) out.push({ path, ...sub });
    if (sub.type === 'object') out.push(...domains(sub, path));
  }
  return out;
}

function valueAt(s, path) {
  return path.split('.').reduce((o, k) => o[k], s);
}

function inDomain(d, v) {
  if (d.type !== 'integer' && !Number.isFinite(v)) return false;
  if (d.exclusiveMinimum !== undefined && !(v > d.exclusiveMinimum)) return false;
  if (d.minimum !== undefined && !(v >= d.minimum)) return false;
  if (d.maximum !== undefined && !(v <= d.maximum)) return false;
  return true;
}

function checkStage(schema, s, stage) {
  for (const d of domains(schema)) {
    if (d['x-stage'] !== stage) continue;
    const v = valueAt(s, d.path);
    if (!inDomain(d, v)) throw new ScenarioError(d.path, `expected ${d['x-expected']}, got ${toChars(v)}`);
  }
}

const cellText = (c) => `[${c[0]}, ${c[1]}]`;

// validate_cells of scenario.cpp.
function checkCells(schema, s) {
  const obstacleAt = new Map();
  s.obstacles.forEach((c, k) => {
    const path = `obstacles[${k}]`;
    if (!(c[0] >= 0 && c[1] >= 0 && c[0] < s.map_size && c[1] < s.map_size)) {
      throw new ScenarioError(path, `expected a cell [i, j] with 0 <= i, j < ${s.map_size}, got ${cellText(c)}`);
    }
    const key = cellText(c);
    if (obstacleAt.has(key)) throw new ScenarioError(path, `cell ${key} repeats obstacles[${obstacleAt.get(key)}]`);
    obstacleAt.set(key, k);
  });
  if (s.robots.length === 0) throw new ScenarioError('robots', 'expected at least one robot');
  if (s.robots.length > schema['x-limits'].robots_max) {
    throw new ScenarioError('robots', `expected at most 2^30 robots, got ${s.robots.length}`);
  }
  const side = s.map_size * s.cell_size;
  const robotAt = new Map();
  s.robots.forEach((p, k) => {
    const path = `robots[${k}]`;
    if (!(Number.isFinite(p[0]) && Number.isFinite(p[1]) && p[0] >= 0 && p[1] >= 0 && p[0] < side && p[1] < side)) {
      throw new ScenarioError(path, `expected a position [x, y] in metres with 0 <= x, y < ${toChars(side)}, got [${toChars(p[0])}, ${toChars(p[1])}]`);
    }
    const c = [Math.floor(p[0] / s.cell_size), Math.floor(p[1] / s.cell_size)];
    const key = cellText(c);
    if (obstacleAt.has(key)) throw new ScenarioError(path, `starts in cell ${key}, which is obstacles[${obstacleAt.get(key)}]`);
    if (robotAt.has(key)) throw new ScenarioError(path, `starts in cell ${key}, already taken by robots[${robotAt.get(key)}]`);
    robotAt.set(key, k);
  });
}

function checkCrossParams(schema, s) {
  const { cosim_step_max_s: stepMax, deposit_max: depositMax } = schema['x-limits'];
  const p = s.params;
  if (s.mode === 'cosim' && !(p.step_size <= stepMax)) {
    throw new ScenarioError('params.step_size', `expected at most ${toChars(stepMax)} s in cosim mode (the controllers are checked to arrive on both bodies up to this step), got ${toChars(p.step_size)}`);
  }
  const deposit = p.max_ph + p.epsilon / p.a2;
  if (!(deposit <= depositMax)) {
    throw new ScenarioError('params', `expected max_ph + epsilon / a2 at most ${toChars(depositMax)} (pheromone must stay finite), got ${toChars(deposit)}`);
  }
}

// null when `doc` (parsed JSON) is a valid scenario, else {path, message} with the CLI's message
// (what follows "swarmcheck: error: FILE: ").
export function validateScenario(schema, doc) {
  try {
    if (!isObject(doc)) throw new ScenarioError('(top level)', 'expected an object');
    for (const key of schema.required) {
      if (!(key in doc)) throw new ScenarioError(key, schema['x-required-messages'][key]);
    }
    const start = { ...schema['x-default'] };
    const s = read(schema, doc, '', start);
    checkStage(schema, s, 'before_cells');
    checkCells(schema, s);
    checkStage(schema, s, 'params');
    checkCrossParams(schema, s);
    checkStage(schema, s, 'after_params');
    checkBody(schema, s);
    return null;
  } catch (e) {
    if (e instanceof ScenarioError) return { path: e.path, message: e.message };
    throw e;
  }
}
