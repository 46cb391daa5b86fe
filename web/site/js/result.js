// SPDX-License-Identifier: Apache-2.0
// How a run is shown: its state, every line lutkit printed (errors and warnings marked, never
// hidden), the files to download and the command line to repeat it with the native CLI.
import { commandLine, formatBytes } from './shell.js';

const exitMeaning = {
  0: 'done',
  1: 'bad input or failed operation',
  2: 'bad usage',
  130: 'interrupted',
};

export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false)
      continue;
    if (key === 'class')
      node.className = value;
    else if (key === 'text')
      node.textContent = value;
    else if (key.startsWith('on'))
      node.addEventListener(key.slice(2), value);
    else
      node.setAttribute(key, value === true ? '' : value);
  }
  for (const child of children.flat()) {
    if (child !== null && child !== undefined && child !== false)
      node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

export function lineKind(line) {
  if (/(^|: )(error|fatal)\b|^lutkit: error/i.test(line) || /\berror:/.test(line))
    return 'error';
  if (/\bwarning\b/i.test(line))
    return 'warning';
  if (/\bnote:/.test(line))
    return 'note';
  return '';
}

export function countKinds(text) {
  const counts = { error: 0, warning: 0 };
  for (const line of text.split('\n')) {
    const kind = lineKind(line);
    if (kind === 'error' || kind === 'warning')
      counts[kind] += 1;
  }
  return counts;
}

function messages(record) {
  const text = [record.stdout, record.stderr].filter((t) => t && t.trim()).join('\n');
  if (!text)
    return null;
  const pre = el('pre', { class: 'messages', tabindex: '0', 'aria-label': 'What lutkit printed' });
  for (const line of text.replace(/\n+$/, '').split('\n')) {
    const kind = lineKind(line);
    pre.append(kind ? el('span', { class: `line-${kind}`, text: line }) : document.createTextNode(line), '\n');
  }
  return pre;
}

export function commandDetails(args, open = false) {
  const line = commandLine(args);
  const code = el('code', { text: line });
  const copy = el('button', { type: 'button', class: 'small', text: 'Copy',
    onclick: async () => {
      try {
        await navigator.clipboard.writeText(line);
        copy.textContent = 'Copied';
      } catch (error) {
        copy.textContent = 'Select the line to copy it';
      }
      setTimeout(() => { copy.textContent = 'Copy'; }, 2000);
    } });
  return el('details', { class: 'command', open },
    el('summary', { text: 'Command (the same with the native lutkit)' }), el('div', { class: 'command-line' }, code, copy));
}

const mimeOf = (name) => {
  if (/\.png$/i.test(name)) return 'image/png';
  if (/\.(cube|txt|spi3d)$/i.test(name)) return 'text/plain';
  return 'application/octet-stream';
};

export function blobUrl(bytes, name) {
  return URL.createObjectURL(new Blob([bytes], { type: mimeOf(name) }));
}

// A view of one card's result: running, a record, or cleared with a note.
export class ResultView {
  constructor(node, runner) {
    this.node = node;
    this.runner = runner;
    this.urls = [];
    this.timer = null;
    node.setAttribute('aria-live', 'polite');
  }

  reset() {
    clearInterval(this.timer);
    this.timer = null;
    for (const url of this.urls)
      URL.revokeObjectURL(url);
    this.urls = [];
    this.node.replaceChildren();
    this.node.className = 'result';
  }

  clear(note) {
    this.reset();
    if (note)
      this.node.append(el('p', { class: 'hint', text: note }));
  }

  running(args, lane, what) {
    this.reset();
    this.node.classList.add('is-running');
    const started = performance.now();
    const time = el('span', { class: 'elapsed', text: '0 s' });
    const cancel = el('button', { type: 'button', class: 'small', text: 'Cancel',
      onclick: () => lane.cancel() });
    this.node.append(el('p', { class: 'status status-running', role: 'status' },
      el('span', { class: 'spinner', 'aria-hidden': 'true' }),
      `${what || 'Working'}… `, time, ' ', cancel));
    if (args)
      this.node.append(commandDetails(args));
    this.timer = setInterval(() => {
      time.textContent = `${((performance.now() - started) / 1000).toFixed(0)} s`;
    }, 500);
  }

  // extras: {downloads: [{name, bytes?, label}], summary: [Node|string], ok: 'text', after: Node}
  show(record, extras = {}) {
    this.reset();
    const status = extras.verdict && record.status === 'done' ? extras.verdict : statusOf(record);
    this.node.classList.add(`is-${status.kind}`);
    this.node.dataset.exit = record.exitCode === null ? '' : String(record.exitCode);
    const statusLine = el('p', { class: `status status-${status.kind}`, role: status.kind === 'error' ? 'alert' : 'status' },
      el('strong', { text: status.title }), status.detail ? ` ${status.detail}` : '');
    this.node.append(statusLine);
    if (record.status === 'done' && record.exitCode === 0 && extras.summary && extras.summary.length)
      this.node.append(el('ul', { class: 'summary' }, extras.summary.map((s) => el('li', {}, s))));
    const succeeded = record.status === 'done' && (record.exitCode === 0 || Boolean(extras.verdict));
    if (succeeded && extras.downloads) {
      const list = el('div', { class: 'downloads' });
      for (const d of extras.downloads) {
        const bytes = d.bytes || record.outputs[d.file || d.name];
        if (!bytes) {
          list.append(el('p', { class: 'line-error', text: `lutkit did not write ${d.file || d.name}` }));
          continue;
        }
        const url = blobUrl(bytes, d.name);
        this.urls.push(url);
        list.append(el('a', { class: 'button download', href: url, download: d.name,
                              'data-file': d.name },
          `Download ${d.name}`, el('span', { class: 'size', text: ` (${formatBytes(bytes.length)})` })));
      }
      this.node.append(list);
    }
    if (extras.after)
      this.node.append(extras.after);
    const printed = messages(record);
    if (printed)
      this.node.append(printed);
    if (record.args)
      this.node.append(commandDetails(record.args, record.status === 'done' && record.exitCode !== 0));
  }

  addUrl(url) {
    this.urls.push(url);
  }
}

export function statusOf(record) {
  const seconds = `${(record.ms / 1000).toFixed(1)} s`;
  if (record.status === 'cancelled')
    return { kind: 'cancelled', title: 'Cancelled.', detail: 'Nothing was written.' };
  if (record.status === 'superseded')
    return { kind: 'cancelled', title: 'Replaced by a newer request.' };
  if (record.status === 'crashed')
    return { kind: 'error', title: 'lutkit stopped unexpectedly:',
             detail: `${record.error}. Nothing was written; lutkit was restarted for the next command (a smaller input, or closing other tabs, may help).` };
  const counts = countKinds(`${record.stdout}\n${record.stderr}`);
  if (record.exitCode !== 0) {
    const meaning = exitMeaning[record.exitCode] || 'failed';
    return { kind: 'error', title: `lutkit refused (exit ${record.exitCode}, ${meaning}):`,
             detail: 'see its message below. Nothing was written.' };
  }
  if (counts.warning)
    return { kind: 'warning', title: `Done in ${seconds}, with ${counts.warning} warning${counts.warning > 1 ? 's' : ''}:`,
             detail: 'read them below.' };
  return { kind: 'ok', title: `Done in ${seconds}.` };
}
