// Key and predicted frames' syntax (codec/src/frame_reader.cpp, FORMAT.md
// "Key frames", "Predicted frames"): what a frame's payload changes in the
// coding state. The caller hands a copy and keeps it only when the frame
// was sound.
import { FrameType } from './format.js';
import { DecodeError } from './decode_error.js';
import { CHANNELS, CHANNEL_COUNT, GROUP_COUNT, GROUP_SPANS, LEVEL_BITS, SHIFT, VELOCITY_UNIT, clamp } from './channel_table.js';
import { FrameModels, decodeDamping } from './frame_models.js';
import { decodeSigned, decodeUnsigned } from './integer_coding.js';
import { roundToUnits } from './quantiser.js';
import { RangeDecoder } from './range_decoder.js';

const CHECK_BITS = 0xf;
const CHECK_BIT_COUNT = 4;
const MAX_TICK_DELTA = 1 << 16;

const bitWidth = (v) => (v === 0 ? 0 : 32 - Math.clz32(v));

function readMotion(rc, m, c, g, shift, fromPartner, predicted, partnerDamping) {
  const unit = VELOCITY_UNIT * 2 ** shift;
  const dv = decodeSigned(rc, m.velocity[g][fromPartner ? 1 : 0]);
  let velocity = predicted + dv * unit;
  if (Math.abs(velocity) > CHANNELS[c].maxVelocity) {
    rc.fail(DecodeError.valueOutOfRange);
    velocity = 0;
  }
  let dampingClass = 0;
  if (velocity !== 0) dampingClass = decodeDamping(rc, m.damping[g][fromPartner ? 1 + partnerDamping : 0]);
  return [velocity, dampingClass];
}

function readKey(state, rc) {
  const m = state.models;
  state.level = rc.raw(LEVEL_BITS);
  const qNew = new Array(CHANNEL_COUNT).fill(0);
  const uNew = new Array(CHANNEL_COUNT).fill(0);
  const dNew = new Array(CHANNEL_COUNT).fill(0);
  for (let c = 0; c < CHANNEL_COUNT; c++) {
    const ch = CHANNELS[c];
    const g = ch.group;
    const s = SHIFT[state.level][g];
    let q = 0;
    let coded = false;
    if (ch.partner >= 0 && rc.bit(m.keySameAsPartner[g]) === 1) {
      q = qNew[ch.partner];
      coded = true;
    }
    if (!coded && rc.bit(m.keyNonzero[g]) === 1) {
      const kMin = roundToUnits(ch.codedMin, s);
      const kMax = roundToUnits(ch.codedMax, s);
      const offset = rc.raw(bitWidth(kMax - kMin));
      if (offset > kMax - kMin) rc.fail(DecodeError.valueOutOfRange);
      q = clamp((kMin + offset) * 2 ** s, ch.codedMin, ch.codedMax);
    }
    const fromPartner = ch.partner >= 0;
    qNew[c] = q;
    [uNew[c], dNew[c]] = readMotion(rc, m, c, g, s, fromPartner, fromPartner ? uNew[ch.partner] : 0, fromPartner ? dNew[ch.partner] : 0);
    state.reconstruction.set(c, q, uNew[c], dNew[c]);
  }
}

function readPredicted(state, rc) {
  const m = state.models;
  const rec = state.reconstruction;
  if (rc.bit(m.levelChanged) === 1) state.level = rc.raw(LEVEL_BITS);
  const updatedNow = new Array(CHANNEL_COUNT).fill(false);
  const residual = new Array(CHANNEL_COUNT).fill(0);
  const uNew = new Array(CHANNEL_COUNT).fill(0);
  const dNew = new Array(CHANNEL_COUNT).fill(0);
  for (let g = 0; g < GROUP_COUNT; g++) {
    const any = rc.bit(m.groupUpdated[g][m.groupUpdatedLast[g] ? 1 : 0]) === 1;
    m.groupUpdatedLast[g] = any;
    if (!any) continue;
    const [first, count] = GROUP_SPANS[g];
    const s = SHIFT[state.level][g];
    for (let c = first; c < first + count; c++) {
      const ch = CHANNELS[c];
      const active = rec.shown(c) !== 0 || rec.velocity[c] !== 0;
      const partnerState = ch.partner < 0 ? 0 : updatedNow[ch.partner] ? 2 : 1;
      const context = partnerState * 4 + (active ? 2 : 0) + (m.updatedLast[c] ? 1 : 0);
      if (rc.bit(m.channelUpdated[c][context]) === 0) continue;
      const fromPartner = ch.partner >= 0 && updatedNow[ch.partner];
      const qPred = rec.shown(c);
      const r = (fromPartner ? residual[ch.partner] : 0) + decodeSigned(rc, m.residual[g][fromPartner ? 1 : 0]);
      const q = qPred + r * 2 ** s;
      if (q <= ch.codedMin - 2 ** s || q >= ch.codedMax + 2 ** s) rc.fail(DecodeError.valueOutOfRange);
      residual[c] = r;
      [uNew[c], dNew[c]] = readMotion(rc, m, c, g, s, fromPartner, fromPartner ? uNew[ch.partner] : rec.velocity[c], fromPartner ? dNew[ch.partner] : 0);
      updatedNow[c] = true;
      rec.set(c, clamp(q, ch.codedMin, ch.codedMax), uNew[c], dNew[c]);
    }
  }
  for (let g = 0; g < GROUP_COUNT; g++) {
    if (!m.groupUpdatedLast[g]) continue;
    const [first, count] = GROUP_SPANS[g];
    for (let c = first; c < first + count; c++) m.updatedLast[c] = updatedNow[c];
  }
}

/** Reads a key or predicted frame's payload into `state`: { error, tickDelta }. */
export function readFramePayload(state, type, payload) {
  const rc = new RangeDecoder(payload);
  if (type === FrameType.key) state.models = new FrameModels();
  const deltaMinusOne = decodeUnsigned(rc, state.models.tickDelta);
  if (deltaMinusOne >= MAX_TICK_DELTA) rc.fail(DecodeError.valueOutOfRange);
  const tickDelta = deltaMinusOne + 1;
  state.reconstruction.advance(tickDelta);
  if (type === FrameType.key) readKey(state, rc);
  else readPredicted(state, rc);
  if (rc.raw(CHECK_BIT_COUNT) !== CHECK_BITS) rc.fail(DecodeError.checkFailed);
  return { error: rc.error, tickDelta };
}
