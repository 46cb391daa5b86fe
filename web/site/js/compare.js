// SPDX-License-Identifier: Apache-2.0
// Before | after, split by a divider (drag it, or its slider with the keyboard), as the editor's
// preview: before on the left, after on the right.
import { el } from './result.js';

let compareCount = 0;

export class Compare {
  constructor(options = {}) {
    const id = options.id || `compare-${++compareCount}`;
    this.before = el('img', { class: 'before', alt: options.beforeAlt || 'Before', 'data-role': 'before' });
    this.after = el('img', { class: 'after', alt: options.afterAlt || 'After', 'data-role': 'after' });
    this.divider = el('div', { class: 'divider', 'aria-hidden': 'true' });
    this.labels = el('div', { class: 'compare-labels', 'aria-hidden': 'true' },
      el('span', { text: 'Before' }), el('span', { text: 'After' }));
    this.stage = el('div', { class: 'compare-stage' }, this.before, this.after, this.divider, this.labels);
    this.slider = el('input', { type: 'range', min: '0', max: '100', step: '1', value: '50',
                                id: `${id}-split`, 'data-role': 'split' });
    this.note = el('p', { class: 'compare-note', 'aria-live': 'polite' });
    this.modeButtons = ['split', 'before', 'after'].map((mode) => el('button', {
      type: 'button', class: 'small', 'data-mode': mode, 'aria-pressed': mode === 'split' ? 'true' : 'false',
      text: mode[0].toUpperCase() + mode.slice(1), onclick: () => this.setMode(mode) }));
    this.node = el('figure', { class: 'compare is-empty', id },
      this.stage,
      el('figcaption', {},
        el('div', { class: 'compare-controls' },
          el('label', { for: this.slider.id, text: 'Divider' }), this.slider,
          el('span', { class: 'mode-buttons', role: 'group', 'aria-label': 'Show' }, this.modeButtons)),
        this.note));
    this.urls = { before: null, after: null };
    this.slider.addEventListener('input', () => this.setSplit(Number(this.slider.value)));
    let dragging = false;
    const move = (event) => {
      const box = this.stage.getBoundingClientRect();
      this.setSplit(Math.round(Math.min(100, Math.max(0, ((event.clientX - box.left) / box.width) * 100))));
    };
    this.stage.addEventListener('pointerdown', (event) => {
      dragging = true;
      this.stage.setPointerCapture(event.pointerId);
      move(event);
    });
    this.stage.addEventListener('pointermove', (event) => { if (dragging) move(event); });
    this.stage.addEventListener('pointerup', () => { dragging = false; });
    this.setSplit(50);
  }

  setSplit(percent) {
    this.slider.value = String(percent);
    this.node.style.setProperty('--split', `${percent}%`);
  }

  setMode(mode) {
    this.node.dataset.mode = mode;
    for (const b of this.modeButtons)
      b.setAttribute('aria-pressed', b.dataset.mode === mode ? 'true' : 'false');
  }

  async setImage(which, url, note) {
    const img = which === 'before' ? this.before : this.after;
    const old = this.urls[which];
    if (url) {
      const probe = new Image();
      probe.src = url;
      try {
        await probe.decode();
      } catch (error) {
        // Shown below: the browser could not draw it.
        if (note !== undefined)
          this.note.textContent = `${note} (this browser cannot display the picture)`;
      }
    }
    img.src = url || '';
    img.dataset.ready = url ? '1' : '0';
    this.urls[which] = url;
    if (old && old !== url)
      URL.revokeObjectURL(old);
    this.node.classList.toggle('is-empty', !this.urls.before && !this.urls.after);
    this.node.classList.toggle('no-after', !this.urls.after);
    if (note !== undefined)
      this.note.textContent = note;
  }

  setNote(text) {
    this.note.textContent = text;
  }

  clear() {
    this.setImage('before', null);
    this.setImage('after', null);
    this.note.textContent = '';
  }
}
