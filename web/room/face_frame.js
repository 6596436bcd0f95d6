// How much of a person a tile shows: the head and the top of the neck, as a
// video call frames a person head and shoulders (the model has no
// shoulders: its neck is a long cylinder, avatar/model/README.md, whose cut
// end must stay out of the frame). Model units (MM_PER_UNIT mm each),
// measured from the midpoint of the eyes in the face's own plane; the
// generic head reaches 1.59 units above the eyes, its chin 1.84 below, and
// it is 2.76 wide.

/** Above the eyes: the top of the hair, and room for a head that lifts or nods back. */
export const FRAME_ABOVE_EYES = 2.2;
/** Below the eyes: the chin, and a little of the neck under it. */
export const FRAME_BELOW_EYES = 2.55;
/** Across: the head, and the wider outline of a head turned toward a neighbour. */
export const FRAME_ACROSS = 3.2;
/** The frame's height over its width: every face tile has this shape. */
export const FRAME_ASPECT = (FRAME_ABOVE_EYES + FRAME_BELOW_EYES) / FRAME_ACROSS;
/**
 * The share of the frame's height, at its bottom, over which the neck fades
 * into the tile (room_page.js lays the fade over the canvas): the face ends
 * under its chin, so the name under it reads as the face's caption rather
 * than a label on a cut-off neck.
 */
export const NECK_FADE_SHARE = 0.42 / (FRAME_ABOVE_EYES + FRAME_BELOW_EYES);
