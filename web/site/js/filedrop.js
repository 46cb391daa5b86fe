// SPDX-License-Identifier: Apache-2.0
// A place to drop a file or pick one (a real file input, so the keyboard and the file dialog work):
// the files are read into memory here and never leave the computer.
import { el } from './result.js';
import { formatBytes } from './shell.js';

let dropCount = 0;

export class FileDrop {
  // options: {id, label, hint, accept, multiple, compact (one line), onFiles(files: [{name, bytes}])}
  constructor(options) {
    this.options = options;
    const id = options.id || `drop-${++dropCount}`;
    this.input = el('input', { type: 'file', id, class: 'visually-hidden', accept: options.accept,
                               multiple: options.multiple, 'data-role': 'file-input' });
    this.chosen = el('span', { class: 'drop-chosen', text: options.empty || 'nothing yet' });
    this.label = el('label', { for: id, class: options.compact ? 'drop compact' : 'drop' },
      el('span', { class: 'drop-title', text: options.label }),
      options.hint ? el('span', { class: 'drop-hint', text: options.hint }) : null,
      el('span', { class: 'drop-action', text: options.multiple ? 'Drop files here or choose them' : 'Drop a file here or choose one' }),
      this.chosen);
    this.node = el('div', { class: 'drop-wrap' }, this.input, this.label);
    this.input.addEventListener('change', () => {
      if (this.input.files.length)
        this.take(Array.from(this.input.files));
      // The same file chosen again is a new choice (it may have been edited since).
      this.input.value = '';
    });
    for (const type of ['dragenter', 'dragover']) {
      this.label.addEventListener(type, (event) => {
        event.preventDefault();
        event.dataTransfer.dropEffect = 'copy';
        this.label.classList.add('is-over');
      });
    }
    this.label.addEventListener('dragleave', () => this.label.classList.remove('is-over'));
    this.label.addEventListener('drop', (event) => {
      event.preventDefault();
      this.label.classList.remove('is-over');
      const files = Array.from(event.dataTransfer.files);
      if (files.length)
        this.take(this.options.multiple ? files : files.slice(0, 1));
    });
  }

  async take(list) {
    const read = [];
    for (const file of list) {
      try {
        read.push({ name: file.name, bytes: new Uint8Array(await file.arrayBuffer()), size: file.size });
      } catch (error) {
        this.setChosen(`${file.name}: cannot be read (${error.message || error})`, true);
        return;
      }
    }
    this.setChosen(read.map((f) => `${f.name} (${formatBytes(f.size)})`).join(', '));
    this.options.onFiles(read);
  }

  setChosen(text, isError = false) {
    this.chosen.textContent = text;
    this.chosen.classList.toggle('line-error', isError);
    this.label.classList.toggle('has-file', !isError && Boolean(text));
    this.label.classList.toggle('has-error', isError);
  }

  // The file was read but lutkit refused it: said in the drop place too.
  refused(name) {
    this.setChosen(`${name}: not usable, see lutkit's message below`, true);
  }
}

// Files dropped next to a drop place must not make the browser open them instead of the page.
export function guardWindowDrops() {
  for (const type of ['dragover', 'drop']) {
    window.addEventListener(type, (event) => {
      if (!event.target.closest || !event.target.closest('.drop'))
        event.preventDefault();
    });
  }
}
