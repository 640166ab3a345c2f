// A time slider with play / pause / step and a speed choice. onChange(index) is called on every
// move; the owner draws.
import { el } from './util.js';

export class Timeline {
  constructor(count, onChange, label = (k) => String(k)) {
    this.count = count;
    this.onChange = onChange;
    this.label = label;
    this.index = 0;
    this.timer = null;
    this.slider = el('input', { type: 'range', min: 0, max: Math.max(0, count - 1), value: 0, class: 'slider', 'aria-label': 'time',
      oninput: () => this.set(Number(this.slider.value)) });
    this.playButton = el('button', { class: 'play', text: '▶ play', onclick: () => this.toggle() });
    this.speed = el('select', { class: 'speed', 'aria-label': 'speed' },
      ...[1, 4, 16, 64].map((s) => el('option', { value: s, text: `${s}×` })));
    this.readout = el('span', { class: 'readout' });
    this.root = el('div', { class: 'timeline' },
      el('button', { class: 'first', text: '|◀', title: 'first', onclick: () => this.set(0) }),
      el('button', { class: 'back', text: '◀', title: 'step back', onclick: () => this.set(this.index - 1) }),
      this.playButton,
      el('button', { class: 'forward', text: '▶', title: 'step', onclick: () => this.set(this.index + 1) }),
      el('button', { class: 'last', text: '▶▶|', title: 'last', onclick: () => this.set(this.count - 1) }),
      this.speed, this.slider, this.readout);
  }

  set(index) {
    this.index = Math.min(Math.max(0, index), this.count - 1);
    this.slider.value = this.index;
    this.readout.textContent = this.label(this.index);
    this.onChange(this.index);
    if (this.index === this.count - 1) this.pause();
  }

  toggle() { if (this.timer) this.pause(); else this.play(); }

  play() {
    if (this.index >= this.count - 1) this.set(0);
    this.playButton.textContent = '❚❚ pause';
    this.timer = setInterval(() => this.set(this.index + Number(this.speed.value)), 50);
  }

  pause() {
    clearInterval(this.timer);
    this.timer = null;
    this.playButton.textContent = '▶ play';
  }
}
