// The invitation in the lobby's address, and the room page's address.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { readInvite, roomPageUrl } from '../../../web/lobby/invite.js';

test('an invite link\'s room, name and token are read; absent ones are empty', () => {
  assert.deepEqual(readInvite('?room=team.a&name=Ann%20Lee&token=fw1.abc.def'),
    { room: 'team.a', name: 'Ann Lee', token: 'fw1.abc.def', servers: '' });
  assert.deepEqual(readInvite(''), { room: '', name: '', token: '', servers: '' });
});

test('a list of servers in the lobby\'s address goes on to the room page', () => {
  const invite = readInvite('?room=r&servers=wss://a.chat.example/ws,wss://b.chat.example/ws');
  assert.equal(invite.servers, 'wss://a.chat.example/ws,wss://b.chat.example/ws');
  const url = roomPageUrl({ room: 'r', name: 'n', asset: '', token: '', servers: invite.servers });
  assert.equal(new URLSearchParams(url.slice(url.indexOf('?'))).get('servers'), invite.servers);
});

test('the room page gets the room, the name, the asset, its key and the token', () => {
  const url = roomPageUrl({ room: 'lobby', name: 'Zoë & co', asset: 'ab'.repeat(16), key: 'k-_3', token: 'fw1.x.y' });
  assert.ok(url.startsWith('room.html?'));
  const query = new URLSearchParams(url.slice(url.indexOf('?')));
  assert.deepEqual(Object.fromEntries(query),
    { room: 'lobby', name: 'Zoë & co', asset: 'ab'.repeat(16), key: 'k-_3', token: 'fw1.x.y' });
  assert.equal(roomPageUrl({ room: 'r', name: 'n', asset: '', token: '' }), 'room.html?room=r&name=n');
});

test('the room page is told the chosen language, and nothing when it is the default', () => {
  assert.equal(roomPageUrl({ room: 'r', name: 'A', language: 'pt-br' }), 'room.html?room=r&name=A&language=pt-br');
  assert.equal(roomPageUrl({ room: 'r', name: 'A' }), 'room.html?room=r&name=A');
});
