// The servers a room page takes from its address (web/shared/server_list.js):
// its own by default; a list of ws:// or wss:// addresses on its own host
// or one under it; a clear reason for anything else.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { MAX_SERVERS, parseServers } from '../../../web/shared/server_list.js';

const page = new URL('https://chat.example/room.html?room=r');
const local = new URL('http://127.0.0.1:8080/room.html');

test('without a list, the page\'s own server: wss:// on https, ws:// on http', () => {
  assert.deepEqual(parseServers(null, page), { servers: ['wss://chat.example/ws'], error: '' });
  assert.deepEqual(parseServers('  ', local), { servers: ['ws://127.0.0.1:8080/ws'], error: '' });
});

test('a list is taken in its order, blanks around each address dropped', () => {
  assert.deepEqual(parseServers('wss://a.chat.example/ws, wss://chat.example:8443/', page),
    { servers: ['wss://a.chat.example/ws', 'wss://chat.example:8443/'], error: '' });
  assert.deepEqual(parseServers('ws://127.0.0.1:8080/,ws://127.0.0.1:8081/', local).servers,
    ['ws://127.0.0.1:8080/', 'ws://127.0.0.1:8081/']);
});

test('a bad list is refused with what is wrong and where', () => {
  const error = (text, where = page) => {
    const parsed = parseServers(text, where);
    assert.deepEqual(parsed.servers, [], text);
    return parsed.error;
  };
  assert.match(error('https://chat.example/'), /^servers: the server \('https:\/\/chat.example\/'\) is not a ws:\/\/ or wss:\/\/ address: list them as servers=wss:/);
  assert.match(error('wss://a.chat.example/ws,,wss://b.chat.example/ws'), /^servers: server 2 of 3 is missing/);
  assert.match(error('wss://a.chat.example/ws,nonsense'), /^servers: server 2 of 2 \('nonsense'\) is not an address/);
  assert.match(error('ws://chat.example/ws'), /an https page may not reach: use wss:\/\//);
  assert.match(error('wss://chat.example.evil.net/ws'), /is not on chat.example or a host under it: the page sends your name, your face's key and your invitation only there/);
  assert.match(error('wss://example/ws'), /is not on chat.example/);
  assert.match(error('ws://127.0.0.2:8080/', local), /is not on 127.0.0.1/);
  assert.match(error('wss://ann:pw@chat.example/ws'), /user name or password/);
  assert.match(error('wss://chat.example/ws,wss://CHAT.example/ws'), /server 2 of 2 .* is listed twice/);
  const many = Array.from({ length: MAX_SERVERS + 1 }, (_, i) => `wss://n${i}.chat.example/ws`).join(',');
  assert.equal(error(many), `servers: at most ${MAX_SERVERS} servers, not ${MAX_SERVERS + 1}`);
});
