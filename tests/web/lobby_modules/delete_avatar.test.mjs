// Deleting one's avatar from the lobby: the request the server expects, and
// what the person is told when it fails.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { deleteAvatar } from '../../../web/lobby/delete_avatar.js';

function answering(status, body = '') {
  const calls = [];
  const fetchImpl = async (url, init) => {
    calls.push({ url, init });
    return { status, text: async () => body };
  };
  return { calls, fetchImpl };
}

test('the key goes in X-Avatar-Key, with DELETE on the avatar', async () => {
  const { calls, fetchImpl } = answering(204);
  await deleteAvatar('ab'.repeat(16), 'k3y', fetchImpl);
  assert.equal(calls.length, 1);
  assert.equal(calls[0].url, `api/avatars/${'ab'.repeat(16)}`);
  assert.equal(calls[0].init.method, 'DELETE');
  assert.equal(calls[0].init.headers['X-Avatar-Key'], 'k3y');
});

test('an avatar gone already counts as deleted', async () => {
  const { fetchImpl } = answering(404, 'no avatar is stored here');
  await deleteAvatar('ab'.repeat(16), 'k3y', fetchImpl);
});

test('a refusal says the server\'s reason', async () => {
  const { fetchImpl } = answering(403, 'that is not the key of avatar X: only whoever uploaded it may delete it\n');
  await assert.rejects(deleteAvatar('ab'.repeat(16), 'wrong', fetchImpl), /only whoever uploaded it/);
});

test('no connection is said as such', async () => {
  const fetchImpl = async () => {
    throw new TypeError('Failed to fetch');
  };
  await assert.rejects(deleteAvatar('ab'.repeat(16), 'k3y', fetchImpl), /did not reach the server/);
});
