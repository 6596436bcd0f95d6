// The engine's avatar model (make_avatar_model and reconstruct_face in
// WebAssembly) against the native C++: the fitted face, every cloned
// action-unit morph, and the skin for each golden FaceParams, for the
// generic face and every sound package.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import {
  NORMAL_TOLERANCE, POSITION_TOLERANCE, assertClose, engine, goldens, maxDifference, packageBytes,
} from './engine_support.mjs';

function checkMesh(mesh, golden, what) {
  assertClose(mesh.positions, golden.positions, POSITION_TOLERANCE, `${what} positions`);
  assertClose(mesh.uvs, golden.uvs, POSITION_TOLERANCE, `${what} uvs`);
  assertClose(mesh.normals, golden.normals, NORMAL_TOLERANCE, `${what} normals`);
}

function checkAvatar(avatar, golden, what) {
  const face = avatar.face;
  checkMesh(face.skin, golden.skin, `${what} skin`);
  face.eyes.forEach((eye, side) => {
    const g = golden.eyes[side];
    assertClose(eye.centre, g.centre, POSITION_TOLERANCE, `${what} eye ${side} centre`);
    assertClose([eye.radius, eye.capAngleRad], [g.radius, g.cap_angle_rad], POSITION_TOLERANCE, `${what} eye ${side}`);
    checkMesh(eye.mesh, g.mesh, `${what} eye ${side}`);
  });
  checkMesh(face.mouthCavity, golden.mouth_cavity, `${what} mouth cavity`);
  checkMesh(face.head.mesh, golden.head.mesh, `${what} head shell`);
  assertClose(face.head.mesh.photoLightNormals, golden.head.mesh.photo_light_normals, NORMAL_TOLERANCE,
    `${what} head shell photo light normals`);
  assertClose(face.head.outline, golden.head.outline, POSITION_TOLERANCE, `${what} head outline`);
  golden.morphs.forEach((g, channel) => {
    const morph = avatar.morph(channel);
    assertClose(morph.vertexDelta, g.vertex_delta, POSITION_TOLERANCE, `${what} morph ${channel} vertex_delta`);
    assertClose(morph.uvDelta, g.uv_delta, POSITION_TOLERANCE, `${what} morph ${channel} uv_delta`);
  });
  for (const frame of golden.frames) {
    const shape = avatar.skinShape(frame.params);
    assertClose(shape.positions, frame.positions, POSITION_TOLERANCE, `${what} ${frame.name} positions`);
    assertClose(shape.uvs, frame.uvs, POSITION_TOLERANCE, `${what} ${frame.name} uvs`);
    assertClose(shape.normals, frame.normals, NORMAL_TOLERANCE, `${what} ${frame.name} normals`);
  }
}

test('the generic avatar is the C++ generic avatar', () => {
  const avatar = engine.genericAvatar();
  try {
    assert.equal(avatar.vertexCount * 3, goldens.generic.skin.positions.length);
    checkAvatar(avatar, goldens.generic, 'generic');
  } finally {
    avatar.release();
  }
});

for (const golden of goldens.packages.filter((p) => p.sound)) {
  test(`the ${golden.name} package's avatar is the C++ avatar`, () => {
    const p = engine.readPackage(packageBytes(golden.file));
    const avatar = engine.avatarFromPackage(p);
    p.release();  // the avatar keeps what it needs
    try {
      checkAvatar(avatar, golden.avatar, golden.name);
    } finally {
      avatar.release();
    }
  });
}

test('the comparison tells another face and another expression apart', () => {
  // Guards the tests above against passing vacuously: a fitted face is not
  // the generic one, and a frame is not the neutral one, by far more than
  // the tolerance.
  const golden = goldens.packages.find((p) => p.sound && p.name === 'photo');
  assert.ok(maxDifference(golden.avatar.skin.positions, goldens.generic.skin.positions) > 100 * POSITION_TOLERANCE);
  const avatar = engine.genericAvatar();
  try {
    const [neutral, joy] = goldens.generic.frames;
    const shape = avatar.skinShape(joy.params);
    assert.ok(maxDifference(shape.positions, neutral.positions) > 100 * POSITION_TOLERANCE);
  } finally {
    avatar.release();
  }
});

test('a released avatar refuses to make frames', () => {
  const avatar = engine.genericAvatar();
  avatar.release();
  assert.throws(() => avatar.skinShape({}), /released/);
});
