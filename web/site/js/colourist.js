// SPDX-License-Identifier: Apache-2.0
// The colourist's tools: convert a LUT with its error report, check it with its report picture,
// apply it to a picture, match a look to reference pictures.
import { Compare } from './compare.js';
import { FileDrop } from './filedrop.js';
import { LivePicture } from './live.js';
import { LutSlot } from './lutslot.js';
import { el, ResultView, blobUrl } from './result.js';
import { fileArg, placeInputs, stem } from './shell.js';
import { strengthControl, strengthArgs, summaryLines } from './common.js';

const outputFormats = [
  { id: 'cube', text: '.cube (Adobe / Resolve)', ext: 'cube', args: [] },
  { id: 'strip', text: 'LUT image, PNG', ext: 'png', args: [], image: true },
  { id: 'hald', text: 'Hald image, PNG', ext: 'png', args: ['--layout', 'hald'], image: true, suffix: '_hald' },
  { id: 'nutexb', text: 'Smash Ultimate .nutexb (the game\'s LUT)', ext: 'nutexb', args: [] },
  { id: 'spi3d', text: 'Sony Imageworks .spi3d', ext: 'spi3d', args: [] },
];
const stripLayouts = [
  ['unreal', 'Unreal / Godot 256x16'], ['unity', 'Unity 256x16'], ['smush', 'Smush-LUT 256x16'],
  ['reshade', 'ReShade 1024x32'], ['unity-32', 'Unity 1024x32'],
];

function field(labelText, control, hint) {
  return el('p', { class: 'field' }, el('label', { for: control.id, text: labelText }), control,
    hint ? el('span', { class: 'hint', text: hint }) : null);
}

export class Colourist {
  constructor(root, runner) {
    this.root = root;
    this.runner = runner;
    this.lane = runner.lane('main');
    this.lut = new LutSlot({ id: 'clut', lane: this.lane, label: 'A LUT file',
      hint: '.cube, a LUT image (PNG) or .nutexb; other formats need the native lutkit',
      onChange: () => this.lutChanged() });
    root.querySelector('[data-mount="lut"]').append(this.lut.node);
    this.mountConvert(root.querySelector('[data-mount="convert"]'));
    this.mountCheck(root.querySelector('[data-mount="check"]'));
    this.mountApply(root.querySelector('[data-mount="apply"]'));
    this.mountMatch(root.querySelector('[data-mount="match"]'));
    this.lutChanged();
  }

  lutChanged() {
    const ready = this.lut.ready;
    for (const b of [this.convertButton, this.checkButton])
      b.disabled = !ready;
    const why = ready ? '' : this.lut.lut ? 'Answer what the LUT is for in step 1 first.' : 'Drop a LUT in step 1 first.';
    this.convertWhy.textContent = why;
    this.checkWhy.textContent = why;
    this.apply.refresh();
  }

  // 2. Convert.
  mountConvert(mount) {
    const format = el('select', { id: 'convert-format', 'data-role': 'convert-format' },
      outputFormats.map((f) => el('option', { value: f.id, text: f.text })));
    const layout = el('select', { id: 'convert-layout' }, stripLayouts.map(([v, t]) => el('option', { value: v, text: t })));
    const depth = el('select', { id: 'convert-depth' },
      el('option', { value: '', text: '8-bit (default)' }), el('option', { value: '16', text: '16-bit' }));
    const size = el('input', { id: 'convert-size', type: 'number', min: '2', max: '256', step: '1',
                               placeholder: 'default', inputmode: 'numeric' });
    const layoutField = field('Layout ', layout);
    const depthField = field('Bit depth ', depth);
    const showImageFields = () => {
      const f = outputFormats.find((o) => o.id === format.value);
      layoutField.hidden = f.id !== 'strip';
      depthField.hidden = !f.image;
      size.disabled = f.id === 'nutexb';
    };
    format.addEventListener('change', showImageFields);
    showImageFields();
    const result = new ResultView(el('div', { class: 'result', id: 'convert-result' }));
    this.convertWhy = el('p', { class: 'hint why' });
    this.convertButton = el('button', { type: 'button', class: 'primary', id: 'convert-run', text: 'Convert',
      onclick: async () => {
        const f = outputFormats.find((o) => o.id === format.value);
        const lut = this.lut.file;
        let name = `${stem(lut.name)}${f.suffix || ''}.${f.ext}`;
        if (name === lut.name)
          name = `${stem(lut.name)}_converted.${f.ext}`;
        const args = ['convert', fileArg(lut.name), fileArg(name), ...f.args, ...this.lut.flags('in')];
        if (f.id === 'strip' && layout.value !== 'unreal')
          args.push('--layout', layout.value);
        if (f.image && depth.value)
          args.push('--bit-depth', depth.value);
        if (size.value && !size.disabled)
          args.push('--size', String(Math.round(Number(size.value))));
        result.running(args, this.lane, `Converting to ${name}`);
        const record = await this.lane.run(args, { [lut.name]: lut.bytes }, { label: 'convert' });
        result.show(record, { downloads: [{ name }], summary: summaryLines(record) });
      } });
    mount.append(field('Into ', format), layoutField, depthField,
      field('Size ', size, 'points per axis (N³); empty: the format\'s own, else the LUT\'s'),
      el('p', { class: 'row' }, this.convertButton), this.convertWhy, result.node);
  }

  // 3. Check, with the report picture.
  mountCheck(mount) {
    const result = new ResultView(el('div', { class: 'result', id: 'check-result' }));
    this.checkWhy = el('p', { class: 'hint why' });
    this.checkButton = el('button', { type: 'button', class: 'primary', id: 'check-run', text: 'Check it',
      onclick: async () => {
        const lut = this.lut.file;
        const report = `${stem(lut.name)}_check.png`;
        const args = ['check', fileArg(lut.name), '--report', fileArg(report), ...this.lut.flags('check')];
        result.running(args, this.lane, 'Checking');
        const record = await this.lane.run(args, { [lut.name]: lut.bytes }, { label: 'check' });
        const picture = record.outputs[report];
        const extras = {};
        if (picture) {
          const url = blobUrl(picture, report);
          extras.after = el('a', { href: url, target: '_blank', class: 'report-link' },
            el('img', { src: url, class: 'report', alt: `${lut.name}: the stress charts before and after, findings circled` }));
          // The verdict is lutkit's first line; exit 1 with the report written is a LUT that
          // fails a check, not a failed command.
          const verdict = (record.stdout.match(/^\S.*?: (pass|warn|fail) \(/m) || [])[1];
          if (record.status === 'done' && verdict === 'fail' && record.exitCode === 1)
            extras.verdict = { kind: 'warning', title: 'The LUT fails a check (exit 1):', detail: 'the findings are below and circled in the picture.' };
          else if (record.status === 'done' && record.exitCode === 0 && verdict === 'warn')
            extras.verdict = { kind: 'warning', title: `Checked in ${(record.ms / 1000).toFixed(1)} s: it passes, with warnings:`, detail: 'the findings are below and circled in the picture.' };
          else if (record.status === 'done' && record.exitCode === 0 && verdict === 'pass')
            extras.verdict = { kind: 'ok', title: `Checked in ${(record.ms / 1000).toFixed(1)} s: it passes every check.` };
          extras.downloads = [{ name: report }];
        }
        result.show(record, extras);
        if (picture)
          result.addUrl(extras.after.href);
      } });
    mount.append(el('p', { class: 'row' }, this.checkButton), this.checkWhy, result.node);
  }

  // 4. Apply to a picture.
  mountApply(mount) {
    this.applyStrength = strengthControl('apply-strength', 'How much of the LUT: 0 none, 1 the LUT, up to 2.',
      (live) => this.apply.refresh(live));
    const compare = new Compare({ id: 'apply-compare', beforeAlt: 'The picture', afterAlt: 'The picture with the LUT' });
    this.apply = new LivePicture({ runner: this.runner, id: 'apply', compare, suffix: '_graded',
      what: 'Applying the LUT', label: 'A picture', hint: 'PNG, JPEG or PPM',
      makeArgs: (input, out) => {
        if (!this.lut.ready)
          return { missing: this.lut.lut ? 'Answer what the LUT is for in step 1.' : 'Drop a LUT in step 1 to apply it.' };
        const { files, names } = placeInputs([this.lut.file], [out, input]);
        return { files, args: ['apply', '--lut', fileArg(names[0]), ...this.lut.flags('lut'), input, '-o', fileArg(out),
                               ...strengthArgs(this.applyStrength)] };
      } });
    mount.append(this.applyStrength.node, this.apply.node);
  }

  // 5. Match a look.
  mountMatch(mount) {
    this.match = { source: null, references: [] };
    const source = new FileDrop({ id: 'match-source', label: 'Your picture', hint: 'the picture to change',
      accept: '.png,.jpg,.jpeg,.ppm', onFiles: ([f]) => { this.match.source = f; update(); } });
    const refs = new FileDrop({ id: 'match-refs', label: 'Reference pictures', hint: 'one or more: their look is pooled',
      accept: '.png,.jpg,.jpeg,.ppm', multiple: true, onFiles: (files) => { this.match.references = files; update(); } });
    const strength = strengthControl('match-strength', 'How much of the match: 0 none, 1 all of it.', () => {});
    const output = el('select', { id: 'match-output' },
      el('option', { value: 'cube', text: '.cube (an edit)' }),
      el('option', { value: 'nutexb', text: 'color_grading_lut.nutexb (the game\'s LUT for a screenshot)' }),
      el('option', { value: 'png', text: 'LUT image, PNG 256x16' }));
    const result = new ResultView(el('div', { class: 'result', id: 'match-result' }));
    const button = el('button', { type: 'button', class: 'primary', id: 'match-run', text: 'Match', disabled: true,
      onclick: async () => {
        const src = this.match.source;
        const out = output.value === 'nutexb' ? 'color_grading_lut.nutexb' : `${stem(src.name)}_look.${output.value}`;
        const report = `${stem(src.name)}_match.png`;
        const { files, names } = placeInputs([src, ...this.match.references], [out, report]);
        const args = ['match', ...names.map(fileArg), fileArg(out), '--report-image', fileArg(report), ...strengthArgs(strength)];
        result.running(args, this.lane, 'Matching');
        const record = await this.lane.run(args, files, { label: 'match' });
        const extras = { downloads: [{ name: out }, { name: report }], summary: summaryLines(record) };
        if (record.status === 'done' && record.exitCode === 0 && record.outputs[out]) {
          const url = blobUrl(record.outputs[report], report);
          const use = el('button', { type: 'button', text: `Use ${out} as your LUT (step 1)`,
            onclick: () => { this.lut.setLut(out, record.outputs[out], { origin: `matched to ${names.slice(1).join(', ')}` }); document.getElementById('c-lut').scrollIntoView(); } });
          extras.after = el('div', {}, el('p', { class: 'row' }, use),
            el('a', { href: url, target: '_blank', class: 'report-link' },
              el('img', { src: url, class: 'report', alt: 'Source, result and reference with their histograms' })));
          result.show(record, extras);
          result.addUrl(url);
        } else {
          result.show(record, extras);
        }
      } });
    const update = () => {
      button.disabled = !(this.match.source && this.match.references.length);
    };
    mount.append(el('div', { class: 'two' }, source.node, refs.node), strength.node,
      field('LUT ', output), el('p', { class: 'row' }, button), result.node);
  }
}
