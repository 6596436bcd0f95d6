// The facewire FaceParams decoder for the browser: a port of the C++
// decoder (codec/src) written from codec/FORMAT.md. It must decode the
// golden vectors (tests/vectors/codec) to exactly the same integers; node's
// test runner checks that (tests/codec/js). ES module, no dependencies.
//
// Usage:
//   const header = readStreamHeader(bytes);            // once per connection
//   const room = new RoomDecoder(header.options);
//   const result = room.decode(roomFrameBytes);          // every room frame
//   const face = room.avatar(id).face(ticksSinceFrame);  // FaceParams-like object
//   if (room.needingKeyFrames().length) send(writeResyncRequest(room.needingKeyFrames()));

export const FORMAT_VERSION = 1;
export const SCHEMA = 1;

export const FrameType = Object.freeze({ streamHeader: 0, key: 1, predicted: 2, room: 3, resyncRequest: 4 });

/** Error codes: the numbers are part of the format and never change (FORMAT.md, "Error codes"). */
export const DecodeError = Object.freeze({
  ok: 0,
  emptyFrame: 1,
  unsupportedVersion: 2,
  unknownFrameType: 3,
  wrongFrameType: 4,
  badMagic: 5,
  unsupportedSchema: 6,
  channelTableMismatch: 7,
  badStreamOptions: 8,
  truncated: 9,
  awaitingKeyFrame: 10,
  sequenceGap: 11,
  staleFrame: 12,
  valueOutOfRange: 13,
  checkFailed: 14,
  tooManyAvatars: 15,
  duplicateAvatar: 16,
  frameTooLarge: 17,
  trailingBytes: 18,
});
const errorNames = Object.fromEntries(Object.entries(DecodeError).map(([k, v]) => [v, k]));
/** The name of an error code ("checkFailed"), for messages. */
export const errorName = (code) => errorNames[code] ?? `error ${code}`;

export const MAX_FRAME_BYTES = 1024;
export const MAX_ROOM_AVATARS = 64;
export const MAX_ROOM_FRAME_BYTES = 64 * 1024;
export const MAX_AVATAR_ID = (1 << 21) - 1;

// ---------------------------------------------------------------------------
// Channels (FORMAT.md, "Channels").

const GROUP = { au: 0, headRotation: 1, headTranslation: 2, eyes: 3, lids: 4, colour: 5 };
const GROUP_COUNT = 6;
const AU_STEP = Math.fround(1 / 256);
const ANGLE_STEP = Math.fround(Math.PI / 3600);
const TRANSLATION_STEP = Math.fround(0.125);
const LID_STEP = Math.fround(1 / 128);
const COLOUR_STEP = Math.fround(1 / 64);

const AU_CHANNELS = [
  'au1_left', 'au1_right', 'au2_left', 'au2_right', 'au4_left', 'au4_right', 'au5_left', 'au5_right',
  'au6_left', 'au6_right', 'au7_left', 'au7_right', 'au9', 'au10_left', 'au10_right', 'au12_left',
  'au12_right', 'au14_left', 'au14_right', 'au15_left', 'au15_right', 'au17', 'au20_left', 'au20_right',
  'au23', 'au24', 'au25', 'au26', 'au27',
];

function makeChannels() {
  const t = [];
  AU_CHANNELS.forEach((name, i) => {
    t.push({ name, group: GROUP.au, step: AU_STEP, min: 0, max: 256, partner: name.endsWith('_right') ? i - 1 : -1, base: -1 });
  });
  const row = (name, group, step, min, max, partner = -1, base = -1) => t.push({ name, group, step, min, max, partner, base });
  row('head_yaw', GROUP.headRotation, ANGLE_STEP, -1376, 1376);
  row('head_pitch', GROUP.headRotation, ANGLE_STEP, -917, 917);
  row('head_roll', GROUP.headRotation, ANGLE_STEP, -688, 688);
  row('head_x', GROUP.headTranslation, TRANSLATION_STEP, -800, 800);
  row('head_y', GROUP.headTranslation, TRANSLATION_STEP, -800, 800);
  row('head_z', GROUP.headTranslation, TRANSLATION_STEP, -800, 800);
  row('eye_left_yaw', GROUP.eyes, ANGLE_STEP, -688, 688, -1, 29);
  row('eye_left_pitch', GROUP.eyes, ANGLE_STEP, -573, 573, -1, 30);
  row('eye_right_yaw', GROUP.eyes, ANGLE_STEP, -688, 688, 35, 29);
  row('eye_right_pitch', GROUP.eyes, ANGLE_STEP, -573, 573, 36, 30);
  row('lid_left', GROUP.lids, LID_STEP, 0, 128);
  row('lid_right', GROUP.lids, LID_STEP, 0, 128, 39);
  for (const region of ['forehead', 'cheek_left', 'cheek_right', 'nose', 'sides'])
    row(`blush_${region}`, GROUP.colour, COLOUR_STEP, 0, 64, region === 'cheek_right' ? 42 : -1);
  row('pallor', GROUP.colour, COLOUR_STEP, 0, 64);
  for (const ch of t) {
    const base = ch.base >= 0 ? t[ch.base] : null;
    ch.codedMin = base ? ch.min + base.min : ch.min;
    ch.codedMax = base ? ch.max + base.max : ch.max;
    ch.maxVelocity = (ch.codedMax - ch.codedMin) * SUB_STEPS;
  }
  return Object.freeze(t.map((c) => Object.freeze(c)));
}

const SUB_STEP_BITS = 8;
const SUB_STEPS = 1 << SUB_STEP_BITS;
const VELOCITY_UNIT = SUB_STEPS / 4;
/** The 47 channels in FaceParams field order. */
export const CHANNELS = makeChannels();
export const CHANNEL_COUNT = CHANNELS.length;
const GROUP_SPANS = [[0, 29], [29, 3], [32, 3], [35, 4], [39, 2], [41, 6]];
// [level][group]: action units, head rotation, head translation, eyes, lids, colour.
const SHIFT = [
  [0, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0], [0, 0, 0, 1, 1, 0], [1, 1, 1, 2, 1, 1],
  [1, 1, 1, 2, 2, 1], [2, 2, 2, 2, 2, 2], [2, 2, 2, 2, 3, 2], [3, 3, 3, 2, 3, 3],
];
const DAMPING_CLASSES = 8;
const DAMPING_NUMERATOR = [0, 3, 4, 6, 8, 10, 12, 16];
const LEVEL_BITS = 3;
const CHECK_BITS = 0xf;
const CHECK_BIT_COUNT = 4;
const MAX_TICK_DELTA = 1 << 16;
const MAX_MAGNITUDE_CLASS = 17;

const clamp = (v, lo, hi) => (v < lo ? lo : v > hi ? hi : v);
const roundToUnits = (q, shift) => (shift === 0 ? q : (q + (1 << (shift - 1))) >> shift);
const bitWidth = (v) => (v === 0 ? 0 : 32 - Math.clz32(v));
// One tick of damping; at least one sub-step goes, so the velocity reaches 0.
const damp = (w, cls) => {
  if (cls === 0 || w === 0) return w;
  const cut = Math.max(1, Math.floor((Math.abs(w) * DAMPING_NUMERATOR[cls]) / 64));
  return w >= 0 ? w - cut : w + cut;
};

// ---------------------------------------------------------------------------
// Adaptive binary range decoder (FORMAT.md, "Range coder", "Adaptive binary models").

const PROB_BITS = 15;
const PROB_ONE = 1 << PROB_BITS;
const PROB_MIN = 32;
const ADAPTATION_STEPS = 62;

class Bit {
  constructor() {
    this.p0 = PROB_ONE / 2;
    this.seen = 0;
  }
  update(bit) {
    const shift = Math.min(31 - Math.clz32(this.seen + 2), 6);
    let p = this.p0;
    if (bit === 0) p += (PROB_ONE - p) >> shift;
    else p -= p >> shift;
    this.p0 = clamp(p, PROB_MIN, PROB_ONE - PROB_MIN);
    if (this.seen < ADAPTATION_STEPS) this.seen += 1;
  }
}

const bits = (n) => Array.from({ length: n }, () => new Bit());

class IntegerModel {
  constructor() {
    this.zero = new Bit();
    this.sign = new Bit();
    this.prefix = bits(MAX_MAGNITUDE_CLASS);
  }
}
const integerModels = (n) => Array.from({ length: n }, () => new IntegerModel());

class RangeDecoder {
  constructor(bytes) {
    this.bytes = bytes;
    this.pos = 0;
    this.range = 0xffffffff;
    this.code = 0;
    this.error = DecodeError.ok;
    for (let i = 0; i < 4; i++) this.code = ((this.code << 8) | this.next()) >>> 0;
    if (this.code >= this.range) this.fail(DecodeError.checkFailed);
  }
  next() {
    return this.pos < this.bytes.length ? this.bytes[this.pos++] : 0;
  }
  normalise() {
    while (this.range < 0x1000000) {
      this.range = this.range * 256;
      this.code = ((this.code << 8) | this.next()) >>> 0;
    }
  }
  bit(model) {
    const bound = (this.range >>> PROB_BITS) * model.p0;
    let b = 0;
    if (this.code < bound) {
      this.range = bound;
    } else {
      this.code -= bound;
      this.range -= bound;
      b = 1;
    }
    model.update(b);
    this.normalise();
    return b;
  }
  raw(count) {
    let value = 0;
    for (let i = 0; i < count; i++) {
      const half = this.range >>> 1;
      let b = 0;
      if (this.code < half) {
        this.range = half;
      } else {
        this.code -= half;
        this.range -= half;
        b = 1;
      }
      value = value * 2 + b;
      this.normalise();
    }
    return value;
  }
  magnitude(model) {
    let k = 0;
    while (k < MAX_MAGNITUDE_CLASS - 1 && this.bit(model.prefix[k]) === 1) k++;
    return 2 ** k + this.raw(k);
  }
  signed(model) {
    if (this.bit(model.zero) === 0) return 0;
    const negative = this.bit(model.sign) === 1;
    const m = this.magnitude(model);
    return negative ? -m : m;
  }
  unsigned(model) {
    if (this.bit(model.zero) === 0) return 0;
    return this.magnitude(model);
  }
  damping(tree) {
    let node = 1;
    for (let i = 0; i < 3; i++) node = 2 * node + this.bit(tree[node]);
    return node - DAMPING_CLASSES;
  }
  fail(error) {
    if (this.error === DecodeError.ok) this.error = error;
  }
}

// ---------------------------------------------------------------------------
// What the decoder carries from frame to frame (FORMAT.md, "Contexts", "Prediction").

class Models {
  constructor() {
    this.tickDelta = new IntegerModel();
    this.levelChanged = new Bit();
    this.groupUpdated = Array.from({ length: GROUP_COUNT }, () => bits(2));
    this.channelUpdated = Array.from({ length: CHANNEL_COUNT }, () => bits(12));
    this.residual = Array.from({ length: GROUP_COUNT }, () => integerModels(2));
    this.velocity = Array.from({ length: GROUP_COUNT }, () => integerModels(2));
    this.damping = Array.from({ length: GROUP_COUNT }, () => Array.from({ length: 1 + DAMPING_CLASSES }, () => bits(DAMPING_CLASSES)));
    this.keySameAsPartner = bits(GROUP_COUNT);
    this.keyNonzero = bits(GROUP_COUNT);
    this.updatedLast = new Array(CHANNEL_COUNT).fill(false);
    this.groupUpdatedLast = new Array(GROUP_COUNT).fill(false);
  }
}

class Reconstruction {
  constructor(maxExtrapolationTicks) {
    this.limit = maxExtrapolationTicks;
    this.value = new Array(CHANNEL_COUNT).fill(0); // sub-steps
    this.velocity = new Array(CHANNEL_COUNT).fill(0); // sub-steps per tick
    this.dampingClass = new Array(CHANNEL_COUNT).fill(0);
    this.age = new Array(CHANNEL_COUNT).fill(0);
  }
  clone() {
    const r = new Reconstruction(this.limit);
    r.value = this.value.slice();
    r.velocity = this.velocity.slice();
    r.dampingClass = this.dampingClass.slice();
    r.age = this.age.slice();
    return r;
  }
  advance(ticks) {
    for (let c = 0; c < CHANNEL_COUNT; c++) this.age[c] = Math.min(this.age[c] + ticks, this.limit);
  }
  shown(c, extra = 0) {
    const ticks = Math.min(this.age[c] + extra, this.limit);
    let v = this.value[c];
    if (this.dampingClass[c] === 0) {
      v += this.velocity[c] * ticks;
    } else {
      let w = this.velocity[c];
      for (let i = 0; i < ticks && w !== 0; i++) {
        v += w;
        w = damp(w, this.dampingClass[c]);
      }
    }
    const ch = CHANNELS[c];
    v = clamp(v, ch.codedMin * SUB_STEPS, ch.codedMax * SUB_STEPS);
    return (v + SUB_STEPS / 2) >> SUB_STEP_BITS;
  }
  set(c, q, velocity, dampingClass) {
    this.value[c] = q * SUB_STEPS;
    this.velocity[c] = velocity;
    this.dampingClass[c] = dampingClass;
    this.age[c] = 0;
  }
  freeze() {
    const shown = Array.from({ length: CHANNEL_COUNT }, (_, c) => this.shown(c));
    for (let c = 0; c < CHANNEL_COUNT; c++) this.set(c, shown[c], 0, 0);
  }
}

class CodingState {
  constructor(maxExtrapolationTicks) {
    this.reconstruction = new Reconstruction(maxExtrapolationTicks);
    this.models = new Models();
    this.level = 0;
  }
}

// ---------------------------------------------------------------------------
// Key and predicted frames (FORMAT.md, "Key frames", "Predicted frames").

function readMotion(rc, m, c, g, shift, fromPartner, predicted, partnerDamping) {
  const unit = VELOCITY_UNIT * 2 ** shift;
  const dv = rc.signed(m.velocity[g][fromPartner ? 1 : 0]);
  let velocity = predicted + dv * unit;
  if (Math.abs(velocity) > CHANNELS[c].maxVelocity) {
    rc.fail(DecodeError.valueOutOfRange);
    velocity = 0;
  }
  let dampingClass = 0;
  if (velocity !== 0) dampingClass = rc.damping(m.damping[g][fromPartner ? 1 + partnerDamping : 0]);
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
      const r = (fromPartner ? residual[ch.partner] : 0) + rc.signed(m.residual[g][fromPartner ? 1 : 0]);
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

function readFramePayload(state, type, payload) {
  const rc = new RangeDecoder(payload);
  if (type === FrameType.key) state.models = new Models();
  const deltaMinusOne = rc.unsigned(state.models.tickDelta);
  if (deltaMinusOne >= MAX_TICK_DELTA) rc.fail(DecodeError.valueOutOfRange);
  const tickDelta = deltaMinusOne + 1;
  state.reconstruction.advance(tickDelta);
  if (type === FrameType.key) readKey(state, rc);
  else readPredicted(state, rc);
  if (rc.raw(CHECK_BIT_COUNT) !== CHECK_BITS) rc.fail(DecodeError.checkFailed);
  return { error: rc.error, tickDelta };
}

// Copies models `src` into `dst` of the same shape (a fresh Models).
function copyModels(dst, src) {
  for (const key of Object.keys(src)) {
    const from = src[key];
    if (from instanceof Bit) {
      dst[key].p0 = from.p0;
      dst[key].seen = from.seen;
    } else if (typeof from === 'object') {
      copyModels(dst[key], from);
    } else {
      dst[key] = from;
    }
  }
}

function cloneState(state) {
  const s = new CodingState(state.reconstruction.limit);
  s.reconstruction = state.reconstruction.clone();
  copyModels(s.models, state.models);
  s.level = state.level;
  return s;
}

/** FaceParams values from the field integers: float32(q * step), as the C++ decoder gives. */
export function dequantise(q) {
  const v = (c) => Math.fround(q[c] * CHANNELS[c].step);
  return {
    au: Array.from({ length: 29 }, (_, c) => v(c)),
    head_yaw_rad: v(29),
    head_pitch_rad: v(30),
    head_roll_rad: v(31),
    head_translation_mm: [v(32), v(33), v(34)],
    eye_left: { yaw_rad: v(35), pitch_rad: v(36) },
    eye_right: { yaw_rad: v(37), pitch_rad: v(38) },
    lid_left: v(39),
    lid_right: v(40),
    blush: [v(41), v(42), v(43), v(44), v(45)],
    pallor: v(46),
  };
}

/** Field integers from coded values: a channel with a base minus its base, clamped. */
function fieldsFromCoded(coded) {
  return coded.map((v, c) => {
    const ch = CHANNELS[c];
    return ch.base < 0 ? v : clamp(v - coded[ch.base], ch.min, ch.max);
  });
}

// ---------------------------------------------------------------------------
// Public decoders.

/** One avatar's decoder; `options` come from readStreamHeader. */
export class Decoder {
  constructor(options = { lossTolerant: false, tickRateHz: 30, maxExtrapolationTicks: 32 }) {
    this.options = options;
    this.state = new CodingState(options.maxExtrapolationTicks);
    this.needsKey = true;
    this.hasSequence = false;
    this.lastSequence = 0;
    this.tick = 0;
    this.framesDecoded = 0;
  }
  loseSync(error) {
    this.state.reconstruction.freeze();
    this.needsKey = true;
    return error;
  }
  /** Decodes one key or predicted frame (Uint8Array); returns a DecodeError code. */
  decode(frame) {
    if (frame.length === 0) return this.loseSync(DecodeError.emptyFrame);
    if (frame.length > MAX_FRAME_BYTES) return this.loseSync(DecodeError.frameTooLarge);
    if (frame[0] >> 4 !== FORMAT_VERSION) return this.loseSync(DecodeError.unsupportedVersion);
    const type = frame[0] & 0x0f;
    if (type > FrameType.resyncRequest) return this.loseSync(DecodeError.unknownFrameType);
    if (type !== FrameType.key && type !== FrameType.predicted) return this.loseSync(DecodeError.wrongFrameType);
    let headerBytes = 1;
    if (this.options.lossTolerant) {
      if (frame.length < 2) return this.loseSync(DecodeError.truncated);
      const sequence = frame[1];
      headerBytes = 2;
      if (this.needsKey) {
        this.lastSequence = sequence;
        this.hasSequence = true;
        if (type === FrameType.predicted) return DecodeError.awaitingKeyFrame;
      } else if (this.hasSequence) {
        const ahead = (sequence - ((this.lastSequence + 1) & 0xff)) & 0xff;
        if (ahead >= 128) return DecodeError.staleFrame;
        this.lastSequence = sequence;
        if (ahead !== 0 && type === FrameType.predicted) return this.loseSync(DecodeError.sequenceGap);
      }
      this.lastSequence = sequence;
      this.hasSequence = true;
    } else if (this.needsKey && type === FrameType.predicted) {
      return DecodeError.awaitingKeyFrame;
    }
    const next = cloneState(this.state);
    const { error, tickDelta } = readFramePayload(next, type, frame.subarray(headerBytes));
    if (error !== DecodeError.ok) return this.loseSync(error);
    this.state = next;
    this.needsKey = false;
    this.tick += tickDelta;
    this.framesDecoded += 1;
    return DecodeError.ok;
  }
  /** The 47 field integers `ticksAfter` ticks after the last decoded frame. */
  quantised(ticksAfter = 0) {
    const rec = this.state.reconstruction;
    return fieldsFromCoded(Array.from({ length: CHANNEL_COUNT }, (_, c) => rec.shown(c, ticksAfter)));
  }
  /** The face (FaceParams field names, float32 values) `ticksAfter` ticks after the last frame. */
  face(ticksAfter = 0) {
    return dequantise(this.quantised(ticksAfter));
  }
  needsKeyFrame() {
    return this.needsKey;
  }
}

class ByteReader {
  constructor(bytes) {
    this.bytes = bytes;
    this.pos = 0;
    this.failed = false;
  }
  u8() {
    if (this.pos >= this.bytes.length) {
      this.failed = true;
      return 0;
    }
    return this.bytes[this.pos++];
  }
  u16() {
    return this.u8() | (this.u8() << 8);
  }
  i16() {
    const v = this.u16();
    return v >= 0x8000 ? v - 0x10000 : v;
  }
  f32() {
    const b = [this.u8(), this.u8(), this.u8(), this.u8()];
    return new DataView(new Uint8Array(b).buffer).getFloat32(0, true);
  }
  varint(maxBytes) {
    let value = 0;
    for (let i = 0; i < maxBytes && i < 5; i++) {
      const byte = this.u8();
      if (this.failed) return 0;
      const payload = byte & 0x7f;
      if (i === 4 && payload > 0x0f) break;
      value += payload * 2 ** (7 * i);
      if ((byte & 0x80) === 0) {
        if (i > 0 && byte === 0) break;
        return value;
      }
    }
    this.failed = true;
    return 0;
  }
  remaining() {
    return this.bytes.length - this.pos;
  }
}

function checkFirstByte(first, expected) {
  if (first >> 4 !== FORMAT_VERSION) return DecodeError.unsupportedVersion;
  if ((first & 0x0f) > FrameType.resyncRequest) return DecodeError.unknownFrameType;
  if ((first & 0x0f) !== expected) return DecodeError.wrongFrameType;
  return DecodeError.ok;
}

/** Parses the stream header: { error, options: { lossTolerant, tickRateHz, maxExtrapolationTicks } }. */
export function readStreamHeader(bytes) {
  if (bytes.length === 0) return { error: DecodeError.emptyFrame };
  const r = new ByteReader(bytes);
  const first = r.u8();
  if (first >> 4 !== FORMAT_VERSION) return { error: DecodeError.unsupportedVersion };
  if ((first & 0x0f) > FrameType.resyncRequest) return { error: DecodeError.unknownFrameType };
  if ((first & 0x0f) !== FrameType.streamHeader) return { error: DecodeError.wrongFrameType };
  const magic = [r.u8(), r.u8(), r.u8(), r.u8()];
  if (r.failed) return { error: DecodeError.truncated };
  if (String.fromCharCode(...magic) !== 'FWFP') return { error: DecodeError.badMagic };
  const schema = r.u16();
  const flags = r.u8();
  const tickRateHz = r.u8();
  const maxExtrapolationTicks = r.u8();
  const channels = r.u8();
  if (r.failed) return { error: DecodeError.truncated };
  if (schema !== SCHEMA) return { error: DecodeError.unsupportedSchema };
  if ((flags & ~1) !== 0 || tickRateHz === 0) return { error: DecodeError.badStreamOptions };
  if (channels !== CHANNEL_COUNT) return { error: DecodeError.channelTableMismatch };
  for (const ch of CHANNELS) {
    const group = r.u8();
    const min = r.i16();
    const max = r.i16();
    const step = r.f32();
    const partner = (r.u8() << 24) >> 24;
    const base = (r.u8() << 24) >> 24;
    if (r.failed) return { error: DecodeError.truncated };
    const sameStep = step === ch.step || (Number.isNaN(step) && Number.isNaN(ch.step));
    if (group !== ch.group || min !== ch.min || max !== ch.max || !sameStep || partner !== ch.partner || base !== ch.base)
      return { error: DecodeError.channelTableMismatch };
  }
  if (r.remaining() !== 0) return { error: DecodeError.trailingBytes };
  return { error: DecodeError.ok, options: { lossTolerant: (flags & 1) !== 0, tickRateHz, maxExtrapolationTicks } };
}

/** Splits a room frame: { error, entries: [{ avatarId, frame }] } (frames are views into `bytes`). */
export function readRoomFrame(bytes) {
  const entries = [];
  if (bytes.length === 0) return { error: DecodeError.emptyFrame, entries };
  if (bytes.length > MAX_ROOM_FRAME_BYTES) return { error: DecodeError.frameTooLarge, entries };
  const r = new ByteReader(bytes);
  const e = checkFirstByte(r.u8(), FrameType.room);
  if (e !== DecodeError.ok) return { error: e, entries };
  let more = true;
  while (more) {
    if (entries.length === MAX_ROOM_AVATARS) return { error: DecodeError.tooManyAvatars, entries };
    const head = r.varint(4);
    if (r.failed) return { error: DecodeError.truncated, entries };
    const avatarId = Math.floor(head / 2);
    more = head % 2 === 1;
    if (avatarId > MAX_AVATAR_ID) return { error: DecodeError.valueOutOfRange, entries };
    let length = r.remaining();
    if (more) {
      length = r.varint(2);
      if (r.failed) return { error: DecodeError.truncated, entries };
    }
    if (length === 0) return { error: DecodeError.emptyFrame, entries };
    if (length > MAX_FRAME_BYTES) return { error: DecodeError.frameTooLarge, entries };
    if (length > r.remaining()) return { error: DecodeError.truncated, entries };
    const frame = bytes.subarray(r.pos, r.pos + length);
    r.pos += length;
    if (entries.some((x) => x.avatarId === avatarId)) return { error: DecodeError.duplicateAvatar, entries };
    entries.push({ avatarId, frame });
  }
  return { error: DecodeError.ok, entries };
}

/** A resync request asking for key frames of `avatarIds` (at most 64). */
export function writeResyncRequest(avatarIds) {
  if (avatarIds.length > MAX_ROOM_AVATARS) throw new RangeError('at most 64 avatars per resync request');
  const out = [(FORMAT_VERSION << 4) | FrameType.resyncRequest];
  const varint = (v) => {
    while (v >= 0x80) {
      out.push((v & 0x7f) | 0x80);
      v = Math.floor(v / 128);
    }
    out.push(v);
  };
  varint(avatarIds.length);
  for (const id of avatarIds) {
    if (!Number.isInteger(id) || id < 0 || id > MAX_AVATAR_ID) throw new RangeError(`bad avatar id ${id}`);
    varint(id);
  }
  return Uint8Array.from(out);
}

/** Parses a resync request: { error, avatarIds }. */
export function readResyncRequest(bytes) {
  const avatarIds = [];
  if (bytes.length === 0) return { error: DecodeError.emptyFrame, avatarIds };
  const r = new ByteReader(bytes);
  const e = checkFirstByte(r.u8(), FrameType.resyncRequest);
  if (e !== DecodeError.ok) return { error: e, avatarIds };
  const count = r.varint(2);
  if (r.failed) return { error: DecodeError.truncated, avatarIds };
  if (count > MAX_ROOM_AVATARS) return { error: DecodeError.tooManyAvatars, avatarIds };
  for (let i = 0; i < count; i++) {
    const id = r.varint(3);
    if (r.failed) return { error: DecodeError.truncated, avatarIds };
    if (id > MAX_AVATAR_ID) return { error: DecodeError.valueOutOfRange, avatarIds };
    avatarIds.push(id);
  }
  if (r.remaining() !== 0) return { error: DecodeError.trailingBytes, avatarIds };
  return { error: DecodeError.ok, avatarIds };
}

/** Decoders for every avatar of one room stream (at most 64). */
export class RoomDecoder {
  constructor(options) {
    this.options = options;
    this.decoders = new Map();
  }
  /** Decodes a room frame: { error, avatars: [[avatarId, error], ...] }. */
  decode(bytes) {
    const { error, entries } = readRoomFrame(bytes);
    const result = { error, avatars: [] };
    if (error !== DecodeError.ok) return result;
    for (const { avatarId, frame } of entries) {
      let decoder = this.decoders.get(avatarId);
      if (!decoder) {
        if (this.decoders.size >= MAX_ROOM_AVATARS) {
          result.avatars.push([avatarId, DecodeError.tooManyAvatars]);
          continue;
        }
        decoder = new Decoder(this.options);
        this.decoders.set(avatarId, decoder);
      }
      result.avatars.push([avatarId, decoder.decode(frame)]);
    }
    return result;
  }
  avatar(avatarId) {
    return this.decoders.get(avatarId) ?? null;
  }
  remove(avatarId) {
    this.decoders.delete(avatarId);
  }
  needingKeyFrames() {
    return [...this.decoders].filter(([, d]) => d.needsKeyFrame()).map(([id]) => id);
  }
}
