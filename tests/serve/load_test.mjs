// Load: 20 sessions teaching at once through HTTP, ten in the kitchen and
// ten in the laundry room, each to 100%. Nothing is lost (every reply is
// heard, in order, and every session ends with its world's every goal
// assertion holding) and no session sees another's state (its questions
// and its world are its own). Usage: node load_test.mjs BINARY SOURCE_DIR
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { startServer } from './serve_process.mjs';
import { PageClient, replies } from './page_client.mjs';

const [binary, sourceDir] = process.argv.slice(2);
const SESSIONS = 20;

test('20 sessions teach at once, nothing lost, none seeing another', { timeout: 600000 }, async () => {
  const server = await startServer(binary, []);
  try {
    const client = new PageClient(server.address);
    const worlds = {
      'tidy-kitchen': { lines: replies(sourceDir, 'kitchen_replies.txt'), total: 35, own: /fridge|dishwasher/, foreign: /hamper|\bwasher|laundry|sweater/ },
      'laundry-room': { lines: replies(sourceDir, 'laundry_replies.txt'), total: 14, own: /hamper|\bwasher/, foreign: /fridge|dishwasher|kitchen|ketchup/ },
    };
    const names = Array.from({ length: SESSIONS }, (_, i) => (i % 2 ? 'laundry-room' : 'tidy-kitchen'));
    const sessions = await Promise.all(names.map((world) => client.start(world)));
    const ends = await Promise.all(sessions.map((s, i) => s.teach(worlds[names[i]].lines)));
    for (let i = 0; i < SESSIONS; ++i) {
      const w = worlds[names[i]];
      const s = sessions[i];
      assert.equal(ends[i].type, 'end', s.id);
      assert.match(ends[i].text, new RegExp(`^The task is learned: ${w.total} of ${w.total} parts of the goal are met, after ${w.lines.length} instructions`));
      // Every reply heard once, in the order sent.
      assert.deepEqual(s.events.filter((e) => e.type === 'reply').map((e) => e.text), w.lines);
      const seqs = s.events.map((e) => e.seq);
      assert.deepEqual(seqs, Array.from({ length: seqs.length }, (_, k) => k + 1), 'events missing or repeated');
      // Its own world, and no other's, in what it was told and shown.
      const said = s.events.filter((e) => e.type === 'question' || e.type === 'say').map((e) => e.text).join('\n');
      assert.match(said, w.own);
      assert.doesNotMatch(said, w.foreign);
      const places = ends[i].world.places.map((p) => p.id);
      const kitchen = names[i] === 'tidy-kitchen';
      assert.equal(places.includes('fridge1'), kitchen, places.join(' '));
      assert.equal(places.includes('hamper1'), !kitchen, places.join(' '));
      // The log the page downloads has the same replies.
      const log = await client.request('GET', `/api/sessions/${s.id}/log`);
      const logged = log.body.trim().split('\n').map((line) => JSON.parse(line));
      assert.deepEqual(logged.filter((e) => e.type === 'reply').map((e) => e.text), w.lines);
      s.close();
    }
  } finally {
    assert.equal(await server.stop(), 0, server.output());
  }
});
