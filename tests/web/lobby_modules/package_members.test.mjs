// The members of an avatar package (avatar/photo/FORMAT.md), as the
// lobby's preview reads them.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { readPackageMembers } from '../../../web/lobby/package_members.js';

function fakePackage(members, version = 1) {
  const manifest = Buffer.from(JSON.stringify({
    format: 'facewire-avatar',
    members: members.map(([name, type, bytes]) => ({ name, type, size: bytes.length, crc32: 0 })),
  }));
  const header = Buffer.alloc(16);
  header.write('FWAV', 0, 'ascii');
  header[4] = version;
  header.writeUInt32LE(manifest.length, 8);
  return Buffer.concat([header, manifest, ...members.map(([, , bytes]) => Buffer.from(bytes))]);
}

test('members are found by name, in manifest order', () => {
  const bytes = fakePackage([['mesh', 'application/x-facewire-fit', [1, 2, 3]], ['preview', 'image/webp', [9, 8]]]);
  const { manifest, members } = readPackageMembers(new Uint8Array(bytes));
  assert.equal(manifest.format, 'facewire-avatar');
  assert.deepEqual([...members.get('preview').bytes], [9, 8]);
  assert.equal(members.get('preview').type, 'image/webp');
  assert.deepEqual([...members.get('mesh').bytes], [1, 2, 3]);
});

test('what is not a package, another version and a cut-off package are refused with a reason', () => {
  assert.throws(() => readPackageMembers(new Uint8Array([1, 2, 3])), /not an avatar package/);
  assert.throws(() => readPackageMembers(fakePackage([], 2)), /format 2/);
  const whole = fakePackage([['preview', 'image/webp', [1, 2, 3, 4]]]);
  assert.throws(() => readPackageMembers(whole.subarray(0, whole.length - 1)), /cut off in member preview/);
  assert.throws(() => readPackageMembers(whole.subarray(0, 20)), /cut off in its manifest/);
});
