// The speed of `apprentice serve` on this machine: a reply's round trip
// (from the POST of a reply to the agent's next question arriving on the
// page's event stream) with 20 sessions teaching at once, and how long the
// page takes to load, in Debian's chromium. A benchmark, not a test: it
// prints figures (docs/benchmarks.md, "apprentice serve") and fails on
// nothing but errors.
//
// Usage: node bench/serve_bench.mjs [BINARY] [--think MS] [--rounds N]
//   --think MS  each teacher waits a random 0.5 to 1.5 times MS before each
//               reply, as a person reads and types (default 1000; 0: replies
//               at once, every session saturating the server)
//   --rounds N  teach each session's world N times over (default 2)
//   --sessions N  sessions teaching at once (default 20)
//   --loads-only  time the page's loads alone, with no sessions teaching
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { startServer, scratchDir, chromiumFlags } from '../tests/serve/serve_process.mjs';
import { PageClient, replies } from '../tests/serve/page_client.mjs';

const sourceDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const option = (name, fallback) => (args.includes(name) ? Number(args[args.indexOf(name) + 1]) : fallback);
const binary = args[0] && !args[0].startsWith('--') ? args[0] : path.join(sourceDir, 'build/apprentice');
const think = option('--think', 1000);
const rounds = option('--rounds', 2);
const SESSIONS = option('--sessions', 20);
const loadsOnly = args.includes('--loads-only');

function percentile(values, p) {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.min(sorted.length - 1, Math.ceil((p / 100) * sorted.length) - 1)];
}
const describe = (values) => `n=${values.length} p50=${percentile(values, 50).toFixed(1)} ms ` +
  `p95=${percentile(values, 95).toFixed(1)} ms max=${Math.max(...values).toFixed(1)} ms`;
// The server's CPU time so far (user + system), in ms, from /proc: what a
// reply costs whatever else the machine is doing.
function cpuMs(pid) {
  const fields = fs.readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
  return (Number(fields[11]) + Number(fields[12])) * 10;  // clock ticks of 10 ms
}
const pause = (ms) => new Promise((resolve) => setTimeout(resolve, ms));

// One teacher over HTTP: the round trip of each reply.
async function teachOverHttp(client, world, lines, times) {
  for (let round = 0; round < rounds; ++round) {
    const session = await client.start(world);
    let asked = await session.question();
    for (const line of lines) {
      if (think > 0) await pause(think * (0.5 + Math.random()));
      const sent = performance.now();
      const r = await session.reply(line, asked.seq);
      if (r.status !== 200) throw new Error(`${world}: "${line}": ${r.status} ${JSON.stringify(r.body)}`);
      asked = await session.question(asked.seq);
      times.push(performance.now() - sent);
    }
    session.close();
  }
}

// One teacher in the browser: from pressing Enter to the next question
// shown in the conversation, measured in the page.
async function teachInPage(context, address, lines, times) {
  const page = await context.newPage();
  for (let round = 0; round < rounds; ++round) {
    await page.goto(address);
    await page.locator('#world-select').selectOption('tidy-kitchen');
    await page.getByRole('button', { name: 'Start teaching' }).click();
    await page.locator('#reply:enabled').waitFor();
    for (const line of lines) {
      if (think > 0) await pause(think * (0.5 + Math.random()));
      await page.locator('#reply:enabled').fill(line);
      const ms = await page.evaluate(() => new Promise((resolve) => {
        const before = document.querySelectorAll('#conversation li.question, #conversation li.summary').length;
        const start = performance.now();
        const observer = new MutationObserver(() => {
          if (document.querySelectorAll('#conversation li.question, #conversation li.summary').length > before) {
            observer.disconnect();
            resolve(performance.now() - start);
          }
        });
        observer.observe(document.querySelector('#conversation'), { childList: true });
        document.querySelector('#reply-form').requestSubmit();
      }));
      times.push(ms);
    }
  }
  await page.close();
}

// When the page is ready for a person, in the page's own clock (from the
// start of the navigation, as a person waits after pressing Enter in the
// address bar): the start screen with its worlds listed; a session with its
// question shown and the reply box enabled.
function markReady() {
  window.__ready = {};
  new MutationObserver(() => {
    const r = window.__ready;
    if (r.start === undefined && document.querySelector('#world-select option')) r.start = performance.now();
    const reply = document.getElementById('reply');
    if (r.resume === undefined && reply && !reply.disabled && document.querySelector('#conversation li.question') &&
        !document.getElementById('session').hidden) r.resume = performance.now();
  }).observe(document, { subtree: true, childList: true, attributes: true });
}

// The page's load, 20 times each: the start screen, and a session resumed,
// each to the point where a person can act. Timed in the page (markReady),
// and from outside (from page.goto until playwright sees it ready, which
// adds playwright's own round trips to chromium).
async function pageLoads(context, address, sessionId) {
  const start = [], resume = [], startOutside = [], resumeOutside = [];
  const page = await context.newPage();
  await page.addInitScript(markReady);
  for (let i = 0; i < 20; ++i) {
    await page.goto('about:blank');
    let t = performance.now();
    await page.goto(address);
    await page.waitForFunction(() => window.__ready.start !== undefined);
    startOutside.push(performance.now() - t);
    start.push(await page.evaluate(() => window.__ready.start));
    await page.goto('about:blank');
    t = performance.now();
    await page.goto(address + '#session=' + sessionId);
    await page.waitForFunction(() => window.__ready.resume !== undefined);
    resumeOutside.push(performance.now() - t);
    resume.push(await page.evaluate(() => window.__ready.resume));
  }
  await page.close();
  return { start, resume, startOutside, resumeOutside };
}

// Where a load's time went, in the page's clock: the page's own response
// (its last byte) and the script's, from the navigation and resource
// timings.
function loadParts() {
  const nav = performance.getEntriesByType('navigation')[0];
  const script = performance.getEntriesByType('resource').find((e) => /\/app\.js/.test(e.name));
  return { page: nav.responseEnd, script: script ? script.responseEnd : null };
}

// Loads with nothing of the page kept by the browser: its script and style
// are fetched too. 10 of each, two ways: in a browser already running with
// the page never seen (its cache emptied before each load; a new tab, as a
// person opens the address), and in a fresh browser context each time (a
// new profile: chromium also starts a renderer for it, which a person's
// browser has running).
async function firstLoads(context, address, sessionId) {
  const out = { start: [], resume: [], freshStart: [], freshResume: [], page: [], script: [] };
  const targets = [['start', address], ['resume', address + '#session=' + sessionId]];
  for (let i = 0; i < 10; ++i) {
    for (const [what, url] of targets) {
      const page = await context.newPage();
      await page.addInitScript(markReady);
      const cdp = await context.newCDPSession(page);
      await cdp.send('Network.clearBrowserCache');
      await page.goto(url);
      await page.waitForFunction((w) => window.__ready[w] !== undefined, what);
      out[what].push(await page.evaluate((w) => window.__ready[w], what));
      const parts = await page.evaluate(loadParts);
      out.page.push(parts.page);
      if (parts.script !== null) out.script.push(parts.script);
      await page.close();
    }
  }
  const fresh = await chromium.launch({ executablePath: '/usr/bin/chromium', headless: true, args: chromiumFlags });
  for (let i = 0; i < 10; ++i) {
    for (const [what, url] of targets) {
      const own = await fresh.newContext();
      const page = await own.newPage();
      await page.addInitScript(markReady);
      await page.goto(url);
      await page.waitForFunction((w) => window.__ready[w] !== undefined, what);
      out[what === 'start' ? 'freshStart' : 'freshResume'].push(await page.evaluate((w) => window.__ready[w], what));
      await own.close();
    }
  }
  await fresh.close();
  return out;
}

// SESSIONS teachers at once, one in the page and the others over HTTP: the
// round trip of each reply, and the server's CPU.
async function teachAtOnce(client, context, server, kitchen, laundry, http, inPage) {
  const began = performance.now();
  const cpuBefore = cpuMs(server.process.pid);
  const teachers = [teachInPage(context, server.address, kitchen, inPage)];
  for (let i = 1; i < SESSIONS; ++i)
    teachers.push(teachOverHttp(client, i % 2 ? 'laundry-room' : 'tidy-kitchen', i % 2 ? laundry : kitchen, http));
  await Promise.all(teachers);
  const seconds = (performance.now() - began) / 1000;
  const cpu = cpuMs(server.process.pid) - cpuBefore;
  const load = os.loadavg()[0].toFixed(1);
  console.log(`apprentice serve, ${SESSIONS} sessions teaching at once (1 in chromium, ${SESSIONS - 1} over HTTP), ` +
              `think time ${think} ms, ${rounds} rounds, ${seconds.toFixed(1)} s`);
  console.log(`reply round trip, post to next question, over HTTP: ${describe(http)}`);
  console.log(`reply round trip, Enter to next question shown, in the page: ${describe(inPage)}`);
  console.log(`all replies: ${describe([...http, ...inPage])}`);
  const count = http.length + inPage.length;
  console.log(`server CPU: ${(cpu / 1000).toFixed(2)} s for ${count} replies, ${(cpu / count).toFixed(1)} ms a reply; ` +
              `load average at the end ${load} on ${os.cpus().length} cores`);
}

const scratch = scratchDir('apprentice-bench-');
const server = await startServer(binary, []);
const context = await chromium.launchPersistentContext(path.join(scratch, 'profile'), {
  executablePath: '/usr/bin/chromium', headless: true, args: chromiumFlags,
});
try {
  const client = new PageClient(server.address);
  const kitchen = replies(sourceDir, 'kitchen_replies.txt');
  const laundry = replies(sourceDir, 'laundry_replies.txt');
  const http = [], inPage = [];
  if (!loadsOnly) await teachAtOnce(client, context, server, kitchen, laundry, http, inPage);
  const idle = await client.start('tidy-kitchen');
  await idle.question();
  const loads = await pageLoads(context, server.address, idle.id);
  const first = await firstLoads(context, server.address, idle.id);
  idle.close();
  console.log(`page load, start screen ready, in the page: ${describe(loads.start)}`);
  console.log(`page load, session resumed to its question, in the page: ${describe(loads.resume)}`);
  console.log(`page load, start screen ready, seen by playwright: ${describe(loads.startOutside)}`);
  console.log(`page load, session resumed, seen by playwright: ${describe(loads.resumeOutside)}`);
  console.log(`first load (cache emptied, browser running), start screen ready, in the page: ${describe(first.start)}`);
  console.log(`first load (cache emptied, browser running), session resumed, in the page: ${describe(first.resume)}`);
  console.log(`  of which the page's response, to its last byte: ${describe(first.page)}`);
  console.log(`  and the script's response, to its last byte: ${describe(first.script)}`);
  console.log(`first load in a fresh browser context, start screen ready, in the page: ${describe(first.freshStart)}`);
  console.log(`first load in a fresh browser context, session resumed, in the page: ${describe(first.freshResume)}`);
} finally {
  await context.close();
  await server.stop();
}
