// The HTTP face of `apprentice serve`: its token, Origin and CSRF checks,
// its limits (body, reply, sessions, idle time), requests that try to name
// a path, and two sessions on one store. Usage: node http_test.mjs BINARY SOURCE_DIR
import { test, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import path from 'node:path';
import { startServer, scratchDir } from './serve_process.mjs';
import { PageClient, replies } from './page_client.mjs';

const [binary, sourceDir] = process.argv.slice(2);
const scratch = scratchDir('apprentice-http-');
after(() => fs.rmSync(scratch, { recursive: true, force: true }));

// Runs one server for the test's body, then stops it (exit 0 expected).
async function withServer(args, body) {
  const server = await startServer(binary, args);
  try {
    await body(server, new PageClient(server.address));
  } finally {
    assert.equal(await server.stop(), 0, server.output());
  }
}

// A raw HTTP/1.1 request, for what fetch will not send (a foreign Host, a
// path with dot segments): the status line and the body.
function raw(port, request) {
  return new Promise((resolve, reject) => {
    const socket = net.connect(port, '127.0.0.1', () => socket.write(request));
    let data = '';
    socket.on('data', (d) => { data += d; });
    socket.on('end', () => resolve({ status: Number(data.split(' ')[1]), text: data }));
    socket.on('error', reject);
  });
}

test('a public --host needs --token; a short token is refused', () => {
  const open = spawnSync(binary, ['serve', '--host', '0.0.0.0', '--port', '0'], { encoding: 'utf8', timeout: 20000 });
  assert.equal(open.status, 2);
  assert.match(open.stderr, /--host 0\.0\.0\.0 lets other machines reach the page: give --token/);
  const short = spawnSync(binary, ['serve', '--port', '0', '--token', 'abc'], { encoding: 'utf8', timeout: 20000 });
  assert.equal(short.status, 2);
  assert.match(short.stderr, /--token must be at least 16 characters/);
});

test('a port already taken is exit 3, saying so', async () => {
  await withServer([], async (server) => {
    const second = spawnSync(binary, ['serve', '--port', String(server.port)], { encoding: 'utf8', timeout: 20000 });
    assert.equal(second.status, 3, second.stdout + second.stderr);
    assert.match(second.stderr, new RegExp(`cannot listen on 127\\.0\\.0\\.1:${server.port} \\(is another program using the port\\?\\)`));
  });
});

test('with a token, every request needs it: a wrong one is refused, the printed address sets a cookie', async () => {
  const token = 'serve-test-token-0123456789';
  await withServer(['--token', token], async (server, client) => {
    assert.match(server.address, new RegExp('\\?token=' + token + '$'));
    assert.equal((await client.request('GET', '/api/options')).status, 401);
    assert.equal((await client.request('GET', '/')).status, 401);
    const wrong = await client.request('GET', '/api/options', undefined, { 'X-Apprentice-Token': token + 'x' });
    assert.equal(wrong.status, 401);
    assert.match(wrong.body.error, /the token is wrong/);
    assert.equal((await client.request('POST', '/api/sessions', { world: 'tidy-kitchen' },
                                         { 'X-Apprentice-Token': 'nope' })).status, 401);
    assert.equal((await client.request('GET', '/api/options', undefined, { 'X-Apprentice-Token': token })).status, 200);
    const page = await client.request('GET', '/?token=' + token);
    assert.equal(page.status, 302);
    const cookie = page.headers.get('set-cookie');
    assert.match(cookie, /HttpOnly; SameSite=Strict/);
    const withCookie = await client.request('GET', '/', undefined, { Cookie: cookie.split(';')[0] });
    assert.equal(withCookie.status, 200);
    assert.match(withCookie.body, /<title>Teach apprentice<\/title>/);
  });
});

test('a foreign Origin, a foreign Host, a cross-site fetch and a request without the CSRF header are refused', async () => {
  await withServer([], async (server, client) => {
    const foreign = await client.request('POST', '/api/sessions', { world: 'tidy-kitchen' }, { Origin: 'http://evil.example' });
    assert.equal(foreign.status, 403);
    assert.match(foreign.body.error, /another site \(http:\/\/evil\.example\) are refused/);
    assert.equal((await client.request('GET', '/api/options', undefined, { Origin: 'http://evil.example' })).status, 403);
    assert.equal((await client.request('GET', '/api/options', undefined, { 'Sec-Fetch-Site': 'cross-site' })).status, 403);
    const noCsrf = await client.request('POST', '/api/sessions', { world: 'tidy-kitchen' }, { 'X-Apprentice-Request': '0' });
    assert.equal(noCsrf.status, 403);
    assert.match(noCsrf.body.error, /X-Apprentice-Request: 1/);
    const form = await client.request('POST', '/api/sessions', 'world=tidy-kitchen',
                                      { 'Content-Type': 'application/x-www-form-urlencoded' });
    assert.equal(form.status, 415);
    const rebound = await raw(server.port, 'GET /api/options HTTP/1.1\r\nHost: attacker.example:' + server.port + '\r\nConnection: close\r\n\r\n');
    assert.equal(rebound.status, 403);
    const same = await client.request('POST', '/api/sessions', { world: 'tidy-kitchen' }, { Origin: 'http://127.0.0.1:' + server.port });
    assert.equal(same.status, 201);
  });
});

test('limits: an oversized body, an oversized world, a reply too long, too many sessions', async () => {
  await withServer(['--max-sessions', '2'], async (server, client) => {
    const huge = await client.request('POST', '/api/sessions', { world: 'tidy-kitchen', padding: 'x'.repeat(400 * 1024) });
    assert.equal(huge.status, 413);
    const bigWorld = await client.request('POST', '/api/sessions', { upload: { name: 'big.yaml', yaml: '#'.repeat(300 * 1024) } });
    assert.equal(bigWorld.status, 400);
    assert.match(bigWorld.body.error, /big\.yaml: the world is larger than 256 KiB/);
    const first = await client.start('tidy-kitchen');
    const second = await client.start('playroom');
    const third = await client.request('POST', '/api/sessions', { world: 'tidy-kitchen' });
    assert.equal(third.status, 503);
    assert.match(third.body.error, /already teaching 2 sessions/);
    const asked = await first.question();
    const long = await first.reply('a'.repeat(2001), asked.seq);
    assert.equal(long.status, 413);
    assert.match(long.body.error, /at most 2000 characters; this one has 2001/);
    assert.equal((await first.reply('   ', asked.seq)).status, 400);
    // A stale question number (answered in another tab) is refused, not misread.
    assert.equal((await first.reply('tidy the kitchen', asked.seq + 5)).status, 409);
    assert.equal((await first.reply('tidy the kitchen', asked.seq)).status, 200);
    assert.equal((await first.reply('clear the table', asked.seq)).status, 409);
    // A session that ends frees its place.
    const stop = await second.question();
    assert.equal((await second.reply('quit', stop.seq)).status, 200);
    const end = await second.waitFor((e) => e.type === 'end');
    assert.match(end.text, /^Stopped: 1 of 14 parts of the goal is met, after 0 instructions\./);
    const fourth = await client.start('tidy-kitchen');
    first.close(); second.close(); fourth.close();
  });
});

test('limits: an uploaded world of a few lines that asks for millions of things, or aliases of aliases, is refused at once', async () => {
  await withServer([], async (server, client) => {
    const head = 'name: many\ndomain: ../domains/kitchen.pddl\nplaces:\n  - {category: floor, kind: surface}\n' +
                 '  - {category: bin, kind: receptacle}\n';
    const entries = Array.from({ length: 30 }, () => '  - {category: block, at: floor1, count: 100000}');
    const tail = '\ntask:\n  name: tidy\n  subtasks:\n    - {verb: clear, place: floor1}\n' +
                 'intent:\n  - {subtask: clear, category: block, place: bin1}\n';
    const many = await client.request('POST', '/api/sessions', { upload: { name: 'many.yaml', yaml: head + 'objects:\n' + entries.join('\n') + tail } });
    assert.equal(many.status, 400);
    assert.equal(many.body.error, 'many.yaml:6: the world has 3000000 things; an uploaded world may have at most 1000');
    const places = Array.from({ length: 101 }, (_, i) => `  - {category: shelf, kind: surface}`).join('\n');
    const wide = await client.request('POST', '/api/sessions', {
      upload: { name: 'wide.yaml', yaml: 'name: wide\ndomain: ../domains/kitchen.pddl\nplaces:\n' + places + '\nobjects: []\n' } });
    assert.equal(wide.status, 400);
    assert.equal(wide.body.error, 'wide.yaml: the world has 101 places; an uploaded world may have at most 100');
    // Twelve levels of nine aliases: 9^12 lists if each alias were walked.
    let bomb = 'a0: &a0 [x, x, x, x, x, x, x, x, x]\n';
    for (let level = 1; level <= 12; ++level) bomb += `a${level}: &a${level} [${Array(9).fill('*a' + (level - 1)).join(', ')}]\n`;
    const aliases = await client.request('POST', '/api/sessions', { upload: { name: 'aliases.yaml', yaml: bomb + head } });
    assert.equal(aliases.status, 400);
    assert.match(aliases.body.error, /^aliases\.yaml:1:1: unknown key 'a0'/);
    const limits = (await client.request('GET', '/api/options')).body.limits;
    assert.equal(limits.max_world_things, 1000);
    assert.equal(limits.max_world_places, 100);
    // The server goes on: a session starts.
    (await client.start('tidy-kitchen')).close();
  });
});

test('limits: event streams open at once, twice the sessions plus 8', async () => {
  await withServer(['--max-sessions', '1'], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    await session.question();  // its own stream is the first
    const streams = [];
    const open = async () => {
      const controller = new AbortController();
      const response = await fetch(`${client.base}/api/sessions/${session.id}/events`, { signal: controller.signal });
      streams.push(controller);
      return response;
    };
    for (let i = 1; i < 10; ++i) assert.equal((await open()).status, 200, 'stream ' + (i + 1));
    const refused = await open();
    assert.equal(refused.status, 503);
    assert.match((await refused.json()).error, /too many pages are open on this server; close some/);
    // Replies still find a thread.
    const asked = await session.question();
    assert.equal((await session.reply('tidy the kitchen', asked.seq)).status, 200);
    assert.equal((await session.question(asked.seq)).text, 'What should I do first to tidy the kitchen?');
    for (const s of streams) s.abort();
    session.close();
  });
});

test('a dropped event stream, opened again with Last-Event-ID as the browser does, goes on after that event', async () => {
  await withServer([], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    const asked = await session.question();
    assert.equal((await session.reply('tidy the kitchen', asked.seq)).status, 200);
    const next = await session.question(asked.seq);
    session.close();
    // What the page's EventSource sends when it reconnects: the last event it saw.
    const controller = new AbortController();
    const response = await fetch(`${client.base}/api/sessions/${session.id}/events`,
                                 { headers: { 'Last-Event-ID': String(asked.seq) }, signal: controller.signal });
    assert.equal(response.status, 200);
    assert.equal(response.headers.get('content-type'), 'text/event-stream');
    let text = '';
    const decoder = new TextDecoder();
    for await (const chunk of response.body) {
      text += decoder.decode(chunk, { stream: true });
      if (text.includes(`id: ${next.seq}\n`)) break;
    }
    controller.abort();
    const ids = [...text.matchAll(/^id: (\d+)$/gm)].map((m) => Number(m[1]));
    assert.equal(ids[0], asked.seq + 1, 'the first event after the one seen');
    assert.ok(ids.includes(next.seq));
    assert.match(text, /"type":"reply"/);
    assert.doesNotMatch(text, /What task should I learn\?/, 'an event seen before is sent again');
  });
});

test('a page that goes away gives its event stream back within seconds, not at the next heartbeat', async (t) => {
  await withServer(['--max-sessions', '1'], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    await session.question();
    const streams = [];
    const open = async () => {
      const controller = new AbortController();
      const response = await fetch(`${client.base}/api/sessions/${session.id}/events`, { signal: controller.signal });
      if (response.status === 200) streams.push(controller);
      return response.status;
    };
    while ((await open()) === 200) assert.ok(streams.length <= 10, 'more than twice the sessions plus 8 streams');
    assert.equal(streams.length, 9, 'the session\'s own stream and 9 more fill the 10 places');
    // The pages go away (a tab closed drops its connection as an abort does):
    // once the server has seen it, the places are free again. It used to
    // see it only when a heartbeat 15 s later failed, up to 30 s after.
    for (const s of streams.splice(0)) s.abort();
    session.close();
    const began = Date.now();
    let free = 0;
    while (free < 10) {
      assert.ok(Date.now() - began < 8000, `only ${free} of 10 stream places were free again after 8 s`);
      if ((await open()) === 200) ++free;
      else await new Promise((resolve) => setTimeout(resolve, 100));
    }
    t.diagnostic(`all 10 places free again ${Date.now() - began} ms after the pages went away`);
    for (const s of streams) s.abort();
  });
});

test('the page carries its options, and names its script and style by version, which the browser may keep', async () => {
  await withServer([], async (server, client) => {
    const page = await client.request('GET', '/');
    assert.equal(page.status, 200);
    assert.equal(page.headers.get('cache-control'), 'no-cache');
    const block = /<script type="application\/json" id="server-options">([^<]*)<\/script>/.exec(page.body);
    assert.ok(block, 'the page has no options block');
    assert.deepEqual(JSON.parse(block[1]), (await client.request('GET', '/api/options')).body);
    for (const file of ['app.js', 'style.css']) {
      const named = new RegExp(`"/${file.replace('.', '\\.')}\\?v=([0-9a-f]{16})"`).exec(page.body);
      assert.ok(named, file + ' is not named by version');
      const kept = await client.request('GET', `/${file}?v=${named[1]}`);
      assert.equal(kept.status, 200);
      assert.equal(kept.headers.get('cache-control'), 'max-age=31536000, immutable');
      assert.equal(kept.body, fs.readFileSync(path.join(sourceDir, 'data/web', file), 'utf8'));
      // Never compressed, though the browser offers brotli: httplib's
      // brotli, at its slowest quality on every request, was most of a
      // first page load's time.
      const asBrowser = await client.request('GET', `/${file}?v=${named[1]}`, undefined,
                                             { 'Accept-Encoding': 'gzip, deflate, br, zstd' });
      assert.equal(asBrowser.headers.get('content-encoding'), null, file);
      assert.equal(asBrowser.body, kept.body);
      // Any other version, or none, is checked each time.
      assert.equal((await client.request('GET', `/${file}?v=0000000000000000`)).headers.get('cache-control'), 'no-cache');
      assert.equal((await client.request('GET', `/${file}`)).headers.get('cache-control'), 'no-cache');
    }
    const browser = { 'Accept-Encoding': 'gzip, deflate, br, zstd' };
    for (const route of ['/', '/api/options', '/nothing-here', '/api/sessions/' + '0'.repeat(32)]) {
      const answer = await client.request('GET', route, undefined, browser);
      assert.equal(answer.headers.get('content-encoding'), null, route);
    }
    assert.equal((await client.request('GET', '/nothing-here', undefined, browser)).body.error, 'there is nothing here');
    assert.match((await client.request('GET', '/api/sessions/' + '0'.repeat(32), undefined, browser)).body.error,
                 /^there is no such session/);
  });
});

test('a session idle past --idle-seconds ends, keeping what it learned, and is forgotten later', async () => {
  const store = path.join(scratch, 'idle.sqlite');
  // 5 s, not 1: under a loaded CI machine the reply that follows a question
  // can take over a second to come, which ended the session too soon.
  await withServer(['--idle-seconds', '5', '--knowledge', store], async (server, client) => {
    const session = await client.start('tidy-kitchen', 'idle');
    let asked = await session.question();
    for (const line of ['tidy the kitchen', 'clear the table', 'plates go in the dishwasher, close it']) {
      await session.reply(line, asked.seq);
      asked = await session.question(asked.seq);
    }
    const end = await session.waitFor((e) => e.type === 'end', 0, 20000);
    assert.match(end.text, /^Stopped: .*What you taught me is kept in the knowledge store "idle"\./);
    assert.ok(session.events.some((e) => e.type === 'say' && e.text === 'No reply came for 5 seconds, so this session has ended.'));
    session.close();
    const deadline = Date.now() + 10000;
    while ((await client.request('GET', '/api/sessions/' + session.id)).status !== 404)
      assert.ok(Date.now() < deadline, 'the ended session was never forgotten');
  });
  const known = spawnSync(binary, ['knowledge', '--knowledge', store, '--json'], { encoding: 'utf8' });
  assert.equal(known.status, 0, known.stderr);
  assert.deepEqual(JSON.parse(known.stdout).goals.map((g) => g.text.includes('ceramic-plate')), [true]);
});

test('an "Is there more?" question offers "There is more" and "That\'s all", each read as if typed', async () => {
  await withServer([], async (server, client) => {
    const asked = [];
    for (const ending of ["that's all", 'there is more']) {
      const session = await client.start('tidy-kitchen');
      const question = await session.teach(['tidy the kitchen', 'repeat while something is on the table', 'clear the table',
                                            'plates and glasses go in the dishwasher, close it']);
      assert.equal(question.text, 'Is there more to clear on the table, or is that all?');
      assert.equal(question.kind, 'subtask-step');
      assert.deepEqual(question.choices, [{ label: 'There is more', reply: 'there is more' }, { label: "That's all", reply: "that's all" }]);
      const choice = question.choices.find((c) => c.reply === ending);
      assert.equal((await session.reply(choice.reply, question.seq)).status, 200);
      const next = await session.question(question.seq);
      const said = session.events.filter((e) => e.seq > question.seq && e.seq < next.seq && e.type === 'say').map((e) => e.text);
      asked.push([said[0], next.text, next.choices]);
      session.close();
    }
    // "That's all": one thing was the whole part, and the task goes on.
    assert.deepEqual(asked[0], ['So that is all there is to clear for one thing.', 'What should I do next to tidy the kitchen?', []]);
    // "There is more": the rest of the table the same way, then a thing it does not know.
    assert.deepEqual(asked[1], ['So I clear everything else on the table the same way.', 'Where should the metal fork on the table go?', []]);
  });
});

test('an ending in the middle of a part is asked back as a yes/no, with Yes and No, and "yes" leaves the rest', async () => {
  await withServer([], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    const question = await session.teach(['tidy the kitchen', 'clear the table', "I'm done"]);
    assert.equal(question.kind, 'confirm');
    assert.match(question.text, /^There are still \d+ things on the table: .* Shall I leave them\?$/);
    assert.deepEqual(question.choices, [{ label: 'Yes', reply: 'yes' }, { label: 'No', reply: 'no' }]);
    assert.equal((await session.reply('yes', question.seq)).status, 200);
    const next = await session.question(question.seq);
    assert.equal(next.text, 'What should I do next to tidy the kitchen?');
    session.close();
  });
});

test('--condition and --llm as for teach: the LLM\'s goal is offered as a yes/no, and the log names the condition', async () => {
  // Two recorded statements that agree, for the first plate on the table.
  const corpus = path.join(scratch, 'plate-goals.jsonl');
  const line = (rank) => JSON.stringify({ condition: 'TBP', object: 'ceramic-plate', start_location: 'table', subtask: 'clear', rank,
                                          response: 'the goal is that the ceramic-plate is in the dishwasher and the dishwasher is closed' });
  fs.writeFileSync(corpus, line(0) + '\n' + line(1) + '\n');
  await withServer(['--condition', 'inst+llm', '--llm', 'corpus:' + corpus], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    const asked = await session.teach(['tidy the kitchen', 'clear the table']);
    assert.equal(asked.kind, 'confirm-goal');
    assert.match(asked.text, /For a ceramic plate on the table, is the goal that the ceramic plate is in the dishwasher and the dishwasher is closed\?$/);
    assert.deepEqual(asked.choices.map((c) => c.reply), ['yes', 'no']);
    assert.equal((await session.reply('yes', asked.seq)).status, 200);
    await session.question(asked.seq);
    assert.ok(session.events.some((e) => e.type === 'say' && e.text === 'So the ceramic plate goes in the dishwasher, and the dishwasher ends closed.'));
    assert.equal(session.events.find((e) => e.type === 'start').condition, 'inst+llm');
    session.close();
  });
  // Without the LLM the default condition asks where the plate goes.
  await withServer([], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    const asked = await session.teach(['tidy the kitchen', 'clear the table']);
    assert.equal(asked.text, 'Where should the ceramic plate on the table go?');
    assert.equal(session.events.find((e) => e.type === 'start').condition, 'inst+search4');
    session.close();
  });
});

test('a wrong --condition, an LLM condition without an LLM, and an LLM that does not answer stop serve before it listens', async () => {
  const env = { ...process.env };
  delete env.APPRENTICE_LLM;
  const run = (args) => spawnSync(binary, ['serve', '--port', '0', ...args], { encoding: 'utf8', timeout: 60000, env });
  const unknown = run(['--condition', 'inst+telepathy']);
  assert.equal(unknown.status, 2, unknown.stderr);
  assert.doesNotMatch(unknown.stdout, /open http/);
  const noLlm = run(['--condition', 'inst+llm']);
  assert.equal(noLlm.status, 2, noLlm.stderr);
  assert.match(noLlm.stderr, /condition inst\+llm needs an LLM: pass --llm SPEC/);
  // A port nothing listens on.
  const closed = await new Promise((resolve) => {
    const probe = net.createServer().listen(0, '127.0.0.1', () => {
      const { port } = probe.address();
      probe.close(() => resolve(port));
    });
  });
  const llm = ['--condition', 'inst+llm', '--llm', `openai:http://127.0.0.1:${closed}/v1`, '--llm-timeout-ms', '2000',
               '--llm-connect-timeout-ms', '1000'];
  const dead = run(llm);
  assert.equal(dead.status, 4, dead.stdout + dead.stderr);
  assert.doesNotMatch(dead.stdout, /open http/);
  // With --llm-optional it serves, without the LLM, and says so.
  await withServer([...llm, '--llm-optional'], async (server, client) => {
    assert.match(server.output(), /The LLM does not answer, so the sessions go on without it \(--llm-optional\): cannot get an answer from the LLM server at http:\/\/127\.0\.0\.1:\d+\/v1\/completions: .*\.\n/);
    const session = await client.start('tidy-kitchen');
    const asked = await session.teach(['tidy the kitchen', 'clear the table']);
    assert.equal(asked.text, 'Where should the ceramic plate on the table go?');
    session.close();
  });
});

test('nothing a client sends names a path', async () => {
  const outside = path.join(scratch, 'outside.sqlite');
  await withServer([], async (server, client) => {
    for (const world of ['../../../../etc/passwd', '/etc/passwd', 'tidy-kitchen.yaml', '../scenarios/tidy-kitchen']) {
      const r = await client.request('POST', '/api/sessions', { world });
      assert.equal(r.status, 404, world);
      assert.match(r.body.error, /this server offers no world named .*; it offers dish-tower, /);
    }
    for (const store of [outside, '../outside', 'outside.sqlite']) {
      const r = await client.request('POST', '/api/sessions', { world: 'tidy-kitchen', store });
      assert.equal(r.status, 404, store);
      assert.match(r.body.error, /no knowledge store named .*it has none/);
    }
    assert.equal(fs.existsSync(outside), false);
    for (const domain of ['/etc/passwd', '../../../../etc/hosts', 'kitchen.pddl']) {
      const yaml = `name: sneaky\ndomain: ${domain}\nplaces: []\nobjects: []\n`;
      const r = await client.request('POST', '/api/sessions', { upload: { name: '../../etc/sneaky.yaml', yaml } });
      assert.equal(r.status, 400, domain);
      assert.match(r.body.error, /^sneaky\.yaml:2: an uploaded world must use one of the server's domains: \.\.\/domains\/kitchen\.pddl or \.\.\/domains\/kitchen-stacking\.pddl, not /);
      assert.doesNotMatch(r.body.error, /root:/);
    }
    for (const route of ['/../../../etc/passwd', '/%2e%2e/%2e%2e/etc/passwd', '/app.js/../../../../etc/passwd',
                         '/api/sessions/..%2f..%2fetc%2fpasswd/log', '/data/scenarios/tidy-kitchen.yaml', '/style.css%00.html']) {
      const r = await raw(server.port, `GET ${route} HTTP/1.1\r\nHost: 127.0.0.1:${server.port}\r\nConnection: close\r\n\r\n`);
      assert.ok(r.status === 404 || r.status === 400, route + ': ' + r.status);
      assert.doesNotMatch(r.text, /root:|intent:/, route);
    }
  });
});

test("the page's agent is teach's: the same replies get the same sentences and the same counts", async () => {
  // With an undo on the way (the page's Undo button sends "undo"), and the reply it took back said again.
  const kitchen = replies(sourceDir, 'kitchen_replies.txt');
  const cereal = kitchen.indexOf('the cereal box goes in the pantry and shut it');
  assert.ok(cereal > 0);
  kitchen.splice(cereal + 1, 0, 'undo', kitchen[cereal]);
  const scenario = path.join(sourceDir, 'data/scenarios/tidy-kitchen.yaml');
  const teach = spawnSync(binary, ['teach', '--scenario', scenario], { input: kitchen.join('\n') + '\n', encoding: 'utf8', timeout: 60000 });
  assert.equal(teach.status, 0, teach.stderr);
  const atTerminal = teach.stdout.split('\n').filter((l) => l.startsWith('Agent: ')).map((l) => l.slice('Agent: '.length));
  const summary = /The task is learned: 35 of 35 parts of the goal are met, after (\d+) instructions\./.exec(teach.stdout);
  assert.ok(summary, teach.stdout.slice(-400));
  await withServer([], async (server, client) => {
    const session = await client.start('tidy-kitchen');
    const end = await session.teach(kitchen);
    session.close();
    assert.equal(end.type, 'end');
    assert.equal(end.finished, true);
    assert.equal(end.instructions, Number(summary[1]));
    const onThePage = session.events.filter((e) => e.type === 'question' || e.type === 'say').map((e) => e.text);
    assert.deepEqual(onThePage, atTerminal);
  });
});

test('two sessions on one store, teaching at once, lose nothing', async () => {
  const store = path.join(scratch, 'shared.sqlite');
  const logs = path.join(scratch, 'study-logs');
  let ids;
  await withServer(['--knowledge', store, '--log-dir', logs], async (server, client) => {
    const a = await client.start('tidy-kitchen', 'shared');
    const b = await client.start('tidy-kitchen', 'shared');
    const kitchen = replies(sourceDir, 'kitchen_replies.txt');
    // a teaches the table; b, at the same time, the counter.
    const counter = [kitchen[0], 'put away what is on the counter', ...kitchen.slice(14, 21), 'quit'];
    const [endA, endB] = await Promise.all([a.teach([...kitchen.slice(0, 13), 'quit']), b.teach(counter)]);
    assert.equal(endA.type, 'end');
    assert.equal(endB.type, 'end');
    ids = [a.id, b.id];
    // --log-dir keeps each session's log as the page downloads it.
    for (const s of [a, b]) {
      const downloaded = await client.request('GET', `/api/sessions/${s.id}/log`);
      assert.equal(fs.readFileSync(path.join(logs, s.id + '.jsonl'), 'utf8'), downloaded.body);
    }
    a.close(); b.close();
  });
  assert.deepEqual(fs.readdirSync(logs).sort(), ids.map((id) => id + '.jsonl').sort());
  for (const id of ids) {
    const lines = fs.readFileSync(path.join(logs, id + '.jsonl'), 'utf8').trim().split('\n').map((l) => JSON.parse(l));
    assert.equal(lines[0].type, 'start');
    assert.equal(lines.at(-1).type, 'end');
    assert.ok(lines.every((l) => !('world' in l)), 'the log holds no drawings of the room');
  }
  const known = spawnSync(binary, ['knowledge', '--knowledge', store, '--json'], { encoding: 'utf8' });
  assert.equal(known.status, 0, known.stderr);
  const kinds = new Set(JSON.parse(known.stdout).goals.map((g) => /\(([a-z-]+)\)/.exec(g.object)[1]));
  for (const kind of ['ceramic-plate', 'ketchup', 'pepsi-can', 'mug', 'coffee-grinder', 'newspaper'])
    assert.ok(kinds.has(kind), kind + ' was lost: ' + [...kinds].join(', '));
});
