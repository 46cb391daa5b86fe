// SPDX-License-Identifier: Apache-2.0
// The modder's route (README's quick start, docs/roundtrip.md): the stage's LUT today, the neutral
// strip, the grade (a strip, .cube or .nutexb; or extracted from a graded screenshot), the
// screenshot as the game shows it, and the files for the game and for engines.
import { Compare } from './compare.js';
import { FileDrop } from './filedrop.js';
import { LivePicture } from './live.js';
import { LutSlot } from './lutslot.js';
import { el, ResultView } from './result.js';
import { fileArg, placeInputs, stem } from './shell.js';
import { strengthControl, strengthArgs, summaryLines } from './common.js';

const neutralLayouts = [
  ['unreal', 'Unreal / Godot / Smash modding, 256x16 (16³)'],
  ['unity', 'Unity, 256x16 (16³)'],
  ['smush', 'Smush-LUT, 256x16 (16³)'],
  ['hald', 'Hald, 64x64 (16³)'],
  ['reshade', 'ReShade LUT.fx, 1024x32 (32³)'],
  ['unity-32', 'Unity, 1024x32 (32³)'],
];

export class Modder {
  constructor(root, runner) {
    this.root = root;
    this.runner = runner;
    this.lane = runner.lane('main');
    this.mountStage(root.querySelector('[data-mount="stage"]'));
    this.mountNeutral(root.querySelector('[data-mount="neutral"]'));
    this.mountGrade(root.querySelector('[data-mount="grade"]'));
    this.mountPreview(root.querySelector('[data-mount="preview"]'));
    this.mountExport(root.querySelector('[data-mount="export"]'));
    this.mountRoundtrip(root.querySelector('[data-mount="roundtrip"]'));
    this.gradeChanged();
  }

  // 1. The stage's LUT: --original-lut for preview, convert to the game's file and embed.
  mountStage(mount) {
    this.stage = { kind: 'neutral', file: null };
    const choice = (value, title, text) => el('label', { class: 'choice' },
      el('input', { type: 'radio', name: 'stage-lut', value, checked: value === 'neutral',
        onchange: () => { this.stage.kind = value; this.stageChanged(); } }),
      el('span', {}, el('strong', { text: title }), el('br'), text));
    this.stageFileRadio = null;
    const fileChoice = choice('file', "The stage's own color_grading_lut.nutexb", 'drop it below');
    this.stageFileRadio = fileChoice.querySelector('input');
    this.stageResult = new ResultView(el('div', { class: 'result' }));
    this.stageDrop = new FileDrop({ id: 'stage-file', label: "The stage's .nutexb:", accept: '.nutexb', compact: true,
      onFiles: ([f]) => this.setStageFile(f) });
    mount.append(el('fieldset', { class: 'choices' },
      el('legend', { class: 'visually-hidden', text: "The stage's LUT today" }),
      choice('neutral', 'None (neutral)', 'lutkit\'s default'),
      choice('builtin', "The game's default stage LUT", 'a stage without its own LUT (builtin:smash-default)'),
      fileChoice), this.stageDrop.node, this.stageResult.node);
  }

  async setStageFile(file) {
    this.stage.file = null;
    this.stage.kind = 'file';
    this.stageFileRadio.checked = true;
    const args = ['info', fileArg(file.name)];
    this.stageResult.running(args, this.lane, `Reading ${file.name}`);
    const record = await this.lane.run(args, { [file.name]: file.bytes }, { label: 'info' });
    this.stageResult.show(record);
    if (record.status === 'done' && record.exitCode === 0)
      this.stage.file = file;
    else
      this.stageDrop.refused(file.name);
    this.stageChanged();
  }

  // [args, files] for the stage's LUT (nothing for neutral).
  originalLut() {
    if (this.stage.kind === 'builtin')
      return { args: ['--original-lut', 'builtin:smash-default'], inputs: [] };
    if (this.stage.kind === 'file') {
      if (!this.stage.file)
        return { missing: "Drop the stage's color_grading_lut.nutexb in step 1 (or choose another stage LUT)." };
      return { args: ['--original-lut'], inputs: [this.stage.file] };
    }
    return { args: [], inputs: [] };
  }

  stageChanged() {
    this.root.dataset.stage = this.stage.kind;
    this.exportResult.clear(this.exportResult.node.childElementCount ? 'The stage\'s LUT changed: make the file again.' : '');
    this.preview.refresh();
  }

  // 2. The neutral strip, any layout.
  mountNeutral(mount) {
    const select = el('select', { id: 'neutral-layout', 'data-role': 'neutral-layout' },
      neutralLayouts.map(([value, text]) => el('option', { value, text })));
    const result = new ResultView(el('div', { class: 'result' }));
    const button = el('button', { type: 'button', id: 'neutral-make', text: 'Make the neutral strip',
      onclick: async () => {
        const layout = select.value;
        const name = layout === 'unreal' ? 'neutral.png' : `neutral_${layout}.png`;
        const args = ['neutral', name, ...(layout === 'unreal' ? [] : ['--layout', layout])];
        result.running(args, this.lane, 'Making the strip');
        const record = await this.lane.run(args, {}, { label: 'neutral' });
        result.show(record, { downloads: [{ name }] });
      } });
    mount.append(el('p', { class: 'row' }, el('label', { for: select.id, text: 'Layout ' }), select, button),
      result.node);
  }

  // 3. The grade: a LUT slot and its strength.
  mountGrade(mount) {
    this.grade = new LutSlot({ id: 'grade', lane: this.lane, label: 'Your graded strip, .cube or .nutexb',
      hint: 'the strip from step 2 after your edit, a .cube from a grading app, or a stage\'s .nutexb',
      onChange: () => this.gradeChanged() });
    this.strength = strengthControl('grade-strength',
      'How much of the grade: 0 none, 1 as graded, up to 2 exaggerates (in the preview and the files).',
      (live) => { this.exportStale(); this.preview.refresh(live); });
    mount.append(this.grade.node, this.strength.node);
  }

  gradeChanged() {
    if (!this.exportButtons)
      return;
    const ready = this.grade.ready;
    for (const b of this.exportButtons)
      b.disabled = !ready;
    this.exportWhy.textContent = ready ? '' : this.grade.lut
      ? 'Answer what your grade is for in step 3 first.' : 'Drop your grade in step 3 first (or make it in step 6).';
    this.exportStale();
    this.preview.refresh();
  }

  exportStale() {
    if (this.exportResult && this.exportResult.node.querySelector('.downloads'))
      this.exportResult.clear('Your grade or its strength changed: make the file again.');
  }

  // 4. The screenshot as the game shows it (lutkit preview).
  mountPreview(mount) {
    const compare = new Compare({ id: 'preview-compare', beforeAlt: 'The screenshot as taken',
                                  afterAlt: 'The screenshot as the game shows it with your grade' });
    this.preview = new LivePicture({ runner: this.runner, id: 'preview', compare, suffix: '_in_game',
      what: 'Previewing in the game', label: 'An in-game screenshot', hint: 'PNG, JPEG or PPM, 8 or 16-bit',
      makeArgs: (input, out) => this.previewArgs(input, out) });
    mount.append(this.preview.node);
  }

  previewArgs(input, out) {
    if (!this.grade.ready)
      return { missing: 'Drop your grade in step 3 to see it here.' };
    const original = this.originalLut();
    if (original.missing)
      return original;
    const lut = this.grade.file;
    const { files, names } = placeInputs([lut, ...original.inputs], [out, input]);
    const args = ['preview', input, '-o', fileArg(out), '--lut', fileArg(names[0]), ...this.grade.flags('lut'),
                  ...original.args, ...names.slice(1).map(fileArg), ...strengthArgs(this.strength)];
    return { args, files };
  }

  // 5. The files: the game's .nutexb, engine strips, a .cube.
  mountExport(mount) {
    const targets = [
      { id: 'nutexb', label: 'color_grading_lut.nutexb', note: 'Smash Ultimate', name: () => 'color_grading_lut.nutexb', args: [], game: true },
      { id: 'reshade', label: 'ReShade strip', note: '1024x32, LUT.fx', name: (s) => `${s}_strip_reshade.png`, args: ['--layout', 'reshade'] },
      { id: 'unity', label: 'Unity strip', note: '1024x32', name: (s) => `${s}_strip_unity-32.png`, args: ['--layout', 'unity-32'] },
      { id: 'unreal', label: 'Unreal strip', note: '256x16, Godot too', name: (s) => `${s}_strip_unreal.png`, args: ['--layout', 'unreal'] },
      { id: 'cube', label: '.cube', note: 'grading apps', name: (s) => `${s}_cube.cube`, args: [] },
    ];
    this.exportResult = new ResultView(el('div', { class: 'result', id: 'export-result' }));
    this.exportWhy = el('p', { class: 'hint why' });
    this.exportButtons = targets.map((t) => el('button', { type: 'button', class: t.game ? 'primary' : '',
      'data-target': t.id, onclick: () => this.export(t) },
    el('span', { text: t.label }), el('small', { text: t.note })));
    mount.append(el('div', { class: 'button-grid' }, this.exportButtons), this.exportWhy, this.exportResult.node);
  }

  async export(target) {
    const lut = this.grade.file;
    const name = target.name(stem(lut.name));
    // The stage's LUT matters when an edit becomes the game's LUT; the game's LUT is copied.
    const original = target.game && this.grade.purpose !== 'smash' ? this.originalLut() : { args: [], inputs: [] };
    if (original.missing) {
      this.exportResult.clear(original.missing);
      return;
    }
    const { files, names } = placeInputs([lut, ...original.inputs], [name]);
    // The game's file is the game's LUT; the others hold the grade itself (an edit), as the
    // editor's engine and grading-app targets.
    const args = ['convert', fileArg(names[0]), fileArg(name), ...target.args, ...(target.game ? [] : ['--target', 'raw']),
                  ...this.grade.flags('in'), ...original.args, ...names.slice(1).map(fileArg),
                  ...strengthArgs(this.strength)];
    this.exportResult.running(args, this.lane, `Making ${name}`);
    const record = await this.lane.run(args, files, { label: 'convert' });
    this.exportResult.show(record, { downloads: [{ name }], summary: summaryLines(record) });
  }

  // 6. The round trip: a patch into a screenshot, the grade read back from it.
  mountRoundtrip(mount) {
    const embedResult = new ResultView(el('div', { class: 'result', id: 'embed-result' }));
    const extractResult = new ResultView(el('div', { class: 'result', id: 'extract-result' }));
    const embedDrop = new FileDrop({ id: 'embed-file', label: 'a. Your screenshot', hint: 'PNG or JPEG; lutkit writes it with the patch as PNG',
      accept: '.png,.jpg,.jpeg,.ppm', onFiles: ([f]) => this.embed(f, embedResult) });
    const extractDrop = new FileDrop({ id: 'extract-file', label: 'b. The same screenshot, graded',
      hint: 'graded in your image editor with global adjustments only, saved as PNG (or JPEG at quality 90+)',
      accept: '.png,.jpg,.jpeg,.ppm', onFiles: ([f]) => this.extract(f, extractResult) });
    mount.append(embedDrop.node, embedResult.node, extractDrop.node, extractResult.node);
  }

  async embed(file, result) {
    const original = this.originalLut();
    if (original.missing) {
      result.clear(original.missing);
      return;
    }
    const out = `${stem(file.name)}_patched.png`;
    const { files, names } = placeInputs([file, ...original.inputs], [out]);
    const args = ['embed', fileArg(names[0]), fileArg(out), ...original.args, ...names.slice(1).map(fileArg)];
    result.running(args, this.lane, 'Adding the patch');
    const record = await this.lane.run(args, files, { label: 'embed' });
    result.show(record, { downloads: [{ name: out }],
      summary: [`Grade ${out} in your image editor (the whole picture, global adjustments only), save it as PNG and drop it in b.`] });
  }

  async extract(file, result) {
    const out = 'color_grading_lut.nutexb';
    const { files, names } = placeInputs([file], [out]);
    const args = ['extract', fileArg(names[0]), out];
    result.running(args, this.lane, 'Reading your grade from the patch');
    const record = await this.lane.run(args, files, { label: 'extract' });
    result.show(record, { downloads: [{ name: out }],
      summary: [...summaryLines(record), 'It is now your grade in step 3: see it in step 4, make other files in step 5.'] });
    if (record.status === 'done' && record.exitCode === 0 && record.outputs[out])
      await this.grade.setLut(out, record.outputs[out], { origin: `extracted from ${file.name}` });
  }
}
