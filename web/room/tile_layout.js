// Where each face's tile sits on the stage: the others in one row (up to
// three) or two, as large as the stage allows, and the viewer's own face in
// a small tile in a corner, as in a video call. Pixels, origin top left.

const GAP = 6;
const NAME_BAND = 22;  // under each face, for its name
const MAX_TILE_ASPECT = 1.3;  // height / width of a tile's face area

/**
 * @param count   the others
 * @param width, height   the stage in CSS pixels
 * @returns { tiles: [{x, y, w, h}], self: {x, y, w, h} }
 */
export function tileLayout(count, stageWidth, stageHeight) {
  const portrait = stageHeight > stageWidth;
  // The self view takes a corner; the faces keep clear of it: a strip on
  // the right of a wide stage, at the bottom of a tall one.
  const selfW = Math.round(Math.max(90, Math.min(200, stageWidth * 0.2)));
  const selfH = Math.round(selfW * 1.2);
  const self = { x: stageWidth - selfW - GAP, y: stageHeight - selfH - GAP, w: selfW, h: selfH };
  const width = portrait ? stageWidth : stageWidth - selfW - GAP;
  const height = portrait ? stageHeight - selfH - GAP : stageHeight;
  const rows = count <= (portrait ? 1 : 3) ? 1 : count <= (portrait ? 4 : 6) ? 2 : 3;
  const columns = Math.max(1, Math.ceil(count / rows));
  const w = (width - GAP * (columns + 1)) / columns;
  // A tile no taller than a head needs (its name included): the rows are
  // centred in what is left.
  const h = Math.min((height - GAP * (rows + 1)) / rows, MAX_TILE_ASPECT * w + NAME_BAND);
  const top = (height - rows * h - (rows - 1) * GAP) / 2;
  const tiles = [];
  for (let i = 0; i < count; ++i) {
    const row = Math.floor(i / columns);
    // A short last row is centred.
    const inRow = Math.min(columns, count - row * columns);
    const left = (width - inRow * w - (inRow - 1) * GAP) / 2;
    tiles.push({ x: left + (i % columns) * (w + GAP), y: top + row * (h + GAP), w, h });
  }
  return { tiles, self, nameBand: NAME_BAND };
}
