// The adaptive contexts a frame is read with, carried from frame to frame
// (codec/src/frame_models.cpp, FORMAT.md "Contexts"): a key frame starts
// them afresh; the decoder copies them before a frame so that a refused
// frame leaves them as they were.
import { AdaptiveBit, adaptiveBits } from './adaptive_bit.js';
import { CHANNEL_COUNT, DAMPING_CLASSES, GROUP_COUNT } from './channel_table.js';
import { IntegerModel, integerModels } from './integer_coding.js';

export class FrameModels {
  constructor() {
    this.tickDelta = new IntegerModel();
    this.levelChanged = new AdaptiveBit();
    this.groupUpdated = Array.from({ length: GROUP_COUNT }, () => adaptiveBits(2));
    this.channelUpdated = Array.from({ length: CHANNEL_COUNT }, () => adaptiveBits(12));
    this.residual = Array.from({ length: GROUP_COUNT }, () => integerModels(2));
    this.velocity = Array.from({ length: GROUP_COUNT }, () => integerModels(2));
    this.damping = Array.from({ length: GROUP_COUNT }, () => Array.from({ length: 1 + DAMPING_CLASSES }, () => adaptiveBits(DAMPING_CLASSES)));
    this.keySameAsPartner = adaptiveBits(GROUP_COUNT);
    this.keyNonzero = adaptiveBits(GROUP_COUNT);
    this.updatedLast = new Array(CHANNEL_COUNT).fill(false);
    this.groupUpdatedLast = new Array(GROUP_COUNT).fill(false);
  }
}

/** Copies models `src` into `dst` of the same shape (a fresh FrameModels). */
export function copyModels(dst, src) {
  for (const key of Object.keys(src)) {
    const from = src[key];
    if (from instanceof AdaptiveBit) {
      dst[key].p0 = from.p0;
      dst[key].seen = from.seen;
    } else if (typeof from === 'object') {
      copyModels(dst[key], from);
    } else {
      dst[key] = from;
    }
  }
}

/** A damping class (0 .. 7) read as three bits down a binary tree of models. */
export function decodeDamping(rc, tree) {
  let node = 1;
  for (let i = 0; i < 3; i++) node = 2 * node + rc.bit(tree[node]);
  return node - DAMPING_CLASSES;
}
