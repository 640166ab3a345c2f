// Two small SVG charts with a cursor: a line chart (eP over steps) and a timeline of 0/1
// signals (the handshake: the Environment's flag and onDestination, each controller's).
import { svgEl } from './util.js';

const W = 560, PAD = 34;

export class LineChart {
  // xs, ys: arrays; yMax: top of the axis
  constructor({ xs, ys, yMax, label, height = 150, colour = '#2563eb' }) {
    this.xs = xs; this.height = height;
    this.xMax = Math.max(1, xs[xs.length - 1] || 1);
    const sx = (x) => PAD + (x / this.xMax) * (W - PAD - 8);
    const sy = (y) => height - 22 - (y / yMax) * (height - 34);
    this.sx = sx;
    const pts = xs.map((x, k) => `${sx(x).toFixed(1)},${sy(ys[k]).toFixed(1)}`).join(' ');
    this.cursorLine = svgEl('line', { class: 'cursor', y1: 8, y2: height - 22, stroke: '#dc2626' });
    this.root = svgEl('svg', { class: 'chart', width: W, height, viewBox: `0 0 ${W} ${height}` },
      svgEl('line', { x1: PAD, y1: height - 22, x2: W - 8, y2: height - 22, stroke: '#999' }),
      svgEl('line', { x1: PAD, y1: 8, x2: PAD, y2: height - 22, stroke: '#999' }),
      svgEl('text', { x: 4, y: 14, class: 'axis', text: String(yMax) }),
      svgEl('text', { x: 4, y: height - 22, class: 'axis', text: '0' }),
      svgEl('text', { x: W - 8, y: height - 6, class: 'axis', 'text-anchor': 'end', text: `step ${this.xMax}` }),
      svgEl('text', { x: PAD + 6, y: 20, class: 'label', text: label }),
      svgEl('polyline', { class: 'line', points: pts, fill: 'none', stroke: colour, 'stroke-width': 2 }),
      this.cursorLine);
  }

  cursor(x) {
    const px = this.sx(x);
    this.cursorLine.setAttribute('x1', px);
    this.cursorLine.setAttribute('x2', px);
  }
}

export class SignalChart {
  // rows: [{label, values: [0|1]}] sampled at xs
  constructor({ xs, rows, title }) {
    const rowH = 18, height = 28 + rows.length * rowH;
    this.xMax = Math.max(1, xs[xs.length - 1] || 1);
    const left = 150;
    this.sx = (x) => left + (x / this.xMax) * (W + 120 - left - 8);
    this.cursorLine = svgEl('line', { class: 'cursor', y1: 16, y2: height - 4, stroke: '#dc2626' });
    this.root = svgEl('svg', { class: 'chart signals', width: W + 120, height, viewBox: `0 0 ${W + 120} ${height}` },
      svgEl('text', { x: 4, y: 12, class: 'label', text: title }));
    rows.forEach((row, r) => {
      const y0 = 22 + r * rowH;
      this.root.append(svgEl('text', { x: 4, y: y0 + 12, class: 'axis', text: row.label }));
      let d = '';
      xs.forEach((x, k) => {
        const y = y0 + (row.values[k] ? 2 : rowH - 4);
        d += `${k ? 'L' : 'M'}${this.sx(x).toFixed(1)} ${y}`;
        if (k + 1 < xs.length) d += `L${this.sx(xs[k + 1]).toFixed(1)} ${y}`;
      });
      this.root.append(svgEl('path', { d, fill: 'none', stroke: row.colour || '#0f766e', 'stroke-width': 1.5 }));
    });
    this.root.append(this.cursorLine);
  }

  cursor(x) {
    const px = this.sx(x);
    this.cursorLine.setAttribute('x1', px);
    this.cursorLine.setAttribute('x2', px);
  }
}
