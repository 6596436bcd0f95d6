// The per-frame draw values (web/engine/face_draw.js, head_pose.js: a
// JavaScript port of avatar/render's face_draw, head_transform and
// eye_transform) against the matrices the C++ made for the same FaceParams.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { MATRIX_TOLERANCE, POSITION_TOLERANCE, assertClose, engine, goldens, packageBytes } from './engine_support.mjs';

const avatars = [
  ['generic', goldens.generic, () => engine.genericAvatar()],
  ...goldens.packages.filter((p) => p.sound).map((p) => [p.name, p.avatar, () => {
    const pkg = engine.readPackage(packageBytes(p.file));
    const avatar = engine.avatarFromPackage(pkg);
    pkg.release();
    return avatar;
  }]),
];

for (const [name, golden, make] of avatars) {
  test(`${name}: head and eye matrices are the renderer's`, () => {
    const avatar = make();
    try {
      for (const frame of golden.frames) {
        const values = avatar.frame(frame.params);
        assertClose(values.model, frame.draw.model, MATRIX_TOLERANCE, `${frame.name} model`);
        values.eyeModels.forEach((m, side) =>
          assertClose(m, frame.draw.eye_models[side], MATRIX_TOLERANCE, `${frame.name} eye ${side}`));
        assert.deepEqual(values.lidClosure, [frame.params.lid_right, frame.params.lid_left]);
        assert.deepEqual(values.blush, frame.params.blush);
        assert.equal(values.pallor, frame.params.pallor);
        assert.equal(values.blood, frame.params.blush.some((b) => b > 0) || frame.params.pallor > 0);
        assertClose(values.positions, frame.positions, POSITION_TOLERANCE, `${frame.name} positions`);
      }
    } finally {
      avatar.release();
    }
  });
}

test('a seat moves the head: place multiplies the pose', () => {
  const avatar = engine.genericAvatar();
  try {
    const place = new Float32Array([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3.4, 0, 0, 1]);
    const at = avatar.frame({}, place);
    assert.ok(Math.abs(at.model[12] - 3.4) < 1e-6, `${at.model[12]}`);
  } finally {
    avatar.release();
  }
});
