// The golden files the C++ writes for the browser's ports
// (tests/web/golden, committed in tests/vectors/<name>/<name>.json), and the
// comparisons their node tests make.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const vectorsDir = join(dirname(fileURLToPath(import.meta.url)), '..', '..', 'vectors');

/** tests/vectors/<name>/<name>.json, parsed. */
export function readGolden(name) {
  return JSON.parse(readFileSync(join(vectorsDir, name, `${name}.json`), 'utf8'));
}

/** `actual` within `tolerance` of `expected` (numbers, or arrays of them), saying where not. */
export function assertClose(actual, expected, tolerance, where) {
  if (Array.isArray(expected)) {
    assert.equal(actual.length, expected.length, `${where}: length`);
    expected.forEach((e, i) => assertClose(actual[i], e, tolerance, `${where}[${i}]`));
    return;
  }
  assert.ok(Number.isFinite(actual), `${where}: ${actual} is not a number`);
  assert.ok(Math.abs(actual - expected) <= tolerance, `${where}: ${actual}, the C++ ${expected} (tolerance ${tolerance})`);
}

/** An angle within `tolerance` of the C++'s, a whole turn apart counting as equal (yaw pi and -pi). */
export function assertAngleClose(actual, expected, tolerance, where) {
  const turn = 2 * Math.PI;
  const d = Math.abs((((actual - expected) % turn) + turn + Math.PI) % turn - Math.PI);
  assert.ok(d <= tolerance, `${where}: ${actual} rad, the C++ ${expected} (tolerance ${tolerance})`);
}
