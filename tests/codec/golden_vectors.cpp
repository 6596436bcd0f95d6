#include "golden_vectors.hpp"

#include <algorithm>
#include <cstdio>

#include "synthetic_correctives.hpp"
#include "synthetic_scene.hpp"

namespace fw::codec::vectors {
namespace {

const char* const kErrorNames[] = {"ok",
                                   "empty_frame",
                                   "unsupported_version",
                                   "unknown_frame_type",
                                   "wrong_frame_type",
                                   "bad_magic",
                                   "unsupported_schema",
                                   "channel_table_mismatch",
                                   "bad_stream_options",
                                   "truncated",
                                   "awaiting_key_frame",
                                   "sequence_gap",
                                   "stale_frame",
                                   "value_out_of_range",
                                   "check_failed",
                                   "too_many_avatars",
                                   "duplicate_avatar",
                                   "frame_too_large",
                                   "trailing_bytes"};

// The faces of `avatar` of the synthetic scene from tick `first`, `count` ticks.
std::vector<FaceParams> window(const bench::Scene& scene, std::size_t avatar, std::size_t first, std::size_t count) {
  const auto& ticks = scene.avatars[avatar].ticks;
  return {ticks.begin() + static_cast<std::ptrdiff_t>(first), ticks.begin() + static_cast<std::ptrdiff_t>(first + count)};
}

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

std::string hex(const std::vector<std::uint8_t>& bytes) {
  std::string s;
  char buf[3];
  for (std::uint8_t b : bytes) {
    std::snprintf(buf, sizeof buf, "%02x", b);
    s += buf;
  }
  return s;
}

// Float with enough digits to come back as the same float32.
double exact(float f) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(f));
  return std::strtod(buf, nullptr);
}

}  // namespace

std::string error_name(DecodeError error) {
  const auto i = static_cast<std::size_t>(error);
  return i < std::size(kErrorNames) ? kErrorNames[i] : "unknown";
}

std::vector<VectorSpec> vector_specs() {
  bench::SyntheticSceneOptions scene_options;
  scene_options.seed = 7;
  scene_options.active_avatars = 3;
  scene_options.idle_avatars = 1;
  scene_options.seconds = 12;
  bench::Scene scene = bench::make_synthetic_scene(scene_options);
  bench::add_synthetic_correctives(scene, scene_options.seed);  // format version 2: correctives that move

  std::vector<VectorSpec> specs;
  {
    VectorSpec s;
    s.name = "avatar_basic";
    s.description = "One avatar over a reliable transport with a generous budget: a key frame, then predicted "
                    "frames of every group, partners, damped and linear velocities, skipped ticks, finer levels.";
    s.options.target_bps = 3000;
    s.options.min_level = 0;
    s.inputs = {window(scene, 0, 30, 150)};
    specs.push_back(s);
  }
  {
    VectorSpec s;
    s.name = "avatar_rate_change";
    s.description = "The budget falls from 1500 to 200 bit/s at tick 60 and comes back to 800 at tick 150: level "
                    "changes, frames reduced to their most urgent channels, skipped ticks.";
    s.options.target_bps = 1500;
    s.options.min_level = 0;
    s.inputs = {window(scene, 1, 0, 210)};
    s.target_changes = {{60, 200.0}, {150, 800.0}};
    specs.push_back(s);
  }
  {
    VectorSpec s;
    s.name = "avatar_loss_tolerant";
    s.description = "A loss-tolerant stream: sequence numbers, heartbeats, periodic key frames; the transport "
                    "loses frames 6 and 20 and delivers frame 12 twice; the decoder asks for a key frame after "
                    "each gap (heard 4 ticks later) and refuses predicted frames until it arrives.";
    s.options.target_bps = 900;
    s.options.stream.loss_tolerant = true;
    s.options.stream.max_extrapolation_ticks = 15;
    s.options.max_key_interval_ticks = 120;
    s.inputs = {window(scene, 2, 60, 240)};
    s.dropped_frames = {6, 20};
    s.duplicated_frames = {12};
    s.resync = true;
    s.resync_delay_ticks = 4;
    specs.push_back(s);
  }
  {
    VectorSpec s;
    s.name = "room";
    s.description = "Room frames of three avatars (one idle); the third joins at tick 40 with a key frame.";
    s.room = true;
    s.options.target_bps = 600;
    s.options.container_bytes_per_frame = 2;
    s.inputs = {window(scene, 0, 200, 120), window(scene, 1, 200, 120), window(scene, 3, 200, 120)};
    s.joins_at = {0, 0, 40};
    specs.push_back(s);
  }
  return specs;
}

std::vector<Message> encode_vector(const VectorSpec& spec) {
  std::vector<Message> messages;
  messages.push_back({0, write_stream_header(spec.options.stream)});
  const std::size_t avatars = spec.inputs.size();
  const auto ticks = static_cast<int>(spec.inputs.front().size());
  std::vector<Encoder> encoders;
  for (std::size_t a = 0; a < avatars; ++a) encoders.emplace_back(spec.options);
  Decoder decoder(spec.options.stream);
  RoomDecoder room_decoder(spec.options.stream);
  int frame_index = 0;
  // Resync requests on their way: (tick the encoder hears it, avatar).
  std::vector<std::pair<int, std::uint32_t>> resync;
  std::vector<std::uint8_t> frame;
  std::vector<std::vector<std::uint8_t>> frames(avatars);
  for (int t = 0; t < ticks; ++t) {
    if (const auto it = spec.target_changes.find(t); it != spec.target_changes.end())
      for (Encoder& e : encoders) e.set_target_bps(it->second);
    for (const auto& [when, id] : resync)
      if (when == t) encoders[id].force_key_frame();
    std::vector<RoomEntry> entries;
    std::vector<std::uint8_t> message;
    for (std::size_t a = 0; a < avatars; ++a) {
      frames[a].clear();
      const int join = spec.joins_at.empty() ? 0 : spec.joins_at[a];
      if (t < join) continue;
      if (encoders[a].encode(spec.inputs[a][static_cast<std::size_t>(t)], frames[a]))
        entries.push_back({static_cast<std::uint32_t>(a), frames[a]});
    }
    if (entries.empty()) continue;
    if (spec.room) {
      write_room_frame(entries, message);
    } else {
      message = frames[0];
    }
    const int index = frame_index++;
    if (!contains(spec.dropped_frames, index)) {
      messages.push_back({t, message});
      if (contains(spec.duplicated_frames, index)) messages.push_back({t, message});
    }
    // The client side, to learn when it would send a resync request (one
    // per lost sync: the decoder asks again only once the key frame came).
    if (!spec.resync) continue;
    for (std::size_t m = messages.size(); m-- > 1 && messages[m].tick == t;) {
      if (spec.room) {
        room_decoder.decode(messages[m].bytes);
      } else {
        decoder.decode(messages[m].bytes);
      }
    }
    std::vector<std::uint32_t> asking;
    if (spec.room) {
      asking = room_decoder.needing_key_frames();
    } else if (decoder.needs_key_frame()) {
      asking = {0};
    }
    for (const std::uint32_t id : asking) {
      const bool pending = std::any_of(resync.begin(), resync.end(), [&](const auto& r) { return r.second == id && r.first > t; });
      if (!pending) resync.emplace_back(t + spec.resync_delay_ticks, id);
    }
  }
  return messages;
}

Decoded decode_vector(const VectorSpec& spec, const std::vector<Message>& messages) {
  Decoded out;
  const std::size_t avatars = spec.inputs.size();
  const auto ticks = static_cast<int>(spec.inputs.front().size());
  StreamOptions options;
  out.errors.push_back({error_name(read_stream_header(messages.front().bytes, options))});
  Decoder decoder(options);
  RoomDecoder room_decoder(options);
  std::vector<int> last_ok(avatars, -1);
  std::size_t m = 1;
  for (int t = 0; t < ticks; ++t) {
    for (; m < messages.size() && messages[m].tick == t; ++m) {
      std::vector<std::string> errors;
      if (spec.room) {
        const auto result = room_decoder.decode(messages[m].bytes);
        if (result.error != DecodeError::ok) errors.push_back(error_name(result.error));
        for (const auto& [id, error] : result.avatars) {
          errors.push_back(error_name(error));
          if (error == DecodeError::ok && id < avatars) last_ok[id] = t;
        }
      } else {
        const DecodeError error = decoder.decode(messages[m].bytes);
        errors.push_back(error_name(error));
        if (error == DecodeError::ok) last_ok[0] = t;
      }
      out.errors.push_back(errors);
    }
    std::vector<QuantisedParams> shown(avatars);
    for (std::size_t a = 0; a < avatars; ++a) {
      const Decoder* d = spec.room ? room_decoder.avatar(static_cast<std::uint32_t>(a)) : &decoder;
      const auto after = static_cast<std::uint32_t>(last_ok[a] < 0 ? 0 : t - last_ok[a]);
      shown[a] = d ? d->quantised(after) : QuantisedParams{};
    }
    if (t == ticks - 1)
      for (const auto& q : shown) out.final_faces.push_back(dequantise(q));
    out.shown.push_back(std::move(shown));
  }
  return out;
}

nlohmann::json to_json(const VectorSpec& spec, const std::vector<Message>& messages, const Decoded& decoded) {
  nlohmann::json j;
  j["name"] = spec.name;
  j["description"] = spec.description;
  j["format_version"] = kFormatVersion;
  j["schema"] = kFaceParamsSchema;
  j["stream_file"] = spec.name + ".fwc";
  j["input_file"] = spec.name + ".fwscene";
  j["kind"] = spec.room ? "room" : "avatar";
  j["avatars"] = spec.inputs.size();
  j["ticks"] = spec.inputs.front().size();
  const EncoderOptions& o = spec.options;
  j["encoder"] = {{"target_bps", o.target_bps},
                  {"container_bytes_per_frame", o.container_bytes_per_frame},
                  {"min_level", o.min_level},
                  {"max_level", o.max_level},
                  {"max_key_interval_ticks", o.max_key_interval_ticks},
                  {"heartbeat_ticks", o.heartbeat_ticks},
                  {"visible_error", "default"},
                  {"loss_tolerant", o.stream.loss_tolerant},
                  {"tick_rate_hz", o.stream.tick_rate_hz},
                  {"max_extrapolation_ticks", o.stream.max_extrapolation_ticks}};
  j["joins_at"] = spec.joins_at;
  nlohmann::json changes = nlohmann::json::object();
  for (const auto& [tick, bps] : spec.target_changes) changes[std::to_string(tick)] = bps;
  j["target_changes"] = changes;
  j["dropped_frames"] = spec.dropped_frames;
  j["duplicated_frames"] = spec.duplicated_frames;
  j["resync"] = spec.resync;
  j["resync_delay_ticks"] = spec.resync_delay_ticks;
  j["how_to_decode"] =
      "Message 0 is the stream header. Deliver each message at its tick to a Decoder (kind avatar) or a "
      "RoomDecoder (kind room); errors lists what each gave (a room frame: its own error if not ok, then one per "
      "entry). shown[t][a] is avatar a's Decoder::quantised(t - tick of its last frame decoded without error), "
      "or zeros before its first; final_faces are the last tick's values as float32.";
  nlohmann::json ms = nlohmann::json::array();
  for (std::size_t i = 0; i < messages.size(); ++i)
    ms.push_back({{"tick", messages[i].tick}, {"bytes", messages[i].bytes.size()}, {"errors", decoded.errors[i]}});
  j["messages"] = ms;
  nlohmann::json shown = nlohmann::json::array();
  for (const auto& tick : decoded.shown) {
    nlohmann::json row = nlohmann::json::array();
    for (const auto& q : tick) row.push_back(q);
    shown.push_back(row);
  }
  j["shown"] = shown;
  nlohmann::json faces = nlohmann::json::array();
  for (const FaceParams& f : decoded.final_faces) {
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t c = 0; c < kChannelCount; ++c) row.push_back(exact(channel_value(f, c)));
    faces.push_back(row);
  }
  j["final_faces"] = faces;
  return j;
}

std::vector<std::uint8_t> to_stream_file(const std::vector<Message>& messages) {
  std::vector<std::uint8_t> out;
  for (const Message& m : messages) {
    std::size_t n = m.bytes.size();
    while (n >= 0x80) {
      out.push_back(static_cast<std::uint8_t>((n & 0x7F) | 0x80));
      n >>= 7;
    }
    out.push_back(static_cast<std::uint8_t>(n));
    out.insert(out.end(), m.bytes.begin(), m.bytes.end());
  }
  return out;
}

bool from_stream_file(const std::vector<std::uint8_t>& file, std::vector<std::vector<std::uint8_t>>& messages) {
  messages.clear();
  std::size_t i = 0;
  while (i < file.size()) {
    std::size_t n = 0;
    for (int shift = 0;; shift += 7) {
      if (i >= file.size() || shift > 21) return false;
      const std::uint8_t b = file[i++];
      n |= static_cast<std::size_t>(b & 0x7F) << shift;
      if ((b & 0x80) == 0) break;
    }
    if (n > file.size() - i) return false;
    messages.emplace_back(file.begin() + static_cast<std::ptrdiff_t>(i), file.begin() + static_cast<std::ptrdiff_t>(i + n));
    i += n;
  }
  return true;
}

nlohmann::json error_cases() {
  // Real frames to corrupt: a reliable and a loss-tolerant stream of one avatar.
  bench::SyntheticSceneOptions scene_options;
  scene_options.seed = 7;
  scene_options.active_avatars = 1;
  scene_options.idle_avatars = 0;
  scene_options.seconds = 4;
  bench::Scene scene = bench::make_synthetic_scene(scene_options);
  bench::add_synthetic_correctives(scene, scene_options.seed);  // format version 2: correctives that move
  auto frames_of = [&](bool loss_tolerant) {
    EncoderOptions o;
    o.target_bps = 4000;
    o.stream.loss_tolerant = loss_tolerant;
    Encoder encoder(o);
    std::vector<std::vector<std::uint8_t>> frames;
    std::vector<std::uint8_t> f;
    for (const FaceParams& p : scene.avatars[0].ticks)
      if (encoder.encode(p, f)) frames.push_back(f);
    return frames;
  };
  const auto reliable = frames_of(false);
  const auto lossy = frames_of(true);
  const std::vector<std::uint8_t>& key = reliable.at(0);
  const std::vector<std::uint8_t>& predicted = reliable.at(3);

  nlohmann::json cases = nlohmann::json::array();
  // A frame for an avatar Decoder, after `setup` frames.
  auto frame_case = [&](const std::string& what, bool loss_tolerant, const std::vector<std::vector<std::uint8_t>>& setup,
                        const std::vector<std::uint8_t>& bytes) {
    StreamOptions options;
    options.loss_tolerant = loss_tolerant;
    Decoder d(options);
    nlohmann::json hs = nlohmann::json::array();
    for (const auto& s : setup) {
      d.decode(s);
      hs.push_back(hex(s));
    }
    const DecodeError e = d.decode(bytes);
    cases.push_back({{"what", what}, {"kind", "frame"}, {"loss_tolerant", loss_tolerant}, {"setup", hs},
                     {"hex", hex(bytes)}, {"error", error_name(e)}, {"needs_key_frame_after", d.needs_key_frame()}});
  };
  auto with = [](std::vector<std::uint8_t> v, std::size_t i, std::uint8_t b) {
    v.at(i) = b;
    return v;
  };
  auto cut = [](std::vector<std::uint8_t> v, std::size_t n) {
    v.resize(v.size() - n);
    return v;
  };
  frame_case("a key frame", false, {}, key);
  frame_case("a predicted frame after its key frame and the frames between", false,
             {reliable[0], reliable[1], reliable[2]}, predicted);
  frame_case("an empty frame", false, {}, {});
  frame_case("a frame of format version 2", false, {}, with(key, 0, 0x21));
  frame_case("frame type 15", false, {}, with(key, 0, 0x2F));
  frame_case("a room frame given to an avatar decoder", false, {}, with(key, 0, 0x23));
  frame_case("a predicted frame before any key frame", false, {}, predicted);
  frame_case("a key frame without its last byte", false, {}, cut(key, 1));
  frame_case("a key frame without its last two bytes", false, {}, cut(key, 2));
  frame_case("a key frame with a bit flipped in its first coded byte", false, {}, with(key, 1, key[1] ^ 0x10));
  frame_case("a key frame whose code starts with four 0xFF bytes", false, {}, {0x21, 0xFF, 0xFF, 0xFF, 0xFF});
  frame_case("a frame of 1025 bytes", false, {}, std::vector<std::uint8_t>(1025, 0x21));
  frame_case("loss-tolerant: a frame without its sequence number", true, {}, {0x21});
  frame_case("loss-tolerant: a key frame", true, {}, lossy.at(0));
  frame_case("loss-tolerant: the next frame", true, {lossy.at(0)}, lossy.at(1));
  frame_case("loss-tolerant: a frame after a lost one", true, {lossy.at(0)}, lossy.at(2));
  frame_case("loss-tolerant: a predicted frame while waiting for a key frame", true, {lossy.at(0), lossy.at(2)},
             lossy.at(3));
  frame_case("loss-tolerant: a duplicate", true, {lossy.at(0), lossy.at(1)}, lossy.at(1));

  auto header_case = [&](const std::string& what, const std::vector<std::uint8_t>& bytes) {
    StreamOptions options;
    cases.push_back({{"what", what}, {"kind", "stream_header"}, {"hex", hex(bytes)},
                     {"error", error_name(read_stream_header(bytes, options))}});
  };
  const auto header = write_stream_header({});
  header_case("a stream header", header);
  header_case("a loss-tolerant stream header", write_stream_header({true, 30, 15}));
  header_case("an empty stream header", {});
  header_case("a stream header cut after its magic", std::vector<std::uint8_t>(header.begin(), header.begin() + 5));
  header_case("a stream header cut in its channel table", cut(header, 3));
  header_case("a stream header with bad magic", with(header, 1, 'X'));
  header_case("a stream header of schema 2", with(header, 5, 2));
  header_case("a stream header with an unknown flag", with(header, 7, 0x02));
  header_case("a stream header with tick rate 0", with(header, 8, 0));
  header_case("a stream header with 46 channels", with(header, 10, 46));
  header_case("a stream header with another AU step", with(header, 11 + 5, header[11 + 5] ^ 0x01));
  auto longer = header;
  longer.push_back(0);
  header_case("a stream header with a byte too many", longer);
  header_case("a key frame given as a stream header", key);

  auto room_case = [&](const std::string& what, const std::vector<std::uint8_t>& bytes) {
    std::vector<RoomEntry> entries;
    const DecodeError e = read_room_frame(bytes, entries);
    nlohmann::json ids = nlohmann::json::array();
    for (const RoomEntry& entry : entries) ids.push_back({entry.avatar_id, entry.frame.size()});
    cases.push_back({{"what", what}, {"kind", "room"}, {"hex", hex(bytes)}, {"error", error_name(e)},
                     {"entries", e == DecodeError::ok ? ids : nlohmann::json::array()}});
  };
  std::vector<std::uint8_t> room;
  const RoomEntry two[] = {{3, key}, {70, predicted}};
  write_room_frame(two, room);
  room_case("a room frame of two avatars (ids 3 and 70)", room);
  room_case("an empty room frame", {});
  room_case("a room frame cut short", cut(room, 1 + predicted.size()));
  room_case("a room frame whose first entry has length 0", {0x23, 0x07, 0x00, 0x21});
  room_case("a room frame naming avatar 3 twice", {0x23, 0x07, 0x01, 0x21, 0x06, 0x21});
  std::vector<std::uint8_t> crowded = {0x23};
  for (int i = 0; i < 65; ++i) {
    crowded.push_back(static_cast<std::uint8_t>((i << 1) | (i < 64 ? 1 : 0)));
    if (i < 64) crowded.push_back(1);
    crowded.push_back(0x22);
  }
  room_case("a room frame of 65 avatars", crowded);
  room_case("a room frame whose entry is longer than 1024 bytes", {0x23, 0x03, 0x81, 0x08, 0x21});
  room_case("a room frame with an avatar id of 2^21", {0x23, 0x80, 0x80, 0x80, 0x02, 0x21});
  room_case("a room frame with an overlong varint", {0x23, 0x86, 0x00, 0x21});
  room_case("a key frame given as a room frame", key);

  auto resync_case = [&](const std::string& what, const std::vector<std::uint8_t>& bytes) {
    std::vector<std::uint32_t> ids;
    const DecodeError e = read_resync_request(bytes, ids);
    cases.push_back({{"what", what}, {"kind", "resync_request"}, {"hex", hex(bytes)}, {"error", error_name(e)},
                     {"avatar_ids", e == DecodeError::ok ? nlohmann::json(ids) : nlohmann::json::array()}});
  };
  std::vector<std::uint8_t> resync;
  const std::uint32_t ids[] = {0, 5, 300};
  write_resync_request(ids, resync);
  resync_case("a resync request for avatars 0, 5 and 300", resync);
  resync_case("a resync request with a byte too many", [&] {
    auto r = resync;
    r.push_back(0);
    return r;
  }());
  resync_case("a resync request cut short", cut(resync, 1));
  resync_case("a resync request for 65 avatars", {0x24, 0x41});
  return cases;
}

}  // namespace fw::codec::vectors
