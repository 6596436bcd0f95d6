// The browser's mute list (web/room/mute_list.js) against the native
// client's (client/room/mute_list.hpp) as the C++ wrote it in
// tests/vectors/mute_list: the same verdict for every avatar id and name
// (the viewer's own and the server's never muted; names compared exactly),
// and the same still face for whom it mutes.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { MuteList, NEUTRAL_FACE } from '../../../web/room/mute_list.js';
import { readGolden } from '../support/golden.mjs';

const golden = readGolden('mute_list');

test('whom a list of names mutes, as natively', () => {
  const list = new MuteList(golden.muted);
  assert.ok(golden.cases.length >= 40);
  for (const c of golden.cases)
    assert.equal(list.mutes(c.id, c.name, golden.you), c.mutes, `avatar ${c.id} named ${JSON.stringify(c.name)}`);
});

test('a muted face is the native still face', () => {
  // A field the browser leaves out counts as 0 (web/engine/README.md), so an
  // action unit missing from NEUTRAL_FACE.au is the C++'s 0.
  const still = golden.still_face;
  const au = still.au.map((_, k) => NEUTRAL_FACE.au[k] ?? 0);
  assert.deepEqual(au, still.au);
  for (const key of Object.keys(still).filter((k) => k !== 'au'))
    assert.deepEqual(NEUTRAL_FACE[key], still[key], key);
});
