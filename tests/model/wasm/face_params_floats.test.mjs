// The FaceParams hand-over to the WebAssembly model (web/engine/
// face_params_floats.js, read back by avatar/model/wasm/face_params_floats.hpp)
// is the codec's channel order: the decoder's FaceParams (web/codec) become
// exactly their channel values, the six corrective weights last.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { CHANNELS, CHANNEL_COUNT, dequantise } from '../../../web/codec/decoder.js';
import { FACE_PARAMS_FLOATS, faceParamsFloats } from '../../../web/engine/face_params_floats.js';

test('hands over one float per codec channel, in channel order', () => {
  assert.equal(FACE_PARAMS_FLOATS, CHANNEL_COUNT);
  assert.equal(FACE_PARAMS_FLOATS, 53);
  // Every channel a distinct value on its grid, so that a slip of one place shows.
  const q = CHANNELS.map((ch, c) => Math.max(ch.min, Math.min(ch.max, (c % 2 ? -1 : 1) * (c + 1))));
  const floats = faceParamsFloats(dequantise(q));
  CHANNELS.forEach((ch, c) => assert.equal(floats[c], Math.fround(q[c] * ch.step), ch.name));
  assert.deepEqual(CHANNELS.slice(-6).map((ch) => ch.name),
    ['corrective0', 'corrective1', 'corrective2', 'corrective3', 'corrective4', 'corrective5']);
});

test('a FaceParams without correctives hands over zeros for them', () => {
  const floats = faceParamsFloats({ au: [0.5], pallor: 0.25 });
  assert.equal(floats[0], 0.5);
  assert.equal(floats[46], 0.25);
  assert.deepEqual([...floats.slice(47)], [0, 0, 0, 0, 0, 0]);
  const given = faceParamsFloats({ corrective: [0.5, -0.25, 1, -1, 0.125, 'x'] });
  assert.deepEqual([...given.slice(47)], [0.5, -0.25, 1, -1, 0.125, 0], 'a value that is not a number counts as 0');
});
