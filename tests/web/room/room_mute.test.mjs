// Muting someone for oneself on the room page, end to end: Ann and Bob in a
// room, each in a browser page. Ann mutes Bob; Bob writes a line and
// smiles. Ann's page shows no line of his (it counts it) and his face holds
// still and neutral, judged from the canvas's pixels and the FaceParams the
// page drew it with, while his line and his smile do reach Ann's client
// (the server sends everything) and Bob's own page shows both. The mute
// outlasts Bob's reconnection; after Ann unmutes, Bob's next line shows.
// The controls fit a phone.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

import { openWeb, sourceFile } from '../support/harness.mjs';
import { pageUntil } from '../support/page_poll.mjs';

const ROOM = 'quiet';
let web;
const pages = {};

before(async () => { web = await openWeb(['--no-demo-room']); });
after(async () => { await web?.close(); });

const room = (page) => page.evaluate(() => {
  if (!window.facewireRoom) return null;  // the page is still starting
  const { client, view } = window.facewireRoom;
  return {
    you: client.you, status: client.status, tiles: view.tiles, self: view.selfTile,
    names: Object.fromEntries([...client.avatars].map(([id, a]) => [a.info.name, id])),
    fullPackages: [...client.avatars].filter(([, a]) => a.package?.quality === 1).map(([id]) => id),
    lines: client.chatLines.map((l) => l.text),
  };
});
const until = (page, predicate, what, timeout) => pageUntil(page, room, predicate, what, timeout);
const tileOf = (state, name) => state.tiles.find((t) => t.id === state.names[name]);
const started = Date.now();
const step = (what) => console.log(`${((Date.now() - started) / 1000).toFixed(1)} s: ${what}`);
/** The middle of a tile, where the face is: eyes, cheeks and mouth (fewer pixels to carry out of the page). */
const faceOf = (rect) => ({ x: rect.x + rect.w / 4, y: rect.y + rect.h / 4, w: rect.w / 2, h: rect.h / 2 });
/**
 * Starts watching a face in the page itself, four times a second (the
 * page's own pixels and FaceParams never leave it; a loaded machine makes
 * every round trip slow): the largest decoded smile (AU 12, channels 15 and
 * 16), the largest of anything the tile was drawn with (action units, head
 * and eye turns, blush), and the largest mean change of the face's pixels
 * from when the watch began. `id` 'self' watches the page's own face.
 */
const watch = (page, id, rect) => page.evaluate(({ id: watched, rect: { x, y, w, h } }) => {
  const { client, view } = window.facewireRoom;
  const canvas = document.getElementById('room-canvas');
  const copy = document.createElement('canvas');
  const pixels = () => {
    const ratio = canvas.width / canvas.clientWidth;
    copy.width = Math.max(1, Math.round(w * ratio));
    copy.height = Math.max(1, Math.round(h * ratio));
    const g = copy.getContext('2d', { willReadFrequently: true });
    g.drawImage(canvas, x * ratio, y * ratio, w * ratio, h * ratio, 0, 0, copy.width, copy.height);
    return g.getImageData(0, 0, copy.width, copy.height).data;
  };
  const magnitude = (p) => Math.max(0, ...Array.from(p.au ?? [], Math.abs)) + Math.abs(p.head_yaw_rad) + Math.abs(p.head_pitch_rad)
    + Math.abs(p.eye_left.yaw_rad) + Math.abs(p.eye_right.yaw_rad) + Math.max(0, ...p.blush);
  const avatar = watched === 'self' ? client.you : watched;
  // Where the face is drawn: a page that grows moves it, and then pixels cannot be compared.
  const where = () => JSON.stringify([canvas.width, canvas.height, watched === 'self' ? view.selfTile : view.tiles.find((t) => t.id === avatar)?.rect]);
  const place = where();
  const baseline = pixels();
  const seen = { smile: 0, drawn: 0, change: 0, looks: 0, moved: 0 };
  const look = () => {
    if (where() !== place) seen.moved += 1;
    const decoded = client.face(avatar);
    if (decoded) seen.smile = Math.max(seen.smile, decoded.au[15], decoded.au[16]);
    const drawn = view.drawnParams.get(avatar);
    if (drawn && watched !== 'self') seen.drawn = Math.max(seen.drawn, magnitude(drawn));
    const now = pixels();
    let sum = 0;
    for (let i = 0; i < now.length; i += 4) sum += Math.abs(now[i] - baseline[i]) + Math.abs(now[i + 1] - baseline[i + 1]) + Math.abs(now[i + 2] - baseline[i + 2]);
    seen.change = Math.max(seen.change, sum / (3 * now.length / 4));
    seen.looks += 1;
  };
  clearInterval(window.faceWatch?.timer);
  window.faceWatch = { seen, timer: setInterval(look, 250) };
}, { id, rect });
const watched = (page) => page.evaluate(() => {
  clearInterval(window.faceWatch.timer);
  return window.faceWatch.seen;
});

test('Ann mutes Bob: his line is hidden and counted, his face holds still and neutral while he smiles', { timeout: 240000 }, async () => {
  // Bob wears a photo's face: its smile shows in many pixels.
  const upload = await fetch(`${web.server.url}api/avatars`, {
    method: 'POST', headers: { 'Content-Type': 'image/jpeg' }, body: readFileSync(sourceFile('tests/data/grace_hopper.jpg')),
  });
  assert.equal(upload.status, 201, await upload.clone().text());
  const { asset, key } = await upload.json();
  step('Bob\'s photo prepared');
  pages.bobUrl = `${web.server.url}room.html?room=${ROOM}&name=Bob&asset=${asset}&key=${key}`;
  // Tall enough for the panel: a panel taller than the window makes the
  // page, and the stage with it, grow with every line of chat.
  const ann = await web.page({ width: 960, height: 960 });
  const bob = await web.page({ width: 960, height: 960 });
  Object.assign(pages, { ann, bob });
  await ann.goto(`${web.server.url}room.html?room=${ROOM}&name=Ann`);
  await until(ann, (s) => s.status === 'joined', 'Ann joining');
  await bob.goto(pages.bobUrl);
  let state = await until(ann, (s) => tileOf(s, 'Bob')?.drawn && s.fullPackages.includes(s.names.Bob), 'Ann seeing Bob\'s full face', 90000);
  await until(bob, (s) => s.status === 'joined' && s.self, 'Bob joining');
  step('both in the room, Ann sees Bob\'s full face');
  const bobId = state.names.Bob;

  // Before: Bob's face lives on Ann's canvas.
  const rect = faceOf(tileOf(state, 'Bob').rect);
  await watch(ann, bobId, rect);
  await ann.waitForTimeout(1500);
  const alive = await watched(ann);
  step('Bob\'s face looked at');

  await ann.click(`#people li[data-avatar="${bobId}"] button.mute`);
  assert.match(await ann.locator('#mute-note').textContent(), /^Bob is muted for you: their lines are hidden and their faces held still/);
  await ann.locator(`#people li.muted[data-avatar="${bobId}"] button.unmute`).waitFor();
  await ann.locator(`#overlay .tile.muted[data-avatar="${bobId}"]`).waitFor();
  assert.deepEqual(await ann.evaluate(() => JSON.parse(localStorage.getItem('facewire.muted.quiet'))), ['Bob']);
  await ann.waitForTimeout(500);  // the tile is drawn at rest from the next frame on
  step('Bob muted');

  // Bob speaks and smiles; meanwhile both pages watch his face.
  await watch(ann, bobId, rect);
  await watch(bob, 'self', faceOf((await room(bob)).self));
  await bob.fill('#chat-text', 'hello from bob');
  await bob.click('#chat-form button');
  await bob.click('[data-expression="joy"]');
  await bob.locator('[data-expression="joy"].accepted').waitFor({ timeout: 10000 });
  await bob.waitForTimeout(2500);  // the smile lasts 3 s
  const onAnn = await watched(ann);
  const own = await watched(bob);
  step('watched the smile');
  console.log(`Bob's face on Ann's canvas: before muting it changed by ${alive.change.toFixed(2)} in 1.5 s; muted, by ` +
    `${onAnn.change.toFixed(2)} (${onAnn.looks} looks, moved ${onAnn.moved}) while his decoded smile there reached ${onAnn.smile.toFixed(2)} ` +
    `(drawn with ${onAnn.drawn}); Bob's own self view changed by ${own.change.toFixed(2)}, his smile ${own.smile.toFixed(2)}`);
  assert.ok(onAnn.looks >= 4 && own.looks >= 4, 'the pages looked often enough');
  assert.equal(onAnn.moved + own.moved, 0, 'the faces stayed where they were drawn');
  assert.ok(onAnn.smile > 0.3, `Bob's smile reached Ann's client (AU 12 ${onAnn.smile.toFixed(2)})`);
  assert.equal(onAnn.drawn, 0, 'Ann\'s page drew Bob with neutral FaceParams throughout');
  assert.ok(onAnn.change < 0.5, `Bob's face on Ann's canvas changed by ${onAnn.change.toFixed(2)}`);
  assert.ok(own.smile > 0.3, `Bob's own face smiles (AU 12 ${own.smile.toFixed(2)})`);
  assert.ok(own.change > 3, `Bob's own page shows his smile (self view changed by ${own.change.toFixed(2)})`);

  // The line reached Ann's client, but not her chat or caption: it is counted.
  await bob.locator('#chat-log li', { hasText: 'hello from bob' }).waitFor();
  await until(ann, (s) => s.lines.includes('hello from bob'), 'Bob\'s line reaching Ann\'s client');
  assert.equal(await ann.locator('#chat-log li', { hasText: 'hello from bob' }).count(), 0);
  assert.doesNotMatch(await ann.locator('#caption').textContent(), /hello from bob/);
  assert.equal(await ann.locator('#chat-hidden').textContent(), '1 line hidden from Bob');
});

test('the mute outlasts Bob\'s reconnection, and after unmuting Bob\'s next line shows', { timeout: 180000 }, async () => {
  const { ann, bob } = pages;
  assert.ok(ann && bob, 'both joined (the test before)');
  const before = (await room(ann)).names.Bob;
  await bob.goto(pages.bobUrl);  // Bob leaves and comes back under a new avatar id
  const state = await until(ann, (s) => s.names.Bob !== undefined && s.names.Bob !== before && tileOf(s, 'Bob')?.drawn,
    'Bob back in Ann\'s room', 90000);
  assert.ok(tileOf(state, 'Bob').muted, 'still muted under his new avatar id');
  await ann.locator(`#people li.muted[data-avatar="${state.names.Bob}"]`).waitFor();
  await until(bob, (s) => s.status === 'joined', 'Bob joined again');
  await bob.fill('#chat-text', 'still muted?');
  await bob.click('#chat-form button');
  await until(ann, (s) => s.lines.includes('still muted?'), 'Bob\'s second line reaching Ann\'s client');
  assert.equal(await ann.locator('#chat-log li', { hasText: 'still muted?' }).count(), 0);
  assert.equal(await ann.locator('#chat-hidden').textContent(), '2 lines hidden from Bob');

  await ann.click(`#people li[data-avatar="${state.names.Bob}"] button.unmute`);
  assert.equal(await ann.locator('#mute-note').textContent(), 'Bob is no longer muted.');
  assert.equal(await ann.evaluate(() => localStorage.getItem('facewire.muted.quiet')), null);
  await bob.fill('#chat-text', 'can you hear me now');
  await bob.click('#chat-form button');
  await ann.locator('#chat-log li', { hasText: 'can you hear me now' }).waitFor({ timeout: 20000 });
  assert.match(await ann.locator('#caption').textContent(), /Bob: can you hear me now/);
  assert.equal(await ann.locator('#chat-hidden').textContent(), '');
  await until(ann, (s) => !tileOf(s, 'Bob').muted, 'Bob\'s tile unmuted');
  await ann.waitForTimeout(300);
  const asDecoded = await ann.evaluate(async (id) => {
    const { NEUTRAL_FACE } = await import('/room/mute_list.js');
    const drawn = window.facewireRoom.view.drawnParams.get(id);
    return drawn !== undefined && drawn !== NEUTRAL_FACE;
  }, state.names.Bob);
  assert.ok(asDecoded, 'Bob\'s face drawn as decoded again');
});

test('on a phone the mute control is there and the page does not scroll sideways', { timeout: 60000 }, async () => {
  const { ann } = pages;
  await ann.setViewportSize({ width: 390, height: 844 });
  await ann.waitForTimeout(500);
  const bobId = (await room(ann)).names.Bob;
  const button = ann.locator(`#people li[data-avatar="${bobId}"] button.mute`);
  await button.scrollIntoViewIfNeeded();
  const box = await button.boundingBox();
  assert.ok(box && box.x >= 0 && box.x + box.width <= 390, `the mute button lies within the phone's width: ${JSON.stringify(box)}`);
  await button.click();
  await ann.locator(`#people li.muted[data-avatar="${bobId}"]`).waitFor();
  const widths = await ann.evaluate(() => [document.documentElement.scrollWidth, document.documentElement.clientWidth]);
  assert.ok(widths[0] <= 390, `the page is ${widths[0]} px wide`);
  assert.deepEqual(web.pageErrors, []);
});
