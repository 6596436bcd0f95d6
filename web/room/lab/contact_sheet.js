// The face lab's contact sheet: the face exactly as the preview shows it at
// the moment asked (the FaceParams it was last drawn with: the room frame's,
// overrides included), frozen, and drawn again by the page's own renderer
// from fixed views into one labelled image. The native sheet
// (avatar/render contact_sheet.hpp) shows fixed expressions; this one shows
// the current state, so only the camera changes from panel to panel.
//
// The views: the head seen from the front, turned 30 and 60 degrees each
// way (the camera moves about the head, as the lab's View slider does:
// "left" is the person's own left, the slider's positive side), and from 20
// degrees above and 20 below, the head level. The sheet's views do not
// follow the preview's View slider. Laid out in rows, two ways: wide (the
// turns in one row, above and below under the front) for a desktop, tall
// (front; the 30s; the 60s; above and below) for a phone held upright;
// whichever shows the panels larger on the screen is drawn (as
// tile_layout.js chooses the room's tiles).
//
// Panels are drawn into a framebuffer of their own on the page's WebGL
// context (the face's meshes and textures live there), read back and
// pasted onto a 2-D canvas: the canvas the preview shows is never drawn on,
// and the viewport and framebuffer binding are put back.

const DEGREE = Math.PI / 180;

/** The views: { key, label, yawDeg, pitchDeg }. */
export const SHEET_VIEWS = Object.freeze([
  { key: 'front', label: 'front', yawDeg: 0, pitchDeg: 0 },
  { key: 'left-30', label: 'left 30°', yawDeg: 30, pitchDeg: 0 },
  { key: 'right-30', label: 'right 30°', yawDeg: -30, pitchDeg: 0 },
  { key: 'left-60', label: 'left 60°', yawDeg: 60, pitchDeg: 0 },
  { key: 'right-60', label: 'right 60°', yawDeg: -60, pitchDeg: 0 },
  { key: 'above-20', label: 'from above 20°', yawDeg: 0, pitchDeg: 20 },
  { key: 'below-20', label: 'from below 20°', yawDeg: 0, pitchDeg: -20 },
].map(Object.freeze));

/** The two ways to lay the views out: rows of view keys, each row centred; seen from the front, the person's right is on the left. */
export const ARRANGEMENTS = Object.freeze({
  wide: [['right-60', 'right-30', 'front', 'left-30', 'left-60'], ['above-20', 'below-20']],
  tall: [['front'], ['right-30', 'left-30'], ['right-60', 'left-60'], ['above-20', 'below-20']],
});

/** Each panel's side in pixels: a wide sheet is 1648 x 740 px, a tall one 664 x 1472; the dialog scales it to fit. */
export const PANEL_SIZE = 320;
/** The band under each panel that holds its label, as a share of the panel's side. */
const LABEL_SHARE = 0.12;
const GAP = 8;
/** Between and around the panels: the lab's own background (lab_view.js clears to it). */
const SHEET_BACKGROUND = 'rgb(28 31 36)';
const LABEL_COLOUR = '#e8e8ec';

/**
 * Where each view's panel goes in `arrangement` (rows of SHEET_VIEWS keys),
 * each row centred. Pure, for node's tests.
 * @returns { width, height, labelHeight, cells: [{ view, x, y, size }] } in pixels
 */
export function sheetLayout(arrangement = ARRANGEMENTS.wide, panelSize = PANEL_SIZE) {
  const labelHeight = Math.round(panelSize * LABEL_SHARE);
  const columns = Math.max(...arrangement.map((row) => row.length));
  const width = GAP + columns * (panelSize + GAP);
  const rowHeight = panelSize + labelHeight + GAP;
  const cells = [];
  arrangement.forEach((row, r) => {
    const left = (width - row.length * (panelSize + GAP) - GAP) / 2 + GAP;
    row.forEach((key, i) => {
      const view = SHEET_VIEWS.find((v) => v.key === key);
      if (!view) throw new Error(`the contact sheet has no view '${key}'`);
      cells.push({ view, x: Math.round(left + i * (panelSize + GAP)), y: GAP + r * rowHeight, size: panelSize });
    });
  });
  return { width, height: GAP + arrangement.length * rowHeight, labelHeight, cells };
}

/**
 * The arrangement's name ('wide' or 'tall') whose panels show largest in a
 * box of `width` x `height` CSS pixels (the sheet is scaled down to fit it,
 * never up).
 */
export function arrangementFor(width, height) {
  const shown = (name) => {
    const { width: w, height: h } = sheetLayout(ARRANGEMENTS[name]);
    return Math.min(1, width / w, height / h);
  };
  return shown('tall') > shown('wide') ? 'tall' : 'wide';
}

/**
 * The downloaded file's name: the avatar's name (letters, digits, '-' and
 * '_' only, at most 40 of them) and the UTC time the sheet was taken.
 */
export function sheetFileName(name, date) {
  const dashed = String(name ?? '').normalize('NFKC').replace(/[^\p{L}\p{N}_-]+/gu, '-').replace(/^-+/, '');
  const safe = Array.from(dashed).slice(0, 40).join('').replace(/-+$/, '') || 'face';  // whole characters, not halves
  const stamp = date.toISOString().replace(/\.\d+Z$/, '').replace(/[-:]/g, '').replace('T', '-');
  return `facewire-sheet-${safe}-${stamp}.png`;
}

/**
 * Renders the sheet of `params` (frozen by the caller) with the lab view's
 * renderer (lab_view.js `camera`, `drawStill`), laid out as `arrangement`
 * (a name of ARRANGEMENTS). Returns { canvas, layout, arrangement, params },
 * or null when the preview has drawn no face yet.
 */
export function renderContactSheet(view, params, arrangement = 'wide', panelSize = PANEL_SIZE) {
  if (!params || !view.drawnFace) return null;
  const layout = sheetLayout(ARRANGEMENTS[arrangement], panelSize);
  const canvas = document.createElement('canvas');
  canvas.width = layout.width;
  canvas.height = layout.height;
  const g = canvas.getContext('2d');
  g.fillStyle = SHEET_BACKGROUND;
  g.fillRect(0, 0, layout.width, layout.height);
  g.fillStyle = LABEL_COLOUR;
  g.font = `${Math.round(layout.labelHeight * 0.62)}px system-ui, sans-serif`;
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  const target = new OffscreenTarget(view.room.gl, panelSize);
  try {
    for (const { view: v, x, y, size } of layout.cells) {
      target.bind();
      view.drawStill(`sheet:${v.key}`, size, params, view.camera(v.yawDeg * DEGREE, v.pitchDeg * DEGREE, 1));
      g.putImageData(new ImageData(target.read(), size, size), x, y);
      g.fillText(v.label, x + size / 2, y + size + layout.labelHeight / 2);
    }
  } finally {
    target.release();
  }
  return { canvas, layout, arrangement, params };
}

/**
 * A square framebuffer on `gl` with depth and stencil (the eye sockets use
 * the stencil), multisampled as the page's canvas is, resolved into a plain
 * one to be read. release() deletes it and puts back what was bound.
 */
class OffscreenTarget {
  constructor(gl, size) {
    this.gl = gl;
    this.size = size;
    this.previous = { framebuffer: gl.getParameter(gl.FRAMEBUFFER_BINDING), viewport: gl.getParameter(gl.VIEWPORT) };
    const samples = Math.min(4, gl.getParameter(gl.MAX_SAMPLES));
    const storage = (format, withSamples) => {
      const buffer = gl.createRenderbuffer();
      gl.bindRenderbuffer(gl.RENDERBUFFER, buffer);
      if (withSamples) gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, format, size, size);
      else gl.renderbufferStorage(gl.RENDERBUFFER, format, size, size);
      return buffer;
    };
    this.buffers = [storage(gl.RGBA8, true), storage(gl.DEPTH24_STENCIL8, true), storage(gl.RGBA8, false)];
    this.drawn = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.drawn);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, this.buffers[0]);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_STENCIL_ATTACHMENT, gl.RENDERBUFFER, this.buffers[1]);
    this.resolved = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.resolved);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, this.buffers[2]);
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    if (status !== gl.FRAMEBUFFER_COMPLETE) {
      this.release();
      throw new Error(`this browser cannot draw the sheet off screen (framebuffer status ${status})`);
    }
  }

  bind() {
    this.gl.bindFramebuffer(this.gl.FRAMEBUFFER, this.drawn);
  }

  /** The panel's RGBA pixels, top row first (as ImageData wants; GL's rows run up). */
  read() {
    const { gl, size } = this;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.drawn);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, this.resolved);
    gl.blitFramebuffer(0, 0, size, size, 0, 0, size, size, gl.COLOR_BUFFER_BIT, gl.NEAREST);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.resolved);
    const upward = new Uint8Array(4 * size * size);
    gl.readPixels(0, 0, size, size, gl.RGBA, gl.UNSIGNED_BYTE, upward);
    const rows = new Uint8ClampedArray(upward.length);
    const stride = 4 * size;
    for (let y = 0; y < size; ++y) rows.set(upward.subarray((size - 1 - y) * stride, (size - y) * stride), y * stride);
    // Opaque, as the page's canvas (alpha: false) shows it: the shaders' alpha is coverage, not transparency.
    for (let i = 3; i < rows.length; i += 4) rows[i] = 255;
    return rows;
  }

  release() {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.previous.framebuffer);
    gl.viewport(...this.previous.viewport);
    gl.deleteFramebuffer(this.drawn);
    gl.deleteFramebuffer(this.resolved);
    for (const buffer of this.buffers) gl.deleteRenderbuffer(buffer);
  }
}
