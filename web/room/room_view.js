// The room drawn from the viewer's own place (PROTOCOL.md 6.1): each of the
// others in a tile, seen from the viewer's eyes as it sits on the view's arc
// (view_geometry.js), its eyes and head re-aimed at where its attention
// target sits in this view (gaze_reaim.js); the viewer's own face in a small
// tile, at once, from the page's own package. Names and the last chat line
// are HTML laid over the canvas (room_page.js places them from `tiles`). A
// face the viewer muted (mute_list.js) is drawn at rest: neutral, still and
// looking straight ahead, whatever the stream says it does. Each face moves
// by the units its person redefined (PROTOCOL.md 5.17), as the client keeps
// them, from the frame its model is built or a new version arrives.
import { mat4 } from '../shared/mat4.js';
import { TURN_SHARE, aimAt, reaim, reaimAtViewer } from './gaze_reaim.js';
import { decodeImage } from './face_renderer.js';
import { RetargetEasing } from './retarget_easing.js';
import { NEUTRAL_FACE as NEUTRAL } from './mute_list.js';
import { MM_PER_UNIT, VIEW_DISTANCE_MM, eyeMidMm, screenOrder, seatToRoom, serverSeat, viewSeats } from './view_geometry.js';
import { tileLayout } from './tile_layout.js';
import { FRAME_ABOVE_EYES, FRAME_ACROSS, FRAME_BELOW_EYES } from './face_frame.js';

const BACKGROUND = [0.16, 0.17, 0.2];
/** A face tile's background as CSS: what the neck fades into over the canvas (room_page.js). */
export const TILE_BACKGROUND_CSS = `rgb(${BACKGROUND.map((c) => Math.round(c * 255)).join(' ')})`;

/** A face's place: translate(origin) * rotate_y(facing), model units. */
const placeOf = (seat) => mat4.multiply(mat4.translation(seat.origin.map((v) => v / MM_PER_UNIT)), mat4.rotationY(seat.facingYawRad));

export class RoomView {
  /** @param mutes the viewer's MuteList (mute_list.js), or none */
  constructor({ gl, engine, renderer, client, mutes = null }) {
    this.gl = gl;
    this.mutes = mutes;
    this.engine = engine;
    this.renderer = renderer;
    this.client = client;
    this.faces = new Map();   // avatar id -> { bytes, model, gpu, units } once its package is built
    this.building = new Map();  // avatar id -> bytes being built
    this.retarget = new RetargetEasing();
    this.generic = engine.genericAvatar();
    const eyeCentres = this.generic.face.eyes.map((e) => e.centre);
    this.eyeMid = eyeMidMm(eyeCentres);
    // Each eye's turn inward to meet at the viewer's eyes, VIEW_DISTANCE_MM away.
    const halfInterocular = (Math.abs(eyeCentres[0][0] - eyeCentres[1][0]) / 2) * MM_PER_UNIT;
    this.vergence = Math.atan2(halfInterocular, VIEW_DISTANCE_MM);
    this.ownFace = null;
    this.tiles = [];
    /** The band under each face tile that holds its name (tile_layout.js). */
    this.nameBand = 0;
    this.frames = 0;
    /** When the viewer's own face was first drawn (performance.now()), for the page's tests. */
    this.selfDrawnMs = null;
    /** What each tile showed last: avatar id (or 'self') -> { area, viewProjection, model, landmarks }. */
    this.shown = new Map();
    /** The FaceParams each tile was drawn with last (avatar id -> params), for whoever inspects the page. */
    this.drawnParams = new Map();
  }

  /** The viewer's own face, from the package the page holds (before any server message). */
  async setOwnPackage(bytes) {
    this.ownFace = await this.build(bytes);
  }

  async build(bytes) {
    const pkg = this.engine.readPackage(bytes);
    try {
      const model = this.engine.avatarFromPackage(pkg);
      const names = ['faceTexture', 'eye', 'mouth', 'closedLid', 'colourMasksA', 'colourMasksB'];
      const decoded = await Promise.all(names.map((n) => decodeImage(pkg.images[n])));
      const images = Object.fromEntries(names.map((n, i) => [n, decoded[i]]));
      const gpu = this.renderer.addFace(model, images, pkg.closedLidRect, pkg.textureLight);
      // units: the unit morphs message its model moves by; none: the shipped units.
      return { bytes, model, gpu, units: null };
    } finally {
      pkg.release();
    }
  }

  /** Builds what arrived since the last frame, and lets go of who left. */
  syncPackages() {
    for (const [id, entry] of this.client.avatars) {
      const bytes = entry.package?.bytes;
      if (!bytes || this.faces.get(id)?.bytes === bytes || this.building.get(id) === bytes) continue;
      this.building.set(id, bytes);
      this.build(bytes).then((face) => {
        if (this.building.get(id) !== bytes) return this.release(face);
        this.building.delete(id);
        const old = this.faces.get(id);
        this.faces.set(id, face);
        if (old) this.release(old);
        return undefined;
      }).catch((error) => {
        this.building.delete(id);
        console.warn(`avatar ${id}: ${error.message}`);
      });
    }
    for (const [id, face] of this.faces) {
      if (!this.client.avatars.has(id)) {
        this.faces.delete(id);
        this.release(face);
      }
    }
    for (const [id, face] of this.faces) this.redefineUnits(id, face);
    if (this.ownFace && this.client.you) this.redefineUnits(this.client.you, this.ownFace);
  }

  /**
   * Gives a face the units its person redefined, when the client keeps a
   * set for it that its model does not move by yet (a new version, or a
   * model just built from a new package); a restore is a set without units.
   */
  redefineUnits(id, face) {
    const wanted = this.client.unitMorphs.get(id) ?? null;
    if (face.units === wanted) return;
    face.units = wanted;
    try {
      face.model.setUnitMorphs(wanted ? wanted.units : []);
    } catch (error) {
      console.warn(`avatar ${id}: ${error.message}; drawing its shipped units`);
      face.model.setUnitMorphs([]);
    }
  }

  release(face) {
    this.renderer.removeFace(face.gpu);
    face.model.release();
  }

  /** Where a face attending `entry` aims: a room point in the server's room and in the view, or null. */
  targets(id, entry, serverSeats, viewPlaces) {
    if (!entry || entry.target !== 2) return null;
    const target = entry.targetAvatar;
    const server = serverSeats.get(target);
    if (!server) return null;
    const inView = target === this.client.you ? [0, 0, 0] : viewPlaces.get(target)?.eyes;
    if (!inView) return null;
    return { server: seatToRoom(server, this.eyeMid), view: inView, viewer: target === this.client.you, key: `${target}` };
  }

  /** Draws one frame on a canvas of `width` x `height` CSS pixels at `pixelRatio`. */
  draw(width, height, pixelRatio, nowMs) {
    const gl = this.gl;
    this.syncPackages();
    const client = this.client;
    const infos = [...client.avatars.values()].map((a) => a.info);
    const others = client.you ? screenOrder(infos, client.you) : [];
    const layout = tileLayout(others.length, width, height);
    this.nameBand = layout.nameBand;
    const seats = viewSeats(others.length, this.eyeMid);
    const viewPlaces = new Map(others.map((info, i) => [info.id, seats[i]]));
    const serverSeats = new Map(infos.map((info) => [info.id, serverSeat(info.seat)]));

    gl.viewport(0, 0, gl.drawingBufferWidth, gl.drawingBufferHeight);
    gl.disable(gl.SCISSOR_TEST);
    gl.clearColor(0.11, 0.12, 0.14, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);

    this.tiles = others.map((info, i) => {
      const rect = layout.tiles[i];
      const face = this.faces.get(info.id);
      const decoded = client.face(info.id, nowMs);
      const drawn = Boolean(face && decoded);
      const muted = Boolean(this.mutes?.mutes(info.id, info.name, client.you));
      if (drawn) {
        const seat = seats[i];
        const entry = client.attention.get(info.id);
        // Muted: at rest, aimed at nobody (not even re-aimed at the viewer).
        const aim = muted ? null : this.targets(info.id, entry, serverSeats, viewPlaces);
        let params = this.mutes ? this.mutes.faceOf(info.id, info.name, client.you, decoded) : decoded;
        if (muted) {
          this.retarget.forget(info.id);
        } else {
          let full = decoded;  // attending nobody here: the stream's own aim
          if (aim) {
            const view = aimAt(seat, this.eyeMid, aim.view);
            const serverAim = aimAt(serverSeats.get(info.id), this.eyeMid, aim.server);
            if (aim.viewer) {
              full = reaimAtViewer(decoded, serverAim, view, this.vergence);
            } else {
              view.yaw *= TURN_SHARE;
              full = reaim(decoded, serverAim, view);
            }
          }
          params = this.retarget.params(info.id, aim ? aim.key : 'nobody', decoded, full, nowMs);
        }
        this.drawnParams.set(info.id, params);
        this.drawTile(info.id, rect, layout.nameBand, height, pixelRatio, face, params, placeOf(seat), this.tileCamera(seat, rect, layout.nameBand));
      }
      return { id: info.id, name: info.name, person: info.person, rect, drawn, muted };
    });

    // The viewer's own face, as a mirror: the package the page holds at
    // once, the decoded face once the stream brings it.
    const own = this.ownFace ?? this.faces.get(client.you);
    if (own) {
      const params = this.ownParams(serverSeats, nowMs);
      const rect = layout.self;
      const aspect = rect.w / rect.h;
      const camera = { position: [0, -0.25, 8.2 / Math.min(1, aspect)], target: [0, -0.25, 0] };
      this.drawTile('self', rect, 0, height, pixelRatio, own, params, mat4.translation([0, 0, 0]), this.camera(camera, 0.5236, aspect));
      this.selfTile = rect;
      this.selfDrawnMs ??= nowMs;
    }
    for (const id of this.drawnParams.keys()) {
      if (client.avatars.has(id)) continue;
      this.drawnParams.delete(id);
      this.retarget.forget(id);
    }
    this.frames += 1;
  }

  /**
   * The viewer's own face for the self view: as decoded, but what it aims at
   * in the server's room is moved to the camera, as a mirror would show a
   * person looking at someone on the screen: the expression stays, the face
   * does not turn away.
   */
  ownParams(serverSeats, nowMs) {
    const client = this.client;
    const decoded = client.you ? client.face(client.you, nowMs) : null;
    if (!decoded) return NEUTRAL;
    const entry = client.attention.get(client.you);
    const seat = serverSeats.get(client.you);
    const target = entry?.target === 2 ? serverSeats.get(entry.targetAvatar) : null;
    if (!seat || !target) return decoded;
    const serverAim = aimAt(seat, this.eyeMid, seatToRoom(target, this.eyeMid));
    return reaim(decoded, serverAim, { yaw: 0, pitch: 0 });
  }

  /**
   * The viewer's eyes looking at a seat's face, framing its head and the top
   * of its neck (face_frame.js) in the tile: the camera stays at the viewer's
   * eyes, so a face that looks at the viewer looks into the camera.
   */
  tileCamera(seat, rect, nameBand) {
    const eyes = seat.eyes.map((v) => v / MM_PER_UNIT);
    const frameHeight = FRAME_ABOVE_EYES + FRAME_BELOW_EYES;
    const target = [eyes[0], eyes[1] + (FRAME_ABOVE_EYES - FRAME_BELOW_EYES) / 2, eyes[2]];
    const distance = Math.hypot(...target);
    const aspect = rect.w / Math.max(1, rect.h - nameBand);
    // A tile of another shape than the frame's shows more around it, never less.
    const spanY = Math.max(frameHeight, FRAME_ACROSS / aspect);
    return this.camera({ position: [0, 0, 0], target }, 2 * Math.atan(spanY / 2 / distance), aspect);
  }

  camera({ position, target }, fovY, aspect) {
    const viewProjection = mat4.multiply(mat4.perspective(fovY, aspect, 0.5, 100), mat4.lookAt(position, target, [0, 1, 0]));
    return { viewProjection, position };
  }

  drawTile(key, rect, nameBand, height, pixelRatio, face, params, place, camera) {
    const gl = this.gl;
    // GL's origin is bottom left; the name band stays free under the face.
    const x = Math.round(rect.x * pixelRatio);
    const y = Math.round((height - rect.y - rect.h + nameBand) * pixelRatio);
    const w = Math.round(rect.w * pixelRatio);
    const h = Math.round((rect.h - nameBand) * pixelRatio);
    gl.viewport(x, y, w, h);
    gl.scissor(x, y, w, h);
    gl.enable(gl.SCISSOR_TEST);
    gl.clearColor(...BACKGROUND, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const frame = face.model.frame(params, place);
    this.renderer.draw([{ face: face.gpu, frame }], camera);
    gl.disable(gl.SCISSOR_TEST);
    const landmarks = Array.from(face.model.face.landmarkVertices, (v) => Array.from(frame.positions.subarray(3 * v, 3 * v + 3)));
    this.shown.set(key, { area: { x: rect.x, y: rect.y, w: rect.w, h: rect.h - nameBand }, viewProjection: camera.viewProjection, model: frame.model, landmarks });
  }

  /**
   * Where landmarks (the 68-point scheme) of the face a tile showed last lie
   * on the canvas, CSS pixels from its top left: for whoever inspects the
   * page (its tests find eyes and mouths this way).
   */
  landmarksOnScreen(key, indices) {
    const shown = this.shown.get(key);
    if (!shown) return null;
    const m = mat4.multiply(shown.viewProjection, shown.model);
    return indices.map((i) => {
      const [x, y, z] = shown.landmarks[i];
      const clip = [0, 1, 2, 3].map((r) => m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
      const { area } = shown;
      return [area.x + (clip[0] / clip[3] + 1) / 2 * area.w, area.y + (1 - clip[1] / clip[3]) / 2 * area.h];
    });
  }
}
