// The face lab's preview drawn as the room draws a face (room_view.js's
// package building and tile drawing, face_renderer.js), alone on the canvas,
// seen by a camera the person turns about the head: from the front at 0,
// from the person's left at +90 degrees.
import { mat4 } from '../../shared/mat4.js';
import { RoomView } from '../room_view.js';

/** The self view's aim (room_view.js), from further: the whole head, turned, and the top of the neck. */
const CAMERA_HEIGHT = -0.25;
const CAMERA_DISTANCE = 11;
const FOV_Y = 0.5236;

export class LabView {
  constructor({ gl, engine, renderer, client }) {
    this.client = client;
    this.room = new RoomView({ gl, engine, renderer, client });
    this.cameraYawRad = 0;
    this.frames = 0;
    /** The FaceParams the face was drawn with last (for whoever inspects the page, and the contact sheet). */
    this.drawnParams = null;
    /** The face (RoomView's { model, gpu }) drawn last: the contact sheet draws it again. */
    this.drawnFace = null;
  }

  /** The page's own package, drawn before the stream's first frame. */
  setOwnPackage(bytes) { return this.room.setOwnPackage(bytes); }

  /** Draws the preview on a canvas of `width` x `height` CSS pixels. */
  draw(width, height, pixelRatio, nowMs) {
    const room = this.room;
    room.syncPackages();
    const you = this.client.you;
    const face = room.ownFace ?? room.faces.get(you);
    const gl = room.gl;
    gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    gl.clearColor(0.11, 0.12, 0.14, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const params = you ? this.client.face(you, nowMs) : null;
    if (!face || !params) return;
    this.showSurface(face);
    const rect = { x: 0, y: 0, w: width, h: height };
    room.drawTile('lab', rect, 0, height, pixelRatio, face, params, mat4.identity(), this.camera(this.cameraYawRad, 0, width / Math.max(1, height)));
    this.drawnParams = params;
    this.drawnFace = face;
    this.frames += 1;
  }

  /**
   * The camera about the head, turned by `yawRad` (toward the person's left
   * when positive) and raised by `pitchRad` (from above when positive), for
   * a picture of `aspect` (width / height): a narrow one is seen from further,
   * so that the head's width still fits.
   */
  camera(yawRad, pitchRad, aspect) {
    const distance = CAMERA_DISTANCE / Math.min(1, aspect);
    const across = distance * Math.cos(pitchRad);
    const position = [across * Math.sin(yawRad), CAMERA_HEIGHT + distance * Math.sin(pitchRad), across * Math.cos(yawRad)];
    return this.room.camera({ position, target: [0, CAMERA_HEIGHT, 0] }, FOV_Y, aspect);
  }

  /**
   * Draws the face last drawn, with `params`, into the bound framebuffer's
   * `size` x `size` corner, seen by `camera` (this.camera's), under the
   * tile key `key` (landmarksOnScreen(key) then finds its points there).
   * Returns false when no face has been drawn yet.
   */
  drawStill(key, size, params, camera) {
    if (!this.drawnFace) return false;
    this.room.drawTile(key, { x: 0, y: 0, w: size, h: size }, 0, size, 1, this.drawnFace, params, mat4.identity(), camera);
    return true;
  }

  /**
   * The simulated skin itself, not only its projection on the action units:
   * the server's residual (PROTOCOL.md 5.18) added to the face the frames
   * rebuild, whenever a newer one came or the face's model was built again.
   */
  showSurface(face) {
    const wanted = this.client.previewSurface;
    if (face.surface === wanted) return;
    face.surface = wanted;
    try {
      face.model.setSurface(wanted ? wanted.moves : []);
    } catch (error) {
      console.warn(`preview surface: ${error.message}; drawing the action units alone`);
      face.model.setSurface([]);
    }
  }

  /** Landmarks (68-point scheme) of the face as last drawn (or of a still's `key`), CSS pixels on its picture. */
  landmarksOnScreen(indices, key = 'lab') { return this.room.landmarksOnScreen(key, indices); }
}
