// Reading the room page's canvas as a viewer sees it: pixels of a region,
// and measures of them (how much is face rather than background, how a
// mouth changed, where an iris sits in its eye opening). Regions come from
// the page's own layout (window.facewireRoom.view), the judgements from the
// pixels alone. The same measures read images a page made (the face lab's
// contact sheet, a PNG read by png_pixels.mjs).

/** RGBA pixels of the room canvas inside `rect` (CSS pixels), as { w, h, data }. */
export async function canvasPixels(page, rect) {
  return page.evaluate(({ x, y, w, h }) => {
    const canvas = document.getElementById('room-canvas');
    const ratio = canvas.width / canvas.clientWidth;
    const copy = document.createElement('canvas');
    copy.width = Math.max(1, Math.round(w * ratio));
    copy.height = Math.max(1, Math.round(h * ratio));
    const g = copy.getContext('2d');
    g.drawImage(canvas, x * ratio, y * ratio, w * ratio, h * ratio, 0, 0, copy.width, copy.height);
    return { w: copy.width, h: copy.height, data: Array.from(g.getImageData(0, 0, copy.width, copy.height).data) };
  }, rect);
}

const luma = (d, i) => 0.299 * d[i] + 0.587 * d[i + 1] + 0.114 * d[i + 2];

/** The share of pixels that are face (skin, hair, eyes: anything lighter or warmer than the tiles' dark blue-grey). */
export function faceShare({ data }) {
  let face = 0;
  for (let i = 0; i < data.length; i += 4) {
    const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
    if (r + g + b > 200 || r > b + 25) face += 1;
  }
  return face / (data.length / 4);
}

/** How much the pixels of a region vary (0 for a flat background). */
export function spread({ data }) {
  let min = 255;
  let max = 0;
  for (let i = 0; i < data.length; i += 4) {
    const l = luma(data, i);
    min = Math.min(min, l);
    max = Math.max(max, l);
  }
  return max - min;
}

/**
 * The points of a grid in a frame tied to the eyes' outer corners
 * (landmarks 36 and 45, [[x, y], [x, y]]): the mouth's region whatever the
 * head does, between the pupils' columns, from under the nose to the chin's top.
 */
export function mouthPoints(corners) {
  const [a, b] = corners;
  const across = [b[0] - a[0], b[1] - a[1]];
  const down = [-across[1], across[0]];  // image y runs down; the face's down is +90 degrees from the eye line
  const points = [];
  for (let j = 0; j < 10; ++j) {
    for (let i = 0; i < 16; ++i) {
      const u = 0.25 + (0.5 * i) / 15;
      const v = 0.55 + (0.4 * j) / 9;
      points.push([a[0] + u * across[0] + v * down[0], a[1] + u * across[1] + v * down[1]]);
    }
  }
  return points;
}

/**
 * Samples luma at mouthPoints(corners) on the room canvas.
 * @param corners [[x, y], [x, y]] of landmarks 36 and 45 on the canvas (CSS px)
 */
export async function mouthSamples(page, corners) {
  return page.evaluate((pts) => {
    const canvas = document.getElementById('room-canvas');
    const ratio = canvas.width / canvas.clientWidth;
    const copy = document.createElement('canvas');
    copy.width = canvas.width;
    copy.height = canvas.height;
    const g = copy.getContext('2d');
    g.drawImage(canvas, 0, 0);
    const { data } = g.getImageData(0, 0, copy.width, copy.height);
    // The mean of a 3x3 block: a sub-pixel sway of the head moves an edge
    // across a single pixel, not across a block.
    return pts.map(([x, y]) => {
      let sum = 0;
      for (let dy = -1; dy <= 1; ++dy) {
        for (let dx = -1; dx <= 1; ++dx) {
          const i = 4 * ((Math.round(y * ratio) + dy) * copy.width + Math.round(x * ratio) + dx);
          sum += 0.299 * data[i] + 0.587 * data[i + 1] + 0.114 * data[i + 2];
        }
      }
      return sum / 9;
    });
  }, mouthPoints(corners));
}

/**
 * A rectangle of an image png_pixels.mjs read ({ width, channels, data }),
 * whole pixels, as RGBA { w, h, data } (what faceShare and spread take).
 */
export function imageRegion(image, { x, y, w, h }) {
  const data = new Uint8Array(4 * w * h);
  for (let row = 0; row < h; ++row) {
    for (let column = 0; column < w; ++column) {
      const from = ((y + row) * image.width + x + column) * image.channels;
      const to = 4 * (row * w + column);
      for (let c = 0; c < 3; ++c) data[to + c] = image.data[from + c];
      data[to + 3] = image.channels === 4 ? image.data[from + 3] : 255;
    }
  }
  return { w, h, data };
}

/** Luma of every pixel of an RGBA region (imageRegion's, canvasPixels'). */
export const lumas = ({ data }) => Array.from({ length: data.length / 4 }, (_, i) => luma(data, 4 * i));

/** mouthSamples on an image png_pixels.mjs read, the corners in its pixels; the same 3x3 means. */
export function imageMouthSamples(image, corners) {
  return mouthPoints(corners).map(([x, y]) => lumas(imageRegion(image, { x: Math.round(x) - 1, y: Math.round(y) - 1, w: 3, h: 3 }))
    .reduce((sum, v) => sum + v, 0) / 9);
}

export const meanAbsDifference = (a, b) => a.reduce((sum, v, i) => sum + Math.abs(v - b[i]), 0) / a.length;

/**
 * Where the iris sits in an eye opening: along the line between the eye's
 * corners, the darkest stretch (a fifth of the eye's width, averaged over a
 * band an eighth of the width high) among the middle 70 % of the opening,
 * where the lids' corners and their shadows do not reach, refined to a
 * fraction of a pixel by its darkness-weighted centre. Returned as the
 * offset of its centre from the corners' midpoint, in eye widths (positive
 * toward `corners[1]`'s side of the screen, i.e. toward +x when corners[1]
 * lies right of corners[0]).
 */
export async function irisOffset(page, corners) {
  const [a, b] = corners;
  const width = Math.hypot(b[0] - a[0], b[1] - a[1]);
  const half = width / 8;
  const rect = { x: Math.min(a[0], b[0]), y: (a[1] + b[1]) / 2 - half, w: Math.abs(b[0] - a[0]), h: 2 * half };
  const pixels = await canvasPixels(page, rect);
  const columns = Array.from({ length: pixels.w }, (_, x) => {
    let sum = 0;
    for (let y = 0; y < pixels.h; ++y) sum += luma(pixels.data, 4 * (y * pixels.w + x));
    return sum / pixels.h;
  });
  const window = Math.max(1, Math.round(pixels.w / 5));
  let best = -1;
  let bestMean = Infinity;
  for (let x = Math.round(pixels.w * 0.15); x + window <= Math.round(pixels.w * 0.85); ++x) {
    const mean = columns.slice(x, x + window).reduce((p, q) => p + q, 0) / window;
    if (mean < bestMean) [best, bestMean] = [x, mean];
  }
  // Refined to a fraction of a pixel: the darkness-weighted centre of the
  // columns around the darkest window (darker than the band's brightest
  // quarter, the sclera), since a whole pixel is a thirtieth of an eye.
  const sclera = [...columns].sort((p, q) => q - p)[Math.floor(columns.length / 4)];
  let weight = 0;
  let moment = 0;
  for (let x = Math.max(0, best - window); x < Math.min(pixels.w, best + 2 * window); ++x) {
    const dark = Math.max(0, sclera - columns[x]);
    weight += dark;
    moment += dark * (x + 0.5);
  }
  const at = weight > 0 ? moment / weight : best + window / 2;
  const centre = rect.x + (at / pixels.w) * rect.w;
  const sign = b[0] >= a[0] ? 1 : -1;
  return (sign * (centre - (a[0] + b[0]) / 2)) / width;
}
