#include "exports_state.hpp"

#include <emscripten/emscripten.h>

namespace {
std::string last_error;
}

void fw::wasm::set_error(std::string message) { last_error = std::move(message); }

extern "C" EMSCRIPTEN_KEEPALIVE const char* fw_last_error() { return last_error.c_str(); }
