// Muting for oneself (web/room/mute_list.js): the lines of a muted name are
// hidden and counted, its faces are drawn at rest, everyone wearing it is
// muted and the viewer never, and the list is kept per room.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { MuteList, NEUTRAL_FACE } from '../../../web/room/mute_list.js';

const YOU = 1;
const lines = [
  { from: 2, name: 'Bob', text: 'hi' },
  { from: 3, name: 'Cat', text: 'hello' },
  { from: 0, name: 'avatar 0', text: 'your line was not sent' },
  { from: 4, name: 'Bob', text: 'another Bob' },
  { from: YOU, name: 'Bob', text: 'the viewer is called Bob too' },
  { from: 2, name: 'Bob', text: 'still here' },
];

test('nobody muted: every line shows and every face is as decoded', () => {
  const mutes = new MuteList();
  const { shown, hidden } = mutes.filterLines(lines, YOU);
  assert.deepEqual(shown, lines);
  assert.equal(hidden.size, 0);
  const decoded = { au: [0.8], head_yaw_rad: 0.3 };
  assert.equal(mutes.faceOf(2, 'Bob', YOU, decoded), decoded);
});

test('a muted name: its lines hidden and counted, the server\'s and the viewer\'s own still shown', () => {
  const mutes = new MuteList(['Bob']);
  const { shown, hidden } = mutes.filterLines(lines, YOU);
  assert.deepEqual(shown.map((l) => l.text), ['hello', 'your line was not sent', 'the viewer is called Bob too']);
  assert.deepEqual([...hidden], [['Bob', 3]]);
});

test('a muted face is drawn at rest: no action units, eyes and head straight ahead, no colour', () => {
  const mutes = new MuteList(['Bob']);
  const smiling = {
    au: new Array(40).fill(0).map((_, i) => (i === 15 ? 0.9 : 0)), head_yaw_rad: 0.4, head_pitch_rad: -0.1, head_roll_rad: 0.05,
    head_translation_mm: [3, 1, 0], eye_left: { yaw_rad: 0.2, pitch_rad: 0.1 }, eye_right: { yaw_rad: 0.2, pitch_rad: 0.1 },
    lid_left: 0.4, lid_right: 0.4, blush: [0.7, 0.7, 0, 0, 0], pallor: 0.2,
  };
  const face = mutes.faceOf(4, 'Bob', YOU, smiling);
  assert.equal(face, NEUTRAL_FACE);
  assert.ok(face.au.every((v) => v === 0));
  for (const key of ['head_yaw_rad', 'head_pitch_rad', 'head_roll_rad', 'lid_left', 'lid_right', 'pallor']) assert.equal(face[key], 0, key);
  assert.deepEqual([face.eye_left, face.eye_right], [{ yaw_rad: 0, pitch_rad: 0 }, { yaw_rad: 0, pitch_rad: 0 }]);
  assert.ok(face.blush.every((v) => v === 0) && face.head_translation_mm.every((v) => v === 0));
  // The viewer's own face is never muted, whatever its name.
  assert.equal(mutes.faceOf(YOU, 'Bob', YOU, smiling), smiling);
  assert.equal(mutes.faceOf(3, 'Cat', YOU, smiling), smiling);
});

test('mute, unmute and toggle; how many wear a name', () => {
  const mutes = new MuteList();
  assert.equal(mutes.toggle('Bob'), true);
  assert.ok(mutes.mutes(2, 'Bob', YOU) && mutes.mutes(4, 'Bob', YOU) && !mutes.mutes(YOU, 'Bob', YOU));
  assert.equal(mutes.toggle('Bob'), false);
  assert.equal(mutes.mutes(2, 'Bob', YOU), false);
  mutes.mute('Cat');
  mutes.mute('Cat');
  assert.deepEqual(mutes.names, ['Cat']);
  mutes.unmute('Cat');
  assert.deepEqual(mutes.names, []);
  const avatars = [{ id: YOU, name: 'Bob' }, { id: 2, name: 'Bob' }, { id: 4, name: 'Bob' }, { id: 3, name: 'Cat' }];
  assert.equal(MuteList.wearing(avatars, 'Bob', YOU), 2);
  assert.equal(MuteList.wearing(avatars, 'Dan', YOU), 0);
});

test('kept per room in storage; a damaged entry mutes nobody', () => {
  const store = new Map();
  const storage = { getItem: (k) => store.get(k) ?? null, setItem: (k, v) => store.set(k, v), removeItem: (k) => store.delete(k) };
  const mutes = MuteList.load(storage, 'kitchen');
  mutes.mute('Bob');
  mutes.save(storage, 'kitchen');
  assert.deepEqual(MuteList.load(storage, 'kitchen').names, ['Bob']);
  assert.deepEqual(MuteList.load(storage, 'garden').names, [], 'another room has its own list');
  mutes.unmute('Bob');
  mutes.save(storage, 'kitchen');
  assert.equal(store.size, 0, 'nobody muted: nothing kept');
  store.set('facewire.muted.kitchen', '{not json');
  assert.deepEqual(MuteList.load(storage, 'kitchen').names, []);
  store.set('facewire.muted.kitchen', JSON.stringify(['Bob', 7, '']));
  assert.deepEqual(MuteList.load(storage, 'kitchen').names, ['Bob']);
  assert.deepEqual(MuteList.load(null, 'kitchen').names, []);
});
