// The browser's package assembly (web/room/package_assembly.js) against the
// native client's (client/room/package_assembler.cpp) as the C++ wrote it in
// tests/vectors/package_assembly: every chunk completes the same package
// (the same bytes), refuses the same way, or waits, run after run.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { PackageAssembly } from '../../../web/room/package_assembly.js';
import { readGolden } from '../support/golden.mjs';

const golden = readGolden('package_assembly');

// The browser's answer in the golden file's terms.
function outcome(result) {
  if (result === null) return { done: null, refused: false };
  if (result.problem !== undefined) {
    assert.equal(typeof result.problem, 'string');
    return { done: null, refused: true };
  }
  return { done: Array.from(result.bytes), doneAvatar: result.avatar, doneQuality: result.quality, refused: false };
}

test('chunks complete, refuse and wait as natively', () => {
  assert.ok(golden.runs.length >= 10);
  for (const run of golden.runs) {
    const assembly = new PackageAssembly();
    for (const [k, step] of run.steps.entries()) {
      if (step.forget !== undefined) {
        assembly.forget(step.forget);
        continue;
      }
      const c = step.add;
      const got = outcome(assembly.add({
        avatar: c.avatar, quality: c.quality, totalBytes: c.total_bytes, offset: c.offset, data: Uint8Array.from(c.data),
      }));
      const where = `${run.what}, step ${k}`;
      assert.equal(got.refused, step.refused, `${where}: refused`);
      assert.deepEqual(got.done, step.done, `${where}: completed package`);
      if (step.done !== null) assert.deepEqual([got.doneAvatar, got.doneQuality], [step.done_avatar, step.done_quality], where);
    }
  }
});
