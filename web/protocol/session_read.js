// Session message readers: a port of codec/src/messages_read.cpp, checked
// against what the C++ readers say of the same bytes (tests/codec/protocol_js).
// Each reader reads every field through a ByteReader whose failure sticks,
// keeps the first field error, and then checks once that nothing was cut
// and nothing follows, exactly as the C++ readers do, so both give the same
// error for the same bytes.
import {
  FIRST_SPEAKING_VERSION, Limits, MessageError as E, MessageType, OLDEST_PROTOCOL_VERSION, PROTOCOL_VERSION, SESSION_BIT,
  LAST_MESSAGE_TYPE, CommandKind, LAST_OVERRIDE_PART, isLanguageCode,
} from './session_types.js';
import { ByteReader } from '../shared/byte_reader.js';
import { decodeUtf8, isCleanText } from './wire.js';

/** Why a failed reader failed, as the C++ failure_of() says. */
const failureOf = (r) => (r.badNumber ? E.badNumber : E.truncated);

class Fields {
  constructor(bytes) {
    this.r = new ByteReader(bytes);
    this.error = E.ok;
  }
  fail(why) {
    if (this.error === E.ok) this.error = why;
  }
  bounded(maxBytes, max) {
    const v = this.r.varint(maxBytes);
    if (!this.r.failed && v > max) this.fail(E.valueOutOfRange);
    return v;
  }
  string(maxBytes, allowLayout = false) {
    const length = this.r.varint(3);
    if (this.r.failed) {
      this.fail(failureOf(this.r));
      return '';
    }
    if (length > maxBytes) {
      this.fail(E.stringTooLong);
      return '';
    }
    const bytes = this.r.take(length);
    if (this.r.failed) {
      this.fail(E.truncated);
      return '';
    }
    if (!isCleanText(bytes, allowLayout)) this.fail(E.badText);
    return decodeUtf8(bytes);
  }
  /** A language (hello's may be empty: the server's default; speaking's not). */
  language(mayBeEmpty) {
    const before = this.error;
    const code = this.string(Limits.languageBytes);
    if (before !== E.ok || this.error !== E.ok || this.r.failed) return code;
    if (code === '') {
      if (!mayBeEmpty) this.fail(E.valueOutOfRange);
    } else if (!isLanguageCode(code)) {
      this.fail(E.badText);
    }
    return code;
  }
  count() {
    const n = this.r.varint(2);
    if (!this.r.failed && n > Limits.listEntries) this.fail(E.tooManyEntries);
    return n;
  }
  /** Whether a list may go on reading entries. */
  get going() { return !this.r.failed && this.error === E.ok; }
  finish(message) {
    if (this.error !== E.ok) return { error: this.error };
    if (this.r.failed) return { error: failureOf(this.r) };
    if (this.r.remaining !== 0) return { error: E.trailingBytes };
    return { error: E.ok, message };
  }
}

function firstByteError(bytes, expected, maxBytes) {
  if (bytes.length === 0) return E.empty;
  if (bytes.length > maxBytes) return E.tooLarge;
  const first = bytes[0];
  if ((first & SESSION_BIT) === 0) return E.notSessionMessage;
  const type = first & 0x7f;
  if (type < MessageType.hello || type > LAST_MESSAGE_TYPE) return E.unknownType;
  if (type !== expected) return E.wrongType;
  return E.ok;
}

function seat(f) {
  const s = { xMm: f.r.i16(), yMm: f.r.i16(), zMm: f.r.i16(), facingYawRad: 0 };
  const facing = f.r.i16();
  if (!f.r.failed && Math.abs(facing) > Limits.facingTenThousandths) f.fail(E.valueOutOfRange);
  s.facingYawRad = facing / 10000;
  return s;
}

function avatarInfo(f) {
  const id = f.bounded(3, Limits.avatarId);
  const flags = f.r.u8();
  if (!f.r.failed && (flags & ~1) !== 0) f.fail(E.badFlags);
  const name = f.string(Limits.displayNameBytes);
  const asset = f.string(Limits.assetIdBytes);
  const previewBytes = f.bounded(4, Limits.packageBytes);
  const fullBytes = f.bounded(4, Limits.packageBytes);
  return { id, person: (flags & 1) !== 0, name, asset, previewBytes, fullBytes, seat: seat(f) };
}

/** Reads the version first: another version may lay out the rest
 * differently. Versions 3 and 4 read (their layouts differ only in hello's
 * language); the version read, or { error }. */
function versioned(f) {
  const version = f.r.u16();
  if (f.r.failed) return { error: failureOf(f.r) };
  if (version < OLDEST_PROTOCOL_VERSION || version > PROTOCOL_VERSION) return { error: E.unsupportedVersion };
  return { version };
}

const readers = {
  [MessageType.hello]: [Limits.upstreamMessageBytes, (f) => {
    const { error, version } = versioned(f);
    if (error !== undefined) return { error };
    const flags = f.r.u8();
    if (!f.r.failed && (flags & ~15) !== 0) f.fail(E.badFlags);
    const maxBps = f.bounded(4, Limits.bitsPerSecond);
    const room = f.string(Limits.roomNameBytes);
    const name = f.string(Limits.displayNameBytes);
    const avatar = f.string(Limits.assetIdBytes);
    const token = f.string(Limits.tokenBytes);
    const avatarKey = f.string(Limits.keyBytes);
    const resume = f.string(Limits.keyBytes);
    const language = version >= FIRST_SPEAKING_VERSION ? f.language(true) : '';
    return f.finish({
      protocolVersion: version, timestamps: (flags & 1) !== 0, noPackages: (flags & 2) !== 0,
      ownPackage: (flags & 4) !== 0, preview: (flags & 8) !== 0, maxBps, room, name, avatar, token, avatarKey, resume, language,
    });
  }],
  [MessageType.welcome]: [Limits.downstreamMessageBytes, (f) => {
    const { error, version } = versioned(f);
    if (error !== undefined) return { error };
    const you = f.bounded(3, Limits.avatarId);
    const room = f.string(Limits.roomNameBytes);
    const tickHz = f.r.u8();
    if (!f.r.failed && tickHz === 0) f.fail(E.valueOutOfRange);
    const maxBps = f.bounded(4, Limits.bitsPerSecond);
    const count = f.count();
    const avatars = [];
    for (let i = 0; i < count && f.going; ++i) avatars.push(avatarInfo(f));
    const resume = f.string(Limits.keyBytes);
    return f.finish({ protocolVersion: version, you, room, tickHz, maxBps, avatars, resume });
  }],
  [MessageType.presence]: [Limits.downstreamMessageBytes, (f) => {
    const change = f.r.u8();
    if (!f.r.failed && change > 1) f.fail(E.valueOutOfRange);
    const avatar = avatarInfo(f);
    return f.finish({ change, avatar });
  }],
  [MessageType.chat]: [Limits.downstreamMessageBytes, (f) => {
    const from = f.bounded(3, Limits.avatarId);
    const text = f.string(Limits.chatBytes);
    return f.finish({ from, text });
  }],
  [MessageType.command]: [Limits.upstreamMessageBytes, (f) => {
    const requestId = f.r.varint(5);
    const kind = f.r.u8();
    if (f.r.failed) return { error: failureOf(f.r) };
    if (kind > CommandKind.playLook) return { error: E.valueOutOfRange };
    const m = {
      requestId, kind, emotion: '', intensity: 1, target: 0, durationMs: 3000, sentence: '',
      override: { part: 0, index: 0, side: 0, value: 0 },
    };
    if (kind === 0) {
      m.emotion = f.string(Limits.emotionBytes);
      const percent = f.r.u8();
      if (!f.r.failed && percent > 100) f.fail(E.valueOutOfRange);
      m.intensity = percent / 100;
      m.durationMs = f.bounded(3, Limits.commandMs);
    } else if (kind === 1 || kind === 2) {
      m.target = f.bounded(3, Limits.avatarId);
      m.durationMs = f.bounded(3, Limits.commandMs);
    } else if (kind === CommandKind.override) {
      const part = f.r.u8();
      const index = f.r.u8();
      const side = f.r.u8();
      const value = f.r.i16();
      if (!f.r.failed && (part > LAST_OVERRIDE_PART || side > 2)) f.fail(E.valueOutOfRange);
      m.override = { part, index, side, value };
    } else if (kind === CommandKind.playLook) {
      m.sentence = f.string(Limits.lookNameBytes);
      if (!f.r.failed && m.sentence === '') f.fail(E.valueOutOfRange);
    } else {
      m.sentence = f.string(Limits.sentenceBytes, true);
    }
    return f.finish(m);
  }],
  [MessageType.commandResult]: [Limits.downstreamMessageBytes, (f) => {
    const requestId = f.r.varint(5);
    const error = f.string(Limits.reasonBytes);
    return f.finish({ requestId, error });
  }],
  [MessageType.packageChunk]: [Limits.downstreamMessageBytes, (f) => {
    const avatar = f.bounded(3, Limits.avatarId);
    const quality = f.r.u8();
    if (!f.r.failed && quality > 1) f.fail(E.valueOutOfRange);
    const totalBytes = f.bounded(4, Limits.packageBytes);
    const offset = f.r.varint(4);
    if (f.r.failed) return { error: failureOf(f.r) };
    if (f.error !== E.ok) return { error: f.error };
    const size = f.r.remaining;
    if (totalBytes === 0 || size === 0 || size > Limits.chunkBytes || offset + size > totalBytes)
      return { error: E.valueOutOfRange };
    const data = f.r.take(size);
    return f.finish({ avatar, quality, totalBytes, offset, data });
  }],
  [MessageType.setRate]: [Limits.upstreamMessageBytes, (f) => f.finish({ maxBps: f.bounded(4, Limits.bitsPerSecond) })],
  [MessageType.ping]: [Limits.upstreamMessageBytes, (f) => {
    const nonce = f.r.u32();
    return f.finish({ nonce, clientTimeUs: f.r.u64() });
  }],
  [MessageType.pong]: [Limits.downstreamMessageBytes, (f) => {
    const nonce = f.r.u32();
    const clientTimeUs = f.r.u64();
    return f.finish({ nonce, clientTimeUs, serverTimeUs: f.r.u64() });
  }],
  [MessageType.linkStats]: [Limits.downstreamMessageBytes, (f) => {
    const targetBps = f.r.varint(5);
    const drainBps = f.r.varint(5);
    const queuedBytes = f.r.varint(5);
    return f.finish({ targetBps, drainBps, queuedBytes, skippedTicks: f.r.varint(5) });
  }],
  [MessageType.closing]: [Limits.downstreamMessageBytes, (f) => {
    const code = f.r.u16();  // unknown codes pass: a newer server may add some
    return f.finish({ code, reason: f.string(Limits.reasonBytes) });
  }],
  [MessageType.timedRoomFrame]: [Limits.downstreamMessageBytes, (f) => {
    const tick = f.r.varint(5);
    const serverTimeUs = f.r.u64();
    if (f.r.failed) return { error: failureOf(f.r) };
    if (f.r.remaining === 0) return { error: E.truncated };
    return { error: E.ok, message: { tick, serverTimeUs, roomFrame: f.r.take(f.r.remaining) } };
  }],
  [MessageType.seats]: [Limits.downstreamMessageBytes, (f) => {
    const count = f.count();
    const seats = [];
    for (let i = 0; i < count && f.going; ++i) seats.push({ avatar: f.bounded(3, Limits.avatarId), seat: seat(f) });
    return f.finish({ seats });
  }],
  [MessageType.attention]: [Limits.downstreamMessageBytes, (f) => {
    const count = f.count();
    const entries = [];
    for (let i = 0; i < count && f.going; ++i) {
      const avatar = f.bounded(3, Limits.avatarId);
      const target = f.r.u8();
      if (!f.r.failed && target > 2) f.fail(E.valueOutOfRange);
      const targetAvatar = target === 2 ? f.bounded(3, Limits.avatarId) : 0;
      entries.push({ avatar, target, targetAvatar });
    }
    return f.finish({ entries });
  }],
  [MessageType.speaking]: [Limits.downstreamMessageBytes, (f) => {
    const avatar = f.bounded(3, Limits.avatarId);
    const tick = f.r.varint(5);
    const durationMs = f.bounded(3, Limits.speakingMs);
    const language = f.language(false);
    const text = f.string(Limits.chatBytes);
    if (!f.r.failed && f.error === E.ok && text === '') f.fail(E.valueOutOfRange);
    return f.finish({ avatar, tick, durationMs, language, text });
  }],
  // Channels and vertices strictly increase (messages_read.cpp).
  [MessageType.unitMorphs]: [Limits.downstreamMessageBytes, (f) => {
    const avatar = f.bounded(3, Limits.avatarId);
    const version = f.r.varint(5);
    const count = f.r.u8();
    if (!f.r.failed && count > Limits.redefinedChannels) f.fail(E.tooManyEntries);
    const units = [];
    for (let i = 0; i < count && f.going; ++i) {
      const channel = f.r.u8();
      if (!f.r.failed && (channel >= Limits.auChannels || (i > 0 && channel <= units[i - 1].channel)))
        f.fail(E.valueOutOfRange);
      units.push({ channel, moves: readMoves(f) });
    }
    return f.finish({ avatar, version, units });
  }],
  // Face-lab previews only (5.18): the skin beyond the frames' action units.
  [MessageType.previewSurface]: [Limits.downstreamMessageBytes, (f) => {
    const avatar = f.bounded(3, Limits.avatarId);
    return f.finish({ avatar, moves: readMoves(f) });
  }],
};

/** A count, then moves of skin vertices strictly increasing (a unit morph's, a preview surface's). */
function readMoves(f) {
  const moveCount = f.r.varint(2);
  if (!f.r.failed && moveCount > Limits.unitMorphMoves) f.fail(E.tooManyEntries);
  const moves = [];
  for (let k = 0; k < moveCount && f.going; ++k) {
    const vertex = f.bounded(2, Limits.unitMorphMoves - 1);
    if (!f.r.failed && k > 0 && vertex <= moves[k - 1].vertex) f.fail(E.valueOutOfRange);
    moves.push({ vertex, delta: [f.r.i16(), f.r.i16(), f.r.i16()] });
  }
  return moves;
}

/**
 * Reads one whole session message of type `type` (a MessageType).
 * Returns { error: MessageError.ok, message } or { error } (see messageErrorName).
 */
export function readMessage(bytes, type) {
  const [maxBytes, read] = readers[type];
  const first = firstByteError(bytes, type, maxBytes);
  if (first !== E.ok) return { error: first };
  const f = new Fields(bytes);
  f.r.u8();
  return read(f);
}

/** The session message's type (the first byte's low seven bits). */
export const sessionType = (bytes) => (bytes.length ? bytes[0] & 0x7f : 0);
