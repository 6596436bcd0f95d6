// Where the faces on the room's stage are, as someone looking at the screen
// would find them: from a screenshot of the stage (names and caption made
// transparent for it), in each tile's box, the rows whose pixels differ
// from the tile's own background. Nothing comes from the layout code's
// numbers but the tiles' boxes, which the page shows as its clickable tiles.
import { readPng } from './png_pixels.mjs';

/** How far (in any channel, 0 to 255) a pixel is from the background before it counts as drawn. */
const DRAWN = 30;
/** How many drawn pixels a row needs to belong to the face (a lone pixel is antialiasing or noise). */
const ROW_PIXELS = 3;

/** The boxes of the stage, its face tiles and their names, CSS pixels from the stage's top left. */
export function stageBoxes(page) {
  return page.evaluate(() => {
    const stage = document.getElementById('stage').getBoundingClientRect();
    const box = (element) => {
      const r = element.getBoundingClientRect();
      return { x: r.x - stage.x, y: r.y - stage.y, w: r.width, h: r.height };
    };
    return {
      stage: { w: stage.width, h: stage.height },
      tiles: [...document.querySelectorAll('#overlay .tile:not(.self)')].map((tile) => ({
        avatar: Number(tile.dataset.avatar), tile: box(tile), name: box(tile.querySelector('.name')),
        nameText: tile.querySelector('.name').textContent,
      })),
    };
  });
}

/** A PNG screenshot of the stage as the person sees it, but with the names' and the caption's text transparent. */
export async function stageShotWithoutText(page) {
  const style = await page.addStyleTag({ content: '#overlay .name, #overlay .name::after, #caption { color: transparent !important; }' });
  try {
    return readPng(await page.locator('#stage').screenshot());
  } finally {
    await style.evaluate((element) => element.remove());
  }
}

/**
 * The rows (image pixels from the stage's top) where the face drawn in
 * `tile` (CSS px) is: { top, bottom } of its drawn rows, or null. The
 * tile's background is its top left pixel's colour.
 */
export function faceRows(png, tile, cssToImage) {
  const { width, channels, data } = png;
  const x0 = Math.ceil(tile.x * cssToImage);
  const x1 = Math.floor((tile.x + tile.w) * cssToImage);
  const y0 = Math.ceil(tile.y * cssToImage);
  const y1 = Math.min(png.height, Math.floor((tile.y + tile.h) * cssToImage));
  const at = (x, y) => (y * width + x) * channels;
  const background = [0, 1, 2].map((c) => data[at(x0 + 1, y0 + 1) + c]);
  let top = null;
  let bottom = null;
  for (let y = y0; y < y1; ++y) {
    let drawn = 0;
    for (let x = x0; x < x1 && drawn < ROW_PIXELS; ++x) {
      const i = at(x, y);
      if (Math.max(...[0, 1, 2].map((c) => Math.abs(data[i + c] - background[c]))) > DRAWN) drawn += 1;
    }
    if (drawn >= ROW_PIXELS) {
      top ??= y;
      bottom = y;
    }
  }
  return top === null ? null : { top, bottom };
}
