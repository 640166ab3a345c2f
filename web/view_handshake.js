// The proof counterexample view: a handshake trace (`swarmcheck prove --trace-dir`), step by
// step; the step that breaks the property is highlighted.
import { el } from './util.js';

const yes = (b) => (b ? '✔' : '·');

export function showHandshake(app, data) {
  const h = data.header;
  const robots = h.robots;
  const head = ['step', 'flag', 'onDest', 'plans'];
  for (let r = 0; r < robots; ++r) head.push(`c${r} onDest`, `c${r} arrival`, `c${r} accepts`, `c${r} reached`);
  head.push('violated');
  const rows = data.steps.map((s) => el('tr', { class: s.violated ? 'violated' : null },
    el('td', { text: String(s.step) }), el('td', { text: String(s.flag) }), el('td', { text: String(s.onDestinationOutput) }),
    el('td', { text: yes(s.plan) }),
    ...s.controllers.flatMap((c) => [el('td', { text: String(c.onDestinationOutput) }), el('td', { text: yes(c.arrival) }),
      el('td', { text: yes(c.accepted) }), el('td', { text: yes(c.reached) })]),
    el('td', { text: s.violated || '' })));
  const broken = data.steps.find((s) => s.violated);
  app.append(...[
    el('h1', { text: `Proof counterexample: ${h.obligation}` }),
    el('p', { class: 'meta', text: `${data.file} · ${robots} robots · master ${h.master} · controller ${h.controller || 'spec'} · ${data.steps.length} steps` }),
    broken ? el('p', { class: 'divergence', text: `step ${broken.step} breaks: ${broken.violated}` }) : null,
    el('p', { class: 'note', text: 'Each row is the state at the start of a master step: the Environment\'s flag and onDestinationOutput, whether it plans in the step, and each controller\'s onDestinationOutput, arrival input, whether it accepts a waypoint and whether its robot stands on its issued waypoint.' }),
    el('table', { class: 'handshake' }, el('thead', {}, el('tr', {}, ...head.map((t) => el('th', { text: t })))), el('tbody', {}, ...rows))].filter(Boolean));
}
