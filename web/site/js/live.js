// SPDX-License-Identifier: Apache-2.0
// A picture before and after a lutkit command (preview for the modder, apply for the colourist).
// The exact picture is always lutkit's own output at full size. While a slider is dragged, the
// same command runs on a smaller copy of the picture (the live proxy, made by the browser in the
// worker) so the picture follows the slider; the exact one replaces it when the slider settles,
// as the editor's proxy does.
import { FileDrop } from './filedrop.js';
import { el, ResultView, blobUrl } from './result.js';
import { fileArg, stem } from './shell.js';

const proxyWidth = 640;
const pictureAccept = '.png,.jpg,.jpeg,.ppm,.pgm,.pnm';

export class LivePicture {
  // options: {runner, id, label, hint, compare (Compare), suffix ('_in_game'), what ('Previewing'),
  //           makeArgs(inputName, outputName) -> {args, files} | {missing: 'why'}}
  constructor(options) {
    this.options = options;
    this.runner = options.runner;
    this.picture = null;
    this.seq = 0;
    this.shown = 0;
    this.compare = options.compare;
    this.drop = new FileDrop({ id: `${options.id}-file`, label: options.label, hint: options.hint,
                               accept: pictureAccept, onFiles: ([f]) => this.setPicture(f) });
    this.resultNode = el('div', { class: 'result' });
    this.result = new ResultView(this.resultNode);
    this.node = el('div', { class: 'live' }, this.drop.node, this.compare.node, this.resultNode);
  }

  get lane() {
    return this.runner.lane('pictures');
  }

  async setPicture(file) {
    const picture = { ...file, proxy: null };
    this.picture = picture;
    await this.compare.setImage('before', null);
    await this.compare.setImage('after', null, '');
    const url = blobUrl(file.bytes, file.name);
    const probe = new Image();
    probe.src = url;
    let shown = true;
    try {
      await probe.decode();
    } catch (error) {
      shown = false;
    }
    if (shown) {
      await this.compare.setImage('before', url, '');
    } else {
      URL.revokeObjectURL(url);
      // lutkit's refusal of the picture is shown; the same command on it would say it again.
      if (!await this.beforeByLutkit(file))
        return;
    }
    if (this.picture === picture)
      this.refresh();
  }

  // A picture the browser cannot draw (PPM, or one it refuses): lutkit writes it as PNG, unchanged
  // (an identity LUT gives every value back); false when lutkit refuses it too.
  async beforeByLutkit(file) {
    const out = `${stem(file.name)}_before.png`;
    const args = ['apply', '--lut', 'builtin:neutral', fileArg(file.name), '-o', fileArg(out)];
    const record = await this.lane.run(args, { [file.name]: file.bytes }, { label: 'before' });
    if (record.status === 'done' && record.exitCode === 0 && record.outputs[out]) {
      await this.compare.setImage('before', blobUrl(record.outputs[out], out), '');
      return true;
    }
    this.result.show(record);
    if (record.status === 'done')
      this.drop.refused(file.name);
    return false;
  }

  outputName() {
    return `${stem(this.picture.name)}${this.options.suffix}.png`;
  }

  // live: a slider is moving (the proxy); else the exact picture.
  async refresh(live = false) {
    if (!this.picture)
      return;
    const picture = this.picture;
    const seq = ++this.seq;
    if (live) {
      // The exact picture of an older setting is not worth waiting for.
      this.lane.cancelKey(`exact-${this.options.id}`);
      const proxy = await this.proxyOf(picture);
      if (!proxy || picture !== this.picture || seq < this.shown)
        return;
      const out = `${stem(proxy.name)}${this.options.suffix}.png`;
      const made = this.options.makeArgs(fileArg(proxy.name), out);
      if (made.missing)
        return;
      const files = { ...made.files, [proxy.name]: proxy.bytes };
      const record = await this.lane.run(made.args, files, { key: `live-${this.options.id}`, label: 'live proxy' });
      if (record.status !== 'done' || picture !== this.picture || seq < this.shown)
        return;
      if (record.exitCode === 0 && record.outputs[out]) {
        this.shown = seq;
        await this.compare.setImage('after', blobUrl(record.outputs[out], out),
          `Live view at ${proxy.width} px wide while you drag; the exact picture follows when you let go.`);
      }
      return;
    }
    const out = this.outputName();
    const made = this.options.makeArgs(fileArg(picture.name), out);
    if (made.missing) {
      await this.compare.setImage('after', null, made.missing);
      this.result.clear();
      return;
    }
    const files = { ...made.files, [picture.name]: picture.bytes };
    this.result.running(made.args, this.lane, this.options.what || 'Working');
    const record = await this.lane.run(made.args, files, { key: `exact-${this.options.id}`, label: 'exact' });
    if (record.status === 'superseded' || picture !== this.picture || seq < this.shown)
      return;
    this.shown = seq;
    const bytes = record.status === 'done' && record.exitCode === 0 ? record.outputs[out] : null;
    if (bytes) {
      await this.compare.setImage('after', blobUrl(bytes, out), 'After: the exact picture, lutkit\'s output at full size.');
      this.result.show(record, { downloads: [{ name: out }] });
    } else {
      await this.compare.setImage('after', null, 'No after picture: see lutkit\'s message below.');
      this.result.show(record);
      if (record.status === 'done' && record.stderr.includes(`${picture.name}:`))
        this.drop.refused(picture.name);
    }
  }

  proxyOf(picture) {
    if (!picture.proxy) {
      const name = `${stem(picture.name)}_live.png`;
      picture.proxy = this.lane.proxy(picture.bytes, proxyWidth, { label: 'live proxy' }).then((record) => {
        if (record.status !== 'done' || !record.proxy)
          return null;
        return { name, bytes: record.proxy.bytes, width: record.proxy.width };
      });
    }
    return picture.proxy;
  }
}
