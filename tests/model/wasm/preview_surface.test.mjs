// The engine's face-lab preview surface (AvatarModel.setSurface, the
// WebAssembly fw_avatar_set_surface, fw::model::carried_surface): a generic
// displacement is added to every frame, carried onto the fit exactly as a
// unit morph of the same moves at full intensity is; [] takes it away; a
// vertex past the face is refused with the reason and changes nothing.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { POSITION_TOLERANCE, assertClose, engine, goldens, maxDifference, packageBytes } from './engine_support.mjs';

const MOVES = [
  { vertex: 3, delta: [410, -300, 120] }, { vertex: 54, delta: [-2000, 900, 0] }, { vertex: 200, delta: [0, 0, 4096] },
];

function checkSurface(avatar, what) {
  const neutral = Float32Array.from(avatar.skinShape({}).positions);
  avatar.setSurface(MOVES);
  const withSurface = Float32Array.from(avatar.skinShape({}).positions);
  assert.ok(maxDifference(withSurface, neutral) > 100 * POSITION_TOLERANCE, `${what}: the surface moved nothing`);
  avatar.setSurface([]);
  assertClose(avatar.skinShape({}).positions, neutral, POSITION_TOLERANCE, `${what}: cleared`);
  // The same moves as a redefined unit at full intensity: carried the same way.
  avatar.setUnitMorphs([{ channel: 0, moves: MOVES }]);
  const au = new Array(29).fill(0);
  au[0] = 1;
  assertClose(avatar.skinShape({ au }).positions, withSurface, POSITION_TOLERANCE, `${what}: as a unit morph`);
  avatar.setUnitMorphs([]);
  assert.throws(() => avatar.setSurface([{ vertex: avatar.vertexCount, delta: [1, 0, 0] }]), /the face has/);
  assertClose(avatar.skinShape({}).positions, neutral, POSITION_TOLERANCE, `${what}: a refused surface kept none`);
}

test('the generic avatar adds a preview surface to its frames', () => {
  const avatar = engine.genericAvatar();
  try {
    const neutral = Float32Array.from(avatar.skinShape({}).positions);
    avatar.setSurface(MOVES);
    const moved = avatar.skinShape({}).positions;
    for (const { vertex, delta } of MOVES)
      for (let k = 0; k < 3; ++k)
        assert.ok(Math.abs(moved[3 * vertex + k] - neutral[3 * vertex + k] - delta[k] / 4096) < 1e-5, `vertex ${vertex}`);
    avatar.setSurface([]);
    checkSurface(avatar, 'generic');
  } finally {
    avatar.release();
  }
});

for (const golden of goldens.packages.filter((p) => p.sound).slice(0, 2)) {
  test(`the ${golden.name} package's avatar carries a preview surface onto its fit as its units`, () => {
    const p = engine.readPackage(packageBytes(golden.file));
    const avatar = engine.avatarFromPackage(p);
    p.release();
    try {
      checkSurface(avatar, golden.name);
    } finally {
      avatar.release();
    }
  });
}
