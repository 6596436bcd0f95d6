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
import { canvasPixels, meanAbsDifference } from '../support/room_pixels.mjs';

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
async function until(page, predicate, what, timeout = 30000) {
  const start = Date.now();
  for (;;) {
    const state = await room(page);
    if (state && predicate(state)) return state;
    if (Date.now() - start > timeout) throw new Error(`${what} did not happen within ${timeout / 1000} s: ${JSON.stringify(state)}`);
    await page.waitForTimeout(200);
  }
}
const tileOf = (state, name) => state.tiles.find((t) => t.id === state.names[name]);
/** Bob's face as Ann's page has it: the decoded smile (AU 12, channels 15 and 16) and what the tile was drawn with. */
const bobOnAnn = (page, bob) => page.evaluate((id) => {
  const { client, view } = window.facewireRoom;
  const decoded = client.face(id);
  const drawn = view.drawnParams.get(id);
  const magnitude = (p) => (p ? Math.max(0, ...Array.from(p.au ?? [], Math.abs)) + Math.abs(p.head_yaw_rad) + Math.abs(p.head_pitch_rad)
    + Math.abs(p.eye_left.yaw_rad) + Math.abs(p.eye_right.yaw_rad) + Math.max(0, ...p.blush) : null);
  return { smile: decoded ? Math.max(decoded.au[15], decoded.au[16]) : null, drawn: magnitude(drawn), live: magnitude(decoded) };
}, bob);

test('Ann mutes Bob: his line is hidden and counted, his face holds still and neutral while he smiles', { timeout: 240000 }, async () => {
  // Bob wears a photo's face: its smile shows in many pixels.
  const upload = await fetch(`${web.server.url}api/avatars`, {
    method: 'POST', headers: { 'Content-Type': 'image/jpeg' }, body: readFileSync(sourceFile('tests/data/grace_hopper.jpg')),
  });
  assert.equal(upload.status, 201, await upload.clone().text());
  const { asset, key } = await upload.json();
  pages.bobUrl = `${web.server.url}room.html?room=${ROOM}&name=Bob&asset=${asset}&key=${key}`;
  const ann = await web.page({ width: 1280, height: 800 });
  const bob = await web.page({ width: 1280, height: 800 });
  Object.assign(pages, { ann, bob });
  await ann.goto(`${web.server.url}room.html?room=${ROOM}&name=Ann`);
  await until(ann, (s) => s.status === 'joined', 'Ann joining');
  await bob.goto(pages.bobUrl);
  let state = await until(ann, (s) => tileOf(s, 'Bob')?.drawn && s.fullPackages.includes(s.names.Bob), 'Ann seeing Bob\'s full face', 90000);
  await until(bob, (s) => s.status === 'joined' && s.self, 'Bob joining');
  const bobId = state.names.Bob;

  // Before: Bob's face lives on Ann's canvas (two looks a second apart differ).
  const rect = tileOf(state, 'Bob').rect;
  const alive = [await canvasPixels(ann, rect)];
  await ann.waitForTimeout(1000);
  alive.push(await canvasPixels(ann, rect));
  const liveMotion = meanAbsDifference(alive[0].data, alive[1].data);

  await ann.click(`#people li[data-avatar="${bobId}"] button.mute`);
  assert.match(await ann.locator('#mute-note').textContent(), /^Bob is muted for you: their lines are hidden and their faces still/);
  await ann.locator(`#people li.muted[data-avatar="${bobId}"] button.unmute`).waitFor();
  await ann.locator(`#overlay .tile.muted[data-avatar="${bobId}"]`).waitFor();
  assert.deepEqual(await ann.evaluate(() => JSON.parse(localStorage.getItem('facewire.muted.quiet'))), ['Bob']);
  await ann.waitForTimeout(800);  // the tile is drawn at rest from the next frame on
  const still = await canvasPixels(ann, rect);
  const atRest = await bobOnAnn(ann, bobId);
  assert.equal(atRest.drawn, 0, 'drawn with neutral FaceParams');

  // Bob speaks and smiles; his own page shows both.
  const bobMouth = async () => canvasPixels(bob, (await room(bob)).self);
  const bobBefore = await bobMouth();
  await bob.fill('#chat-text', 'hello from bob');
  await bob.click('#chat-form button');
  await bob.click('[data-expression="joy"]');
  await bob.locator('#chat-log li', { hasText: 'hello from bob' }).waitFor();
  await bob.locator('[data-expression="joy"].accepted').waitFor({ timeout: 10000 });

  // The line reached Ann's client, but not her chat or caption: it is counted.
  await until(ann, (s) => s.lines.includes('hello from bob'), 'Bob\'s line reaching Ann\'s client');
  assert.equal(await ann.locator('#chat-log li', { hasText: 'hello from bob' }).count(), 0);
  assert.doesNotMatch(await ann.locator('#caption').textContent(), /hello from bob/);
  assert.equal(await ann.locator('#chat-hidden').textContent(), '1 line hidden from Bob');

  // The smile reached Ann's client too, yet her canvas shows Bob unchanged.
  let smile = 0;
  let drawn = 0;
  let change = 0;
  for (let i = 0; i < 20 && smile < 0.3; ++i) {
    await ann.waitForTimeout(250);
    const now = await bobOnAnn(ann, bobId);
    smile = Math.max(smile, now.smile ?? 0);
    drawn = Math.max(drawn, now.drawn ?? 0);
    change = Math.max(change, meanAbsDifference(still.data, (await canvasPixels(ann, rect)).data));
  }
  const bobAfter = await bobMouth();
  const ownChange = meanAbsDifference(bobBefore.data, bobAfter.data);
  const ownSmile = await bob.evaluate(() => {
    const { client } = window.facewireRoom;
    const face = client.face(client.you);
    return Math.max(face.au[15], face.au[16]);
  });
  console.log(`Bob's tile on Ann's canvas: before muting it changed by ${liveMotion.toFixed(2)} in a second; muted, by ` +
    `${change.toFixed(2)} while his decoded smile reached ${smile.toFixed(2)} (drawn with ${drawn}); Bob's own self view ` +
    `changed by ${ownChange.toFixed(2)}, his smile ${ownSmile.toFixed(2)}`);
  assert.ok(smile > 0.3, `Bob's smile reached Ann's client (AU 12 ${smile.toFixed(2)})`);
  assert.equal(drawn, 0, 'Ann\'s page drew Bob with neutral FaceParams throughout');
  assert.ok(change < 0.5, `Bob's tile on Ann's canvas changed by ${change.toFixed(2)}`);
  assert.ok(ownChange > 3 * Math.max(change, 0.3), `Bob's own page shows his smile (self view changed by ${ownChange.toFixed(2)})`);
  assert.ok(ownSmile > 0.3);
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
  const { drawn } = await bobOnAnn(ann, state.names.Bob);
  assert.ok(drawn !== null, 'Bob drawn');
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
