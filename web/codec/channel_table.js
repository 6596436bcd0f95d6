// The 53 channels in FaceParams field order, their groups, ranges, steps,
// partners and bases; the quantiser's shift per quality level and group;
// velocity damping (codec/src/channel_table.cpp, FORMAT.md "Channels").
// The stream header repeats this table, and a decoder refuses a stream
// whose table differs, so every number here is the C++'s.

export const GROUP = Object.freeze({ au: 0, headRotation: 1, headTranslation: 2, eyes: 3, lids: 4, colour: 5, correctives: 6 });
export const GROUP_COUNT = 7;
/** Corrective weights of the physics face, the last channels (FaceParams::corrective). */
export const CORRECTIVE_COUNT = 6;
const AU_STEP = Math.fround(1 / 256);
const ANGLE_STEP = Math.fround(Math.PI / 3600);
const TRANSLATION_STEP = Math.fround(0.125);
const LID_STEP = Math.fround(1 / 128);
const COLOUR_STEP = Math.fround(1 / 64);
const CORRECTIVE_STEP = Math.fround(1 / 64);

/** Values are kept in sub-steps of the grid, so that velocities can be fractional. */
export const SUB_STEP_BITS = 8;
export const SUB_STEPS = 1 << SUB_STEP_BITS;
/** A coded velocity counts in quarters of a step per tick. */
export const VELOCITY_UNIT = SUB_STEPS / 4;

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
  for (let k = 0; k < CORRECTIVE_COUNT; ++k) row(`corrective${k}`, GROUP.correctives, CORRECTIVE_STEP, -64, 64);
  for (const ch of t) {
    const base = ch.base >= 0 ? t[ch.base] : null;
    ch.codedMin = base ? ch.min + base.min : ch.min;
    ch.codedMax = base ? ch.max + base.max : ch.max;
    ch.maxVelocity = (ch.codedMax - ch.codedMin) * SUB_STEPS;
  }
  return Object.freeze(t.map((c) => Object.freeze(c)));
}

/** The 53 channels in FaceParams field order. */
export const CHANNELS = makeChannels();
export const CHANNEL_COUNT = CHANNELS.length;
/** [first channel, count] of each group. */
export const GROUP_SPANS = [[0, 29], [29, 3], [32, 3], [35, 4], [39, 2], [41, 6], [47, CORRECTIVE_COUNT]];
// [level][group]: action units, head rotation, head translation, eyes, lids, colour, correctives.
export const SHIFT = [
  [0, 0, 0, 0, 0, 0, 0], [0, 0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 1, 0, 1], [1, 1, 1, 2, 1, 1, 1],
  [1, 1, 1, 2, 2, 1, 2], [2, 2, 2, 2, 2, 2, 2], [2, 2, 2, 2, 3, 2, 3], [3, 3, 3, 2, 3, 3, 4],
];
export const DAMPING_CLASSES = 8;
const DAMPING_NUMERATOR = [0, 3, 4, 6, 8, 10, 12, 16];
export const LEVEL_BITS = 3;

export const clamp = (v, lo, hi) => (v < lo ? lo : v > hi ? hi : v);

// One tick of damping; at least one sub-step goes, so the velocity reaches 0.
export const damp = (w, cls) => {
  if (cls === 0 || w === 0) return w;
  const cut = Math.max(1, Math.floor((Math.abs(w) * DAMPING_NUMERATOR[cls]) / 64));
  return w >= 0 ? w - cut : w + cut;
};

/** Field integers from coded values: a channel with a base minus its base, clamped. */
export function fieldsFromCoded(coded) {
  return coded.map((v, c) => {
    const ch = CHANNELS[c];
    return ch.base < 0 ? v : clamp(v - coded[ch.base], ch.min, ch.max);
  });
}
