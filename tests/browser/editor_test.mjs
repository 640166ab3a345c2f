// The editors in Chromium, round trip: place robots and obstacles in `swarmcheck edit`'s page,
// export, and `swarmcheck run` accepts the file and reports the same robots; a bad value shows
// the CLI's own message. The mission editor's export is accepted by `mission plan` unchanged.
//   node editor_test.mjs SWARMCHECK_BIN SOURCE_DIR
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { check, cliArgs, done, launch, open, scratch, swarmcheck } from './lib.mjs';

const [bin, source] = cliArgs();
const dir = scratch('editor');
const html = join(dir, 'editor.html');
check(swarmcheck(bin, ['edit', '-o', html]).status === 0, 'edit writes the scenario editor');
const ctx = await launch();
const page = await open(ctx, `file://${html}`);

async function clickCell(i, j) {
  const box = await page.locator('.editor canvas.cells').boundingBox();
  const n = Number(await page.inputValue('input[name="map_size"]'));
  const px = box.width / n;
  await page.mouse.click(box.x + (i + 0.5) * px, box.y + (n - 0.5 - j) * px);
}

// A smaller map: the default's corner robots fall outside, with the CLI's message.
await page.fill('input[name="map_size"]', '6');
const status = (await page.textContent('p.status')).trim();
const bad = join(dir, 'bad.json');
writeFileSync(bad, await page.inputValue('textarea.export'));
const cli = swarmcheck(bin, ['run', bad]);
check(cli.status === 2, 'run refuses what the page calls invalid');
check(cli.err.trim() === `swarmcheck: error: ${bad}: ${status}`, `same message: page "${status}", CLI "${cli.err.trim()}"`);

// Remove the robots outside, keep robot 0 at (0.5, 0.5); place three robots and two obstacles.
await page.evaluate(() => { const e = window.swarmcheckEditor; e.s.robots = e.s.robots.filter((p) => p[0] < 6 && p[1] < 6); e.s.obstacles = []; e.changed(true); });
await clickCell(5, 5);
await clickCell(2, 4);
await page.check('input[name="tool"][value="obstacle"]');
await clickCell(3, 3);
await clickCell(1, 2);
await clickCell(4, 1);
await clickCell(4, 1);   // a second click removes it
await page.fill('input[name="params.s_range"]', '2');
check((await page.textContent('p.status')).includes('valid'), 'the page says the scenario is valid');
check(await page.locator('.editor circle.robot').count() === 3, 'three robots on the map');

const [download] = await Promise.all([page.waitForEvent('download'), page.click('button.download')]);
const file = join(dir, 'scenario.json');
await download.saveAs(file);
const exported = JSON.parse(readFileSync(file, 'utf8'));
check(JSON.stringify(exported.robots) === JSON.stringify([[0.5, 0.5], [5.5, 5.5], [2.5, 4.5]]), `robots exported where they were placed: ${JSON.stringify(exported.robots)}`);
check(JSON.stringify(exported.obstacles) === JSON.stringify([[3, 3], [1, 2]]), `obstacles exported: ${JSON.stringify(exported.obstacles)}`);
const trace = join(dir, 'run.jsonl');
const run = swarmcheck(bin, ['run', file, '--json', '--trace', trace, '--trace-every', '1000']);
check(run.status === 0, `swarmcheck run accepts the exported file (${run.err.trim()})`);
const summary = JSON.parse(run.out);
check(summary.robots === 3 && summary.map_size === 6 && summary.completed, `run reports 3 robots on map 6 and completes: ${run.out.trim()}`);
const header = JSON.parse(readFileSync(trace, 'utf8').split('\n')[0]);
check(JSON.stringify(header.scenario.robots) === JSON.stringify(exported.robots) && header.scenario.params.s_range === 2, 'the run\'s scenario has the same robots and s_range');
await page.screenshot({ path: join(dir, 'editor.png'), fullPage: true });
check(page.problems.length === 0, `no errors or requests (${page.problems.join('; ')})`);
await page.close();

// Mission editor: open the thesis mission, add a robot and a region, export, `mission plan` reads it.
const mission = join(source, 'scenarios', 'thesis', 'thesis-mission.json');
const mhtml = join(dir, 'mission-editor.html');
check(swarmcheck(bin, ['edit', 'scenarios/thesis/thesis-mission.json', '-o', mhtml], { cwd: source }).status === 0, 'edit writes the mission editor');
const mpage = await open(ctx, `file://${mhtml}`);
check((await mpage.textContent('p.status')).includes('structure valid'), 'the thesis mission is valid in the editor');
const plane = await mpage.locator('svg.plane').boundingBox();
await mpage.check('input[name="mtool"][value="region"]');
await mpage.mouse.move(plane.x + 40, plane.y + 40);
await mpage.mouse.down();
await mpage.mouse.move(plane.x + 90, plane.y + 80);
await mpage.mouse.up();
check(await mpage.locator('svg.plane rect.region').count() === 9, 'a dragged region is added');
await mpage.check('input[name="mtool"][value="task"]');
await mpage.mouse.click(plane.x + 300, plane.y + 300);
const out = await mpage.inputValue('textarea.export');
const mfile = join(source, 'scenarios', 'thesis', `.editor-test-${process.pid}.json`);   // beside control2.fsm
writeFileSync(mfile, out);
const plan = swarmcheck(bin, ['mission', 'plan', mfile, '--json']);
(await import('node:fs')).unlinkSync(mfile);
check(plan.status === 0, `mission plan accepts the exported mission (${plan.err.trim()})`);
const reference = swarmcheck(bin, ['mission', 'plan', mission, '--json']);
check(JSON.parse(plan.out).makespan === JSON.parse(reference.out).makespan, 'and plans the same makespan (a new region and task mean nothing to the FSM)');
// Unmap an event: the page gives the CLI's message.
await mpage.selectOption('select[aria-label="a1s robot"]', '');
const mstatus = (await mpage.textContent('p.status')).trim();
check(mstatus === 'events: event "a1s" of control2.fsm has no meaning (expected "a1s": {"robot": ..., "task": ...} or {"robot": ..., "region": ...})', `unmapped event: ${mstatus}`);
await mpage.screenshot({ path: join(dir, 'mission-editor.png') });
check(mpage.problems.length === 0, `mission editor: no errors (${mpage.problems.join('; ')})`);
await ctx.close();
done();
