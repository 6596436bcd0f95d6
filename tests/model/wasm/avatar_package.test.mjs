// The engine's package reader (fw::model::parse_avatar_package in
// WebAssembly) against the native reader: the same fields from every sound
// package, the same refusal and message for every damaged one.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { AvatarPackageError } from '../../../web/engine/engine.js';
import { engine, goldens, packageBytes } from './engine_support.mjs';

const refusals = ['damaged', 'other_format_version', 'other_generic_face'];

test('the goldens hold sound and damaged packages', () => {
  assert.ok(goldens.packages.filter((p) => p.sound).length >= 2);
  // Both kinds of texture light: a photo's (the default) and albedo.
  const lights = goldens.packages.filter((p) => p.sound).map((p) => p.package.texture_light);
  assert.deepEqual([...new Set(lights)].sort(), ['albedo', 'photo']);
  assert.ok(goldens.packages.filter((p) => !p.sound).length >= 8);
});

test('the engine fits to the same generic face as the C++', () => {
  assert.equal(engine.genericFaceVersion, goldens.generic_face_version);
});

for (const golden of goldens.packages.filter((p) => p.sound)) {
  test(`reads the ${golden.name} package as the C++ does`, () => {
    const p = engine.readPackage(packageBytes(golden.file));
    try {
      const g = golden.package;
      assert.equal(p.version, g.version);
      assert.equal(p.genericFaceVersion, g.generic_face_version);
      assert.deepEqual([...p.skinTone], g.skin_tone);
      assert.deepEqual([...p.irisColour], g.iris_colour);
      assert.equal(p.textureLight, g.texture_light);
      // Parsed values are the same floats, bit for bit: no arithmetic between.
      assert.deepEqual([...p.closedLidRect], g.closed_lid_rect);
      assert.deepEqual([...p.headOutline], g.head_outline);
      assert.deepEqual([...p.fittedVertices], g.fitted_vertices);
      assert.deepEqual([...p.landmarks], g.landmarks);
      for (const [name, image] of Object.entries(g.images)) {
        if (image === null) {
          assert.equal(p.images[name], null, name);
        } else {
          assert.equal(p.images[name].type, image.type, name);
          assert.equal(p.images[name].bytes.length, image.size, name);
        }
      }
      assert.equal(p.hasEyeLayer, g.images.eye !== null);
    } finally {
      p.release();
    }
  });
}

for (const golden of goldens.packages.filter((p) => !p.sound)) {
  test(`refuses the ${golden.name} package with the C++ reader's message`, () => {
    assert.throws(() => engine.readPackage(packageBytes(golden.file)), (e) => {
      assert.ok(e instanceof AvatarPackageError, `${e}`);
      assert.equal(e.message, golden.error);
      assert.equal(e.refusal, refusals[golden.refusal]);
      assert.equal(e.outOfDate, golden.refusal !== 0);
      return true;
    });
  });
}

test('a package accepts an ArrayBuffer as well as bytes', () => {
  const bytes = packageBytes(goldens.packages[0].file);
  const p = engine.readPackage(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length));
  assert.equal(p.version, 1);
  p.release();
  p.release();  // twice is harmless
});

test('a released package makes no avatar', () => {
  const p = engine.readPackage(packageBytes(goldens.packages[0].file));
  p.release();
  assert.throws(() => engine.avatarFromPackage(p), /released/);
});
