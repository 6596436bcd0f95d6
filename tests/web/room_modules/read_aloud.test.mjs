// Read aloud's schedule (web/room/read_aloud.js): a line starts with the
// first frame the page shows after its speaking message, a lead later;
// the speaker's next line, their leaving or muting, and turning read aloud
// off stop it; muted people and avatar 0 are never heard.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { LEAD_MS, MAX_WAITING_LINES, ReadAloudSchedule, leadingSilence, placeSound } from '../../../web/room/read_aloud.js';

const line = (avatar, text = 'hello', durationMs = 1000) => ({ avatar, tick: 0, durationMs, language: 'en', text });

test('a line starts when the page shows the first frame after its message, not before', () => {
  const s = new ReadAloudSchedule();
  const id = s.heard(line(3), 10);  // 10 frames had come when the message did
  assert.ok(id > 0);
  assert.deepEqual(s.shown(10, 100), { start: [], cancel: [] }, 'the page still shows frame 10');
  const { start, cancel } = s.shown(11, 133);
  assert.deepEqual(cancel, []);
  assert.equal(start.length, 1);
  assert.equal(start[0].id, id);
  assert.equal(start[0].shownMs, 133);
  assert.deepEqual(s.shown(12, 166), { start: [], cancel: [] }, 'it starts once');
});

test('frames skipped by the page still start the line, with the frame that is shown', () => {
  const s = new ReadAloudSchedule();
  s.heard(line(3), 10);
  assert.equal(s.shown(14, 200).start[0].shownMs, 200);
});

test("the speaker's next line cuts the one still playing; another speaker's does not", () => {
  const s = new ReadAloudSchedule();
  const first = s.heard(line(3, 'one', 5000), 0);
  const other = s.heard(line(4, 'two', 5000), 0);
  s.shown(1, 0);
  const next = s.heard(line(3, 'three', 5000), 1);
  const { start, cancel } = s.shown(2, 1000);
  assert.deepEqual(cancel, [first]);
  assert.deepEqual(start.map((x) => x.id), [next]);
  assert.ok(!cancel.includes(other));
});

test('a line that is over is not cut by the next', () => {
  const s = new ReadAloudSchedule();
  s.heard(line(3, 'short', 500), 0);
  s.shown(1, 0);
  s.heard(line(3, 'later'), 1);
  assert.deepEqual(s.shown(2, 600).cancel, []);
});

test('avatar 0 and muted people are never heard; muting mid-line stops it', () => {
  let muted = new Set([5]);
  const s = new ReadAloudSchedule((avatar) => muted.has(avatar));
  assert.equal(s.heard(line(0), 0), 0);
  assert.equal(s.heard(line(5), 0), 0);
  const id = s.heard(line(6, 'x', 5000), 0);
  assert.deepEqual(s.shown(1, 0).start.map((x) => x.id), [id]);
  muted = new Set([5, 6]);
  assert.deepEqual(s.silence(6), [id]);
  const late = s.heard(line(7), 1);
  muted.add(7);  // muted between the message and its frame
  assert.deepEqual(s.shown(2, 50), { start: [], cancel: [late] });
});

test('a speaker who leaves is stopped, heard lines included; turning off stops everything', () => {
  const s = new ReadAloudSchedule();
  const playing = s.heard(line(3, 'a', 5000), 0);
  s.shown(1, 0);
  const waiting = s.heard(line(3, 'b'), 1);
  assert.deepEqual(s.silence(3).sort(), [playing, waiting].sort());
  assert.deepEqual(s.shown(2, 10), { start: [], cancel: [] });
  const a = s.heard(line(3), 2);
  s.shown(3, 20);
  const b = s.heard(line(4), 3);
  assert.deepEqual(s.stopAll().sort(), [a, b].sort());
  assert.deepEqual(s.shown(4, 30), { start: [], cancel: [] });
});

test("the sound's first phoneme comes the lead and espeak-ng's own silence after the frame", () => {
  assert.deepEqual(placeSound({ shownMs: 1000, silenceMs: 20, soundMs: 1500, nowMs: 1040 }), { atMs: 1000 + LEAD_MS + 20, offsetMs: 0 });
  // Synthesised late: started at once, as far into the sound as the lips are.
  assert.deepEqual(placeSound({ shownMs: 1000, silenceMs: 20, soundMs: 1500, nowMs: 1270 }), { atMs: 1270, offsetMs: 100 });
  assert.equal(placeSound({ shownMs: 1000, silenceMs: 20, soundMs: 1500, nowMs: 2700 }), null, 'all over: not played');
});

test('leading silence ends at the first sample above 1 % of full scale', () => {
  assert.equal(leadingSilence(Int16Array.from([0, 3, -300, 328, -329, 2000])), 4);
  assert.equal(leadingSilence(Int16Array.from([0, 0])), 2);
  assert.equal(LEAD_MS, 150, 'the lead of the server\'s lip track (PhonemeTiming::kLeadS)');
});

test('a page that draws no frames (hidden) keeps only the newest waiting lines', () => {
  const s = new ReadAloudSchedule();
  const ids = Array.from({ length: MAX_WAITING_LINES + 3 }, (_, i) => s.heard(line(3, `line ${i}`), 5));
  const { start, cancel } = s.shown(6, 0);
  assert.deepEqual(cancel.slice(0, 3), ids.slice(0, 3), 'the oldest three were let go');
  // Of one speaker's lines due at one frame, only the newest is heard; the others are let go too.
  assert.deepEqual(start.map((x) => x.id), [ids.at(-1)]);
  assert.deepEqual(cancel.sort((a, b) => a - b), ids.slice(0, -1));
});
