// The browser's engine: the avatar package reader, the avatar model (fit and
// motion cloning) and face reconstruction of avatar/model, compiled to
// WebAssembly, behind a small API (web/engine/README.md). The FaceParams
// stream itself is decoded by web/codec/decoder.js.
import { AvatarModel } from './avatar_model.js';
import { readAvatarPackage } from './avatar_package.js';
import { startWasmModule } from './wasm_module.js';

export { AvatarPackageError, PackageRefusal } from './avatar_package.js';
export { faceDraw } from './face_draw.js';
export { eyeTransform, headTransform } from './head_pose.js';

export class Engine {
  /** @internal use loadEngine */
  constructor(module, genericFaceVersion) {
    this.module = module;
    /** The generic face's version (avatar/model); packages for another are refused. */
    this.genericFaceVersion = genericFaceVersion;
  }

  /** Parses a .fwa; throws AvatarPackageError with what is wrong. */
  readPackage(bytes) {
    return readAvatarPackage(this.module, bytes);
  }

  /** The person's avatar: the generic face fitted by the package, its action units cloned onto the fit. */
  avatarFromPackage(avatarPackage) {
    if (!avatarPackage?.handle) throw new Error('the package was released or is not one (use readPackage)');
    return new AvatarModel(this.module, this.module._fw_avatar_from_package(avatarPackage.handle));
  }

  /** The generic face itself, for avatars without a package. */
  genericAvatar() {
    return new AvatarModel(this.module, this.module._fw_avatar_generic());
  }
}

/**
 * Starts the engine.
 * @param {object} options
 * @param {string} options.genericFaceJson  the text of /generic_face.json
 * @param {string} [options.moduleUrl]  facewire_model.js, if not beside this file
 * @param {ArrayBuffer|Uint8Array} [options.wasmBinary]  facewire_model.wasm's bytes, if not fetched
 */
export async function loadEngine(options) {
  const { module, genericFaceVersion } = await startWasmModule(options);
  return new Engine(module, genericFaceVersion);
}

/** loadEngine with the generic face fetched from the server that served this page. */
export async function loadEngineFromServer(genericFaceUrl = '/generic_face.json') {
  const response = await fetch(genericFaceUrl);
  if (!response.ok) throw new Error(`${genericFaceUrl}: HTTP ${response.status}`);
  return loadEngine({ genericFaceJson: await response.text() });
}
