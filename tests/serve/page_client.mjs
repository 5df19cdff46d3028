// A client of `apprentice serve` that speaks HTTP as the page does: JSON
// requests with the CSRF header, and the session's Server-Sent Events read
// as they come. For the HTTP and load tests and the benchmark.
import fs from 'node:fs';
import path from 'node:path';

export function replies(sourceDir, file) {
  return fs.readFileSync(path.join(sourceDir, 'tests/serve', file), 'utf8')
    .split('\n').filter((line) => line.trim() !== '' && !line.startsWith('#'));
}

export class PageClient {
  constructor(base, headers = {}) {
    this.base = base.replace(/\?.*$/, '').replace(/\/$/, '');
    this.headers = headers;
  }

  // {status, body}: the body parsed as JSON where it is JSON.
  async request(method, route, body, headers = {}) {
    const options = { method, headers: { ...this.headers, ...headers }, redirect: 'manual' };
    if (body !== undefined) {
      options.headers['Content-Type'] ??= 'application/json';
      options.headers['X-Apprentice-Request'] ??= '1';
      options.body = typeof body === 'string' ? body : JSON.stringify(body);
    }
    const response = await fetch(this.base + route, options);
    const text = await response.text();
    let parsed = text;
    try { parsed = JSON.parse(text); } catch (e) { /* not JSON */ }
    return { status: response.status, body: parsed, headers: response.headers };
  }

  async start(world, store = '') {
    const r = await this.request('POST', '/api/sessions', { world, store });
    if (r.status !== 201) throw new Error('cannot start a session: ' + r.status + ' ' + JSON.stringify(r.body));
    return new SessionClient(this, r.body.id);
  }
}

// One session's events, read from its stream as they come; reconnects from
// the last event seen when the server closes the stream, as EventSource does.
export class SessionClient {
  constructor(client, id) {
    this.client = client;
    this.id = id;
    this.events = [];  // {seq, ...body}
    this.waiters = [];
    this.closed = false;
    this.controller = new AbortController();
    this.reading = this.read();
  }

  async read() {
    while (!this.closed) {
      const last = this.events.length ? this.events[this.events.length - 1].seq : 0;
      let response;
      try {
        response = await fetch(`${this.client.base}/api/sessions/${this.id}/events?after=${last}`,
                               { headers: this.client.headers, signal: this.controller.signal });
      } catch (e) {
        if (this.closed) return;
        throw e;
      }
      if (response.status !== 200) throw new Error('events: ' + response.status);
      const decoder = new TextDecoder();
      let buffer = '';
      try {
        for await (const chunk of response.body) {
          buffer += decoder.decode(chunk, { stream: true });
          let end;
          while ((end = buffer.indexOf('\n\n')) >= 0) {
            this.parse(buffer.slice(0, end));
            buffer = buffer.slice(end + 2);
          }
        }
      } catch (e) {
        if (this.closed) return;
      }
      if (this.events.some((e) => e.type === 'end')) return;
    }
  }

  parse(block) {
    let seq = null, data = null;
    for (const line of block.split('\n')) {
      if (line.startsWith('id: ')) seq = Number(line.slice(4));
      if (line.startsWith('data: ')) data = line.slice(6);
    }
    if (data === null) return;
    this.events.push({ seq, ...JSON.parse(data) });
    for (const w of this.waiters.splice(0)) w();
  }

  // The first event after `after` (a seq) that passes `test`.
  async waitFor(test, after = 0, timeoutMs = 30000) {
    const deadline = Date.now() + timeoutMs;
    for (;;) {
      const found = this.events.find((e) => e.seq > after && test(e));
      if (found) return found;
      if (Date.now() > deadline) throw new Error(`session ${this.id}: no such event in ${timeoutMs} ms; last: ` +
                                                 JSON.stringify(this.events.slice(-3).map((e) => e.text || e.type)));
      await new Promise((resolve) => {
        this.waiters.push(resolve);
        setTimeout(resolve, 200);
      });
    }
  }

  question(after = 0) { return this.waitFor((e) => e.type === 'question' || e.type === 'end', after); }

  reply(text, question) {
    return this.client.request('POST', `/api/sessions/${this.id}/reply`, { text, question });
  }

  // Answers each question with the next reply; resolves to the end event.
  async teach(lines) {
    let asked = await this.question();
    for (const line of lines) {
      if (asked.type === 'end') throw new Error(`session ${this.id} ended before "${line}"`);
      const r = await this.reply(line, asked.seq);
      if (r.status !== 200) throw new Error(`reply "${line}": ${r.status} ${JSON.stringify(r.body)}`);
      asked = await this.question(asked.seq);
    }
    return asked;
  }

  close() {
    this.closed = true;
    this.controller.abort();
  }
}
