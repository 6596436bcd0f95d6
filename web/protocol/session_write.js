// Session message writers: a port of codec/src/messages_write.cpp, checked
// byte for byte against the C++ writers (tests/codec/protocol_js). Field
// limits are the caller's to respect (session_types.js Limits): the room
// page checks what a person types before it is sent.
import { FIRST_SPEAKING_VERSION, MessageType, PROTOCOL_VERSION, SESSION_BIT } from './session_types.js';
import { WireWriter } from './wire.js';

function start(type) {
  const w = new WireWriter();
  w.u8(SESSION_BIT | type);
  return w;
}

// Whole millimetres and ten-thousandths of a radian, clamped to an i16.
function toI16(value, scale, limit) {
  const v = Number.isFinite(value) ? Math.min(limit, Math.max(-limit, Math.fround(value * scale))) : 0;
  return roundHalfAway(v);
}
// C's lround: halves away from zero (Math.round takes -2.5 to -2).
const roundHalfAway = (v) => Math.sign(v) * Math.round(Math.abs(v));

function seat(w, s) {
  w.i16(toI16(s.xMm, 1, 32767));
  w.i16(toI16(s.yMm, 1, 32767));
  w.i16(toI16(s.zMm, 1, 32767));
  w.i16(toI16(s.facingYawRad, 10000, 31416));
}

function avatarInfo(w, a) {
  w.varint(a.id);
  w.u8(a.person ? 1 : 0);
  w.string(a.name);
  w.string(a.asset);
  w.varint(a.previewBytes);
  w.varint(a.fullBytes);
  seat(w, a.seat);
}

const writers = {
  [MessageType.hello]: (w, m) => {
    const version = m.protocolVersion ?? PROTOCOL_VERSION;
    w.u16(version);
    w.u8((m.timestamps ? 1 : 0) | (m.noPackages ? 2 : 0) | (m.ownPackage ? 4 : 0) | (m.preview ? 8 : 0));
    w.varint(m.maxBps ?? 0);
    w.string(m.room);
    w.string(m.name);
    w.string(m.avatar ?? '');
    w.string(m.token ?? '');
    w.string(m.avatarKey ?? '');
    w.string(m.resume ?? '');
    // Version 4 on: the language the person's lines are said in ('' = the server's default).
    if (version >= FIRST_SPEAKING_VERSION) w.string(m.language ?? '');
  },
  [MessageType.welcome]: (w, m) => {
    w.u16(m.protocolVersion ?? PROTOCOL_VERSION);
    w.varint(m.you);
    w.string(m.room);
    w.u8(m.tickHz);
    w.varint(m.maxBps);
    w.varint(m.avatars.length);
    for (const a of m.avatars) avatarInfo(w, a);
    w.string(m.resume ?? '');
  },
  [MessageType.presence]: (w, m) => {
    w.u8(m.change);
    avatarInfo(w, m.avatar);
  },
  [MessageType.chat]: (w, m) => {
    w.varint(m.from ?? 0);
    w.string(m.text);
  },
  [MessageType.command]: (w, m) => {
    w.varint(m.requestId);
    w.u8(m.kind);
    if (m.kind === 0) {
      w.string(m.emotion);
      const clamped = Number.isFinite(m.intensity) ? Math.min(1, Math.max(0, m.intensity)) : 0;
      w.u8(roundHalfAway(Math.fround(Math.fround(clamped) * 100)));
      w.varint(m.durationMs);
    } else if (m.kind === 1 || m.kind === 2) {
      w.varint(m.target);
      w.varint(m.durationMs);
    } else if (m.kind === 4) {
      const o = m.override;
      w.u8(o.part);
      w.u8(o.index);
      w.u8(o.side);
      w.i16(o.value);
    } else {
      w.string(m.sentence);
    }
  },
  [MessageType.commandResult]: (w, m) => {
    w.varint(m.requestId);
    w.string(m.error);
  },
  [MessageType.packageChunk]: (w, m) => {
    w.varint(m.avatar);
    w.u8(m.quality);
    w.varint(m.totalBytes);
    w.varint(m.offset);
    w.bytes(m.data);
  },
  [MessageType.setRate]: (w, m) => w.varint(m.maxBps),
  [MessageType.ping]: (w, m) => {
    w.u32(m.nonce);
    w.u64(m.clientTimeUs);
  },
  [MessageType.pong]: (w, m) => {
    w.u32(m.nonce);
    w.u64(m.clientTimeUs);
    w.u64(m.serverTimeUs);
  },
  [MessageType.linkStats]: (w, m) => {
    w.varint(m.targetBps);
    w.varint(m.drainBps);
    w.varint(m.queuedBytes);
    w.varint(m.skippedTicks);
  },
  [MessageType.closing]: (w, m) => {
    w.u16(m.code);
    w.string(m.reason);
  },
  [MessageType.timedRoomFrame]: (w, m) => {
    w.varint(m.tick);
    w.u64(m.serverTimeUs);
    w.bytes(m.roomFrame);
  },
  [MessageType.seats]: (w, m) => {
    w.varint(m.seats.length);
    for (const e of m.seats) {
      w.varint(e.avatar);
      seat(w, e.seat);
    }
  },
  [MessageType.attention]: (w, m) => {
    w.varint(m.entries.length);
    for (const e of m.entries) {
      w.varint(e.avatar);
      w.u8(e.target);
      if (e.target === 2) w.varint(e.targetAvatar);
    }
  },
  [MessageType.speaking]: (w, m) => {
    w.varint(m.avatar);
    w.varint(m.tick);
    w.varint(m.durationMs);
    w.string(m.language);
    w.string(m.text);
  },
  [MessageType.unitMorphs]: (w, m) => {
    w.varint(m.avatar);
    w.varint(m.version);
    w.u8(m.units.length);
    for (const unit of m.units) {
      w.u8(unit.channel);
      writeMoves(w, unit.moves);
    }
  },
  [MessageType.previewSurface]: (w, m) => {
    w.varint(m.avatar);
    writeMoves(w, m.moves);
  },
};

function writeMoves(w, moves) {
  w.varint(moves.length);
  for (const move of moves) {
    w.varint(move.vertex);
    for (const d of move.delta) w.i16(d);
  }
}

/** One whole session message of type `type` (a MessageType) as bytes. */
export function writeMessage(type, message) {
  const w = start(type);
  writers[type](w, message);
  return w.result();
}
