// Everything one avatar's decoder carries from frame to frame
// (codec/src/coding_state.hpp): the reconstruction, the adaptive models and
// the quality level.
import { FrameModels, copyModels } from './frame_models.js';
import { Reconstruction } from './reconstruction.js';

export class CodingState {
  constructor(maxExtrapolationTicks) {
    this.reconstruction = new Reconstruction(maxExtrapolationTicks);
    this.models = new FrameModels();
    this.level = 0;
  }
}

/** A deep copy: a frame is read into the copy and kept only when it is sound. */
export function cloneState(state) {
  const s = new CodingState(state.reconstruction.limit);
  s.reconstruction = state.reconstruction.clone();
  copyModels(s.models, state.models);
  s.level = state.level;
  return s;
}
