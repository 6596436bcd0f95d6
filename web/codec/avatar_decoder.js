// One avatar's decoder (codec/src/decoder.cpp's Decoder; the name
// decoder.js is the folder's public entry): sequence numbers of a
// loss-tolerant stream, the wait for a key frame, and the face held still
// when a frame is lost or refused, until the next key frame.
import { FORMAT_VERSION, FrameType, MAX_FRAME_BYTES } from './format.js';
import { DecodeError } from './decode_error.js';
import { CHANNEL_COUNT, fieldsFromCoded } from './channel_table.js';
import { CodingState, cloneState } from './coding_state.js';
import { readFramePayload } from './frame_reader.js';
import { dequantise } from './quantiser.js';

/** `options` come from readStreamHeader. */
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
  /** The 53 field integers `ticksAfter` ticks after the last decoded frame. */
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
