// SPDX-License-Identifier: Apache-2.0
// The command line a run is, as a POSIX shell reads it: what the page shows so the same command
// can be repeated with the native CLI (docs/web.md).

export function quote(word) {
  if (word !== '' && /^[A-Za-z0-9_.,:=+@%/-]+$/.test(word))
    return word;
  return `'${word.replace(/'/g, `'\\''`)}'`;
}

export function commandLine(args) {
  return ['lutkit', ...args].map(quote).join(' ');
}

// A file name as an argument: one that starts with '-' would be read as an option.
export function fileArg(name) {
  return name.startsWith('-') ? `./${name}` : name;
}

// Inputs under their own names, renamed only where two differ in bytes under one name or one has
// the name of an output; returns {files, names} (names: the name each input was given).
export function placeInputs(inputs, outputNames = []) {
  const files = {};
  const names = [];
  const taken = new Set(outputNames);
  for (const { name, bytes } of inputs) {
    let chosen = name;
    for (let n = 1; taken.has(chosen) && !(files[chosen] === bytes); ++n)
      chosen = n === 1 ? `in-${name}` : `in${n}-${name}`;
    files[chosen] = bytes;
    taken.add(chosen);
    names.push(chosen);
  }
  return { files, names };
}

export function formatBytes(n) {
  if (n < 1024)
    return `${n} bytes`;
  if (n < 1024 * 1024)
    return `${(n / 1024).toFixed(1)} KB`;
  return `${(n / 1024 / 1024).toFixed(1)} MB`;
}

export function stem(name) {
  const dot = name.lastIndexOf('.');
  return dot > 0 ? name.slice(0, dot) : name;
}

export function extension(name) {
  const dot = name.lastIndexOf('.');
  return dot > 0 ? name.slice(dot + 1).toLowerCase() : '';
}
