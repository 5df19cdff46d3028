// The page of `apprentice serve` in a real browser: Debian's chromium,
// headless, driven by playwright-core, clicking and typing as a person
// would. Usage: node page_test.mjs BINARY SOURCE_DIR ARTIFACT_DIR
// (ctest passes them; screenshots go to ARTIFACT_DIR).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { startServer, scratchDir, kitchenReplies, chromiumFlags } from './serve_process.mjs';

const [binary, sourceDir, artifacts] = process.argv.slice(2);
fs.mkdirSync(artifacts, { recursive: true });
const scratch = scratchDir('apprentice-page-');
let server, context;

before(async () => {
  server = await startServer(binary, ['--knowledge', path.join(scratch, 'kitchen.sqlite'), '--log-dir', path.join(scratch, 'logs')]);
  context = await chromium.launchPersistentContext(path.join(scratch, 'profile'), {
    executablePath: '/usr/bin/chromium', headless: true, args: chromiumFlags, viewport: { width: 1500, height: 1000 },
  });
});

after(async () => {
  if (context) await context.close();
  if (server) assert.equal(await server.stop(), 0, server.output());
  fs.rmSync(scratch, { recursive: true, force: true });
});

// The number of questions the conversation shows.
const questions = (page) => page.locator('#conversation li.question').count();

// Types a reply into the box and presses Enter, then waits for the agent's
// next question (or the end).
async function reply(page, text) {
  const before = await questions(page);
  await page.locator('#reply:enabled').click();
  await page.keyboard.type(text);
  await page.keyboard.press('Enter');
  await page.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length > n ||
                                     document.querySelector('#conversation li.summary') !== null, before);
}

// Until the page has drawn every action it was sent.
const drawn = (page) => page.waitForFunction(() => document.body.dataset.drawing === 'no');

// Where the room, as drawn, has the thing: its place's id ("table1", "hand").
const placeOf = (page, id) => page.locator(`#world g.item[data-id="${id}"]`).getAttribute('data-place');

async function startSession(page, world, store) {
  await page.goto(server.address);
  await page.locator('#start').waitFor();
  await page.locator('#world-select').selectOption(world);
  await page.locator('#store-select').selectOption(store);
  await page.getByRole('button', { name: 'Start teaching' }).click();
  await page.locator('#conversation li.question').first().waitFor();
}

const lastQuestion = (page) => page.locator('#conversation li.question').last().locator('.text').textContent();

test('the kitchen taught to 100% through the page, with an undo and a reload on the way', async () => {
  const page = await context.newPage();
  await startSession(page, 'tidy-kitchen', 'kitchen');
  assert.equal(await lastQuestion(page), 'What task should I learn?');
  assert.equal(await placeOf(page, 'cereal-box1'), 'table1');
  const replies = kitchenReplies(sourceDir);
  for (let i = 0; i < replies.length; ++i) {
    await reply(page, replies[i]);
    if (replies[i] === 'the cereal box goes in the pantry and shut it') {
      // The cereal box went into the pantry; undo puts it back on the
      // table, and the page draws it there.
      await page.waitForFunction(() => document.querySelector('#world g.item[data-id="cereal-box1"]')?.dataset.place === 'pantry1');
      const before = await questions(page);
      await page.getByRole('button', { name: 'Undo' }).click();
      await page.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length > n, before);
      await page.waitForFunction(() => document.querySelector('#world g.item[data-id="cereal-box1"]')?.dataset.place === 'table1');
      assert.match(await page.locator('#conversation').textContent(), /I forgot what you told me last/);
      assert.equal(await lastQuestion(page), 'Where should the cereal box on the table go?');
      await drawn(page);
      await page.screenshot({ path: path.join(artifacts, 'after-undo.png') });
      await reply(page, replies[i]);
    }
    if (replies[i] === 'put away what is on the counter') {
      // The README's picture: the page while teaching, the thing asked about highlighted.
      await drawn(page);
      await page.screenshot({ path: path.join(artifacts, 'teaching.png') });
    }
    if (i === 10) {
      // A reload resumes where it was: the same conversation, the same question.
      const shown = await questions(page);
      const asked = await lastQuestion(page);
      await page.reload();
      await page.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length === n, shown);
      assert.equal(await lastQuestion(page), asked);
      await page.locator('#reply:enabled').waitFor();
    }
  }
  const summary = page.locator('#conversation li.summary');
  await summary.waitFor();
  assert.match(await summary.textContent(), /The task is learned: 35 of 35 parts of the goal are met, after 28 instructions/);
  await drawn(page);
  assert.equal(await placeOf(page, 'cereal-box1'), 'pantry1');
  assert.equal(await placeOf(page, 'metal-fork2'), 'drawer1');
  assert.equal(await page.locator('#world g.place[data-id="dish-rack1"] g.item').count(), 0);
  assert.equal(await page.locator('#world g.place[data-id="fridge1"]').getAttribute('data-door'), 'closed');
  assert.match(await page.locator('#knowledge').textContent(), /the ketchup goes in the fridge/i);
  await page.locator('#world-panel').screenshot({ path: path.join(artifacts, 'world.png') });
  await page.locator('#talk-panel').screenshot({ path: path.join(artifacts, 'conversation.png') });
  await page.screenshot({ path: path.join(artifacts, 'page.png') });
  // The study log, as the page's link downloads it: one JSON line per event.
  const log = await page.evaluate(async () => (await fetch(document.querySelector('#download-log').href)).text());
  const events = log.trim().split('\n').map((line) => JSON.parse(line));
  // Every reply typed, the undo and the reply said again after it.
  assert.equal(events.filter((e) => e.type === 'reply').length, replies.length + 2);
  assert.ok(events.some((e) => e.type === 'learned'));
  assert.ok(events.every((e) => typeof e.time === 'string' && Number.isInteger(e.ms)));
  await page.close();
});

test('two tabs on two worlds at once, each its own session; a "Which ...?" answered by its button', async () => {
  const kitchen = await context.newPage();
  const playroom = await context.newPage();
  // Neither keeps anything: the kitchen store holds the first test's lessons.
  await startSession(kitchen, 'tidy-kitchen', '');
  await startSession(playroom, 'playroom', '');
  await reply(kitchen, 'tidy the kitchen');
  await reply(playroom, 'tidy up the playroom');
  await reply(kitchen, 'clear the table');
  await reply(playroom, 'first pick up everything off the floor');
  assert.equal(await lastQuestion(kitchen), 'Where should the ceramic plate on the table go?');
  assert.equal(await lastQuestion(playroom), 'Where should the block on the floor go?');
  await reply(playroom, 'blocks go in the bin');
  assert.match(await lastQuestion(playroom), /^Which bin: /);
  const before = await questions(playroom);
  await playroom.getByRole('button', { name: 'Red bin' }).click();
  await playroom.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length > n, before);
  assert.match(await playroom.locator('#conversation').textContent(), /So the block goes in the red bin\./);
  assert.doesNotMatch(await kitchen.locator('#conversation').textContent(), /block|playroom/);
  assert.doesNotMatch(await playroom.locator('#conversation').textContent(), /kitchen|plate/);
  await playroom.getByRole('button', { name: 'Stop' }).click();
  await playroom.locator('#conversation li.summary').waitFor();
  assert.match(await playroom.locator('#conversation li.summary .text').textContent(), /^Stopped: 4 of 14 parts of the goal are met/);
  // The kitchen goes on after the playroom stopped.
  await reply(kitchen, 'in the dishwasher, close it');
  assert.equal(await lastQuestion(kitchen), 'Where should the metal fork on the table go?');
  await kitchen.close();
  await playroom.close();
});

test('a yes/no question answered by its button, and a goal forgotten by its Forget button', async () => {
  // The kitchen store holds the first test's goals for tidying the kitchen
  // ("clean up the kitchen" and "sort the kitchen" are read as tidying
  // it); taught as another task, "reset the kitchen", the agent asks
  // whether those goals apply.
  const page = await context.newPage();
  await startSession(page, 'tidy-kitchen', 'kitchen');
  await reply(page, 'reset the kitchen');
  await reply(page, 'clear the table');
  assert.match(await lastQuestion(page), /^Does the ceramic plate on the table go like /);
  assert.deepEqual(await page.locator('#choices button').allTextContents(), ['Yes', 'No']);
  const before = await questions(page);
  await page.getByRole('button', { name: 'Yes' }).click();
  await page.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length > n, before);
  assert.match(await page.locator('#conversation').textContent(), /So the ceramic plate goes in the dishwasher/);
  const ketchup = page.locator('#knowledge li.goal', { hasText: 'the ketchup goes in the fridge' }).first();
  await ketchup.waitFor();
  const count = await page.locator('#knowledge li.goal', { hasText: 'the ketchup goes' }).count();
  const asked = await questions(page);
  await ketchup.getByRole('button', { name: 'Forget' }).click();
  await page.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length > n, asked);
  assert.match(await page.locator('#conversation li.person').last().textContent(), /forget ketchup/);
  assert.ok(await page.locator('#knowledge li.goal', { hasText: 'the ketchup goes' }).count() < count);
  await page.getByRole('button', { name: 'Stop' }).click();
  await page.locator('#conversation li.summary').waitFor();
  await page.close();
});

test('an "Is there more?" question gets its two buttons, and "There is more" goes on with the rest', async () => {
  const page = await context.newPage();
  await startSession(page, 'tidy-kitchen', '');
  // A loop announced before its part: the agent does one thing, then asks
  // whether the part has more to it.
  for (const line of ['tidy the kitchen', 'repeat while something is on the table', 'clear the table',
                      'plates and glasses go in the dishwasher, close it'])
    await reply(page, line);
  assert.equal(await lastQuestion(page), 'Is there more to clear on the table, or is that all?');
  assert.deepEqual(await page.locator('#choices button').allTextContents(), ['There is more', "That's all"]);
  await drawn(page);
  await page.screenshot({ path: path.join(artifacts, 'is-there-more.png') });
  const before = await questions(page);
  await page.getByRole('button', { name: 'There is more' }).click();
  await page.waitForFunction((n) => document.querySelectorAll('#conversation li.question').length > n, before);
  assert.match(await page.locator('#conversation li.person').last().textContent(), /there is more/);
  assert.match(await page.locator('#conversation').textContent(), /So I clear everything else on the table the same way\./);
  // The second plate was put away as the first, without asking.
  assert.equal(await lastQuestion(page), 'Where should the metal fork on the table go?');
  assert.equal(await page.locator('#choices button').count(), 0);
  await page.getByRole('button', { name: 'Stop' }).click();
  await page.locator('#conversation li.summary').waitFor();
  await page.close();
});

test('an uploaded broken world gets a readable error with its line', async () => {
  const page = await context.newPage();
  await page.goto(server.address);
  await page.locator('#start').waitFor();
  await page.locator('#world-select option').first().waitFor({ state: 'attached' });
  // The start screen alone: no room, no conversation yet.
  assert.equal(await page.locator('#session').isVisible(), false);
  await page.screenshot({ path: path.join(artifacts, 'start.png') });
  const broken = 'name: my-bathroom\ndomain: ../domains/kitchen.pddl\nplaces:\n  - {category: sink, kind: bathtub}\nobjects: []\n';
  await page.locator('#world-file').setInputFiles({ name: 'bathroom.yaml', mimeType: 'text/yaml', buffer: Buffer.from(broken) });
  await page.getByRole('button', { name: 'Start teaching' }).click();
  const error = page.locator('#start-error');
  await error.waitFor();
  const text = await error.textContent();
  assert.match(text, /bathroom\.yaml:4:/);
  assert.match(text, /bathtub/);
  assert.doesNotMatch(text, /\/work|\/home|\/usr|data\/scenarios/);
  await error.screenshot({ path: path.join(artifacts, 'upload-error.png') });
  await page.close();
});
