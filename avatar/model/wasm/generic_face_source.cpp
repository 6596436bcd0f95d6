// The generic face asset for the WebAssembly build. Natively the asset is
// compiled into the binary (fw_embed_file); here it comes from JavaScript,
// which fetched the very file the renderer reads (/generic_face.json): the
// page downloads it once, and the engine can never fit avatars to another
// face than the one drawn. The module's creator passes the text as
// `genericFaceJson`; it is copied in while the module starts, before any
// code can ask for generic_face().
#include <cstddef>
#include <string>
#include <string_view>

#include <emscripten/emscripten.h>

#include "exports_state.hpp"
#include "fw/model/face_asset.hpp"
#include "fw/model/generic_face.hpp"

// clang-format off
EM_JS(int, fw_asset_length, (), {
  const text = Module['genericFaceJson'];
  return typeof text === 'string' ? lengthBytesUTF8(text) : 0;
});
EM_JS(void, fw_asset_copy, (char* into, int size), {
  stringToUTF8(Module['genericFaceJson'], into, size + 1);
});
// clang-format on

namespace {

const std::string& asset_text() {
  static const std::string text = [] {
    std::string s(static_cast<std::size_t>(fw_asset_length()), '\0');
    // stringToUTF8 writes a terminating NUL: std::string keeps room for it.
    if (!s.empty()) fw_asset_copy(s.data(), static_cast<int>(s.size()));
    return s;
  }();
  return text;
}

}  // namespace

namespace fw::embedded {
extern const std::string_view generic_face_json;
const std::string_view generic_face_json = asset_text();
}  // namespace fw::embedded

extern "C" {

/// Checks the asset before anything relies on it: generic_face() aborts on
/// a bad one (natively that is a broken build; here, a bad download).
/// @return the generic face's version, or 0 and fw_last_error()
EMSCRIPTEN_KEEPALIVE int fw_model_init() {
  fw::model::GenericFace face;
  std::string error;
  if (fw::embedded::generic_face_json.empty()) {
    fw::wasm::set_error("no generic face asset was given (genericFaceJson)");
    return 0;
  }
  if (!fw::model::parse_face_asset(fw::embedded::generic_face_json, face, error)) {
    fw::wasm::set_error("the generic face asset is unusable: " + error);
    return 0;
  }
  return fw::model::generic_face().version;
}

}
