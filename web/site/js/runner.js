// SPDX-License-Identifier: Apache-2.0
// Runs lutkit commands in Web Workers (worker.js), off the page's thread. A lane is one worker and
// its queue: commands of one lane run one after another, lanes run side by side (the page uses
// one lane for its commands and one for the live preview). A run resolves to a record, never
// rejects: its status says what happened, and the page shows every record.
//
//   status 'done'      the command ran: exitCode, stdout, stderr, outputs (name -> Uint8Array)
//          'crashed'   the worker failed (out of memory outside lutkit's own checks, a lost
//                      worker): error; the lane's worker is replaced, the next run gets a new one
//          'cancelled' the user stopped it (the worker is replaced)
//          'superseded' a newer run with the same key was asked for before this one started

let nextId = 1;

export class Runner {
  constructor(onEvent = () => {}) {
    this.onEvent = onEvent;
    this.lanes = new Map();
    this.failNextRun = null;
    this.workerUrl = new URL('../worker.js', import.meta.url);
  }

  lane(name) {
    if (!this.lanes.has(name))
      this.lanes.set(name, new Lane(this, name));
    return this.lanes.get(name);
  }

  emit(event) {
    try {
      this.onEvent(event);
    } catch (error) {
      console.error(error);
    }
  }
}

class Lane {
  constructor(runner, name) {
    this.runner = runner;
    this.name = name;
    this.queue = [];
    this.current = null;
    this.generation = 0;
    this.spawn();
  }

  spawn() {
    const generation = ++this.generation;
    this.state = 'loading';
    this.loadError = null;
    this.loadStarted = performance.now();
    this.runner.emit({ type: 'engine', lane: this.name, state: 'loading' });
    const worker = new Worker(this.runner.workerUrl, { type: 'module' });
    this.worker = worker;
    worker.onmessage = (event) => {
      if (generation === this.generation)
        this.onMessage(event.data);
    };
    const onError = (event) => {
      if (generation !== this.generation)
        return;
      if (event.preventDefault)
        event.preventDefault();
      const message = event.message || (event.type === 'messageerror'
        ? 'a message from the worker could not be read' : 'the worker stopped');
      this.onWorkerError(message);
    };
    worker.onerror = onError;
    worker.onmessageerror = onError;
    worker.postMessage({ type: 'load' });
  }

  replace() {
    this.worker.terminate();
    this.spawn();
  }

  onMessage(msg) {
    if (msg.type === 'ready') {
      this.state = 'ready';
      this.runner.emit({ type: 'engine', lane: this.name, state: 'ready',
                         ms: performance.now() - this.loadStarted, compileMs: msg.ms });
      this.pump();
      return;
    }
    if (msg.type === 'load-failed') {
      this.failLoad(msg.error);
      return;
    }
    const job = this.current;
    if (!job || job.id !== msg.id)
      return;
    this.current = null;
    if (msg.type === 'result') {
      const r = msg.result;
      this.finish(job, { status: 'done', exitCode: r.exitCode, stdout: r.stdout, stderr: r.stderr,
                         outputs: r.files });
    } else if (msg.type === 'proxy') {
      this.finish(job, { status: 'done', exitCode: 0, stdout: '', stderr: '',
                         outputs: {}, proxy: { bytes: msg.bytes, width: msg.width, height: msg.height } });
    } else if (msg.type === 'failed') {
      this.finish(job, { status: 'crashed', error: msg.error });
      this.replace();
      return;
    }
    this.pump();
  }

  onWorkerError(message) {
    if (this.state !== 'ready') {
      this.failLoad(message);
      return;
    }
    const job = this.current;
    this.current = null;
    if (job)
      this.finish(job, { status: 'crashed', error: message });
    this.replace();
  }

  failLoad(error) {
    this.state = 'failed';
    this.loadError = error;
    this.runner.emit({ type: 'engine', lane: this.name, state: 'failed', error });
    const jobs = this.queue.splice(0);
    if (this.current)
      jobs.unshift(this.current);
    this.current = null;
    for (const job of jobs)
      this.finish(job, { status: 'crashed', error: `lutkit did not load: ${error}` });
  }

  // args: the CLI's argv without "lutkit"; files: name -> Uint8Array (copied to the worker).
  // options.key: a newer run with the same key supersedes this one while it waits.
  run(args, files = {}, options = {}) {
    return this.enqueue({ kind: 'run', args: args.map(String), files, key: options.key,
                          label: options.label });
  }

  proxy(bytes, width, options = {}) {
    return this.enqueue({ kind: 'proxy', bytes, width, key: options.key, label: options.label,
                          args: null, files: {} });
  }

  enqueue(spec) {
    const job = { ...spec, id: nextId++, lane: this.name, inputs: Object.keys(spec.files || {}) };
    const promise = new Promise((resolve) => { job.resolve = resolve; });
    if (job.key) {
      for (const old of this.queue.filter((j) => j.key === job.key))
        this.finish(old, { status: 'superseded' });
      this.queue = this.queue.filter((j) => j.key !== job.key);
    }
    this.queue.push(job);
    this.runner.emit({ type: 'queued', record: this.record(job) });
    if (this.state === 'failed')
      this.finish(this.queue.pop(), { status: 'crashed', error: `lutkit did not load: ${this.loadError}` });
    else
      this.pump();
    return promise;
  }

  pump() {
    if (this.current || this.state !== 'ready' || !this.queue.length)
      return;
    const job = this.queue.shift();
    this.current = job;
    job.started = performance.now();
    this.runner.emit({ type: 'start', record: this.record(job) });
    // The page's self-test (tests/web) sets runner.failNextRun to 'run' (the run dies) or
    // 'uncaught' (the worker dies): what an allocation failing outside lutkit's checks does.
    const fail = job.kind === 'run' ? this.runner.failNextRun : null;
    if (fail) {
      this.runner.failNextRun = null;
      this.worker.postMessage({ type: 'crash', id: job.id, how: fail });
    } else if (job.kind === 'run')
      this.worker.postMessage({ type: 'run', id: job.id, args: job.args, files: job.files });
    else if (job.kind === 'proxy')
      this.worker.postMessage({ type: 'proxy', id: job.id, bytes: job.bytes, width: job.width });
  }

  // Stops the running command (the worker is replaced) and drops the waiting ones.
  cancel() {
    const jobs = this.queue.splice(0);
    const running = this.current;
    this.current = null;
    if (running) {
      this.finish(running, { status: 'cancelled' });
      this.replace();
    }
    for (const job of jobs)
      this.finish(job, { status: 'cancelled' });
  }

  // Stops the run with this key if it is running (the worker is replaced) and drops the waiting
  // ones: a newer request makes them pointless.
  cancelKey(key) {
    for (const job of this.queue.filter((j) => j.key === key))
      this.finish(job, { status: 'superseded' });
    this.queue = this.queue.filter((j) => j.key !== key);
    if (this.current && this.current.key === key) {
      const running = this.current;
      this.current = null;
      this.finish(running, { status: 'superseded' });
      this.replace();
    }
  }

  get busy() {
    return Boolean(this.current) || this.queue.length > 0;
  }

  record(job) {
    return { id: job.id, lane: job.lane, kind: job.kind, args: job.args, inputs: job.inputs,
             label: job.label, started: job.started };
  }

  finish(job, outcome) {
    if (!job || job.done)
      return;
    job.done = true;
    const ms = job.started === undefined ? 0 : performance.now() - job.started;
    const record = { ...this.record(job), ms, exitCode: null, stdout: '', stderr: '', outputs: {},
                     ...outcome };
    this.runner.emit({ type: 'end', record });
    job.resolve(record);
  }
}
