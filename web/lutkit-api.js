// SPDX-License-Identifier: Apache-2.0
// lutkit for the browser: the automation interface (docs/web.md). Appended to Emscripten's ES
// module (cmake/LutkitPortablePrograms.cmake, --extern-post-js), so lutkit.mjs exports both its
// factory (default) and createLutkit().
//
//   import { createLutkit } from './lutkit.mjs';
//   const lutkit = await createLutkit();                 // compiles lutkit.wasm once
//   const r = await lutkit.run(['convert', 'graded.png', 'color_grading_lut.nutexb'],
//                              { 'graded.png': bytes });
//   r.exitCode, r.stdout (text), r.stdoutBytes, r.stderr (text),
//   r.files['color_grading_lut.nutexb'] (a Uint8Array)
//
// Each run() is a fresh instance of the compiled module: the command runs as in a new process,
// with the same argv, exit codes, messages and output bytes as the native CLI, over an in-memory
// file system holding only the files given (relative names, folders allowed). `files` in the
// result holds every file the command wrote or changed.

const lutkitWorkDir = '/work';

function lutkitIsNode() {
  return typeof process === 'object' && typeof process.versions === 'object' &&
         typeof process.versions.node === 'string';
}

async function lutkitCompile(wasm) {
  if (wasm instanceof WebAssembly.Module)
    return wasm;
  if (wasm instanceof ArrayBuffer || ArrayBuffer.isView(wasm))
    return WebAssembly.compile(wasm);
  const url = wasm ? new URL(String(wasm), import.meta.url) : new URL('lutkit.wasm', import.meta.url);
  if (lutkitIsNode() && url.protocol === 'file:') {
    const fs = await import('fs');
    return WebAssembly.compile(fs.readFileSync(url));
  }
  const response = fetch(url);
  if (WebAssembly.compileStreaming) {
    try {
      return await WebAssembly.compileStreaming(response);
    } catch (e) {
      // A server that does not say application/wasm: compile the bytes instead.
    }
  }
  const r = await fetch(url);
  if (!r.ok)
    throw new Error(`lutkit: cannot load ${url}: HTTP ${r.status}`);
  return WebAssembly.compile(await r.arrayBuffer());
}

function lutkitMakeDirs(FS, path) {
  const parts = path.split('/').slice(0, -1);
  let at = '';
  for (const p of parts) {
    if (!p)
      continue;
    at += (at ? '/' : '') + p;
    try {
      FS.mkdir(at);
    } catch (e) {
      // exists
    }
  }
}

function lutkitWalk(FS, dir, prefix, out) {
  for (const name of FS.readdir(dir)) {
    if (name === '.' || name === '..')
      continue;
    const path = dir + '/' + name;
    const rel = prefix ? prefix + '/' + name : name;
    const st = FS.stat(path);
    if (FS.isDir(st.mode))
      lutkitWalk(FS, path, rel, out);
    else if (FS.isFile(st.mode))
      out.push([rel, path]);
  }
}

function lutkitSameBytes(a, b) {
  if (a.length !== b.length)
    return false;
  for (let i = 0; i < a.length; ++i)
    if (a[i] !== b[i])
      return false;
  return true;
}

// options.wasm: the URL (relative to lutkit.mjs), bytes or compiled WebAssembly.Module of
// lutkit.wasm (default: lutkit.wasm beside lutkit.mjs).
export async function createLutkit(options = {}) {
  if (lutkitIsNode()) {
    // Emscripten 3.1's Node code expects CommonJS's require and __dirname, which an ES module
    // does not have.
    const { createRequire } = await import('module');
    const { fileURLToPath } = await import('url');
    const path = await import('path');
    if (typeof globalThis.require === 'undefined')
      globalThis.require = createRequire(import.meta.url);
    if (typeof globalThis.__dirname === 'undefined')
      globalThis.__dirname = path.dirname(fileURLToPath(import.meta.url));
  }
  const compiled = await lutkitCompile(options.wasm);
  const decoder = new TextDecoder();
  const run = async (args, files = {}, runOptions = {}) => {
    const out = [];
    const err = [];
    let exitCode = null;
    const stdin = runOptions.stdin ? new Uint8Array(runOptions.stdin) : new Uint8Array(0);
    let stdinAt = 0;
    const mod = await createLutkitModule({
      noInitialRun: true,
      instantiateWasm(imports, done) {
        WebAssembly.instantiate(compiled, imports).then((instance) => done(instance, compiled));
        return {};
      },
      preRun: [(m) => {
        m.FS.init(() => (stdinAt < stdin.length ? stdin[stdinAt++] : null),
                  (c) => { if (c !== null) out.push(c); },
                  (c) => { if (c !== null) err.push(c); });
      }],
      onExit(code) {
        exitCode = code;
      },
      // The command's exit ends this instance, never the page or the Node process.
      quit(status, toThrow) {
        exitCode = status;
        throw toThrow;
      },
      print() {},
      printErr() {},
    });
    const FS = mod.FS;
    FS.mkdir(lutkitWorkDir);
    FS.chdir(lutkitWorkDir);
    const given = new Map();
    for (const [name, bytes] of Object.entries(files)) {
      if (!name || name.startsWith('/') || name.split('/').includes('..'))
        throw new Error(`lutkit: file names are relative to the work folder: ${name}`);
      const data = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
      lutkitMakeDirs(FS, name);
      FS.writeFile(name, data);
      given.set(name, data);
    }
    let returned;
    try {
      returned = mod.callMain(args.map(String));
    } catch (e) {
      if (exitCode === null && !(e && e.name === 'ExitStatus'))
        throw e;
    }
    if (exitCode === null)
      exitCode = typeof returned === 'number' ? returned : 1;
    const written = {};
    const all = [];
    lutkitWalk(FS, lutkitWorkDir, '', all);
    for (const [rel, path] of all) {
      const data = FS.readFile(path);
      const before = given.get(rel);
      if (!before || !lutkitSameBytes(before, data))
        written[rel] = data;
    }
    const stdoutBytes = new Uint8Array(out);
    return {
      exitCode,
      stdout: decoder.decode(stdoutBytes),
      stdoutBytes,
      stderr: decoder.decode(new Uint8Array(err)),
      files: written,
    };
  };
  return { run };
}
