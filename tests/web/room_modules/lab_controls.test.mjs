// The face lab's sliders send the overrides server/PROTOCOL.md 5.16 defines,
// and its sender keeps under the server's message rate with only the newest
// value of each control.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { OverridePart } from '../../../web/protocol/session_types.js';
import { SLIDERS, Side, overrideOf } from '../../../web/room/lab/lab_controls.js';
import { OverrideSender } from '../../../web/room/lab/override_sender.js';
import { offsetOf, readScriptResult } from '../../../web/room/lab/script_result.js';

const slider = (key) => SLIDERS.find((s) => s.key === key);

test('a slider sends ten-thousandths, clamped to its range, on the side chosen', () => {
  assert.deepEqual(overrideOf(slider('emotion-joy'), 100), { part: OverridePart.emotion, index: 0, side: 0, value: 10000 });
  assert.deepEqual(overrideOf(slider('au-12'), 40, Side.left), { part: OverridePart.actionUnit, index: 12, side: 1, value: 4000 });
  assert.equal(overrideOf(slider('au-26'), 40, Side.left).side, Side.both, 'a midline unit has no sides');
  assert.equal(overrideOf(slider('emotion-joy'), 250).value, 10000, 'past the end');
  const yaw = overrideOf(slider('head-yaw'), -30);
  assert.equal(yaw.part, OverridePart.headYaw);
  assert.equal(yaw.value, Math.round((-30 * Math.PI / 180) * 10000));
  assert.ok(Math.abs(overrideOf(slider('head-yaw'), 1000).value) <= 12000, 'within FaceParams yaw range');
  assert.deepEqual(overrideOf(slider('lid-right'), 100), { part: OverridePart.lids, index: 0, side: Side.right, value: 10000 });
  assert.deepEqual(overrideOf(slider('blush-2'), 50), { part: OverridePart.blush, index: 2, side: 0, value: 5000 });
});

test('the physics level: one slider per muscle in the server\'s order, and the skin\'s age and looseness', () => {
  const muscles = SLIDERS.filter((s) => s.group === 'muscles');
  assert.equal(muscles.length, 42, 'avatar/physics kMuscleCount');
  assert.deepEqual(muscles.map((s) => s.index), [...Array(42).keys()]);
  assert.equal(slider('muscle-22').label, 'zygomatic major (left)', 'left 2i, right 2i + 1 (facial_muscles.hpp)');
  assert.equal(slider('muscle-23').label, 'zygomatic major (right)');
  assert.deepEqual(overrideOf(slider('muscle-22'), 80, Side.right), { part: OverridePart.muscle, index: 22, side: 0, value: 8000 },
    'a muscle names its side itself');
  assert.deepEqual(overrideOf(slider('skin-age'), 100), { part: OverridePart.skinAge, index: 0, side: 0, value: 10000 });
  assert.deepEqual(overrideOf(slider('skin-looseness'), 30), { part: OverridePart.skinLooseness, index: 0, side: 0, value: 3000 });
});

test('the sender sends the newest value of each control, at most every interval', () => {
  let now = 0;
  let pending = null;
  const sent = [];
  const sender = new OverrideSender({
    send: (o) => sent.push(o), intervalMs: 50, now: () => now,
    setTimer: (fn) => { pending = fn; return 1; }, clearTimer: () => { pending = null; },
  });
  const joy = (value) => ({ part: OverridePart.emotion, index: 0, side: 0, value });
  sender.set(joy(100));
  assert.deepEqual(sent, [joy(100)], 'the first goes at once');
  now = 10;
  sender.set(joy(200));
  sender.set(joy(300));
  sender.set({ part: OverridePart.pallor, index: 0, side: 0, value: 5 });
  assert.equal(sent.length, 1, 'a drag waits for the interval');
  now = 50;
  pending();
  assert.deepEqual(sent.slice(1), [joy(300), { part: OverridePart.pallor, index: 0, side: 0, value: 5 }]);
  sender.set(joy(400));
  sender.sendInstead({ part: OverridePart.reset, index: 0, side: 0, value: 0 });
  assert.equal(sent.at(-1).part, OverridePart.reset, 'a reset drops what waits');
  assert.equal(sent.filter((o) => o.value === 400).length, 0);
});

test('a check\'s error gives its line and column and where it is in the text', () => {
  assert.equal(readScriptResult(''), null);
  assert.deepEqual(readScriptResult('line 3, column 6: a number was expected'), { line: 3, column: 6, message: 'a number was expected' });
  assert.deepEqual(readScriptResult('script 2:1: x'), { line: 2, column: 1, message: 'x' });
  assert.deepEqual(readScriptResult('the script is empty'), { line: null, column: null, message: 'the script is empty' });
  assert.equal(offsetOf('ab\ncd\nef', 3, 2), 7);
});
