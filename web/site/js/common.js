// SPDX-License-Identifier: Apache-2.0
// Pieces both sections use: the strength slider and the figures picked out of what lutkit printed.
import { el } from './result.js';

// A strength slider (0..2, the CLI's --strength). onChange(live): live while it moves, then once
// more (live = false) when it settles.
export function strengthControl(id, hint, onChange) {
  const input = el('input', { type: 'range', id, min: '0', max: '2', step: '0.05', value: '1',
                              'data-role': 'strength', 'aria-describedby': `${id}-hint` });
  const output = el('output', { for: id, class: 'value', text: '1.00' });
  const reset = el('button', { type: 'button', class: 'small', text: 'Reset to 1',
    onclick: () => { input.value = '1'; output.textContent = '1.00'; onChange(false); } });
  input.addEventListener('input', () => {
    output.textContent = Number(input.value).toFixed(2);
    onChange(true);
  });
  input.addEventListener('change', () => onChange(false));
  const node = el('div', { class: 'strength' },
    el('label', { for: id, text: 'Strength' }), input, output, reset,
    el('p', { class: 'hint', id: `${id}-hint`, text: hint }));
  return { node, input, get value() { return Number(input.value); } };
}

// The CLI's default is 1: no flag then, so the command line is the plain one.
export function strengthArgs(control) {
  const v = control.value;
  if (Math.abs(v - 1) < 1e-9)
    return [];
  return ['--strength', String(Number(v.toFixed(2)))];
}

const figures = [
  [/^\s*exact composition:\s*(.*?)\s*(\((written|not written)\))?\s*$/m,
    (m) => `In the game, against your grade (exact composition): ${m[1]}`],
  [/^\s*least-squares refinement:\s*(max .*?)\s*(\((written|not written)\))?\s*$/m,
    (m) => `In the game, refinement: ${m[1]}${m[2] ? ` ${m[2]}` : ''}`],
  [/^\s*over all inputs, between the lattice points too:\s*(.*)$/m,
    (m) => `Expected in-game error, over all inputs: ${m[1]}`],
  [/^\s*at the LUT's lattice points:\s*(.*)$/m, (m) => `Expected error at the LUT's points: ${m[1]}`],
  [/^resample\s+(.*)$/m, (m) => `Resampling: ${m[1]}`],
  [/^storage\s+\([^)]*\):\s*(.*?)(,\s*[\d.e+]+ ms)?$/m, (m) => `Storage: ${m[1]}`],
  [/^clamped\s+(.*)$/m, (m) => `Clamped: ${m[1]}`],
  [/^[Mm]ethod\s+(\S+)/m, (m) => `Method: ${m[1]}`],
  [/^before\s+(sliced Wasserstein.*)$/m, (m) => `Distance to the reference before: ${m[1]}`],
  [/^after\s+(sliced Wasserstein.*)$/m, (m) => `Distance to the reference after: ${m[1]}`],
];

// The figures a user looks for first, as lutkit printed them (the whole output is shown too).
export function summaryLines(record) {
  const text = `${record.stdout}\n${record.stderr}`;
  const lines = [];
  for (const [pattern, format] of figures) {
    const m = text.match(pattern);
    if (m)
      lines.push(format(m));
  }
  return lines;
}
