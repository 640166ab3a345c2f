// `swarmcheck serve` against the pages of other sites, in Chromium (issue 38). A page served from
// another origin (here http://127.0.0.1:OTHER, a port of its own) tries what any page the user
// visits could: text/plain POSTs that need no preflight (fetch in no-cors mode, a form posted into
// a hidden frame), a JSON POST (which needs a preflight), reading the schema, framing the live
// page. None may start a run or read anything. A DNS-rebinding page (a name of the attacker's that
// resolves to 127.0.0.1: Chromium maps rebind.test there) gets 403 for every page.
//   node cross_origin_test.mjs SWARMCHECK_BIN SOURCE_DIR
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import http from 'node:http';
import { join } from 'node:path';
import { check, cliArgs, done, launch } from './lib.mjs';

const [bin, source] = cliArgs();
const runsMax = 8;
const server = spawn(bin, ['serve', '--port', '0', '--runs-max', String(runsMax), '--runs-per-client', String(runsMax)],
  { stdio: ['ignore', 'pipe', 'inherit'] });
process.on('exit', () => { if (server.exitCode === null) server.kill('SIGKILL'); });
const port = await new Promise((resolve, reject) => {
  let text = '';
  server.stdout.on('data', (d) => { text += d; const m = /127\.0\.0\.1:(\d+)/.exec(text); if (m) resolve(Number(m[1])); });
  server.on('exit', (code) => reject(new Error(`serve exited with ${code}`)));
  setTimeout(() => reject(new Error('serve did not start')), 10000);
});
const base = `http://127.0.0.1:${port}`;
const exited = new Promise((resolve) => server.on('exit', (code) => resolve(code)));
const scenario = readFileSync(join(source, 'scenarios/default.json'), 'utf8');

// The attacker's page, on another port of the same machine: another origin.
const attackerPage = `<!DOCTYPE html><html><body>
<iframe name="sink" style="display:none"></iframe>
<form id="f" method="POST" action="${base}/api/runs" enctype="text/plain" target="sink">
  <input name='${scenario.replace(/'/g, '&#39;').replace(/\n/g, ' ')}' value="">
</form>
<iframe id="frame" src="${base}/"></iframe>
<script>
(async () => {
  const results = {};
  const body = ${JSON.stringify(scenario)};
  // 1. Ten plain-text POSTs in no-cors mode: sent without a preflight. The answer would be opaque;
  // the server's Cross-Origin-Resource-Policy makes Chromium withhold even that (a rejection).
  let attempted = 0;
  for (let k = 0; k < 10; ++k) {
    attempted += 1;
    try { await fetch('${base}/api/runs', { method: 'POST', mode: 'no-cors', headers: { 'Content-Type': 'text/plain' }, body }); } catch (e) {}
  }
  results.noCorsAttempted = attempted;
  // 2. A form posted into a hidden frame (a navigation: Chromium sends it, with our Origin).
  document.getElementById('f').submit();
  await new Promise((r) => setTimeout(r, 1500));
  // 3. A JSON POST needs a CORS preflight, which the server does not grant: the fetch fails.
  try {
    const r = await fetch('${base}/api/runs', { method: 'POST', headers: { 'Content-Type': 'application/json' }, body });
    results.json = 'answered ' + r.status;
  } catch (e) { results.json = 'blocked'; }
  // 4. Reading the schema (a GET): blocked by the same-origin policy (and refused by the server).
  try { const r = await fetch('${base}/api/schema'); results.schema = 'read ' + (await r.text()).length; } catch (e) { results.schema = 'blocked'; }
  document.body.dataset.results = JSON.stringify(results);
})();
</script></body></html>`;
const attacker = http.createServer((req, res) => { res.writeHead(200, { 'Content-Type': 'text/html' }); res.end(attackerPage); });
await new Promise((resolve) => attacker.listen(0, '127.0.0.1', resolve));
const attackerBase = `http://127.0.0.1:${attacker.address().port}`;

try {
  const ctx = await launch(['--host-resolver-rules=MAP rebind.test 127.0.0.1']);
  const page = await ctx.newPage();
  // The POSTs to /api/runs that left the browser, and why Chromium failed those it failed.
  const posts = [];
  page.on('request', (r) => { if (r.method() === 'POST' && r.url() === `${base}/api/runs`) posts.push(r); });
  await page.goto(`${attackerBase}/`);
  await page.waitForFunction(() => document.body.dataset.results !== undefined, null, { timeout: 60000 });
  const results = JSON.parse(await page.evaluate(() => document.body.dataset.results));
  // Ten no-cors POSTs and the form's went out; a failed one failed on the server's answer
  // (ERR_BLOCKED_BY_RESPONSE: CORP same-origin), not before it was sent.
  // (The JSON POST is the twelfth: it fails at its preflight, below.)
  const plain = posts.filter((r) => (r.headers()['content-type'] || '').startsWith('text/plain'));
  const failures = plain.map((r) => (r.failure() ? r.failure().errorText : 'answered'));
  check(results.noCorsAttempted === 10 && plain.length === 11 && failures.every((f) => f === 'answered' || f.includes('ERR_BLOCKED_BY_RESPONSE')),
    `the other site's page sent its ten text/plain POSTs and its form (${plain.length}: ${[...new Set(failures)].join(', ')})`);
  check(results.json === 'blocked', `its JSON POST was stopped at the preflight (${results.json})`);
  check(results.schema === 'blocked', `it could not read the schema (${results.schema})`);
  // The live page framed by the other site's page, and the form's answer in its hidden frame:
  // frame-ancestors 'none' makes Chromium show neither (an error page in their place).
  const framed = page.frames().filter((f) => f !== page.mainFrame()).map((f) => f.url());
  check(framed.length === 2 && framed.every((u) => !u.startsWith(base)), `no frame shows a page of the server (${framed.join(', ')})`);

  // None of it started a run: every slot is still free for the user's own requests.
  let started = 0;
  for (let k = 0; k < runsMax; ++k) {
    const r = await fetch(`${base}/api/runs`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: scenario });
    if (r.status === 201) started += 1;
  }
  check(started === runsMax, `after the attack all ${runsMax} run slots were free (${started} started)`);

  // A DNS-rebinding page: its own name, our address. Every page is refused, so it reads nothing.
  const rebind = await ctx.newPage();
  const response = await rebind.goto(`http://rebind.test:${port}/`);
  const text = await rebind.textContent('body');
  check(response.status() === 403 && text.includes('is not this server'), `a page under another name gets 403 (${response.status()})`);
  check(!(await rebind.content()).includes('swarmcheck-data'), 'and no part of the live page');
  const headers = response.headers();
  check(headers['x-content-type-options'] === 'nosniff' && headers['content-security-policy'] === "frame-ancestors 'none'",
    'the refusal carries nosniff and frame-ancestors none');
  await ctx.close();
} finally {
  attacker.close();
  server.kill('SIGTERM');
}
check((await exited) === 0, 'SIGTERM stops the server cleanly');
done();
