// The grid map: a canvas for the cells (heat map, obstacles, unvisited dots) under an SVG for
// the robots (paths, waypoints, headings). World y grows upwards; cell (i, j) is column i, row j
// from the bottom. Every cell is cellPx x cellPx pixels, so a test can read a cell's colour.
import { el, svgEl, rgbCss, heatRgb } from './util.js';

export class MapView {
  // opts: {mapSize, cellSize, palette, obstacles: [[i, j]], sidePx}
  constructor(opts) {
    this.n = opts.mapSize;
    this.cellSize = opts.cellSize;
    this.palette = opts.palette;
    this.obstacles = new Set((opts.obstacles || []).map(([i, j]) => i * this.n + j));
    this.cellPx = Math.max(1, Math.floor((opts.sidePx || 560) / this.n));
    this.sidePx = this.cellPx * this.n;
    this.canvas = el('canvas', { width: this.sidePx, height: this.sidePx, class: 'cells' });
    this.svg = svgEl('svg', { class: 'overlay', width: this.sidePx, height: this.sidePx, viewBox: `0 0 ${this.sidePx} ${this.sidePx}` });
    this.root = el('div', { class: 'map', style: `width:${this.sidePx}px;height:${this.sidePx}px` }, this.canvas, this.svg);
    this.highlight = new Set();
  }

  // World metres to overlay pixels.
  px(x) { return (x / this.cellSize) * this.cellPx; }
  py(y) { return this.sidePx - (y / this.cellSize) * this.cellPx; }

  setObstacles(list) { this.obstacles = new Set(list.map(([i, j]) => i * this.n + j)); }

  // field: {pheromone, visited} or null; vmax: the heat map's top; visitedFallback: Uint8Array
  // (cells known visited when the trace has no field).
  drawCells(field, vmax, visitedFallback) {
    const ctx = this.canvas.getContext('2d');
    const { n, cellPx } = this;
    const stops = this.palette.heat;
    const img = ctx.createImageData(this.sidePx, this.sidePx);
    for (let i = 0; i < n; ++i) {
      for (let j = 0; j < n; ++j) {
        const k = i * n + j;
        let rgb;
        if (this.obstacles.has(k)) rgb = this.palette.obstacle;
        else if (field && vmax > 0) rgb = heatRgb(stops, Math.sqrt(field.pheromone[k] / vmax));
        else rgb = stops[0];
        const x0 = i * cellPx, y0 = (n - 1 - j) * cellPx;
        for (let y = y0; y < y0 + cellPx; ++y) {
          let o = (y * this.sidePx + x0) * 4;
          for (let x = 0; x < cellPx; ++x, o += 4) {
            img.data[o] = rgb[0]; img.data[o + 1] = rgb[1]; img.data[o + 2] = rgb[2]; img.data[o + 3] = 255;
          }
        }
      }
    }
    ctx.putImageData(img, 0, 0);
    const visited = field ? field.visited : visitedFallback;
    ctx.fillStyle = rgbCss(this.palette.unvisited);
    const r = Math.max(1, cellPx * 0.12);
    for (let i = 0; i < n; ++i) {
      for (let j = 0; j < n; ++j) {
        const k = i * n + j;
        if (this.obstacles.has(k) || (visited && visited[k])) continue;
        ctx.beginPath();
        ctx.arc((i + 0.5) * cellPx, (n - 0.5 - j) * cellPx, r, 0, 2 * Math.PI);
        ctx.fill();
      }
    }
    if (cellPx >= 8) {
      ctx.strokeStyle = 'rgba(0, 0, 0, 0.12)';
      ctx.lineWidth = 1;
      ctx.beginPath();
      for (let k = 0; k <= n; ++k) {
        ctx.moveTo(k * cellPx + 0.5, 0); ctx.lineTo(k * cellPx + 0.5, this.sidePx);
        ctx.moveTo(0, k * cellPx + 0.5); ctx.lineTo(this.sidePx, k * cellPx + 0.5);
      }
      ctx.stroke();
    }
    for (const k of this.highlight) {
      const i = Math.floor(k / n), j = k % n;
      ctx.strokeStyle = '#dc2626';
      ctx.lineWidth = 3;
      ctx.strokeRect(i * cellPx + 1.5, (n - 1 - j) * cellPx + 1.5, cellPx - 3, cellPx - 3);
    }
  }

  // robots: [{x, y, theta, wx, wy, path: [[x, y]], waiting, label, axle}]; heading when cosim.
  // With `axle` ([x, y]: the 20-sim body's axle midpoint) the robot is drawn there and (x, y), the
  // point its body reports, as a dot in front of it.
  drawRobots(robots, cosim) {
    this.svg.replaceChildren();
    const r = Math.min(12, Math.max(3, this.cellPx * 0.3));
    robots.forEach((b, k) => {
      const colour = rgbCss(this.palette.robots[k % this.palette.robots.length]);
      if (b.path && b.path.length > 1) {
        const pts = b.path.map(([x, y]) => `${this.px(x).toFixed(1)},${this.py(y).toFixed(1)}`).join(' ');
        this.svg.append(svgEl('polyline', { class: 'path', points: pts, fill: 'none', stroke: colour, 'stroke-width': 2, 'stroke-opacity': 0.7 }));
      }
      if (b.wx !== undefined && cosim) {
        this.svg.append(svgEl('line', { class: 'to-waypoint', x1: this.px(b.x), y1: this.py(b.y), x2: this.px(b.wx), y2: this.py(b.wy), stroke: colour, 'stroke-dasharray': '3 3' }));
        this.svg.append(svgEl('rect', { class: 'waypoint', x: this.px(b.wx) - 4, y: this.py(b.wy) - 4, width: 8, height: 8, fill: 'none', stroke: colour, 'stroke-width': 2 }));
      }
      const g = svgEl('g', { class: 'robot-group' });
      const [cx, cy] = b.axle ? b.axle : [b.x, b.y];
      if (b.waiting) g.append(svgEl('circle', { class: 'waiting', cx: this.px(cx), cy: this.py(cy), r: r + 5, fill: 'none', stroke: '#f59e0b', 'stroke-width': 3, 'stroke-dasharray': '4 2' }));
      g.append(svgEl('circle', { class: 'robot', 'data-robot': k, cx: this.px(cx), cy: this.py(cy), r, fill: colour, stroke: '#111', 'stroke-width': 1.5 },
        svgEl('title', { text: b.label || `robot ${k}` })));
      if (cosim && b.theta !== undefined) {
        g.append(svgEl('line', { class: 'heading', x1: this.px(cx), y1: this.py(cy),
          x2: this.px(cx) - Math.sin(b.theta) * r * 1.6, y2: this.py(cy) - Math.cos(b.theta) * r * 1.6, stroke: 'white', 'stroke-width': 2 }));
      }
      if (b.axle) {
        g.append(svgEl('circle', { class: 'reported-point', cx: this.px(b.x), cy: this.py(b.y), r: Math.max(2, r * 0.3), fill: '#111' },
          svgEl('title', { text: `robot ${k}: the point its body reports (axle at ${cx.toFixed(4)}, ${cy.toFixed(4)})` })));
      }
      if (b.label) g.append(svgEl('text', { x: this.px(b.x) + r + 2, y: this.py(b.y) - r, class: 'robot-label', text: b.label }));
      this.svg.append(g);
    });
  }

  // The cell under a mouse event on the map, or null.
  cellAt(event) {
    const box = this.canvas.getBoundingClientRect();
    const i = Math.floor((event.clientX - box.left) / this.cellPx);
    const j = this.n - 1 - Math.floor((event.clientY - box.top) / this.cellPx);
    return i >= 0 && j >= 0 && i < this.n && j < this.n ? [i, j] : null;
  }
}
