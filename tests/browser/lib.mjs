// Shared by the browser tests: Debian's Chromium through playwright-core (no browser download),
// the swarmcheck binary, a scratch folder, screenshots kept as artefacts.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

export const SKIP = 77;

// SWARMCHECK_BIN SOURCE_DIR from the command line, made absolute (tests run commands elsewhere).
export function cliArgs() {
  const [bin, source] = process.argv.slice(2);
  if (!bin || !source) {
    console.log('usage: node TEST.mjs SWARMCHECK_BIN SOURCE_DIR');
    process.exit(2);
  }
  return [resolve(bin), resolve(source)];
}   // ctest SKIP_RETURN_CODE

export const CHROMIUM = process.env.SWARMCHECK_CHROMIUM || '/usr/bin/chromium';

// The flags this machine needs (no background networking: the network is closed).
const FLAGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

export async function launch(extraArgs = []) {
  if (!existsSync(CHROMIUM)) {
    console.log(`SKIP: ${CHROMIUM} is not installed (scripts/install-deps installs Debian's chromium)`);
    process.exit(SKIP);
  }
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch {
    console.log('SKIP: playwright-core is not installed in tests/browser (scripts/install-deps runs npm ci there)');
    process.exit(SKIP);
  }
  const profile = mkdtempSync(join(tmpdir(), 'swarmcheck-chromium-'));
  return chromium.launchPersistentContext(profile, { executablePath: CHROMIUM, headless: true, args: [...FLAGS, ...extraArgs], viewport: { width: 1280, height: 900 } });
}

export function scratch(name) {
  const dir = join(process.env.SWARMCHECK_ARTEFACTS || join(tmpdir(), 'swarmcheck-browser'), name);
  mkdirSync(dir, { recursive: true });
  return dir;
}

export function swarmcheck(bin, args, opts = {}) {
  const r = spawnSync(bin, args, { encoding: 'utf8', ...opts });
  return { status: r.status, out: r.stdout, err: r.stderr };
}

// A page that fails on any console error, page error or request that leaves the file / server.
export async function open(context, url, { allowOrigin } = {}) {
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('request', (r) => {
    const u = r.url();
    if (!(u.startsWith('file:') || u.startsWith('data:') || u.startsWith('blob:') || (allowOrigin && u.startsWith(allowOrigin)))) problems.push(`network request: ${u}`);
  });
  await page.goto(url);
  await page.waitForFunction(() => document.body.dataset.ready !== undefined);
  const ready = await page.evaluate(() => document.body.dataset.ready);
  if (ready !== 'yes') throw new Error(`page did not start: ${await page.textContent('#app')}`);
  // A stray null or undefined appended as text is a page bug too.
  const stray = await page.evaluate(() => [...document.querySelectorAll('#app, #app *')].flatMap((e) => [...e.childNodes])
    .filter((n) => n.nodeType === 3 && /^(null|undefined)$/.test(n.textContent.trim())).length);
  if (stray) problems.push(`${stray} stray null/undefined text node(s)`);
  page.problems = problems;
  return page;
}

let failures = 0;
export function check(ok, what) {
  if (ok) console.log(`ok - ${what}`);
  else { console.log(`not ok - ${what}`); failures += 1; }
}
export function done() {
  console.log(failures ? `${failures} check(s) failed` : 'all checks passed');
  process.exit(failures ? 1 : 0);
}
