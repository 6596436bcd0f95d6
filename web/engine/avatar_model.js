// One avatar as the renderer needs it: fw::model::make_avatar_model (the
// generic face fitted to the person, action units motion-cloned onto the
// fit) and, every frame, fw::model::reconstruct_face (the skin's positions
// and texture coordinates for FaceParams) with the normals the renderer
// derives from them, run in WebAssembly: the same code as the native client.
import { faceDraw } from './face_draw.js';
import { FACE_PARAMS_FLOATS, faceParamsFloats } from './face_params_floats.js';
import { copyFloats, copyUint32, lastError } from './wasm_module.js';

// Numbers of avatar/model/wasm/avatar_exports.cpp.
const PART = { skin: 0, eyeRight: 1, eyeLeft: 2, mouthCavity: 3, head: 4, eyeSocketRight: 5, eyeSocketLeft: 6 };
const MESH_FIELD = { positions: 0, uvs: 1, normals: 3, photoLightNormals: 4 };
const FLOATS = { textureFrame: 0, eyeCentres: 1, eyeShapes: 2, headCentre: 3, headOutline: 4 };
const INDICES = { landmarkVertices: 0, eyeHoleRight: 1, eyeHoleLeft: 2, mouthSlit: 3, triangleRegions: 4 };

// The module's copy is freed when the JavaScript object is collected, should
// nobody call release().
const collector = new FinalizationRegistry(({ module, handle, paramsPointer }) => {
  module._fw_avatar_release(handle);
  module._free(paramsPointer);
});

function readMesh(module, handle, part) {
  const floats = (field) => copyFloats(module, module._fw_avatar_mesh_floats(handle, part, field),
    module._fw_avatar_mesh_floats_count(handle, part, field));
  return {
    positions: floats(MESH_FIELD.positions),  // x, y, z per vertex, model units
    uvs: floats(MESH_FIELD.uvs),              // u, v per vertex, v up
    normals: floats(MESH_FIELD.normals),      // at rest
    // Under which the photo saw each vertex's colour (the shader's rest
    // normals): the normals at rest but on the head's back (head_back.hpp).
    photoLightNormals: floats(MESH_FIELD.photoLightNormals),
    triangles: copyUint32(module, module._fw_avatar_triangles(handle, part),
      module._fw_avatar_triangles_count(handle, part)),
  };
}

// The fitted face, shaped like the asset (avatar/model/README.md) but with
// flat typed arrays, ready for WebGL buffers.
function readFace(module, handle) {
  const floats = (which) => Array.from(copyFloats(module, module._fw_avatar_floats(handle, which),
    module._fw_avatar_floats_count(handle, which)));
  const indices = (which) => copyUint32(module, module._fw_avatar_indices(handle, which),
    module._fw_avatar_indices_count(handle, which));
  const [originX, originY, size] = floats(FLOATS.textureFrame);
  const centres = floats(FLOATS.eyeCentres);
  const shapes = floats(FLOATS.eyeShapes);
  const eye = (side, part, socketPart) => ({
    centre: centres.slice(side * 3, side * 3 + 3),
    radius: shapes[side * 2],
    capAngleRad: shapes[side * 2 + 1],
    mesh: readMesh(module, handle, part),
    socket: readMesh(module, handle, socketPart),  // fw/model/eye_socket.hpp: its far wall, seen through the hole
  });
  return {
    textureFrame: { origin: [originX, originY], size },
    skin: readMesh(module, handle, PART.skin),
    triangleRegions: indices(INDICES.triangleRegions),  // index into the asset's "regions"
    landmarkVertices: indices(INDICES.landmarkVertices),
    eyeHoles: [indices(INDICES.eyeHoleRight), indices(INDICES.eyeHoleLeft)],  // [right, left]
    mouthSlit: indices(INDICES.mouthSlit),
    eyes: [eye(0, PART.eyeRight, PART.eyeSocketRight), eye(1, PART.eyeLeft, PART.eyeSocketLeft)],  // [right, left]
    mouthCavity: readMesh(module, handle, PART.mouthCavity),
    head: {
      centre: floats(FLOATS.headCentre),
      outline: floats(FLOATS.headOutline),
      mesh: readMesh(module, handle, PART.head),
    },
  };
}

/** Calls `use(pointer)` with `ints` copied into the module's memory as int32s, freed after. */
function withInts(module, ints, use) {
  const pointer = module._malloc(ints.length * 4);
  try {
    module.HEAP32.set(Int32Array.from(ints), pointer >>> 2);
    use(pointer);
  } finally {
    module._free(pointer);
  }
}

export class AvatarModel {
  /** @internal use Engine.avatarFromPackage or Engine.genericAvatar */
  constructor(module, handle) {
    if (!handle) throw new Error(`the avatar could not be made: ${lastError(module)}`);
    this.module = module;
    this.handle = handle;
    /** The fitted face's meshes and layers (static; the skin's shape changes per frame). */
    this.face = readFace(module, handle);
    this.vertexCount = this.face.skin.positions.length / 3;
    const v = this.vertexCount;
    // Reused every frame: the renderer uploads them and asks for the next.
    this.shape = { positions: new Float32Array(3 * v), uvs: new Float32Array(2 * v), normals: new Float32Array(3 * v) };
    this.paramsPointer = module._malloc(FACE_PARAMS_FLOATS * 4);
    this.paramsFloats = new Float32Array(FACE_PARAMS_FLOATS);
    collector.register(this, { module, handle, paramsPointer: this.paramsPointer }, this);
  }

  /** An action-unit channel's morph as cloned onto this face: { vertexDelta (3V), uvDelta (2V) }. */
  morph(channel) {
    const v = this.vertexCount;
    return {
      vertexDelta: copyFloats(this.module, this.module._fw_avatar_morph(this.handle, channel, 0), 3 * v),
      uvDelta: copyFloats(this.module, this.module._fw_avatar_morph(this.handle, channel, 1), 2 * v),
    };
  }

  /**
   * Redefines action units (server/PROTOCOL.md 5.17): `units` as a unit
   * morphs message carries them ([{ channel, moves: [{ vertex, delta: [dx, dy,
   * dz] }] }], web/protocol's reader), carried onto this face by
   * fw::model::set_unit_morphs; every other unit is the shipped one again, so
   * [] restores the shipped face. Frames after it use them.
   */
  setUnitMorphs(units) {
    this.ensureAlive();
    const ints = [units.length];
    for (const unit of units) {
      ints.push(unit.channel, unit.moves.length);
      for (const move of unit.moves) ints.push(move.vertex, move.delta[0], move.delta[1], move.delta[2]);
    }
    withInts(this.module, ints, (pointer) => {
      if (!this.module._fw_avatar_set_unit_morphs(this.handle, pointer, ints.length))
        throw new Error(`the redefined units could not be set: ${lastError(this.module)}`);
    });
  }

  /**
   * A face-lab preview's simulated skin beyond its action units
   * (server/PROTOCOL.md 5.18): `moves` as a preview surface message carries
   * them ([{ vertex, delta: [dx, dy, dz] }], generic vertices in the wire's
   * steps), carried onto this face as the units are
   * (fw::model::carried_surface) and added to every frame after it; []
   * clears it.
   */
  setSurface(moves) {
    this.ensureAlive();
    const ints = [moves.length];
    for (const move of moves) ints.push(move.vertex, move.delta[0], move.delta[1], move.delta[2]);
    withInts(this.module, ints, (pointer) => {
      if (!this.module._fw_avatar_set_surface(this.handle, pointer, ints.length))
        throw new Error(`the preview surface could not be set: ${lastError(this.module)}`);
    });
  }

  /**
   * The skin's shape for FaceParams `params`: positions (3V, model units, the
   * generic mesh's vertex order), uvs (2V) and normals (3V). The arrays are
   * this avatar's own and are overwritten by the next call.
   */
  skinShape(params) {
    this.ensureAlive();
    const m = this.module;
    m.HEAPF32.set(faceParamsFloats(params, this.paramsFloats), this.paramsPointer >>> 2);
    const pointer = m._fw_avatar_frame(this.handle, this.paramsPointer);
    const v = this.vertexCount;
    const at = pointer >>> 2;
    this.shape.positions.set(m.HEAPF32.subarray(at, at + 3 * v));
    this.shape.uvs.set(m.HEAPF32.subarray(at + 3 * v, at + 5 * v));
    this.shape.normals.set(m.HEAPF32.subarray(at + 5 * v, at + 8 * v));
    return this.shape;
  }

  /**
   * Everything the renderer needs for one frame: the skin's shape (skinShape)
   * and the draw values (face_draw.js: model and eye matrices, lids, blood).
   * @param params  FaceParams (decoder field names)
   * @param [place]  the seat's model matrix; identity if left out
   */
  frame(params, place) {
    return { ...this.skinShape(params), ...faceDraw(params, this.face.eyes.map((e) => e.centre), place) };
  }

  ensureAlive() {
    if (!this.handle) throw new Error('this avatar was released');
  }

  /** Frees the avatar in the module; it cannot be used afterwards. */
  release() {
    if (!this.handle) return;
    collector.unregister(this);
    this.module._fw_avatar_release(this.handle);
    this.module._free(this.paramsPointer);
    this.handle = 0;
  }
}
