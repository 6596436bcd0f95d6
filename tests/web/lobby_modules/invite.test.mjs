// The invitation in the lobby's address, and the room page's address.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { readInvite, roomPageUrl } from '../../../web/lobby/invite.js';

test('an invite link\'s room, name and token are read; absent ones are empty', () => {
  assert.deepEqual(readInvite('?room=team.a&name=Ann%20Lee&token=fw1.abc.def'),
    { room: 'team.a', name: 'Ann Lee', token: 'fw1.abc.def' });
  assert.deepEqual(readInvite(''), { room: '', name: '', token: '' });
});

test('the room page gets the room, the name, the asset, its key and the token', () => {
  const url = roomPageUrl({ room: 'lobby', name: 'Zoë & co', asset: 'ab'.repeat(16), key: 'k-_3', token: 'fw1.x.y' });
  assert.ok(url.startsWith('room.html?'));
  const query = new URLSearchParams(url.slice(url.indexOf('?')));
  assert.deepEqual(Object.fromEntries(query),
    { room: 'lobby', name: 'Zoë & co', asset: 'ab'.repeat(16), key: 'k-_3', token: 'fw1.x.y' });
  assert.equal(roomPageUrl({ room: 'r', name: 'n', asset: '', token: '' }), 'room.html?room=r&name=n');
});
