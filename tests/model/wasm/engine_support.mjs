// What the engine's tests share: the engine built in this build tree, the
// goldens the C++ wrote for it (write_engine_goldens, run by ctest just
// before), and comparison within a tolerance.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

import { loadEngine } from '../../../web/engine/engine.js';

function fromEnvironment(name) {
  const value = process.env[name];
  if (!value) throw new Error(`${name} is not set: run these tests through ctest (web_engine_js)`);
  return value;
}

const goldensDir = fromEnvironment('FW_ENGINE_GOLDENS');
const moduleDir = fromEnvironment('FW_ENGINE_MODULE_DIR');
const sourceDir = fromEnvironment('FW_SOURCE_DIR');

export const goldens = JSON.parse(readFileSync(join(goldensDir, 'goldens.json'), 'utf8'));
export const packageBytes = (file) => new Uint8Array(readFileSync(join(goldensDir, file)));

// The module as the browser gets it; the .wasm handed over as bytes, since
// this emscripten's ES module fetches it only in a browser.
export const engine = await loadEngine({
  genericFaceJson: readFileSync(join(sourceDir, 'avatar/model/assets/generic_face.json'), 'utf8'),
  moduleUrl: pathToFileURL(join(moduleDir, 'facewire_model.js')).href,
  wasmBinary: readFileSync(join(moduleDir, 'facewire_model.wasm')),
});

// Tolerances. The WebAssembly module runs the same C++ in float32 as the
// native build, and IEEE arithmetic is the same on both: today its results
// are bit for bit the native ones. What may differ is the C library (musl's
// sin, cos and atan2 against glibc's, within an ulp or two; they place the
// head shell's rays) and a compiler's choice of instructions after an
// upgrade. Model coordinates are of order 1 to 5, where a float's ulp is 1e-7
// to 5e-7: 2e-6 (a tenth of a micrometre on a face) allows a few ulps and
// nothing else, since a real difference (another AU weight, another fit, a
// lid closed) moves vertices by 1e-3 or more.
export const POSITION_TOLERANCE = 2e-6;
// Unit normals from cross products of nearby vertices amplify the rounding
// of their positions by the inverse of an edge length (about 0.1 units).
export const NORMAL_TOLERANCE = 2e-5;
// The head and eye matrices are a JavaScript port computed in doubles, the
// renderer's in glm's floats: float rounding of entries of order 1 to 3.
export const MATRIX_TOLERANCE = 1e-6;

/** The largest absolute difference between two arrays of numbers of the same length. */
export function maxDifference(actual, expected) {
  assert.equal(actual.length, expected.length, 'length');
  let worst = 0;
  for (let i = 0; i < expected.length; ++i) {
    const d = Math.abs(actual[i] - expected[i]);
    if (!(d <= worst)) worst = d;  // NaN counts as the worst
  }
  return worst;
}

export function assertClose(actual, expected, tolerance, what) {
  const worst = maxDifference(actual, expected);
  assert.ok(worst <= tolerance, `${what}: differs from the C++ by up to ${worst} (allowed ${tolerance})`);
}
