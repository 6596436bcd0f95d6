// Reading an avatar package (.fwa, avatar/photo/FORMAT.md) in the browser:
// fw::model::parse_avatar_package itself, run in WebAssembly, so a package
// the native client refuses is refused here with the same message. What it
// parsed is copied out; the C++ package stays in the module (by handle) for
// making the avatar, until release().
import { copyBytes, copyFloats, lastError, withBytesInModule } from './wasm_module.js';

/** Why a package was refused (fw::model::PackageRefusal, in its order). */
export const PackageRefusal = Object.freeze(['damaged', 'other_format_version', 'other_generic_face']);

/** A refused package: `message` says what is wrong; `refusal` is one of PackageRefusal. */
export class AvatarPackageError extends Error {
  constructor(message, refusal) {
    super(message);
    this.name = 'AvatarPackageError';
    this.refusal = refusal;
  }
  /** Sound but made for another package format or generic face: prepare it again from its photo. */
  get outOfDate() {
    return this.refusal !== 'damaged';
  }
}

// Numbers of avatar/model/wasm/package_exports.cpp.
const FLOATS = { fittedVertices: 0, landmarks: 1, headOutline: 2, closedLidRect: 3 };
const MEMBERS = ['faceTexture', 'closedLid', 'eye', 'mouth', 'colourMasksA', 'colourMasksB', 'preview'];

// The C++ copy of a package is freed when its JavaScript object is collected,
// should nobody call release().
const collector = new FinalizationRegistry(({ module, handle }) => module._fw_package_release(handle));

export class AvatarPackage {
  /** @internal use readAvatarPackage */
  constructor(module, handle) {
    this.module = module;
    this.handle = handle;
    this.version = module._fw_package_int(handle, 0);
    this.genericFaceVersion = module._fw_package_int(handle, 1);
    /** What the colour textures hold: 'photo' (its own light) or 'albedo' (a procedural face's, lit by the renderer). */
    this.textureLight = module._fw_package_int(handle, 2) === 1 ? 'albedo' : 'photo';
    const floats = (which) => copyFloats(module, module._fw_package_floats(handle, which),
      module._fw_package_floats_count(handle, which));
    /** Where each generic skin vertex lies on this face: x, y pairs, model units. */
    this.fittedVertices = floats(FLOATS.fittedVertices);
    /** The 68 landmarks (x, y pairs) in the model frame. */
    this.landmarks = floats(FLOATS.landmarks);
    /** The head's silhouette radii, one per ray of the generic head; empty for the generic outline. */
    this.headOutline = floats(FLOATS.headOutline);
    /** Where the closed-lid image lies on the face texture: u0, v0, u1, v1 (v up). */
    this.closedLidRect = floats(FLOATS.closedLidRect);
    /** sRGB 0-255. */
    this.skinTone = copyBytes(module, module._fw_package_rgb(handle, 0), 3);
    this.irisColour = copyBytes(module, module._fw_package_rgb(handle, 1), 3);
    /** Image members: { type: 'image/webp' | 'image/png', bytes: Uint8Array }; `eye` is null without an eye layer. */
    this.images = {};
    MEMBERS.forEach((name, which) => {
      const size = module._fw_package_member_size(handle, which);
      this.images[name] = size === 0 ? null : {
        type: module.UTF8ToString(module._fw_package_member_type(handle, which)),
        bytes: copyBytes(module, module._fw_package_member(handle, which), size),
      };
    });
    collector.register(this, { module, handle }, this);
  }

  /** Without an eye layer the face texture keeps the photo's eyes (non-masking mode). */
  get hasEyeLayer() {
    return this.images.eye !== null;
  }

  /** Frees the C++ copy (the avatar made from it keeps its own). */
  release() {
    if (!this.handle) return;
    collector.unregister(this);
    this.module._fw_package_release(this.handle);
    this.handle = 0;
  }
}

/**
 * Parses and validates a package.
 * @param module  the started WebAssembly model (wasm_module.js)
 * @param {ArrayBuffer|Uint8Array} bytes  the .fwa file
 * @throws {AvatarPackageError} with the native reader's message ("bad avatar package: ...")
 */
export function readAvatarPackage(module, bytes) {
  const view = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  const handle = withBytesInModule(module, view, (pointer) => module._fw_package_parse(pointer, view.length));
  if (handle === 0) {
    throw new AvatarPackageError(lastError(module), PackageRefusal[module._fw_last_refusal()] ?? 'damaged');
  }
  return new AvatarPackage(module, handle);
}
