// Starting the WebAssembly model (avatar/model compiled by emscripten, built
// into <build>/web/engine/facewire_model.js and .wasm, served beside this
// file) and copying arrays out of its memory.
//
// Copies, not views: the module's memory grows when a room fills up, and a
// view of the old memory would then read nothing.

const DEFAULT_MODULE_URL = new URL('./facewire_model.js', import.meta.url).href;

/**
 * Starts the module.
 * @param {object} options
 * @param {string} options.genericFaceJson  the text of /generic_face.json (the face the renderer draws)
 * @param {string} [options.moduleUrl]      where facewire_model.js is (default: beside this file)
 * @param {ArrayBuffer|Uint8Array} [options.wasmBinary]  the .wasm bytes, when not fetched beside the module
 */
export async function startWasmModule({ genericFaceJson, moduleUrl = DEFAULT_MODULE_URL, wasmBinary } = {}) {
  if (typeof genericFaceJson !== 'string' || genericFaceJson.length === 0) {
    throw new Error('the engine needs the generic face asset (the text of /generic_face.json)');
  }
  const { default: createFacewireModel } = await import(moduleUrl);
  const options = { genericFaceJson };
  if (wasmBinary) options.wasmBinary = wasmBinary;
  const module = await createFacewireModel(options);
  const version = module._fw_model_init();
  if (version === 0) throw new Error(module.UTF8ToString(module._fw_last_error()));
  return { module, genericFaceVersion: version };
}

/** The last error of the module's C functions. */
export const lastError = (module) => module.UTF8ToString(module._fw_last_error());

export function copyFloats(module, pointer, count) {
  if (!pointer) return new Float32Array(0);
  return module.HEAPF32.slice(pointer >>> 2, (pointer >>> 2) + count);
}

export function copyUint32(module, pointer, count) {
  if (!pointer) return new Uint32Array(0);
  return module.HEAPU32.slice(pointer >>> 2, (pointer >>> 2) + count);
}

export function copyBytes(module, pointer, count) {
  if (!pointer) return new Uint8Array(0);
  return module.HEAPU8.slice(pointer, pointer + count);
}

/** Runs `use(pointer)` with `bytes` copied into the module's memory, freed afterwards. */
export function withBytesInModule(module, bytes, use) {
  const pointer = module._malloc(Math.max(1, bytes.length));
  try {
    module.HEAPU8.set(bytes, pointer);
    return use(pointer);
  } finally {
    module._free(pointer);
  }
}
