// The editor's validation (web/validate.js, driven by the schema the binary generates) against
// the CLI: for each scenario below, `swarmcheck run FILE` must fail with exactly the message the
// page shows, or both must accept it. No browser needed: node imports the page's module.
//   node validate_test.mjs SWARMCHECK_BIN SOURCE_DIR
import { writeFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import { check, cliArgs, done, scratch, swarmcheck } from './lib.mjs';

const [bin, source] = cliArgs();
const { validateScenario, toChars } = await import(pathToFileURL(resolve(source, 'web', 'validate.js')).href);
const dir = scratch('validate');

// The schema as the pages get it.
const schemaRun = swarmcheck(bin, ['edit', '-o', join(dir, 'editor.html')]);
check(schemaRun.status === 0, 'edit writes the editor');
const html = (await import('node:fs')).readFileSync(join(dir, 'editor.html'), 'utf8');
const dataText = /<script type="application\/json" id="swarmcheck-data">(.*?)<\/script>/s.exec(html)[1];
const schema = JSON.parse(dataText).schema;

const base = { map_size: 4, robots: [[0.5, 0.5]] };
const cases = [
  base,
  { ...base, mode: 'abstract', obstacles: [[1, 1], [2, 3]] },
  [1],
  { robots: [[0.5, 0.5]] },
  { map_size: 4 },
  { ...base, colour: 'red' },
  { ...base, map_size: 'big' },
  { ...base, map_size: 0 },
  { ...base, map_size: 70000 },
  { ...base, map_size: 3000000000 },
  { ...base, cell_size: -2 },
  { ...base, cell_size: 0 },
  { ...base, robots: [[4.5, 0.5]] },
  { ...base, robots: [[0.5]] },
  { ...base, robots: 'none' },
  { ...base, robots: [] },
  { ...base, robots: [[0.5, 0.5], [0.7, 0.2]] },
  { ...base, robots: [[1.5, 1.5]], obstacles: [[1, 1]] },
  { ...base, obstacles: [[4, 0]] },
  { ...base, obstacles: [[1, 1], [1, 1]] },
  { ...base, obstacles: [[-1, 0]] },
  { ...base, params: { a1: -1 } },
  { ...base, params: { a2: 0 } },
  { ...base, params: { s_range: 0 } },
  { ...base, params: { s_range: 2000000 } },
  { ...base, params: { epsilon: -0.5 } },
  { ...base, params: { ertu: -1e-7 } },
  { ...base, params: { eta: 0 } },
  { ...base, params: { step_size: 0.3 } },
  { ...base, params: { step_size: 0.3 }, mode: 'abstract' },
  { ...base, params: { max_ph: 2e12 } },
  { ...base, params: { epsilon: 1e9, a2: 1e-4 } },
  { ...base, params: { speed: 1 } },
  { ...base, params: { a1: 'x' } },
  { ...base, params: 3 },
  { ...base, rule: 'greedy' },
  { ...base, rule: 3 },
  { ...base, mode: 'cosim', seed: -1 },
  { ...base, seed: 1.5 },
  { ...base, max_steps: 2147483648 },
  { ...base, max_steps: -1 },
  { ...base, cell_size: 0.25, robots: [[0.1, 0.1], [0.2, 0.2]] },
  { ...base, cell_size: 2.5, robots: [[9.99, 0.5]] },
  { ...base, params: { step_size: 0.6 }, mode: 'cosim' },
  { ...base, controller: 'thesis', body: 'intocps', rule: 'thesis' },
  { ...base, controller: 'pid' },
  { ...base, body: 'rigid' },
  { ...base, body: 3 },
  { ...base, body: { parameters: {} } },
  { ...base, body: { kind: 'intocps', mass: 2 } },
  { ...base, body: { kind: 'kinematic', parameters: { mu: 1 } } },
  { ...base, body: { kind: 'intocps', parameters: [] } },
  { ...base, body: { kind: 'intocps', parameters: { 'initial_position[2]': 0.5, mu: 0.2 } } },
  { ...base, body: { kind: 'intocps', parameters: { colour: 1 } } },
  { ...base, body: { kind: 'intocps', parameters: { 'initial_position[0]': 1 } } },
  { ...base, body: { kind: 'intocps', parameters: { mu: 'high' } } },
  { ...base, body: { kind: 'intocps', parameters: { mu: -1 } } },
  { ...base, body: { kind: 'intocps', parameters: { mu: 1e6 } } },
  { ...base, body: { kind: 'intocps', parameters: { battery_initial_energy: -1 } } },
  { ...base, body: { kind: 'intocps', parameters: { battery_mass: 0.05, robot_inertia_without_battery: -1 } } },
  { ...base, body: { kind: 'intocps', parameters: { 'wheel_right.R2.r': 1e9 } } },
  { ...base, body: { kind: 'intocps', parameters: { 'servo_right.resistance.r': 1e9 } } },
  { ...base, body: { kind: 'intocps', parameters: { 'servo_left.voltage_limit.minimum': 99 } } },
  { ...base, body: { kind: 'intocps', parameters: { 'servo_left.internal_controller.tauI': 0 } } },
];

cases.forEach((doc, k) => {
  const file = join(dir, `case${k}.json`);
  writeFileSync(file, JSON.stringify(doc));
  const cli = swarmcheck(bin, ['run', file, '--steps', '0']);
  const page = validateScenario(schema, doc);
  // --steps 0: a valid scenario stops at once, not completed (status 1); bad input is status 2.
  const expected = cli.status !== 2 ? null : cli.err.trim().replace(`swarmcheck: error: ${file}: `, '');
  const got = page ? page.message : null;
  check(expected === got, `case ${k} ${JSON.stringify(doc).slice(0, 70)}: CLI ${JSON.stringify(expected)} page ${JSON.stringify(got)}`);
});

// std::to_chars's shortest form, which the messages print numbers with.
for (const [v, text] of [[1e12, '1e+12'], [2147483648, '2147483648'], [0.2, '0.2'], [-1, '-1'], [1e-7, '1e-07'], [123456.5, '123456.5'], [1e21, '1e+21'], [0.001, '0.001'], [1.5e-5, '1.5e-05']]) {
  check(toChars(v) === text, `toChars(${v}) = ${text} (got ${toChars(v)})`);
}
done();
