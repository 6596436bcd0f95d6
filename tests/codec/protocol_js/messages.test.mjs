// The browser's session messages (web/protocol) against the C++ code's own
// verdicts (tests/codec/message_vectors.cpp, written into the build tree by
// the ctest fixture and named by FW_MESSAGE_VECTORS): the same fields and
// bytes for every message, and for every damaged copy the same error, or
// the same fields and rewritten bytes when it still reads.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

import { MessageError, PROTOCOL_VERSION, classify, messageErrorName } from '../../../web/protocol/session_types.js';
import { readMessage } from '../../../web/protocol/session_read.js';
import { writeMessage } from '../../../web/protocol/session_write.js';

const path = process.env.FW_MESSAGE_VECTORS;
assert.ok(path, 'FW_MESSAGE_VECTORS names the vectors codec_message_vectors wrote (run through ctest)');
const vectors = JSON.parse(readFileSync(path, 'utf8'));

const fromHex = (hex) => Uint8Array.from(hex.match(/../g) ?? [], (h) => parseInt(h, 16));
const toHex = (bytes) => Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');
const BYTE_FIELDS = new Set(['data', 'roomFrame']);

/** The C++ fields as the port takes them: byte fields from hex. */
function portFields(fields) {
  if (Array.isArray(fields)) return fields.map(portFields);
  if (fields === null || typeof fields !== 'object') return fields;
  return Object.fromEntries(Object.entries(fields).map(([k, v]) => [k, BYTE_FIELDS.has(k) ? fromHex(v) : portFields(v)]));
}

/**
 * Field by field: byte fields as hex; u64 clocks (BigInt) as JSON parsed
 * them; floats (seats travel as ten-thousandths of a radian, intensity as
 * hundredths) to float precision; the rest exactly. The bytes written back
 * are compared exactly besides.
 */
function assertSameFields(got, want, where) {
  if (Array.isArray(want)) {
    assert.equal(got.length, want.length, `${where}: length`);
    want.forEach((w, i) => assertSameFields(got[i], w, `${where}[${i}]`));
    return;
  }
  for (const [key, w] of Object.entries(want)) {
    const g = got[key];
    const at = `${where}.${key}`;
    if (BYTE_FIELDS.has(key)) assert.equal(toHex(g), w, at);
    else if (typeof g === 'bigint') assert.equal(Number(g), w, at);  // both rounded alike past 2^53
    else if (key === 'intensity') assert.equal(Math.round(g * 100), Math.round(w * 100), at);
    else if (typeof w === 'number' && !Number.isInteger(w)) assert.ok(Math.abs(g - w) < 1e-6, `${at}: ${g} != ${w}`);
    else if (w !== null && typeof w === 'object') assertSameFields(g, w, at);
    else assert.equal(g, w, at);
  }
}

test('the port speaks the same protocol version', () => {
  assert.equal(PROTOCOL_VERSION, vectors.protocolVersion);
});

test('every message reads to the C++ fields and writes to the C++ bytes', () => {
  assert.ok(vectors.messages.length >= 15);
  for (const v of vectors.messages) {
    const bytes = fromHex(v.hex);
    assert.equal(classify(bytes), 'session');
    const read = readMessage(bytes, v.type);
    assert.equal(read.error, MessageError.ok, `type ${v.type}: ${messageErrorName(read.error)}`);
    assertSameFields(read.message, v.fields, `type ${v.type}`);
    assert.equal(toHex(writeMessage(v.type, portFields(v.fields))), v.hex, `type ${v.type} written`);
  }
});

test('every damaged message gets the C++ reader\'s verdict', () => {
  assert.ok(vectors.damaged.length > 1000);
  let reads = 0;
  for (const v of vectors.damaged) {
    const read = readMessage(fromHex(v.hex), v.type);
    assert.equal(messageErrorName(read.error), messageErrorName(v.error), `type ${v.type}, bytes ${v.hex}`);
    if (v.error !== MessageError.ok) continue;
    ++reads;
    assertSameFields(read.message, v.fields, `type ${v.type}, bytes ${v.hex}`);
    assert.equal(toHex(writeMessage(v.type, read.message)), v.rewritten, `type ${v.type}, bytes ${v.hex} rewritten`);
  }
  assert.ok(reads > 50, 'some damage still reads (a changed value), and must read the same');
});
