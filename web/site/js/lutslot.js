// SPDX-License-Identifier: Apache-2.0
// The LUT a section works on: dropped (or made by another step), described by `lutkit info
// --json`, and, where the file does not say what it is for, asked once (an edit or the game's
// LUT, as the editor asks; the answer is kept for that file's bytes in this browser). Its flags
// go on every command that reads it, so each command line says what the page assumed.
import { FileDrop } from './filedrop.js';
import { el, ResultView, commandDetails, lineKind } from './result.js';
import { fileArg, extension } from './shell.js';

const layouts = [
  ['unreal', 'Unreal / Godot 256x16'],
  ['unity', 'Unity 256x16'],
  ['smush', 'Smush-LUT 256x16'],
  ['hald', 'Hald'],
  ['reshade', 'ReShade 1024x32'],
  ['unity-32', 'Unity 1024x32'],
];
const imageExtensions = new Set(['png', 'jpg', 'jpeg', 'ppm', 'pgm', 'tif', 'tiff', 'exr']);
export const lutAccept = '.cube,.nutexb,.png,.spi3d,.3dl,.csp,.clf,.ctf,.cub,.itx,.spi1d,.cc,.ccc,.cdl,.look,.mga,.m3d,.vf,.lut,.tif,.tiff,.exr';
const purposeKey = 'lutkit.purpose.';

export async function digest(bytes) {
  if (globalThis.crypto && crypto.subtle) {
    const hash = new Uint8Array(await crypto.subtle.digest('SHA-256', bytes));
    return Array.from(hash.slice(0, 16), (b) => b.toString(16).padStart(2, '0')).join('');
  }
  return `${bytes.length}`;
}

function rememberAnswer(hash, answer) {
  try {
    localStorage.setItem(purposeKey + hash, answer);
  } catch (error) {
    // Storage off (private mode): asked again next time.
  }
}

function recalledAnswer(hash) {
  try {
    return localStorage.getItem(purposeKey + hash);
  } catch (error) {
    return null;
  }
}

export const purposeWords = {
  raw: 'an edit (the look itself)',
  smash: "the game's LUT (Smash Ultimate's color_grading_lut)",
};

let slotCount = 0;

export class LutSlot {
  // options: {runner lane, id, label, hint, onChange()}
  constructor(options) {
    this.options = options;
    this.lane = options.lane;
    this.lut = null;
    this.id = options.id || `lut-${++slotCount}`;
    this.drop = new FileDrop({ id: `${this.id}-file`, label: options.label, hint: options.hint,
                               accept: lutAccept, onFiles: ([f]) => this.setLut(f.name, f.bytes) });
    this.facts = el('div', { class: 'lut-facts', 'aria-live': 'polite' });
    this.resultNode = el('div', { class: 'result' });
    this.result = new ResultView(this.resultNode);
    this.node = el('div', { class: 'lut-slot', id: this.id }, this.drop.node, this.resultNode, this.facts);
  }

  get ready() {
    return Boolean(this.lut && this.lut.info && this.purpose);
  }

  // raw or smash: what the file says, else the user's answer (null while not answered).
  get purpose() {
    if (!this.lut || !this.lut.info)
      return null;
    return this.lut.info.purpose || this.lut.answer || null;
  }

  get isImage() {
    return this.lut && imageExtensions.has(extension(this.lut.name));
  }

  // The LUT's file for a command: {name, bytes}.
  get file() {
    return this.lut ? { name: this.lut.name, bytes: this.lut.bytes } : null;
  }

  // Flags for a command that reads this LUT. kind: 'in' (convert, extract: --in-target,
  // --in-layout), 'lut' (apply, preview: --lut-target, --lut-layout), 'check' (--target,
  // --in-layout), 'info' (--in-layout).
  flags(kind, lut = this.lut) {
    const args = [];
    const said = lut && lut.info && lut.info.purpose;
    if (!said && lut && lut.answer) {
      if (kind === 'in')
        args.push('--in-target', lut.answer);
      else if (kind === 'lut')
        args.push('--lut-target', lut.answer);
      else if (kind === 'check')
        args.push('--target', lut.answer);
    }
    if (lut && lut.layout)
      args.push(kind === 'lut' ? '--lut-layout' : '--in-layout', lut.layout);
    return args;
  }

  // A new file (or the same one read in another layout) becomes the slot's LUT once lutkit has
  // read it; a file lutkit refuses leaves the LUT the slot had, as the editor leaves its document.
  async setLut(name, bytes, options = {}) {
    const candidate = { name, bytes, info: null, answer: null, layout: options.layout || null,
                        origin: options.origin || null, hash: await digest(bytes) };
    this.pending = candidate;
    if (options.origin)
      this.drop.setChosen(`${name} (${options.origin})`);
    const args = ['info', '--json', fileArg(name), ...this.flags('info', candidate)];
    this.result.running(args, this.lane, `Reading ${name}`);
    const record = await this.lane.run(args, { [name]: bytes }, { label: 'info' });
    if (this.pending !== candidate)
      return;
    this.pending = null;
    let info = null;
    if (record.status === 'done' && record.exitCode === 0) {
      try {
        info = JSON.parse(record.stdout);
      } catch (error) {
        info = null;
      }
    }
    if (!info) {
      this.drop.refused(name);
      if (this.lut)
        this.drop.setChosen(`${name}: not usable, see lutkit's message below; still ${this.lut.name}`, true);
      this.result.show(record);
      // An image lutkit could not read as it detected it may read in a layout named.
      if (record.status === 'done' && imageExtensions.has(extension(name)))
        this.result.node.append(this.layoutChoice(candidate));
      return;
    }
    candidate.info = info;
    candidate.record = record;
    if (!info.purpose) {
      const recalled = recalledAnswer(candidate.hash);
      if (recalled === 'raw' || recalled === 'smash') {
        candidate.answer = recalled;
        candidate.recalled = true;
      }
    }
    this.lut = candidate;
    this.result.clear();
    this.renderFacts(record);
    this.changed();
  }

  clear() {
    this.lut = null;
    this.pending = null;
    this.facts.replaceChildren();
    this.result.clear();
    this.drop.setChosen('');
    this.changed();
  }

  renderFacts(record) {
    const lut = this.lut;
    const info = lut.info;
    const kind = info.dialect ? `${info.format} (${info.dialect})` : info.format;
    const depth = info.float ? 'float' : `${info.source_bit_depth}-bit`;
    const neutral = info.neutral === 'exact' ? 'neutral (no change)'
      : info.neutral === 'no' ? `a grade (max change ${(info.max_deviation_from_identity * 255).toFixed(0)} 8-bit steps)`
        : `near neutral (${info.neutral})`;
    this.facts.replaceChildren(
      el('p', { class: 'facts-line' }, el('strong', { text: lut.name }),
        `: ${kind}, ${info.size}³, ${depth}, ${neutral}${info.title ? `, “${info.title}”` : ''}.`));
    this.facts.append(this.purposeBlock());
    if (this.isImage)
      this.facts.append(this.layoutChoice());
    const notes = record.stderr.split('\n').filter((l) => l.trim());
    if (notes.length) {
      const pre = el('pre', { class: 'messages' });
      for (const line of notes)
        pre.append(el('span', { class: `line-${lineKind(line) || 'plain'}`, text: line }), '\n');
      this.facts.append(pre);
    }
    this.facts.append(commandDetails(record.args));
  }

  purposeBlock() {
    const lut = this.lut;
    const info = lut.info;
    if (info.purpose) {
      const source = info.purpose_source === 'format' ? `a .${extension(lut.name)} always is`
        : 'the file says so';
      return el('p', { class: 'purpose-line', 'data-purpose': info.purpose },
        'For: ', el('strong', { text: purposeWords[info.purpose] }), ` (${source}).`);
    }
    if (lut.answer && !lut.asking) {
      const change = el('button', { type: 'button', class: 'small link', text: 'Change',
        onclick: () => { lut.asking = true; this.renderFacts(this.lastRecord()); } });
      return el('p', { class: 'purpose-line', 'data-purpose': lut.answer },
        'For: ', el('strong', { text: purposeWords[lut.answer] }),
        lut.recalled ? ' (your earlier answer for this file). ' : ' (your answer). ', change);
    }
    const name = `${this.id}-purpose`;
    const choice = (value, title, text) => el('label', { class: 'choice' },
      el('input', { type: 'radio', name, value, checked: lut.answer === value,
        onchange: () => this.answer(value) }),
      el('span', {}, el('strong', { text: title }), el('br'), text));
    return el('fieldset', { class: 'purpose-question', role: 'group', 'data-question': 'purpose' },
      el('legend', { text: `What is ${lut.name} for? The file does not say.` }),
      choice('raw', 'An edit: the look itself',
        "a graded neutral strip, a colourist's .cube, an engine's strip, Smush-LUT's graded neutral.png"),
      choice('smash', "The game's LUT",
        'what goes into color_grading_lut.nutexb as it is: Smush-LUT\'s output, a LUT extracted for the game'),
      el('p', { class: 'hint', text: 'Asked once for this file. Making the game\'s LUT from it twice would make the game show the grade wrong.' }));
  }

  lastRecord() {
    return this.lut.record;
  }

  answer(value) {
    const lut = this.lut;
    lut.answer = value;
    lut.asking = false;
    lut.recalled = false;
    rememberAnswer(lut.hash, value);
    this.renderFacts(this.lastRecord());
    this.changed();
  }

  layoutChoice(lut = this.lut) {
    const detected = lut.info && lut.info.dialect ? `detected (${lut.info.dialect})` : 'detected';
    const select = el('select', { id: `${this.id}-layout`, 'data-role': 'layout',
      onchange: () => this.setLut(lut.name, lut.bytes, { layout: select.value || null, origin: lut.origin }) },
    el('option', { value: '', text: lut.layout ? 'detect it' : detected }),
    layouts.map(([value, text]) => el('option', { value, text, selected: lut.layout === value })));
    return el('p', { class: 'layout-line' },
      el('label', { for: select.id, text: 'Strip layout: ' }), select);
  }

  changed() {
    this.node.dataset.ready = this.ready ? '1' : '0';
    if (this.options.onChange)
      this.options.onChange(this);
  }
}
