// Redefined action units on the room page, end to end (PROTOCOL.md 5.17):
// Ann and Bob in a room, each in a browser page. Ann's page sends a face
// script that redefines AU 12 (brows and forehead far up) and then plays
// it. In Bob's page Ann's face moves by the redefined unit: its skin for a
// smile is not the one her package's shipped units give, and it is what the
// C++ makes of the same units (the engine's goldens hold that); Bob's own
// face, which nobody redefined, is unchanged. A restore brings Ann's
// shipped units back.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';

import { openWeb } from '../support/harness.mjs';
import { pageUntil } from '../support/page_poll.mjs';

const ROOM = 'units';
const DEFINITION = `AU 12
Above_Brow 6 0 40 0
Above_Brow 7 0 40 0
Brow 3 0 40 0
Brow 4 0 40 0
Brow 5 0 40 0
Brow 6 0 40 0
Brow 7 0 40 0
Brow 8 0 40 0
end`;
const SMILE = 'ClearAllFrame BeginKeyFrame 12 2.0 Animate 3 "Texture" end';
let web;
let ann;
let bob;

before(async () => { web = await openWeb(['--no-demo-room']); });
after(async () => { await web?.close(); });

const room = (page) => page.evaluate(() => {
  if (!window.facewireRoom) return null;  // the page is still starting
  const { client, view } = window.facewireRoom;
  return {
    you: client.you, status: client.status,
    names: Object.fromEntries([...client.avatars].map(([id, a]) => [a.info.name, id])),
    built: [...view.faces.keys()].filter((id) => client.face(id)),  // built, and a frame of it decoded
    units: Object.fromEntries([...client.unitMorphs].map(([id, m]) => [id, { version: m.version, count: m.units.length }])),
    results: Object.fromEntries(client.results),
  };
});
const until = (page, predicate, what, timeout) => pageUntil(page, room, predicate, what, timeout);

/**
 * How far (model units) the skin the page draws avatar `id` with moves from
 * the skin its package's shipped units give, for a full smile on both sides
 * (AU 12, channels 15 and 16): the face's own model against a model built
 * afresh from the same package in the page's engine.
 */
const departure = (page, id) => page.evaluate((avatar) => {
  const { view } = window.facewireRoom;
  const face = view.faces.get(avatar);
  if (!face) return null;
  const params = { ...window.facewireRoom.client.face(avatar) };
  params.au = new Float32Array(params.au.length);
  params.au[15] = 1;
  params.au[16] = 1;
  const drawn = Float32Array.from(face.model.skinShape(params).positions);
  const pkg = view.engine.readPackage(face.bytes);
  const shipped = view.engine.avatarFromPackage(pkg);
  pkg.release();
  try {
    const positions = shipped.skinShape(params).positions;
    let largest = 0;
    for (let i = 0; i < positions.length; ++i) largest = Math.max(largest, Math.abs(positions[i] - drawn[i]));
    return largest;
  } finally {
    shipped.release();
  }
}, id);

/** The departure once it meets `done`, or the last one seen after 10 s (frames are drawn a few times a second). */
async function departureOnce(page, id, done) {
  const deadline = Date.now() + 10000;
  for (;;) {
    const seen = await departure(page, id);
    if (done(seen) || Date.now() > deadline) return seen;
    await new Promise((resolve) => { setTimeout(resolve, 200); });
  }
}

test('a redefined unit moves its person\'s face in the other page, and only that face', async () => {
  ann = await web.page({ width: 800, height: 600 });
  bob = await web.page({ width: 800, height: 600 });
  await ann.goto(`${web.server.url}room.html?room=${ROOM}&name=Ann`);
  await until(ann, (s) => s.status === 'joined', 'Ann joining');
  await bob.goto(`${web.server.url}room.html?room=${ROOM}&name=Bob`);
  const joined = await until(bob, (s) => s.status === 'joined' && s.names.Ann && s.built.includes(s.names.Ann)
    && s.built.includes(s.you), 'Bob joining and building both faces');
  const annId = joined.names.Ann;
  assert.equal(await departure(bob, annId), 0, 'before the definition, Ann is drawn with her shipped units');

  const request = await ann.evaluate((script) => window.facewireRoom.client.facs(script), DEFINITION);
  await until(ann, (s) => request in s.results, 'the definition\'s result');
  assert.equal((await room(ann)).results[request], '', 'the room took the definition');
  await ann.evaluate((sentence) => window.facewireRoom.client.facs(sentence), SMILE);

  const seen = await until(bob, (s) => s.units[annId]?.count > 0, 'Bob\'s client receiving Ann\'s units');
  assert.ok(!(joined.you in seen.units), 'nobody redefined Bob');
  const annMoved = await departureOnce(bob, annId, (d) => d > 0.05);
  const bobMoved = await departure(bob, joined.you);
  console.log(`a smile with the drawn units departs from the shipped one by ${annMoved} (Ann), ${bobMoved} (Bob)`);
  assert.ok(annMoved > 0.05, `Ann's face moves by the redefined unit (${annMoved})`);
  assert.equal(bobMoved, 0, 'Bob\'s face keeps the shipped units');

  // A restore: a new version without units; Bob's page draws the shipped AU 12 again.
  const restore = await ann.evaluate(() => window.facewireRoom.client.facs('AU 12 end'));
  await until(ann, (s) => restore in s.results, 'the restore\'s result');
  await until(bob, (s) => s.units[annId]?.count === 0, 'Bob\'s client receiving the restore');
  assert.equal(await departureOnce(bob, annId, (d) => d === 0), 0, 'restored: Ann\'s shipped units');
});
