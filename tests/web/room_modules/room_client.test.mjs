// The browser's room client (web/room/room_client.js) driven through a
// stand-in socket with messages written by the protocol port: joining,
// presence, seats, attention, chat, packages in chunks, commands going up,
// and what it does when a connection ends.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { readMessage } from '../../../web/protocol/session_read.js';
import { AttentionTarget, CloseCode, MessageType, PresenceChange } from '../../../web/protocol/session_types.js';
import { writeMessage } from '../../../web/protocol/session_write.js';
import { RoomClient } from '../../../web/room/room_client.js';

const seat = (x) => ({ xMm: x, yMm: 0, zMm: 0, facingYawRad: 0 });
const info = (id, name, x = 0) => ({ id, person: true, name, asset: '', previewBytes: 0, fullBytes: 0, seat: seat(x) });

class FakeSocket {
  constructor(url) {
    this.url = url;
    this.readyState = 1;
    this.sent = [];
    this.closedWith = null;
  }
  send(bytes) { this.sent.push(Uint8Array.from(bytes)); }
  close(code) { this.closedWith = code; }
  deliver(type, message) { this.onmessage({ data: writeMessage(type, message).buffer }); }
  drop() { this.onclose(); }
}

function client(extra = {}) {
  const sockets = [];
  let now = 0;
  const c = new RoomClient({
    url: 'ws://a/,ws://b/', room: 'r', name: 'Ann', openSocket: (url) => {
      const s = new FakeSocket(url);
      sockets.push(s);
      return s;
    },
    now: () => now, ...extra,
  });
  c.start();
  sockets[0].onopen();
  return { c, sockets, advance: (ms) => { now += ms; } };
}

const welcome = { you: 2, room: 'r', tickHz: 30, maxBps: 9600, avatars: [info(1, 'Bo', -420), info(2, 'Ann', 420)] };

test('says hello, then keeps the welcome, presence, seats, attention and chat', (t) => {
  const { c, sockets } = client({ maxBps: 9600, asset: 'ab', ownPackage: true });
  t.after(() => c.stop());
  const hello = readMessage(sockets[0].sent[0], MessageType.hello);
  assert.equal(hello.error, 0);
  assert.equal(hello.message.name, 'Ann');
  assert.equal(hello.message.maxBps, 9600);
  assert.equal(hello.message.avatar, 'ab');
  assert.ok(hello.message.ownPackage);

  sockets[0].deliver(MessageType.welcome, welcome);
  assert.equal(c.status, 'joined');
  assert.equal(c.you, 2);
  assert.deepEqual([...c.avatars.keys()], [1, 2]);

  sockets[0].deliver(MessageType.presence, { change: PresenceChange.joined, avatar: info(3, 'Cy', 0) });
  sockets[0].deliver(MessageType.seats, { seats: [{ avatar: 1, seat: seat(-500) }, { avatar: 3, seat: seat(7) }] });
  assert.equal(c.avatars.get(1).info.seat.xMm, -500);
  assert.equal(c.avatars.get(3).info.seat.xMm, 7);

  sockets[0].deliver(MessageType.attention, { entries: [
    { avatar: 1, target: AttentionTarget.avatar, targetAvatar: 2 }, { avatar: 9, target: AttentionTarget.room, targetAvatar: 0 }] });
  assert.equal(c.attention.get(1).targetAvatar, 2);
  assert.ok(!c.attention.has(9), 'an avatar nobody knows is ignored');

  sockets[0].deliver(MessageType.chat, { from: 3, text: 'hi all' });
  assert.deepEqual(c.chatLines.at(-1), { from: 3, name: 'Cy', text: 'hi all' });

  sockets[0].deliver(MessageType.presence, { change: PresenceChange.left, avatar: info(3, '', 0) });
  assert.ok(!c.avatars.has(3));
});

test('packages arrive in chunks and a full one is never replaced by a preview', (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].deliver(MessageType.welcome, welcome);
  const full = Uint8Array.from({ length: 10 }, (_, i) => i);
  sockets[0].deliver(MessageType.packageChunk, { avatar: 1, quality: 1, totalBytes: 10, offset: 0, data: full.subarray(0, 6) });
  assert.equal(c.avatars.get(1).package, null);
  sockets[0].deliver(MessageType.packageChunk, { avatar: 1, quality: 1, totalBytes: 10, offset: 6, data: full.subarray(6) });
  assert.deepEqual(c.avatars.get(1).package, { quality: 1, bytes: full });
  sockets[0].deliver(MessageType.packageChunk, { avatar: 1, quality: 0, totalBytes: 2, offset: 0, data: Uint8Array.of(7, 7) });
  assert.equal(c.avatars.get(1).package.quality, 1);
});

test('commands and chat go up as protocol messages', (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].deliver(MessageType.welcome, welcome);
  const id = c.express('joy', 0.8, 2000);
  c.lookAt(1, 4000);
  c.chat('hello');
  c.setRate(2400);
  const up = sockets[0].sent.slice(1);
  const express = readMessage(up[0], MessageType.command).message;
  assert.equal(express.requestId, id);
  assert.equal(express.emotion, 'joy');
  assert.equal(express.intensity, 0.8);
  assert.equal(readMessage(up[1], MessageType.command).message.target, 1);
  assert.equal(readMessage(up[2], MessageType.chat).message.text, 'hello');
  assert.equal(readMessage(up[3], MessageType.setRate).message.maxBps, 2400);
  sockets[0].deliver(MessageType.commandResult, { requestId: id, error: '' });
  assert.equal(c.results.get(id), '');
});

test('a drop reconnects to the next server; a final refusal stops with its reason', async (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].deliver(MessageType.welcome, welcome);
  sockets[0].drop();
  assert.equal(c.status, 'reconnecting');
  await new Promise((resolve) => setTimeout(resolve, 700));  // the first back-off is 0.5 s
  assert.equal(sockets.length, 2);
  assert.equal(sockets[1].url, 'ws://b/', 'the next server of the list');
  sockets[1].onopen();
  sockets[1].deliver(MessageType.closing, { code: CloseCode.unauthorized, reason: 'the token expired; ask for a new invite' });
  sockets[1].drop();
  assert.equal(c.status, 'closed');
  assert.equal(c.error, 'the token expired; ask for a new invite');
  await new Promise((resolve) => setTimeout(resolve, 700));
  assert.equal(sockets.length, 2, 'no new connection after a final refusal');
});

test('a server that shuts down passes the client to the next, and the list goes round', async (t) => {
  const { c, sockets } = client({ url: undefined, servers: ['ws://a/ws', 'ws://b/ws'] });
  t.after(() => c.stop());
  assert.equal(sockets[0].url, 'ws://a/ws');
  sockets[0].deliver(MessageType.welcome, welcome);
  sockets[0].deliver(MessageType.closing, { code: CloseCode.shuttingDown, reason: 'the server is shutting down; try again soon' });
  sockets[0].drop();
  assert.equal(c.server, 'ws://b/ws');
  assert.deepEqual(c.moves.at(-1), { to: 'ws://b/ws', why: 'the server is shutting down; try again soon' });
  await new Promise((resolve) => setTimeout(resolve, 700));
  assert.equal(sockets[1].url, 'ws://b/ws');
  sockets[1].onopen();
  const hello = readMessage(sockets[1].sent[0], MessageType.hello).message;
  assert.equal(hello.name, 'Ann', 'the same person on the next server');
  sockets[1].drop();  // never welcomed there: back to the first
  assert.deepEqual(c.moves.at(-1), { to: 'ws://a/ws', why: 'no connection' });
  await new Promise((resolve) => setTimeout(resolve, 1200));  // the second back-off is 1 s
  assert.equal(sockets[2].url, 'ws://a/ws');
});

test('the resume key of the last welcome goes with the hello to the next server', async (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].deliver(MessageType.welcome, { ...welcome, resume: 'resume-7' });
  sockets[0].drop();
  await new Promise((resolve) => setTimeout(resolve, 700));
  sockets[1].onopen();
  assert.equal(readMessage(sockets[1].sent[0], MessageType.hello).message.resume, 'resume-7');
});

test('a face being prepared is asked for again on the server that prepares it', async (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].deliver(MessageType.closing, { code: CloseCode.avatarBeingPrepared, reason: 'being prepared' });
  sockets[0].drop();
  assert.equal(c.server, 'ws://a/');
  assert.equal(c.moves.length, 0);
});

test('a malformed message closes the connection with a reason', (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].onmessage({ data: Uint8Array.of(0x82, 0x02).buffer });
  assert.equal(sockets[0].closedWith, 1002);
  assert.match(c.error, /malformed message \(truncated\)/);
});

test('hello carries the language; a speaking line is kept and handed on with the frames received before it', (t) => {
  const seen = [];
  const { c, sockets } = client({ language: 'de', onChange: (what, detail) => { if (what === 'speaking') seen.push(detail); } });
  t.after(() => c.stop());
  const hello = readMessage(sockets[0].sent[0], MessageType.hello);
  assert.equal(hello.message.protocolVersion, 5);
  assert.equal(hello.message.language, 'de');
  sockets[0].deliver(MessageType.welcome, welcome);
  const line = { avatar: 1, tick: 90, durationMs: 1800, language: 'de', text: 'Guten Tag' };
  sockets[0].deliver(MessageType.speaking, line);
  assert.deepEqual(c.speakingLines, [line]);
  assert.deepEqual(seen, [{ line, framesReceived: 0 }]);
});

test('without a language, hello asks for the server\'s default', (t) => {
  const { c, sockets } = client();
  t.after(() => c.stop());
  assert.equal(readMessage(sockets[0].sent[0], MessageType.hello).message.language, '');
});

test('a stream header of format version 1 closes with a reason that says to reload', (t) => {
  // The first bytes of a stream header of the previous release (format
  // version 1, before the corrective channels): refused, and the error says
  // what to do, not that the server sent something no server sends.
  const { c, sockets } = client();
  t.after(() => c.stop());
  sockets[0].deliver(MessageType.welcome, welcome);
  const old = new Uint8Array(11 + 47 * 11);
  old.set([0x10, 0x46, 0x57, 0x46, 0x50, 1, 0, 0, 30, 32, 47]);
  sockets[0].onmessage({ data: old.buffer });
  assert.equal(sockets[0].closedWith, 1002);
  assert.match(c.error, /format version 1.*decodes version 2: reload the page/);
  assert.equal(c.decoder ?? null, null);
});
