// Where each face's tile sits on the stage, as large as the stage allows,
// and the viewer's own face in a small tile in the bottom right corner, as
// in a video call. Pixels, origin top left.
//
// Every face tile has the frame's shape (face_frame.js) with the name band
// under it, so a face's size is its tile's width: the arrangement chosen is
// the one, of every number of columns, whose tiles are widest. That uses the
// stage's height as well as its width: three faces sit in one row on a wide
// desktop stage (a row of tall tiles, each nearly the stage's height), in
// two columns on a tall phone stage (two rows of faces twice as wide as a
// row of three, and larger than a column of three, whose height would
// limit them to a third of the stage each). The faces keep clear of the
// self view: the tiles move up, or left, out of its corner, or are laid out
// beside or above it; an arrangement that overlaps it is not chosen unless
// none is clear.
import { FRAME_ASPECT } from './face_frame.js';

const GAP = 6;
/** Under each face, for its name (room.css's `.tile .name` is as high). */
const NAME_BAND = 24;

/** The self view: a fifth of the stage's width, between 90 and 200 px, in the bottom right corner. */
function selfTile(stageWidth, stageHeight) {
  const w = Math.round(Math.max(90, Math.min(200, stageWidth * 0.2)));
  const h = Math.round(w * 1.2);
  return { x: stageWidth - w - GAP, y: stageHeight - h - GAP, w, h };
}

/** `count` tiles in `columns` columns, as large as the area (from the stage's top left) allows and centred in it; a short last row is centred too. */
function grid(count, columns, stageWidth, stageHeight) {
  const rows = Math.ceil(count / columns);
  const cellWidth = (stageWidth - GAP * (columns + 1)) / columns;
  const cellHeight = (stageHeight - GAP * (rows + 1)) / rows;
  const w = Math.max(0, Math.min(cellWidth, (cellHeight - NAME_BAND) / FRAME_ASPECT));
  const h = w * FRAME_ASPECT + NAME_BAND;
  const top = (stageHeight - rows * h - (rows - 1) * GAP) / 2;
  return Array.from({ length: count }, (_, i) => {
    const row = Math.floor(i / columns);
    const inRow = Math.min(columns, count - row * columns);
    const left = (stageWidth - inRow * w - (inRow - 1) * GAP) / 2;
    return { x: left + (i % columns) * (w + GAP), y: top + row * (h + GAP), w, h };
  });
}

const overlaps = (a, b) => a.x < b.x + b.w + GAP && b.x < a.x + a.w + GAP && a.y < b.y + b.h + GAP && b.y < a.y + a.h + GAP;

/** The tiles moved up, or else left, just enough to clear the self view; null when neither fits on the stage. */
function clearOfSelf(tiles, self) {
  const hit = tiles.filter((t) => overlaps(t, self));
  if (hit.length === 0) return tiles;
  const up = Math.max(...hit.map((t) => t.y + t.h)) - (self.y - GAP);
  if (Math.min(...tiles.map((t) => t.y)) - up >= GAP) return tiles.map((t) => ({ ...t, y: t.y - up }));
  const left = Math.max(...hit.map((t) => t.x + t.w)) - (self.x - GAP);
  if (Math.min(...tiles.map((t) => t.x)) - left >= GAP) return tiles.map((t) => ({ ...t, x: t.x - left }));
  return null;
}

/**
 * @param count   the others
 * @param stageWidth, stageHeight   the stage in CSS pixels
 * @returns { tiles: [{x, y, w, h}], self: {x, y, w, h}, nameBand }: each
 *   tile's face above its bottom `nameBand` pixels, its name in them
 */
export function tileLayout(count, stageWidth, stageHeight) {
  const self = selfTile(stageWidth, stageHeight);
  // The whole stage, or the stage less a strip beside or above the self view
  // (when the tiles cannot move out of its way, a face alone on a phone).
  const areas = [[stageWidth, stageHeight], [self.x - GAP, stageHeight], [stageWidth, self.y - GAP]];
  let best = null;
  let widest = null;  // on a stage too small to clear the self view, the faces go over it
  for (let columns = 1; columns <= count; ++columns) {
    for (const [width, height] of areas) {
      const tiles = grid(count, columns, width, height);
      if (!widest || tiles[0].w > widest[0].w) widest = tiles;
      const clear = clearOfSelf(tiles, self);
      if (clear && (!best || clear[0].w > best[0].w)) best = clear;
    }
  }
  return { tiles: best ?? widest ?? [], self, nameBand: NAME_BAND };
}
