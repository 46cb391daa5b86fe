// SPDX-License-Identifier: Apache-2.0
// Runs lutkit.mjs's run() under Node for tests/web/node_runner.py: reads one JSON request per line
// ({args, files: {name: base64}, stdin: base64}) and prints one JSON result per line.
import readline from 'readline';
const site = process.argv[2];
const { createLutkit } = await import(site + '/lutkit.mjs');
const lk = await createLutkit();
const rl = readline.createInterface({ input: process.stdin });
for await (const line of rl) {
  const q = JSON.parse(line);
  const files = {};
  for (const [k, v] of Object.entries(q.files)) files[k] = Buffer.from(v, 'base64');
  const t0 = performance.now();
  const r = await lk.run(q.args, files, q.stdin ? { stdin: Buffer.from(q.stdin, 'base64') } : {});
  const out = {};
  for (const [k, v] of Object.entries(r.files)) out[k] = Buffer.from(v).toString('base64');
  process.stdout.write(JSON.stringify({ exitCode: r.exitCode, stdout: Buffer.from(r.stdoutBytes).toString('base64'),
    stderr: r.stderr, files: out, ms: performance.now() - t0 }) + '\n');
}
