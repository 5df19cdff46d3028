// The page of `apprentice serve`: the start screen, then one teaching
// session: the room drawn as SVG, the conversation, and what the agent
// knows. Everything comes from the server's events (Server-Sent Events);
// a reload replays them, so the page resumes where it was. Plain script,
// no libraries: the server serves this file itself.
'use strict';

const SVG = 'http://www.w3.org/2000/svg';
const $ = (id) => document.getElementById(id);

const state = {
  session: null,      // the session's id
  question: null,     // the event number of the question waiting, or null
  source: null,       // the EventSource
  frames: [],         // worlds still to draw, oldest first
  drawing: false,
  asked: null,        // the id of the thing the question is about
  ended: false,
};

// Requests that change something carry the CSRF header the server requires.
async function api(method, path, body) {
  const options = { method, headers: {}, credentials: 'same-origin' };
  if (body !== undefined) {
    options.headers['Content-Type'] = 'application/json';
    options.headers['X-Apprentice-Request'] = '1';
    options.body = JSON.stringify(body);
  }
  const response = await fetch(path, options);
  let data = {};
  try { data = await response.json(); } catch (e) { data = {}; }
  if (!response.ok) throw new Error(data.error || ('the server answered ' + response.status));
  return data;
}

function element(tag, attributes, text) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function svg(tag, attributes, text) {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

function sessionFromAddress() {
  const m = /session=([0-9a-f]{32})/.exec(location.hash);
  return m ? m[1] : null;
}

function capitalize(s) { return s ? s[0].toUpperCase() + s.slice(1) : s; }

// ---- the start screen ----

// The worlds, stores and limits: in the page itself (the server places
// them there), else asked for.
async function serverOptions() {
  const block = $('server-options');
  if (block) {
    try { return JSON.parse(block.textContent); } catch (e) { /* asked for below */ }
  }
  return api('GET', '/api/options');
}

async function showStart(message) {
  $('loading').hidden = true;
  $('session').hidden = true;
  $('start').hidden = false;
  if (message) showStartError(message);
  const options = await serverOptions();
  const worlds = $('world-select');
  worlds.replaceChildren();
  for (const name of options.worlds) {
    const o = element('option', { value: name }, name);
    if (name === options.default_world) o.selected = true;
    worlds.append(o);
  }
  const stores = $('store-select');
  stores.replaceChildren(element('option', { value: '' }, 'None: nothing is kept after the session'));
  for (const name of options.stores) {
    const o = element('option', { value: name }, name);
    if (name === options.default_store) o.selected = true;
    stores.append(o);
  }
  const kib = Math.round(options.limits.max_world_bytes / 1024);
  $('world-limit').textContent = kib + ' KiB';
  state.limits = options.limits;
  $('world-file').addEventListener('change', () => {
    document.querySelector('input[name=source][value=upload]').checked = true;
  });
}

function showStartError(message) {
  const box = $('start-error');
  box.replaceChildren(element('p', {}, 'This room cannot be used:'), element('pre', {}, message));
  box.hidden = false;
}

async function startSession(event) {
  event.preventDefault();
  $('start-error').hidden = true;
  const body = { store: $('store-select').value };
  const upload = document.querySelector('input[name=source][value=upload]').checked;
  if (upload) {
    const file = $('world-file').files[0];
    if (!file) return showStartError('Choose a scenario file first.');
    if (state.limits && file.size > state.limits.max_world_bytes)
      return showStartError(file.name + ' is larger than ' + Math.round(state.limits.max_world_bytes / 1024) +
                            ' KiB, the limit for a room of your own.');
    body.upload = { name: file.name, yaml: await file.text() };
  } else {
    body.world = $('world-select').value;
  }
  $('start-button').disabled = true;
  try {
    const session = await api('POST', '/api/sessions', body);
    location.hash = 'session=' + session.id;
    openSession(session.id);
  } catch (e) {
    showStartError(e.message);
  } finally {
    $('start-button').disabled = false;
  }
}

// ---- a session ----

async function openSession(id) {
  // The event stream opens at once, beside the request for the session's
  // description; what it sends before that answer is shown just after it.
  const source = new EventSource('/api/sessions/' + id + '/events');
  const early = [];
  let ready = false;
  source.onmessage = (message) => {
    if (ready) handle(JSON.parse(message.data), Number(message.lastEventId));
    else early.push(message);
  };
  let description;
  try {
    description = await api('GET', '/api/sessions/' + id);
  } catch (e) {
    source.close();
    history.replaceState(null, '', '/');
    return showStart('That session is gone: ' + e.message);
  }
  state.session = id;
  $('loading').hidden = true;
  $('start').hidden = true;
  $('session').hidden = false;
  $('session-label').textContent = 'Teaching in ' + description.world +
    (description.store ? ' · remembering in "' + description.store + '"' : ' · nothing is kept');
  $('download-log').href = '/api/sessions/' + id + '/log';
  $('download-log').setAttribute('download', 'apprentice-' + id + '.jsonl');
  $('conversation').replaceChildren();
  setWaiting(false);  // until its question comes
  state.source = source;
  ready = true;
  for (const message of early.splice(0)) handle(JSON.parse(message.data), Number(message.lastEventId));
  // The browser reconnects by itself after a dropped connection; it gives
  // up only when the server refuses (the session is gone, the server stopped).
  source.onerror = () => {
    if (source.readyState === EventSource.CLOSED && !state.ended)
      $('reply-error').textContent = 'The connection to the server was lost. Reload the page to go on.';
  };
}

function say(who, text, kind) {
  const line = element('li', { class: who + (kind ? ' ' + kind : '') });
  line.append(element('span', { class: 'speaker' }, who === 'agent' ? 'Robot' : 'You'), element('span', { class: 'text' }, text));
  $('conversation').append(line);
  line.scrollIntoView({ block: 'nearest' });
}

function handle(event, seq) {
  switch (event.type) {
    case 'question':
      say('agent', event.text, 'question');
      state.question = seq;
      state.asked = event.object;
      showChoices(event.choices || []);
      setWaiting(true);
      // The question first; the room and what it knows just after, so
      // that the question is shown without waiting for them.
      if (event.world) document.body.dataset.drawing = 'yes';
      setTimeout(() => {
        showKnowledge(event.knowledge || []);
        showProgress(event.progress);
        queueWorld(event.world, null);
      }, 0);
      break;
    case 'say': say('agent', event.text); break;
    case 'reply':
      // Answered, here or in another tab: the agent works until its next question.
      say('person', event.text);
      state.question = null;
      setWaiting(false);
      break;
    case 'action': queueWorld(event.world, event); break;
    case 'learned': case 'forgotten': break;  // shown with the next question's knowledge
    case 'end':
      say('agent', event.text, 'summary');
      if (event.error) say('agent', event.error, 'problem');
      state.ended = true;
      state.question = null;
      state.asked = null;
      showProgress(event.progress);
      queueWorld(event.world, null);
      setWaiting(false);
      $('question-area').hidden = true;
      $('ended').hidden = false;
      if (state.source) state.source.close();
      break;
  }
}

function setWaiting(waiting) {
  for (const b of document.querySelectorAll('#question-area button, #knowledge button.forget')) b.disabled = !waiting;
  $('reply').disabled = !waiting;
  if (waiting) $('reply').focus();
}

function showChoices(choices) {
  const box = $('choices');
  box.replaceChildren();
  for (const c of choices) {
    const b = element('button', { type: 'button', class: 'choice' }, c.label);
    b.addEventListener('click', () => send(c.reply));
    box.append(b);
  }
}

function showProgress(progress) {
  $('progress').textContent = progress ? progress.achieved + ' of ' + progress.total + ' goals hold' : '';
}

function showKnowledge(entries) {
  // Drawn again only when it changed, or when its Forget buttons must change state.
  const key = JSON.stringify(entries) + (state.question === null);
  if (key === state.knowledgeShown) return;
  state.knowledgeShown = key;
  const list = $('knowledge');
  const rules = $('rules');
  list.replaceChildren();
  rules.replaceChildren();
  let ruleCount = 0;
  for (const entry of entries) {
    const item = element('li', { class: entry.what });
    item.append(element('span', { class: 'known' }, entry.text));
    if (entry.source) item.append(element('span', { class: 'source' }, capitalize(entry.source)));
    if (entry.forget) {
      const b = element('button', { type: 'button', class: 'forget', title: 'Say "' + entry.forget + '"' }, 'Forget');
      b.addEventListener('click', () => send(entry.forget));
      b.disabled = state.question === null;
      item.append(b);
    }
    if (entry.what === 'rule') { rules.append(item); ++ruleCount; } else list.append(item);
  }
  $('knows-empty').hidden = entries.length > 0;
  $('rules-box').hidden = ruleCount === 0;
  $('rules-summary').textContent = ruleCount + (ruleCount === 1 ? ' rule' : ' rules') + ' for how to do things';
}

async function send(text) {
  text = text.trim();
  if (!text || state.question === null) return;
  const question = state.question;
  $('reply-error').textContent = '';
  setWaiting(false);
  state.question = null;
  try {
    await api('POST', '/api/sessions/' + state.session + '/reply', { text, question });
    $('reply').value = '';
  } catch (e) {
    $('reply-error').textContent = e.message;
    state.question = question;
    setWaiting(true);
  }
}

// ---- the room, drawn ----

// Worlds are drawn one after another, a moment apart, so that each action
// is seen as it happens even when several arrive at once. A long backlog
// (a reload, a known task done alone) is cut to its last few frames, so
// that the drawing never lags far behind the conversation.
// document.body.dataset.drawing says whether frames are still to come.
const FRAME_MS = 150, MAX_BACKLOG = 6;

function queueWorld(world, action) {
  if (!world) return;
  state.frames.push({ world, action });
  if (state.frames.length > MAX_BACKLOG) state.frames.splice(0, state.frames.length - MAX_BACKLOG);
  if (!state.drawing) nextFrame();
}

function nextFrame() {
  const frame = state.frames.shift();
  if (!frame) {
    state.drawing = false;
    document.body.dataset.drawing = 'no';
    return;
  }
  state.drawing = true;
  document.body.dataset.drawing = 'yes';
  drawWorld(frame.world, frame.action);
  $('action-caption').textContent = frame.action ? frame.action.text : '';
  setTimeout(nextFrame, state.frames.length > 0 ? FRAME_MS : 0);
}

const PLACE_W = 210, CHIP_H = 22, GAP = 14, COLUMNS = 4;

function drawWorld(world, action) {
  const root = $('world');
  root.replaceChildren();
  $('world-title').textContent = 'The ' + (world.location || 'room');
  const acting = new Set(action ? action.objects : []);
  const places = world.places;
  const heights = places.map((p) => 34 + Math.max(1, p.items.length) * CHIP_H + 8);
  let y = GAP;
  // The robot's hand, above the room.
  const hand = svg('g', { class: 'hand', transform: `translate(${GAP},${y})` });
  hand.append(svg('rect', { class: 'hand-box', width: PLACE_W, height: 32, rx: 6 }));
  hand.append(svg('text', { class: 'place-name', x: 10, y: 21 }, "Robot's hand"));
  if (world.hand) hand.append(chip(world.hand, 104, 7, PLACE_W - 112, acting, 'hand'));
  else hand.append(svg('text', { class: 'empty', x: 110, y: 21 }, 'empty'));
  root.append(hand);
  y += 32 + GAP;
  for (let row = 0; row * COLUMNS < places.length; ++row) {
    const members = places.slice(row * COLUMNS, row * COLUMNS + COLUMNS);
    const h = Math.max(...heights.slice(row * COLUMNS, row * COLUMNS + COLUMNS));
    members.forEach((place, i) => root.append(drawPlace(place, GAP + i * (PLACE_W + GAP), y, h, acting)));
    y += h + GAP;
  }
  const width = GAP + COLUMNS * (PLACE_W + GAP);
  root.setAttribute('viewBox', `0 0 ${width} ${y}`);
  root.setAttribute('width', width);
  root.setAttribute('height', y);
}

function drawPlace(place, x, y, h, acting) {
  const g = svg('g', { class: 'place ' + place.kind + (acting.has(place.id) ? ' acting' : ''), 'data-id': place.id,
                       'data-door': place.door || 'none', transform: `translate(${x},${y})` });
  const label = capitalize(place.name) + (place.door ? (place.door === 'open' ? ' (open)' : ' (closed)') : '');
  if (place.kind === 'surface') {
    g.append(svg('rect', { class: 'surface-top', x: 0, y: 24, width: PLACE_W, height: h - 24, rx: 3 }));
    g.append(svg('rect', { class: 'surface-edge', x: 0, y: h - 6, width: PLACE_W, height: 6 }));
  } else {
    g.append(svg('rect', { class: 'box', x: 0, y: 24, width: PLACE_W, height: h - 24, rx: 4 }));
  }
  g.append(svg('text', { class: 'place-name', x: 4, y: 17 }, label));
  place.items.forEach((item, i) => g.append(chip(item, 8, 30 + i * CHIP_H, PLACE_W - 16, acting, place.id)));
  if (place.items.length === 0) g.append(svg('text', { class: 'empty', x: 10, y: 46 }, 'nothing'));
  if (place.door === 'closed') {
    // A closed door: a translucent front, so that what is inside still shows.
    g.append(svg('rect', { class: 'door closed', x: 0, y: 24, width: PLACE_W, height: h - 24, rx: 4 }));
    g.append(svg('circle', { class: 'handle', cx: PLACE_W - 12, cy: 24 + (h - 24) / 2, r: 4 }));
  } else if (place.door === 'open') {
    g.append(svg('path', { class: 'door open', d: `M ${PLACE_W} 24 l 14 -10 v ${h - 14} l -14 -10 z` }));
  }
  return g;
}

function chip(item, x, y, w, acting, where) {
  const classes = ['item'];
  if (item.id === state.asked) classes.push('asked');
  if (acting.has(item.id)) classes.push('acting');
  const g = svg('g', { class: classes.join(' '), 'data-id': item.id, 'data-place': where, transform: `translate(${x},${y})` });
  g.append(svg('rect', { width: w, height: CHIP_H - 4, rx: 9 }));
  const text = capitalize(item.name) + (item.on ? ' (on the ' + item.on + ')' : '');
  g.append(svg('text', { x: 9, y: 13 }, text));
  g.append(svg('title', {}, text));
  return g;
}

// ---- wiring ----

document.addEventListener('DOMContentLoaded', () => {
  $('start-form').addEventListener('submit', startSession);
  $('reply-form').addEventListener('submit', (e) => { e.preventDefault(); send($('reply').value); });
  for (const b of document.querySelectorAll('#commands button')) b.addEventListener('click', () => send(b.dataset.reply));
  const id = sessionFromAddress();
  (id ? openSession(id) : showStart()).catch((e) => showStart(e.message));
});
