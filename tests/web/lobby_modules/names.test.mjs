// Room and display names as the protocol allows them (server/PROTOCOL.md, 5.1).
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { displayNameProblem, roomNameProblem } from '../../../web/lobby/names.js';

test('room names: 1 to 64 of A-Z a-z 0-9 _ - .', () => {
  for (const good of ['lobby', 'a', 'Team_1.standup-2', 'x'.repeat(64)]) assert.equal(roomNameProblem(good), '', good);
  assert.match(roomNameProblem(''), /Pick a room/);
  assert.match(roomNameProblem('x'.repeat(65)), /at most 64/);
  for (const bad of ['my room', 'café', 'a/b', 'a?b']) assert.match(roomNameProblem(bad), /only hold/, bad);
});

test('display names: 1 to 32 bytes of UTF-8, spaces around not counted', () => {
  assert.equal(displayNameProblem('Ann'), '');
  assert.equal(displayNameProblem(' Ann '), '');
  assert.equal(displayNameProblem('é'.repeat(16)), '', '32 bytes');
  assert.match(displayNameProblem('é'.repeat(17)), /at most 32 bytes/, '34 bytes');
  assert.match(displayNameProblem('   '), /Type the name/);
});
