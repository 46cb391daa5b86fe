// SPDX-License-Identifier: Apache-2.0
// The page's worker (a module worker): every lutkit command the page runs runs here, through
// lutkit.mjs's createLutkit().run(), never on the page's own thread (docs/web.md). One worker per
// lane (js/runner.js); the page replaces a worker that failed or was cancelled.
//
// Messages in:  {type: 'load'}
//               {type: 'run', id, args, files}        files: name -> Uint8Array (copied in)
//               {type: 'proxy', id, bytes, width}     a smaller PNG of a picture (the live proxy)
//               {type: 'crash', how}                  the page's self-test of a failed worker
// Messages out: {type: 'ready', ms} | {type: 'load-failed', error}
//               {type: 'result', id, result}          result as run() resolves (files transferred)
//               {type: 'failed', id, error}           run() threw: the instance died (e.g. out of
//                                                     memory outside lutkit's own checks)
import { createLutkit } from './lutkit.mjs';

let lutkit = null;

function describe(error) {
  if (error && typeof error === 'object') {
    const name = error.name || 'Error';
    const message = error.message || String(error);
    return `${name}: ${message}`;
  }
  return String(error);
}

function engine() {
  if (!lutkit)
    lutkit = createLutkit();
  return lutkit;
}

async function makeProxy(id, bytes, width) {
  // The browser's decoder, off the page's thread: only for the live picture while a slider moves
  // (the exact picture, lutkit's, replaces it when the slider settles).
  const blob = new Blob([bytes]);
  const probe = await createImageBitmap(blob);
  const scale = Math.min(1, width / probe.width);
  const w = Math.max(1, Math.round(probe.width * scale));
  const h = Math.max(1, Math.round(probe.height * scale));
  probe.close();
  const bitmap = await createImageBitmap(blob, {
    resizeWidth: w, resizeHeight: h, resizeQuality: 'medium',
    colorSpaceConversion: 'none', premultiplyAlpha: 'none',
  });
  const canvas = new OffscreenCanvas(w, h);
  canvas.getContext('2d').drawImage(bitmap, 0, 0);
  bitmap.close();
  const png = new Uint8Array(await (await canvas.convertToBlob({ type: 'image/png' })).arrayBuffer());
  self.postMessage({ type: 'proxy', id, bytes: png, width: w, height: h }, [png.buffer]);
}

self.onmessage = async (event) => {
  const msg = event.data;
  if (msg.type === 'load') {
    const t0 = performance.now();
    try {
      await engine();
      self.postMessage({ type: 'ready', ms: performance.now() - t0 });
    } catch (error) {
      lutkit = null;
      self.postMessage({ type: 'load-failed', error: describe(error) });
    }
  } else if (msg.type === 'run') {
    try {
      const result = await (await engine()).run(msg.args, msg.files);
      const transfer = [result.stdoutBytes.buffer];
      for (const data of Object.values(result.files))
        transfer.push(data.buffer);
      self.postMessage({ type: 'result', id: msg.id, result }, transfer);
    } catch (error) {
      self.postMessage({ type: 'failed', id: msg.id, error: describe(error) });
    }
  } else if (msg.type === 'proxy') {
    try {
      await makeProxy(msg.id, msg.bytes, msg.width);
    } catch (error) {
      self.postMessage({ type: 'failed', id: msg.id, error: describe(error) });
    }
  } else if (msg.type === 'crash') {
    // What a dying instance looks like to the page, for its tests (tests/web): an allocation that
    // fails outside lutkit's own checks, thrown from a run or left uncaught in the worker.
    const error = new RangeError('WebAssembly.Memory(): could not allocate memory (self-test)');
    if (msg.how === 'run')
      self.postMessage({ type: 'failed', id: msg.id, error: describe(error) });
    else
      setTimeout(() => { throw error; });
  }
};
