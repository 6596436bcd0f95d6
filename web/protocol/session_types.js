// The room protocol's session messages (server/PROTOCOL.md): their type
// bytes, error codes and limits, as codec/include/fw/codec/messages.hpp
// defines them. The numbers are part of the protocol and never change.

export const PROTOCOL_VERSION = 5;
/** The oldest hello or welcome that still reads (version 3: no language). */
export const OLDEST_PROTOCOL_VERSION = 3;
/** The first version whose hello carries a language and whose sessions are sent speaking. */
export const FIRST_SPEAKING_VERSION = 4;
/** The first version whose sessions are sent unit morphs. */
export const FIRST_UNIT_MORPHS_VERSION = 5;
export const SESSION_BIT = 0x80;

export const MessageType = Object.freeze({
  hello: 1, welcome: 2, presence: 3, chat: 4, command: 5, commandResult: 6, packageChunk: 7, setRate: 8,
  ping: 9, pong: 10, linkStats: 11, closing: 12, timedRoomFrame: 13, seats: 14, attention: 15, speaking: 16,
  unitMorphs: 17, previewSurface: 18,
});
export const LAST_MESSAGE_TYPE = MessageType.previewSurface;

export const MessageError = Object.freeze({
  ok: 0, empty: 1, notSessionMessage: 2, unknownType: 3, wrongType: 4, truncated: 5, tooLarge: 6,
  stringTooLong: 7, badText: 8, valueOutOfRange: 9, trailingBytes: 10, tooManyEntries: 11,
  unsupportedVersion: 12, badFlags: 13, badNumber: 14,
});
const errorNames = Object.fromEntries(Object.entries(MessageError).map(([k, v]) => [v, k]));
export const messageErrorName = (code) => errorNames[code] ?? `error ${code}`;

export const CloseCode = Object.freeze({
  normal: 0, protocolError: 1, messageTooLarge: 2, unsupportedVersion: 3, unauthorized: 4, roomFull: 5,
  rateLimited: 6, handshakeTimeout: 7, idleTimeout: 8, shuttingDown: 9, badRequest: 10, serverFull: 11,
  avatarBeingPrepared: 12,
});
export const PresenceChange = Object.freeze({ joined: 0, left: 1 });
export const CommandKind = Object.freeze({ express: 0, lookAt: 1, snub: 2, facs: 3, override: 4, check: 5, playLook: 6 });
/** What a face-lab override sets (PROTOCOL.md 5.16): its `part`. */
export const OverridePart = Object.freeze({
  emotion: 0, actionUnit: 1, headYaw: 2, headPitch: 3, headRoll: 4, eyeYaw: 5, eyePitch: 6, lids: 7, blush: 8,
  pallor: 9, behaviour: 10, reset: 11, muscle: 12, skinAge: 13, skinLooseness: 14,
});
/** The last part a reader takes (messages.hpp kLastOverridePart). */
export const LAST_OVERRIDE_PART = OverridePart.skinLooseness;
export const PackageQuality = Object.freeze({ preview: 0, full: 1 });
export const AttentionTarget = Object.freeze({ nobody: 0, room: 1, avatar: 2 });

export const Limits = Object.freeze({
  upstreamMessageBytes: 8 * 1024,
  downstreamMessageBytes: 64 * 1024 + 64,
  roomNameBytes: 64,
  displayNameBytes: 32,
  assetIdBytes: 64,
  tokenBytes: 512,
  keyBytes: 64,
  chatBytes: 500,
  languageBytes: 16,
  speakingMs: 20_000,
  emotionBytes: 16,
  sentenceBytes: 4096,
  lookNameBytes: 32,
  reasonBytes: 120,
  listEntries: 64,
  packageBytes: 8 * 1024 * 1024,
  chunkBytes: 16 * 1024,
  bitsPerSecond: 100_000_000,
  commandMs: 600_000,
  avatarId: (1 << 21) - 1,
  facingTenThousandths: 31416,
  auChannels: 29,
  redefinedChannels: 8,
  unitMorphMoves: 1024,
  /** A unit morph's displacement steps per model unit. */
  unitMorphStepsPerUnit: 4096,
});

/** Whether `code` has a language's shape: 1 .. 16 bytes of a-z, 0-9 and `-`
 * (whether the server speaks it is the server's to say). */
export const isLanguageCode = (code) =>
  typeof code === 'string' && code.length >= 1 && code.length <= Limits.languageBytes && /^[a-z0-9-]+$/.test(code);

/** What a message on the connection is, from its first byte. */
export function classify(bytes) {
  if (bytes.length === 0) return 'invalid';
  const first = bytes[0];
  if (first & SESSION_BIT) {
    const type = first & 0x7f;
    return type >= MessageType.hello && type <= LAST_MESSAGE_TYPE ? 'session' : 'invalid';
  }
  // A codec message of any format version is classed by its type; its reader
  // refuses another version (unsupportedVersion) with a message saying to reload.
  if (first >> 4 === 0) return 'invalid';
  switch (first & 0x0f) {
    case 0: return 'streamHeader';
    case 3: return 'roomFrame';
    case 4: return 'resyncRequest';
    default: return 'invalid';  // bare key and predicted frames travel only inside room frames
  }
}
