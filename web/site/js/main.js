// SPDX-License-Identifier: Apache-2.0
// The page: tabs, lutkit's state in the header, the list of every command run, and the two
// sections (js/modder.js, js/colourist.js). Every lutkit command runs in a worker (js/runner.js).
import { Runner } from './runner.js';
import { Modder } from './modder.js';
import { Colourist } from './colourist.js';
import { guardWindowDrops } from './filedrop.js';
import { el, statusOf } from './result.js';
import { commandLine } from './shell.js';

const page = { startedAt: performance.now(), readyAt: null, version: null, runs: [] };
window.lutkitPage = page;

// onShow(panelId): a section is built the first time its tab is shown (less work at the start).
function setupTabs(onShow) {
  const tabs = Array.from(document.querySelectorAll('[role="tab"]'));
  const select = (tab, focus, remember = true) => {
    for (const t of tabs) {
      const on = t === tab;
      t.setAttribute('aria-selected', on ? 'true' : 'false');
      t.tabIndex = on ? 0 : -1;
      document.getElementById(t.getAttribute('aria-controls')).hidden = !on;
    }
    onShow(tab.getAttribute('aria-controls'));
    if (focus)
      tab.focus();
    if (remember)
      history.replaceState(null, '', `#${tab.getAttribute('aria-controls')}`);
  };
  for (const tab of tabs) {
    tab.addEventListener('click', () => select(tab, false));
    tab.addEventListener('keydown', (event) => {
      const i = tabs.indexOf(tab);
      if (event.key === 'ArrowRight' || event.key === 'ArrowLeft') {
        event.preventDefault();
        select(tabs[(i + (event.key === 'ArrowRight' ? 1 : tabs.length - 1)) % tabs.length], true);
      }
    });
  }
  const fromHash = tabs.find((t) => `#${t.getAttribute('aria-controls')}` === location.hash);
  select(fromHash || tabs.find((t) => t.getAttribute('aria-selected') === 'true'), false, false);
}

function setupEngineStatus(runner) {
  const node = document.getElementById('engine');
  return (event) => {
    if (event.type !== 'engine' || event.lane !== 'main')
      return;
    node.dataset.state = event.state;
    if (event.state === 'loading')
      node.textContent = page.readyAt ? 'Restarting lutkit…' : 'Loading lutkit…';
    else if (event.state === 'failed')
      node.textContent = `lutkit did not load: ${event.error}`;
    else if (event.state === 'ready' && page.version)
      node.textContent = `${page.version} ready`;
  };
}

function setupLog() {
  const list = document.getElementById('log-list');
  const count = document.getElementById('log-count');
  const entries = new Map();
  return (event) => {
    if (event.type !== 'start' && event.type !== 'end')
      return;
    const r = event.record;
    if (r.kind !== 'run')
      return;
    let entry = entries.get(r.id);
    if (!entry) {
      entry = el('li', { class: 'log-entry', 'data-id': String(r.id) });
      entries.set(r.id, entry);
      list.prepend(entry);
      count.textContent = String(entries.size);
      while (list.children.length > 200) {
        const last = list.lastElementChild;
        entries.delete(Number(last.dataset.id));
        last.remove();
      }
    }
    if (event.type === 'start') {
      entry.className = 'log-entry is-running';
      entry.replaceChildren(el('code', { text: commandLine(r.args) }), el('span', { class: 'log-state', text: ' running…' }));
      return;
    }
    page.runs.push({ args: r.args, status: r.status, exitCode: r.exitCode, ms: r.ms, label: r.label });
    const status = statusOf(r);
    entry.className = `log-entry is-${status.kind}`;
    entry.dataset.exit = r.exitCode === null ? '' : String(r.exitCode);
    const text = [r.stdout, r.stderr, r.error].filter(Boolean).join('\n').trim();
    const what = r.status === 'done' ? `exit ${r.exitCode}, ${(r.ms / 1000).toFixed(1)} s` : r.status;
    entry.replaceChildren(
      el('details', {},
        el('summary', {}, el('code', { text: commandLine(r.args) }), el('span', { class: 'log-state', text: ` ${what}${r.label ? ` · ${r.label}` : ''}` })),
        text ? el('pre', { class: 'messages', text }) : el('p', { class: 'hint', text: 'It printed nothing.' })));
  };
}

async function start() {
  // Opened as a file: Chromium never gets here (it refuses this module); Firefox does, and runs
  // the page from the folder. The notice comes back if lutkit cannot load (docs/web.md).
  const fromFile = location.protocol === 'file:';
  document.documentElement.classList.remove('from-file');
  guardWindowDrops();
  const listeners = [];
  const runner = new Runner((event) => { for (const l of listeners) l(event); });
  listeners.push(setupEngineStatus(runner), setupLog());
  page.runner = runner;
  setupTabs((panel) => {
    if (panel === 'modder' && !page.modder)
      page.modder = new Modder(document.getElementById('modder'), runner);
    else if (panel === 'colourist' && !page.colourist)
      page.colourist = new Colourist(document.getElementById('colourist'), runner);
  });
  page.uiReadyAt = performance.now();
  document.documentElement.dataset.ui = 'ready';
  // The first command proves lutkit runs here, and names its version.
  const record = await runner.lane('main').run(['--version'], {}, { label: 'start' });
  const node = document.getElementById('engine');
  if (record.status === 'done' && record.exitCode === 0) {
    page.version = record.stdout.trim() || 'lutkit';
    page.readyAt = performance.now();
    node.dataset.state = 'ready';
    node.textContent = `${page.version} ready`;
    node.title = `${commandLine(record.args)} ran in ${record.ms.toFixed(0)} ms`;
    document.documentElement.dataset.engine = 'ready';
  } else {
    node.dataset.state = 'failed';
    node.textContent = `lutkit did not start: ${record.error || record.stderr || `exit ${record.exitCode}`}`;
    document.documentElement.dataset.engine = 'failed';
    if (fromFile)
      document.documentElement.classList.add('from-file', 'file-failed');
  }
}

start().catch((error) => {
  const node = document.getElementById('engine');
  node.dataset.state = 'failed';
  node.textContent = `The page failed to start: ${error.message || error}`;
  throw error;
});
