// Small DOM helpers shared by every page.

// el('div', {class: 'x', onclick: f}, child, 'text', ...)
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  setAttrs(node, attrs);
  for (const c of children.flat()) if (c !== null && c !== undefined) node.append(c);
  return node;
}

export function svgEl(tag, attrs = {}, ...children) {
  const node = document.createElementNS('http://www.w3.org/2000/svg', tag);
  setAttrs(node, attrs);
  for (const c of children.flat()) if (c !== null && c !== undefined) node.append(c);
  return node;
}

function setAttrs(node, attrs) {
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith('on')) node.addEventListener(k.slice(2), v);
    else if (k === 'text') node.textContent = v;
    else node.setAttribute(k, v === true ? '' : v);
  }
}

export const rgbCss = ([r, g, b]) => `rgb(${r}, ${g}, ${b})`;

// The heat colour of t in [0, 1]: the same interpolation as views/svg.cpp (heat()).
export function heatRgb(stops, t) {
  if (!(t > 0)) return stops[0];
  if (t >= 1) return stops[stops.length - 1];
  const pos = t * (stops.length - 1);
  const k = Math.floor(pos);
  const f = pos - k;
  return [0, 1, 2].map((ch) => Math.round(stops[k][ch] + f * (stops[k + 1][ch] - stops[k][ch])));
}

export const fixed = (x, d = 2) => (typeof x === 'number' ? x.toFixed(d) : String(x));

export function downloadText(name, text, type = 'application/json') {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}

export function section(title, ...children) {
  return el('section', { class: 'panel' }, el('h2', { text: title }), ...children);
}
