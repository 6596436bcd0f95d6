#pragma once
// Messages with every field set, for tests that need a typical one rather
// than a particular one: the codec's round trips, its golden vectors (which
// the browser's reader decodes too), and the fuzz targets' seeds.
#include <string>
#include <utility>

#include "fw/codec/messages.hpp"

namespace fw::test {

/// A hello with every field set, a name outside ASCII among them.
inline codec::Hello sample_hello() {
  codec::Hello hello;
  hello.room = "lobby";
  hello.name = "Zoë";
  hello.avatar = "0123456789abcdef0123456789abcdef";
  hello.token = "fw1.e30.sig";
  hello.max_bps = 9600;
  hello.timestamps = true;
  hello.own_package = true;
  hello.avatar_key = "k3y-_AZaz09k3y-_AZaz09";
  hello.resume = "r-e_sume0123456789abcd";
  hello.language = "pt-br";
  return hello;
}

/// The same hello as a version-3 client sends it: no language.
inline codec::Hello sample_hello_v3() {
  codec::Hello hello = sample_hello();
  hello.protocol_version = 3;
  hello.language.clear();
  return hello;
}

/// A speaking message with every field set, its text outside ASCII.
inline codec::Speaking sample_speaking() {
  return {.avatar = 300, .tick = 70000, .duration_ms = 2140, .language = "de", .text = "Grüß Gott, wie geht's?"};
}

/// A face script as a person sends it (PROTOCOL.md 5.5, a FACS command).
inline codec::Command facs_command(std::uint32_t request_id, std::string sentence) {
  codec::Command command;
  command.request_id = request_id;
  command.kind = codec::Command::Kind::facs;
  command.sentence = std::move(sentence);
  return command;
}

/// A unit morphs message: a bilateral unit's two channels and a unit that
/// moves nothing, displacements of both signs and the extremes.
inline codec::UnitMorphs sample_unit_morphs() {
  return {.avatar = 300,
          .version = 3,
          .units = {{.channel = 0, .moves = {{12, {0, 410, -3}}, {140, {-32768, 32767, 1}}}},
                    {.channel = 1, .moves = {{13, {5, 409, 0}}}},
                    {.channel = 20, .moves = {}}}};
}

/// A preview surface: moves of both signs and the extremes, the last vertex
/// the highest a message may name.
inline codec::PreviewSurface sample_preview_surface() {
  return {.avatar = 1, .moves = {{0, {3, -2, 0}}, {54, {-32768, 32767, 120}}, {1023, {0, 0, 1}}}};
}

}  // namespace fw::test
