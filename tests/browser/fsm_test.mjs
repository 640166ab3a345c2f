// `swarmcheck view X.fsm` in Chromium: the graph laid out by dot, marked and initial states,
// controllable and uncontrollable edges styled apart, and the search box.
//   node fsm_test.mjs SWARMCHECK_BIN SOURCE_DIR
import { join } from 'node:path';
import { check, cliArgs, done, launch, open, scratch, swarmcheck } from './lib.mjs';

const [bin, source] = cliArgs();
const dir = scratch('fsm');
const fsm = join(source, 'scenarios', 'thesis', 'control2.fsm');
const html = join(dir, 'control2.html');
const r = swarmcheck(bin, ['view', 'scenarios/thesis/control2.fsm', '-o', html], { cwd: source });
if (r.status === 2 && r.err.includes('`dot`')) {
  console.log(`SKIP: ${r.err.trim()}`);
  process.exit(77);
}
check(r.status === 0, `view writes the automaton page (${r.err.trim()})`);
const check_json = JSON.parse(swarmcheck(bin, ['fsm', 'check', fsm, '--json']).out);
const exported = JSON.parse(swarmcheck(bin, ['fsm', 'export', fsm, '--to', 'json']).out);
const matching = exported.states.filter((s) => s.name.includes('s13')).length;

const ctx = await launch();
const page = await open(ctx, `file://${html}`);
const nodes = await page.locator('.graph g.node').count();
check(nodes === 72 + 1, `72 states drawn (and the initial arrow's point): ${nodes}`);
check(await page.locator('.graph g.node[id="state:s134:146:143"] ellipse').count() === 2, 'the marked state is a double circle');
check(await page.locator('.graph g.edge.c').count() > 0 && await page.locator('.graph g.edge.uc').count() > 0, 'controllable and uncontrollable edges both drawn, with their classes');
const dashed = await page.$$eval('.graph g.edge.uc path', (ps) => ps.every((p) => (p.getAttribute('stroke-dasharray') || '').length > 0));
check(dashed, 'uncontrollable edges are dashed');
check(await page.locator('.graph g.edge').count() === 99 + 1, 'all 99 transitions drawn (and the initial arrow)');
await page.fill('input.search', 's13');
const hits = await page.locator('.graph g.node.hit').count();
check(hits === matching && (await page.textContent('.count')).startsWith(`${matching} states`), `search "s13" highlights the ${matching} matching states (${hits})`);
check(await page.locator('table.states tbody tr:not([hidden])').count() === matching, 'and filters the state list');
await page.keyboard.press('Enter');
check(await page.locator('.graph g.node.focus').count() === 1, 'Enter focuses the next match');
check(check_json.states === 72, 'the page and `fsm check` agree on the state count');
await page.screenshot({ path: join(dir, 'view-fsm.png') });
check(page.problems.length === 0, `no errors or requests (${page.problems.join('; ')})`);
await ctx.close();

// Without dot: one clear message, status 2, no page.
const nodot = swarmcheck(bin, ['view', fsm, '-o', join(dir, 'nodot.html')], { env: { ...process.env, PATH: '/nonexistent' } });
check(nodot.status === 2 && nodot.err.includes('`dot` program is not installed'), `without dot: status 2 and says so (${nodot.err.trim()})`);
done();
