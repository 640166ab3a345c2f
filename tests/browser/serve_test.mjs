// `swarmcheck serve` with pages in Chromium: two pages run the default scenario at once and get
// their steps until completion (one pauses and resumes on the way); closing a page stops its run;
// bad requests get HTTP 4xx with the CLI's message; malformed HTTP does not bring it down.
//   node serve_test.mjs SWARMCHECK_BIN SOURCE_DIR
import { spawn } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import net from 'node:net';
import { join } from 'node:path';
import { check, cliArgs, done, launch, open, scratch, swarmcheck } from './lib.mjs';

const [bin] = cliArgs();
const dir = scratch('serve');
const expected = JSON.parse(swarmcheck(bin, ['run', '--json']).out);

const server = spawn(bin, ['serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
// Whatever way this script ends (a skip when Chromium or playwright-core is missing, a failed
// check), the server goes too: left running it holds ctest's output pipe until the timeout.
process.on('exit', () => { if (server.exitCode === null) server.kill('SIGKILL'); });
const port = await new Promise((resolve, reject) => {
  let text = '';
  server.stdout.on('data', (d) => { text += d; const m = /127\.0\.0\.1:(\d+)/.exec(text); if (m) resolve(Number(m[1])); });
  server.on('exit', (code) => reject(new Error(`serve exited with ${code}`)));
  setTimeout(() => reject(new Error('serve did not start')), 10000);
});
const base = `http://127.0.0.1:${port}`;
check(port > 0, `serve listens on 127.0.0.1:${port}`);
const exited = new Promise((resolve) => server.on('exit', (code, sig) => resolve({ code, sig })));

// API bodies are JSON, declared so (a page of another origin cannot send that without a preflight).
const post = (path, body, type = 'application/json') => fetch(`${base}${path}`, { method: 'POST', headers: { 'Content-Type': type }, body });

try {
  // ---- requests checked like files ----
  const badScenario = { map_size: 4, robots: [[0.5, 0.5], [0.7, 0.2]] };
  const file = join(dir, 'bad.json');
  writeFileSync(file, JSON.stringify(badScenario));
  const cli = swarmcheck(bin, ['run', file]).err.trim().replace(file, 'request body');
  let r = await post('/api/runs', JSON.stringify(badScenario));
  check(r.status === 400 && (await r.text()).trim() === cli, `a bad scenario: 400 with the CLI's message (${cli})`);
  r = await post('/api/validate', '{"map_size": 4, "robots": [[0.5, 0.5]], "rule": "greedy"}');
  check(r.status === 400 && (await r.text()).includes('request body: rule: expected one of thesis|deterministic|stochastic, got "greedy"'), 'validate: 400 with the message');
  r = await post('/api/validate', '{"map_size": 4, "robots": [[0.5, 0.5]]}');
  check(r.status === 200, 'validate: a good scenario is 200');
  r = await post('/api/runs', JSON.stringify({ map_size: 4096, robots: [[0.5, 0.5]] }));
  check(r.status === 400 && (await r.text()).includes('map_size: expected at most 512 for a live run'), 'a map too big for a live run: 400');
  r = await post('/api/runs', 'x'.repeat(2 << 20));
  check(r.status === 413, `a 2 MiB body: 413 (${r.status})`);
  r = await fetch(`${base}/api/runs/0123456789abcdef/events`);
  check(r.status === 404, 'an unknown run: 404');
  r = await post('/api/runs/0123456789abcdef/control', '{');
  check(r.status === 404, 'control of an unknown run: 404');
  r = await fetch(`${base}/no/such/page`);
  check(r.status === 404 && (await r.text()).includes('no route GET /no/such/page (the routes: GET /,'), 'an unknown path: 404 naming it and the routes');
  r = await fetch(`${base}/api/validate`, { method: 'PUT', headers: { 'Content-Type': 'application/json' }, body: '{}' });
  check(r.status === 405 && (await r.text()).includes('no route PUT /api/validate'), 'a method a route does not take: 405');
  r = await post('/api/validate', ' '.repeat(9000) + '{"map_size": 4, "robots": [[0.5, 0.5]]}', 'application/x-www-form-urlencoded');
  check(r.status === 415 && (await r.text()).includes("expected Content-Type: application/json, got application/x-www-form-urlencoded (curl: -H 'Content-Type: application/json'"),
        'a body sent as a form: 415 saying how to send it');
  r = await post('/api/runs', '{"map_size": 4, "robots": [[0.5, 0.5]]}', 'text/plain');
  check(r.status === 415, `a scenario sent as text/plain: 415 (${r.status})`);
  for (const garbage of ['\x00\x01\x02 garbage\r\n\r\n', 'GET /' + 'a'.repeat(70000) + ' HTTP/1.1\r\n\r\n', 'POST /api/runs HTTP/1.1\r\nContent-Length: 99999999999999999999\r\n\r\n{', 'GET / HTTP/1.1\r\nHost']) {
    await new Promise((resolve) => {
      const s = net.connect(port, '127.0.0.1', () => { s.end(garbage); });
      s.on('data', () => {}); s.on('close', resolve); s.on('error', resolve);
      setTimeout(() => { s.destroy(); resolve(); }, 3000);
    });
  }
  r = await fetch(`${base}/`);
  check(r.status === 200 && (await r.text()).includes('swarmcheck-data'), 'after malformed requests the server still serves the page');
  r = await post('/api/view', JSON.stringify({ name: 'p.jsonl', text: '{"format": "swarmcheck-trace", "system": "handshake", "robots": 1}\n{"step": 0}\n' }));
  check(r.status === 400 && (await r.text()).includes('p.jsonl:2: expected a step'), 'a malformed proof trace posted to /api/view: 400 naming the file and line');
  r = await post('/api/view', '{"format": "swarmcheck-trace"}\n');
  check(r.status === 400 && (await r.text()).includes('request body: format: unknown key (expected one of: name, text)'), '/api/view wants {name, text}');

  // ---- two pages run at once until completion ----
  const ctx = await launch();
  const pages = [await open(ctx, `${base}/`, { allowOrigin: base }), await open(ctx, `${base}/`, { allowOrigin: base })];
  // Page 0 at 1000 steps a frame; page 1 starts at 10 (so that it is surely still running when it
  // pauses), then speeds up to 1000 through the control request.
  await pages[0].selectOption('select.speed', '1000');
  await pages[1].selectOption('select.speed', '10');
  for (const p of pages) await p.click('button.run');
  await pages[1].waitForFunction(() => Number(document.body.dataset.received || 0) >= 3);
  await pages[1].click('button.pause');
  // A frame already on its way may still land (slowly, on a loaded machine): wait until the step
  // has held for 300 ms (at most 10 s), then it must hold.
  const step = () => pages[1].evaluate(() => document.body.dataset.liveStep);
  let paused = await step();
  for (let t = 0; t < 10000; t += 300) {
    await pages[1].waitForTimeout(300);
    const now = await step();
    if (now === paused) break;
    paused = now;
  }
  await pages[1].waitForTimeout(600);
  check(await pages[1].evaluate(() => document.body.dataset.liveStep) === paused, `paused: no step arrives (stays at ${paused})`);
  await pages[1].click('button.pause');
  const before = Number(await pages[1].evaluate(() => document.body.dataset.received));
  await pages[1].selectOption('select.speed', '1000');
  await pages[1].waitForFunction((n) => Number(document.body.dataset.received) >= n + 2, before);
  const a = Number(await pages[1].evaluate(() => document.body.dataset.liveStep));
  await pages[1].waitForFunction((n) => Number(document.body.dataset.received) >= n + 4, before);
  const b = Number(await pages[1].evaluate(() => document.body.dataset.liveStep));
  check(b - a >= 1000 || b === expected.completion_step, `after the speed change, frames are 1000 steps apart (${a} -> ${b} in two frames)`);
  for (const [k, p] of pages.entries()) {
    await p.waitForFunction(() => document.body.dataset.done !== undefined, null, { timeout: 60000 });
    const step = Number(await p.evaluate(() => document.body.dataset.liveStep));
    const received = Number(await p.evaluate(() => document.body.dataset.received));
    check(await p.evaluate(() => document.body.dataset.done) === 'completed' && step === expected.completion_step,
      `page ${k}: completed at step ${step} (run --json: ${expected.completion_step}) after ${received} frames`);
    check((await p.textContent('.live-status')).includes(`completed at step ${expected.completion_step}`), `page ${k} says so`);
  }
  await pages[0].screenshot({ path: join(dir, 'serve.png'), fullPage: true });
  for (const p of pages) check(p.problems.length === 0, `no errors (${p.problems.join('; ')})`);

  // ---- the viewer: a trace file picked in the page opens as a view ----
  const trace = join(dir, 'small.jsonl');
  swarmcheck(bin, ['run', '--mode', 'abstract', '--trace', trace, '--trace-field', '5']);
  const [popup] = await Promise.all([pages[0].waitForEvent('popup'), pages[0].setInputFiles('input.view-file', trace)]);
  await popup.waitForFunction(() => document.body.dataset.ready !== undefined);
  check(await popup.evaluate(() => document.body.dataset.ready) === 'yes' && (await popup.locator('circle.robot').count()) === 4,
    'a trace picked in the page opens as its view, four robots drawn');
  await popup.close();

  // ---- closing the page stops its run ----
  const p3 = await open(ctx, `${base}/`, { allowOrigin: base });
  await p3.selectOption('select.speed', '1');
  const [created] = await Promise.all([p3.waitForResponse((res) => res.url().includes('/api/runs?')), p3.click('button.run')]);
  const { id } = await created.json();
  await p3.waitForFunction(() => Number(document.body.dataset.received || 0) >= 2);
  await p3.close();
  let gone = false;
  for (let k = 0; k < 50 && !gone; ++k) {
    await new Promise((res) => setTimeout(res, 100));
    const c = await post(`/api/runs/${id}/control`, '{"paused": false}');
    gone = c.status === 404;
  }
  check(gone, 'the run stops when its page closes');
  await ctx.close();
} finally {
  server.kill('SIGTERM');
}
const { code } = await exited;
check(code === 0, `SIGTERM stops the server cleanly (exit ${code})`);
done();
