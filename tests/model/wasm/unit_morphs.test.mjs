// The engine's redefined units (AvatarModel.setUnitMorphs, the WebAssembly
// fw_avatar_set_unit_morphs) against the native C++ (fw::model::
// set_unit_morphs): the skin for each golden FaceParams with the units a
// unit morphs message carries, on the generic face and every sound
// package's fit; an empty set gives the shipped frames back.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { POSITION_TOLERANCE, assertClose, engine, goldens, maxDifference, packageBytes } from './engine_support.mjs';

function checkRedefined(avatar, golden, redefined, what) {
  avatar.setUnitMorphs(redefined.units);
  let largest = 0;
  redefined.frames.forEach((frame, i) => {
    const shape = avatar.skinShape(golden.frames[i].params);
    assertClose(shape.positions, frame.positions, POSITION_TOLERANCE, `${what} ${frame.name} positions, redefined`);
    assertClose(shape.uvs, frame.uvs, POSITION_TOLERANCE, `${what} ${frame.name} uvs, redefined`);
    largest = Math.max(largest, maxDifference(frame.positions, golden.frames[i].positions));
  });
  // Not vacuous: some frame moves otherwise than with the shipped units.
  assert.ok(largest > 100 * POSITION_TOLERANCE, `${what}: the redefined units changed no frame`);
  avatar.setUnitMorphs([]);
  golden.frames.forEach((frame) => {
    assertClose(avatar.skinShape(frame.params).positions, frame.positions, POSITION_TOLERANCE,
      `${what} ${frame.name} positions, restored`);
  });
}

test('the generic avatar with redefined units is the C++ one', () => {
  const avatar = engine.genericAvatar();
  try {
    checkRedefined(avatar, goldens.generic, goldens.generic_redefined, 'generic');
  } finally {
    avatar.release();
  }
});

for (const golden of goldens.packages.filter((p) => p.sound)) {
  test(`the ${golden.name} package's avatar with redefined units is the C++ one`, () => {
    const p = engine.readPackage(packageBytes(golden.file));
    const avatar = engine.avatarFromPackage(p);
    p.release();
    try {
      checkRedefined(avatar, golden.avatar, golden.redefined, golden.name);
    } finally {
      avatar.release();
    }
  });
}

test('units the face cannot take are refused with the reason, and the face keeps its units', () => {
  const avatar = engine.genericAvatar();
  try {
    const before = Float32Array.from(avatar.skinShape(goldens.generic.frames[1].params).positions);
    const past = [{ channel: 0, moves: [{ vertex: avatar.vertexCount, delta: [1, 0, 0] }] }];
    assert.throws(() => avatar.setUnitMorphs(past), /the face has/);
    const unordered = [{ channel: 3, moves: [] }, { channel: 2, moves: [] }];
    assert.throws(() => avatar.setUnitMorphs(unordered), /not a later action-unit channel/);
    assert.deepEqual(avatar.skinShape(goldens.generic.frames[1].params).positions, before);
  } finally {
    avatar.release();
  }
});
