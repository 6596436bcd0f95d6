// The browser's reconnect policy (web/room/reconnect_policy.js) against the
// native client's decisions (client/transport/failover_policy.cpp,
// RoomSession::backoff) as the C++ wrote them in
// tests/vectors/reconnect_policy: the same step for every close code and a
// drop, and the same back-off, to the millisecond.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { ReconnectPolicy } from '../../../web/room/reconnect_policy.js';
import { readGolden } from '../support/golden.mjs';

const golden = readGolden('reconnect_policy');

// The browser's answer in the C++'s words. The room page never uploads a
// face (the lobby did), so it is held to could_upload_here = false.
const step = (next) => (!next.retry ? 'stop' : next.moveOn ? 'next_server' : 'same_server');

test('every close code leads where the native client goes', () => {
  assert.ok(golden.closings.length >= 13);
  for (const { code, step: expected } of golden.closings) {
    const policy = new ReconnectPolicy();
    assert.equal(step(policy.next({ code, reason: 'r' })), expected, `close code ${code}`);
  }
});

test('a connection that ends without a closing moves on', () => {
  assert.equal(step(new ReconnectPolicy().next(null)), golden.drop);
});

test('failures in a row wait as long as the native client waits', () => {
  const policy = new ReconnectPolicy();
  const delays = golden.backoff.map(() => policy.next(null).delayMs);
  assert.deepEqual(delays, golden.backoff.map((b) => b.delay_ms));
  // A welcome starts the count again.
  policy.welcomed();
  assert.equal(policy.next(null).delayMs, golden.backoff[0].delay_ms);
});

test('an avatar being prepared counts as a failed attempt, as natively', () => {
  // The native client waits its back-off before asking the same server again.
  const policy = new ReconnectPolicy();
  const prepared = golden.closings.find((c) => c.step === 'same_server');
  assert.ok(prepared, 'the C++ sends someone back to the same server for some code');
  const delays = [];
  for (let i = 0; i < 3; ++i) delays.push(policy.next({ code: prepared.code, reason: '' }).delayMs);
  delays.push(policy.next(null).delayMs);
  assert.deepEqual(delays, golden.backoff.slice(0, 4).map((b) => b.delay_ms));
});
