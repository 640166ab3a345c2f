// The automaton view: dot's layout (marked states doubled, the initial state entered by an arrow,
// controllable events solid and blue with a bar at the tail, uncontrollable dashed and red), a
// search box that highlights the states whose names contain the text, and the state list.
import { el } from './util.js';

export function showFsm(app, data) {
  const graph = el('div', { class: 'graph' });
  if (data.svg) graph.innerHTML = data.svg;
  else graph.append(el('p', { class: 'note', text: data.no_layout }));
  const nodes = new Map();
  for (const g of graph.querySelectorAll('g.node')) {
    const id = g.getAttribute('id') || '';
    if (id.startsWith('state:')) nodes.set(id.slice(6), g);
  }
  const initial = data.states.length ? data.states[0].name : null;
  const controllable = new Map(data.events.map((e) => [e.name, e.controllable]));
  const rows = data.states.map((s) => el('tr', { 'data-state': s.name, onclick: () => focus(s.name) },
    el('td', { text: s.name }), el('td', { text: (s.name === initial ? 'initial ' : '') + (s.marked ? 'marked' : '') }),
    el('td', {}, ...s.out.map(([e, t]) => el('span', { class: controllable.get(e) ? 'ev c' : 'ev uc', text: `${e} → ${t}` })))));
  const count = el('span', { class: 'count' });
  let hits = [];
  let at = 0;
  const search = el('input', { type: 'search', class: 'search', placeholder: 'search states…', 'aria-label': 'search states',
    oninput: () => filter(search.value), onkeydown: (e) => { if (e.key === 'Enter' && hits.length) { at = (at + 1) % hits.length; focus(hits[at]); } } });
  function filter(text) {
    const q = text.trim().toLowerCase();
    hits = q ? data.states.filter((s) => s.name.toLowerCase().includes(q)).map((s) => s.name) : [];
    at = 0;
    for (const [name, g] of nodes) g.classList.toggle('hit', hits.includes(name));
    rows.forEach((r) => { r.hidden = q !== '' && !r.dataset.state.toLowerCase().includes(q); });
    count.textContent = q ? `${hits.length} state${hits.length === 1 ? '' : 's'} match` : '';
    if (hits.length) focus(hits[0], false);
  }
  function focus(name, select = true) {
    for (const g of nodes.values()) g.classList.remove('focus');
    const g = nodes.get(name);
    if (g) { g.classList.add('focus'); g.scrollIntoView({ block: 'center', inline: 'center' }); }
    if (select) rows.forEach((r) => r.classList.toggle('focus', r.dataset.state === name));
  }
  const c = data.events.filter((e) => e.controllable).length;
  app.append(
    el('h1', { text: `Automaton: ${data.file}` }),
    el('p', { class: 'meta', text: `${data.states.length} states (${data.states.filter((s) => s.marked).length} marked), ${data.transitions} transitions, ${data.events.length} events (${c} controllable, ${data.events.length - c} uncontrollable); initial state ${initial ?? '— (empty automaton)'}` }),
    el('div', { class: 'legend' }, el('span', { class: 'ev c', text: 'controllable ⊣→' }), ' ', el('span', { class: 'ev uc', text: 'uncontrollable ⇢' }), ' · double circle: marked · arrow from nowhere: initial'),
    el('div', { class: 'toolbar' }, search, count, el('button', { class: 'fit', text: 'fit to width', onclick: () => graph.classList.toggle('fit') })),
    graph,
    el('details', { open: data.svg ? null : true }, el('summary', { text: `States (${data.states.length})` + (data.listed_transitions < data.transitions ? `, first ${data.listed_transitions} transitions listed` : '') }),
      el('table', { class: 'states' }, el('thead', {}, el('tr', {}, el('th', { text: 'state' }), el('th', { text: '' }), el('th', { text: 'transitions' }))), el('tbody', {}, ...rows))));
}
