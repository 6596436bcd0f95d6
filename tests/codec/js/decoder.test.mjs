// The browser decoder (web/codec/decoder.js) on the golden vectors
// (tests/vectors/codec): it must reproduce exactly what the C++ decoder
// wrote there, integer for integer, error code for error code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

import {
  CHANNEL_COUNT, Decoder, DecodeError, RoomDecoder, errorName, readResyncRequest, readRoomFrame,
  readStreamHeader, writeResyncRequest,
} from '../../../web/codec/decoder.js';
import { classify } from '../../../web/protocol/session_types.js';

const here = dirname(fileURLToPath(import.meta.url));
const vectorsDir = join(here, '..', '..', 'vectors', 'codec');
const snake = (name) => name.replace(/[A-Z]/g, (c) => `_${c.toLowerCase()}`);
const nameOf = (code) => snake(errorName(code));
const fromHex = (hex) => Uint8Array.from(hex.match(/../g) ?? [], (h) => parseInt(h, 16));

// A stream file: each message as a LEB128 length and its bytes.
function splitStream(bytes) {
  const messages = [];
  let i = 0;
  while (i < bytes.length) {
    let n = 0;
    for (let shift = 0; ; shift += 7) {
      assert.ok(i < bytes.length && shift <= 21, 'malformed stream file');
      const b = bytes[i++];
      n += (b & 0x7f) * 2 ** shift;
      if ((b & 0x80) === 0) break;
    }
    messages.push(bytes.subarray(i, i + n));
    i += n;
  }
  return messages;
}

const vectorFiles = readdirSync(vectorsDir).filter((f) => f.endsWith('.json') && f !== 'errors.json');

test('there are golden vectors to decode', () => {
  assert.ok(vectorFiles.length >= 4, `only ${vectorFiles.length} vectors in ${vectorsDir}`);
});

for (const file of vectorFiles) {
  test(`decodes the golden vector ${file} exactly`, () => {
    const v = JSON.parse(readFileSync(join(vectorsDir, file), 'utf8'));
    const messages = splitStream(new Uint8Array(readFileSync(join(vectorsDir, v.stream_file))));
    assert.equal(messages.length, v.messages.length, 'message count');
    const header = readStreamHeader(messages[0]);
    assert.deepEqual([nameOf(header.error)], v.messages[0].errors, 'stream header');
    const room = v.kind === 'room';
    const decoder = room ? new RoomDecoder(header.options) : new Decoder(header.options);
    const lastOk = new Array(v.avatars).fill(-1);
    let m = 1;
    for (let t = 0; t < v.ticks; t++) {
      for (; m < messages.length && v.messages[m].tick === t; m++) {
        assert.equal(messages[m].length, v.messages[m].bytes, `message ${m} length`);
        const errors = [];
        if (room) {
          const result = decoder.decode(messages[m]);
          if (result.error !== DecodeError.ok) errors.push(nameOf(result.error));
          for (const [id, error] of result.avatars) {
            errors.push(nameOf(error));
            if (error === DecodeError.ok && id < v.avatars) lastOk[id] = t;
          }
        } else {
          const error = decoder.decode(messages[m]);
          errors.push(nameOf(error));
          if (error === DecodeError.ok) lastOk[0] = t;
        }
        assert.deepEqual(errors, v.messages[m].errors, `message ${m} at tick ${t}`);
      }
      for (let a = 0; a < v.avatars; a++) {
        const d = room ? decoder.avatar(a) : decoder;
        const after = lastOk[a] < 0 ? 0 : t - lastOk[a];
        const shown = d ? d.quantised(after) : new Array(CHANNEL_COUNT).fill(0);
        assert.deepEqual(shown, v.shown[t][a], `avatar ${a} at tick ${t}`);
        if (t === v.ticks - 1) {
          const face = d ? d.face(after) : null;
          const flat = face
            ? [...face.au, face.head_yaw_rad, face.head_pitch_rad, face.head_roll_rad, ...face.head_translation_mm,
              face.eye_left.yaw_rad, face.eye_left.pitch_rad, face.eye_right.yaw_rad, face.eye_right.pitch_rad,
              face.lid_left, face.lid_right, ...face.blush, face.pallor, ...face.corrective]
            : new Array(CHANNEL_COUNT).fill(0);
          assert.deepEqual(flat, v.final_faces[a].map(Math.fround), `avatar ${a} final float32 face`);
        }
      }
    }
    assert.equal(m, messages.length, 'every message delivered');
    // Format version 2: the corrective channels move in every vector.
    const correctives = new Set(v.shown.flatMap((tick) => tick.map((face) => face.slice(CHANNEL_COUNT - 6).join())));
    assert.ok(correctives.size > 3, `${file}: the corrective weights should move`);
  });
}

test('refuses a stream of format version 1 and says to reload', () => {
  // The committed version-1 stream (before the corrective channels).
  const messages = splitStream(new Uint8Array(readFileSync(join(vectorsDir, 'version1', 'avatar_basic.fwc'))));
  assert.equal(readStreamHeader(messages[0]).error, DecodeError.unsupportedVersion);
  const d = new Decoder({ lossTolerant: false, tickRateHz: 30, maxExtrapolationTicks: 32 });
  for (const frame of messages.slice(1)) assert.equal(d.decode(frame), DecodeError.unsupportedVersion);
  assert.equal(classify(messages[0]), 'streamHeader', 'classed as a stream header, so that its reader says why');
});

test('gives the documented error code for every corrupt message of errors.json', () => {
  const cases = JSON.parse(readFileSync(join(vectorsDir, 'errors.json'), 'utf8'));
  assert.ok(cases.length > 30);
  for (const c of cases) {
    const bytes = fromHex(c.hex);
    if (c.kind === 'frame') {
      const d = new Decoder({ lossTolerant: c.loss_tolerant, tickRateHz: 30, maxExtrapolationTicks: 32 });
      for (const s of c.setup) d.decode(fromHex(s));
      assert.equal(nameOf(d.decode(bytes)), c.error, c.what);
      assert.equal(d.needsKeyFrame(), c.needs_key_frame_after, `${c.what}: needs a key frame after`);
    } else if (c.kind === 'stream_header') {
      assert.equal(nameOf(readStreamHeader(bytes).error), c.error, c.what);
    } else if (c.kind === 'room') {
      const r = readRoomFrame(bytes);
      assert.equal(nameOf(r.error), c.error, c.what);
      if (r.error === DecodeError.ok) assert.deepEqual(r.entries.map((e) => [e.avatarId, e.frame.length]), c.entries, c.what);
    } else if (c.kind === 'resync_request') {
      const r = readResyncRequest(bytes);
      assert.equal(nameOf(r.error), c.error, c.what);
      if (r.error === DecodeError.ok) assert.deepEqual(r.avatarIds, c.avatar_ids, c.what);
    } else {
      assert.fail(`unknown case kind ${c.kind}`);
    }
  }
});

test('writes the resync requests the C++ side reads', () => {
  const cases = JSON.parse(readFileSync(join(vectorsDir, 'errors.json'), 'utf8'));
  const written = cases.find((c) => c.kind === 'resync_request' && c.error === 'ok');
  assert.deepEqual(Buffer.from(writeResyncRequest(written.avatar_ids)).toString('hex'), written.hex);
  assert.throws(() => writeResyncRequest(new Array(65).fill(1)), RangeError);
});

test('never throws and never reads outside a frame, whatever the bytes', () => {
  // A small deterministic fuzz: mutated golden frames and random bytes.
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) >>> 0) >>> 8) / 2 ** 24;
  const messages = splitStream(new Uint8Array(readFileSync(join(vectorsDir, 'avatar_basic.fwc'))));
  const header = readStreamHeader(messages[0]);
  for (let round = 0; round < 300; round++) {
    const d = new Decoder(header.options);
    for (let i = 1; i < messages.length; i++) {
      const frame = Uint8Array.from(messages[i]);
      if (random() < 0.3) frame[Math.floor(random() * frame.length)] ^= 1 << Math.floor(random() * 8);
      const error = d.decode(random() < 0.1 ? frame.subarray(0, Math.floor(random() * frame.length)) : frame);
      assert.ok(error >= 0 && error <= 18);
      for (const q of d.quantised(Math.floor(random() * 40))) assert.ok(Number.isInteger(q));
    }
    const noise = Uint8Array.from({ length: Math.floor(random() * 64) }, () => Math.floor(random() * 256));
    d.decode(noise);
    readRoomFrame(noise);
    readStreamHeader(noise);
    readResyncRequest(noise);
  }
});
