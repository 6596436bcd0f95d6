// The face lab's controls as data: each slider's group, label, range and the
// override it sends (PROTOCOL.md 5.16). No DOM here, so that what a slider
// sends is tested without a browser (tests/web/room_modules/lab_controls.test.mjs).
import { OverridePart } from '../../protocol/session_types.js';

/** FACS action units the face shows, with their names; `middle`: one channel (no sides). */
export const ACTION_UNITS = [
  [1, 'inner brow raiser'], [2, 'outer brow raiser'], [4, 'brow lowerer'], [5, 'upper lid raiser'],
  [6, 'cheek raiser'], [7, 'lid tightener'], [9, 'nose wrinkler', true], [10, 'upper lip raiser'],
  [12, 'lip corner puller'], [14, 'dimpler'], [15, 'lip corner depressor'], [17, 'chin raiser', true],
  [20, 'lip stretcher'], [23, 'lip tightener', true], [24, 'lip pressor', true], [25, 'lips part', true],
  [26, 'jaw drop', true], [27, 'mouth stretch', true],
].map(([au, name, middle = false]) => ({ au, name, middle }));

/**
 * The physics face's muscles, one side's, in the server's order
 * (avatar/physics facial_muscles.hpp, PROTOCOL.md 5.16): muscle i of the
 * person's left side has index 2i, its right twin 2i + 1.
 */
export const MUSCLES = [
  'frontalis, inner', 'frontalis, outer', 'corrugator', 'procerus', 'levator palpebrae',
  'orbicularis oculi, orbital', 'orbicularis oculi, palpebral', 'levator labii sup. alaeque nasi', 'nasalis',
  'levator labii superioris', 'zygomatic minor', 'zygomatic major', 'buccinator', 'risorius',
  'depressor anguli oris', 'depressor labii inferioris', 'mentalis', 'orbicularis oris, peripheral',
  'orbicularis oris, marginal', 'masseter', 'digastric',
];
const EMOTIONS = ['joy', 'sadness', 'anger', 'fear', 'surprise', 'disgust'];
const REGIONS = ['forehead', 'left cheek', 'right cheek', 'nose', 'sides'];
const DEGREE = Math.PI / 180;

/** Side of an action unit or lid: both, the person's left, their right. */
export const Side = Object.freeze({ both: 0, left: 1, right: 2 });

const percent = (key, group, label, part, index = 0, side = 0) => ({
  key, group, label, min: 0, max: 100, rest: 0, unit: '%', part, index, side, scale: 100,
});
const degrees = (key, label, part, limit) => ({
  key, group: 'head', label, min: -limit, max: limit, rest: 0, unit: '°', part, index: 0, side: 0, scale: 10000 * DEGREE,
});

/**
 * Every slider: { key, group, label, min, max, rest, unit, part, index, side, scale }.
 * A slider at `v` sends value round(v * scale): ten-thousandths of an intensity or a radian.
 * Angles stop at FaceParams' ranges (server/simulation/face_overrides.hpp).
 */
export const SLIDERS = [
  ...EMOTIONS.map((name, i) => percent(`emotion-${name}`, 'emotions', name, OverridePart.emotion, i)),
  ...ACTION_UNITS.map(({ au, name, middle }) =>
    ({ ...percent(`au-${au}`, 'action-units', `AU${au} ${name}${middle ? ' (middle)' : ''}`, OverridePart.actionUnit, au), middle })),
  degrees('head-yaw', 'head turn', OverridePart.headYaw, 68),
  degrees('head-pitch', 'head nod', OverridePart.headPitch, 45),
  degrees('head-roll', 'head tilt', OverridePart.headRoll, 34),
  degrees('eye-yaw', 'eyes left/right', OverridePart.eyeYaw, 34),
  degrees('eye-pitch', 'eyes up/down', OverridePart.eyePitch, 28),
  percent('lid-left', 'lids', 'left lid closed', OverridePart.lids, 0, Side.left),
  percent('lid-right', 'lids', 'right lid closed', OverridePart.lids, 0, Side.right),
  ...REGIONS.map((name, i) => percent(`blush-${i}`, 'colour', `blush: ${name}`, OverridePart.blush, i)),
  percent('pallor', 'colour', 'pallor', OverridePart.pallor),
  ...MUSCLES.flatMap((name, i) => ['left', 'right'].map((side, k) =>
    percent(`muscle-${2 * i + k}`, 'muscles', `${name} (${side})`, OverridePart.muscle, 2 * i + k))),
  percent('skin-age', 'skin', 'age', OverridePart.skinAge),
  percent('skin-looseness', 'skin', 'looseness', OverridePart.skinLooseness),
];

export const GROUPS = [
  ['emotions', 'Emotions'], ['action-units', 'Action units'], ['head', 'Head and eyes'], ['lids', 'Lids'],
  ['colour', 'Colour regions'], ['muscles', 'Muscles'], ['skin', 'Skin'],
];

/**
 * The override a slider at `value` sends; `side` is the action units'
 * both/left/right choice (midline units always go to both: they have one channel).
 */
export function overrideOf(slider, value, side = Side.both) {
  const clamped = Math.min(slider.max, Math.max(slider.min, Number(value)));
  const auSide = slider.part === OverridePart.actionUnit ? (slider.middle ? Side.both : side) : slider.side;
  return { part: slider.part, index: slider.index, side: auSide, value: Math.round(clamped * slider.scale) };
}

export const behaviourOverride = (on) => ({ part: OverridePart.behaviour, index: 0, side: 0, value: on ? 1 : 0 });
export const RESET_OVERRIDE = Object.freeze({ part: OverridePart.reset, index: 0, side: 0, value: 0 });
