// Scene file parsing. Scene files are user input: one ByteReader over the
// whole file, one function per part of the format, every count and size
// checked against the limits and against the bytes that remain before
// anything is allocated, and the first problem reported with the byte where
// it was found.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "fw/codec/codec.hpp"
#include "scene_file_layout.hpp"

namespace fw::behavior {
namespace scene_layout {

namespace {

// A byte as a person reads it: the character if it is printable, else hex.
std::string describe_byte(std::uint8_t byte) {
  if (byte > 0x20 && byte < 0x7F) return std::string("'") + static_cast<char>(byte) + "'";
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", byte);
  return hex;
}

}  // namespace

int read_magic(codec::ByteReader& in, std::string& error) {
  const std::size_t available = std::min(in.remaining(), kMagicBytes);
  const auto magic = in.bytes(available);
  if (available < kMagicBytes || !std::equal(kMagicStem.begin(), kMagicStem.end(), magic.begin())) {
    error = "not a scene file: no FWSCENE1, FWSCENE2 or FWSCENE3 magic at byte 0 (a face script is text: run it with "
            "facewire-server script)";
    return 0;
  }
  const int version = magic.back() - '0';
  if (version < kOldestVersion || version > kNewestVersion) {
    error = "a scene file of version " + describe_byte(magic.back()) + " (byte 7); this build reads versions 1 to 3: "
            "read it with the facewire that wrote it";
    return 0;
  }
  return version;
}

}  // namespace scene_layout

namespace {

namespace layout = scene_layout;

// The counts the header announces.
struct Header {
  int version = 0;
  std::uint32_t fps = 0;
  std::uint32_t avatars = 0;
  std::uint32_t ticks = 0;
  std::uint32_t events = 0;
};

class SceneParser {
 public:
  explicit SceneParser(std::span<const std::uint8_t> bytes) : in_(bytes), size_(bytes.size()) {}

  bool parse(Scene& scene) {
    Header header;
    Scene parsed;
    header.version = layout::read_magic(in_, error_);
    if (header.version == 0 || !read_header(header) || !read_avatars(header, parsed.avatars) ||
        !read_faces(header, parsed.avatars) || !read_events(header, parsed.events) || !check_end(header))
      return false;
    parsed.fps = static_cast<int>(header.fps);
    scene = std::move(parsed);
    return true;
  }

  const std::string& error() const { return error_; }

 private:
  // ---- Header ---------------------------------------------------------------

  bool read_header(Header& h) {
    const std::size_t header_bytes = h.version == 1 ? layout::kHeaderBytesV1 : layout::kHeaderBytesV2;
    if (size_ < header_bytes) return cut_short("the header", 0, header_bytes);
    const std::uint16_t schema = in_.u16_le();
    const std::uint16_t channels = in_.u16_le();
    h.fps = in_.u16_le();
    h.avatars = in_.u16_le();
    h.ticks = in_.u32_le();
    if (h.version >= 2) h.events = in_.u32_le();
    if (schema != layout::schema_of(h.version) || channels != layout::channels_of(h.version))
      return fail("a version " + std::to_string(h.version) + " scene of FaceParams schema " + std::to_string(schema) +
                  " with " + std::to_string(channels) + " channels (bytes 8-11); this build reads version " +
                  std::to_string(h.version) + " scenes of schema " + std::to_string(layout::schema_of(h.version)) +
                  " with " + std::to_string(layout::channels_of(h.version)));
    return check_count("ticks per second", h.fps, 1, kMaxSceneFps, 12) &&
           check_count("avatars", h.avatars, 1, kMaxSceneAvatars, 14) &&
           check_count("ticks", h.ticks, 1, kMaxSceneTicks, 16) &&
           check_count("events", h.events, 0, kMaxSceneEvents, 20);
  }

  bool check_count(const std::string& what, std::uint32_t count, std::size_t least, std::size_t most, std::size_t at) {
    if (count >= least && count <= most) return true;
    return fail("the header says " + std::to_string(count) + " " + what + " (byte " + std::to_string(at) +
                "); a scene has " + std::to_string(least) + " to " + std::to_string(most) + " " + what);
  }

  // ---- Avatars ----------------------------------------------------------------

  bool read_avatars(const Header& h, std::vector<SceneAvatar>& avatars) {
    avatars.resize(h.avatars);  // at most kMaxSceneAvatars: checked in the header
    for (std::uint32_t a = 0; a < h.avatars; ++a)
      if (!read_avatar(h, a, avatars[a])) return false;
    return true;
  }

  bool read_avatar(const Header& h, std::uint32_t index, SceneAvatar& avatar) {
    const std::string what = "avatar " + std::to_string(index);
    const std::size_t start = in_.position();
    const std::uint8_t flags = in_.u8();
    const std::uint8_t name_bytes = in_.u8();
    if (in_.failed()) return cut_short(what, start, layout::kAvatarFixedBytes);
    if ((flags & ~layout::kFlagIdle) != 0)
      return fail(what + " has flags " + std::to_string(flags) + " (byte " + std::to_string(start) +
                  "); only bit 0 (idle) is defined");
    if (name_bytes > kMaxSceneNameBytes)
      return fail(what + " has a name of " + std::to_string(name_bytes) + " bytes (byte " + std::to_string(start + 1) +
                  "); at most " + std::to_string(kMaxSceneNameBytes));
    const auto name = in_.bytes(name_bytes);
    if (in_.failed()) return cut_short(what + "'s name", start + layout::kAvatarFixedBytes, name_bytes);
    avatar.name.assign(name.begin(), name.end());
    avatar.idle = (flags & layout::kFlagIdle) != 0;
    return h.version < 2 || read_presence_and_seat(h, what, avatar);  // versions 2 and 3
  }

  // Version 2: when the avatar is in the room, and where it sits.
  bool read_presence_and_seat(const Header& h, const std::string& what, SceneAvatar& avatar) {
    const std::size_t start = in_.position();
    avatar.joined_tick = in_.u32_le();
    avatar.left_tick = in_.u32_le();
    Seat seat;
    seat.origin_mm.x = in_.f32_le();
    seat.origin_mm.y = in_.f32_le();
    seat.origin_mm.z = in_.f32_le();
    seat.facing_yaw_rad = in_.f32_le();
    if (in_.failed()) return cut_short(what + "'s presence and seat", start, layout::kPresenceBytes + layout::kSeatBytes);
    if (!layout::presence_fits(avatar, h.ticks))
      return fail(what + " joins at tick " + std::to_string(avatar.joined_tick) + " and leaves at tick " +
                  std::to_string(avatar.left_tick) + " (byte " + std::to_string(start) + "); in a scene of " +
                  std::to_string(h.ticks) + " ticks it joins at one of them and leaves after that, at the latest " +
                  "at the end, or stays (4294967295)");
    for (const float value : {seat.origin_mm.x, seat.origin_mm.y, seat.origin_mm.z, seat.facing_yaw_rad})
      if (!std::isfinite(value))
        return fail(what + "'s seat holds " + std::to_string(value) + " (bytes " +
                    std::to_string(start + layout::kPresenceBytes) + "-" + std::to_string(in_.position() - 1) +
                    "); a seat is four finite numbers");
    avatar.seat = seat;
    return true;
  }

  // ---- Faces --------------------------------------------------------------------

  bool read_faces(const Header& h, std::vector<SceneAvatar>& avatars) {
    const std::size_t start = in_.position();
    const std::uint64_t faces_bytes = std::uint64_t{h.ticks} * h.avatars * layout::face_bytes(h.version);
    // Version 1 ends with the faces; version 2 has the events after them.
    const bool fits = h.version == 1 ? in_.remaining() == faces_bytes : in_.remaining() >= faces_bytes;
    if (!fits)
      return fail("size does not match " + std::to_string(h.ticks) + " ticks of " + std::to_string(h.avatars) +
                  " avatars: their faces take " + std::to_string(faces_bytes) + " bytes from byte " +
                  std::to_string(start) + ", and " + std::to_string(in_.remaining()) + " bytes are left" +
                  (h.version == 1 ? " (a version 1 file ends with its faces)" : "") +
                  ": the file is truncated or corrupt; record or copy it again");
    for (SceneAvatar& a : avatars) a.ticks.resize(h.ticks);
    bool any_corrective = false;
    for (std::uint32_t t = 0; t < h.ticks; ++t)
      for (std::uint32_t a = 0; a < h.avatars; ++a) {
        codec::FaceParams& face = avatars[a].ticks[t];
        if (!read_face(layout::channels_of(h.version), t, a, face)) return false;
        for (const float w : face.corrective) any_corrective = any_corrective || w != 0.0f;
      }
    // One file per scene: the writer uses version 3 only for correctives.
    if (h.version >= layout::kFirstCorrectiveVersion && !any_corrective)
      return fail("a version 3 scene whose corrective weights are all 0 (faces from byte " + std::to_string(start) +
                  "): version 3 is for scenes with correctives, and this one is written as version 2; the file "
                  "is corrupt or was not written by facewire");
    return true;
  }

  // `channels` floats in channel order; a file of a version without the
  // corrective channels leaves them 0.
  bool read_face(std::size_t channels, std::uint32_t tick, std::uint32_t avatar, codec::FaceParams& face) {
    for (std::size_t c = 0; c < channels; ++c) {
      const std::size_t at = in_.position();
      const float value = in_.f32_le();
      if (!std::isfinite(value))
        return fail("avatar " + std::to_string(avatar) + " at tick " + std::to_string(tick) + ": channel " +
                    std::to_string(c) + " holds " + std::to_string(value) + " (byte " + std::to_string(at) +
                    "); face values are finite numbers");
      codec::set_channel_value(face, c, value);
    }
    return true;
  }

  // ---- Events -------------------------------------------------------------------

  bool read_events(const Header& h, std::vector<SceneEvent>& events) {
    const std::uint64_t least_bytes = std::uint64_t{h.events} * layout::kEventFixedBytes;
    if (in_.remaining() < least_bytes)
      return fail("the event list is cut short: " + std::to_string(h.events) + " events take at least " +
                  std::to_string(least_bytes) + " bytes from byte " + std::to_string(in_.position()) + ", and " +
                  std::to_string(in_.remaining()) + " bytes are left: the file is truncated or its event count "
                  "(byte 20) is corrupt");
    events.resize(h.events);  // at most one per kEventFixedBytes left: checked just above
    std::uint32_t previous_tick = 0;
    for (std::uint32_t e = 0; e < h.events; ++e) {
      if (!read_event(h, e, previous_tick, events[e])) return false;
      previous_tick = events[e].tick;
    }
    return true;
  }

  bool read_event(const Header& h, std::uint32_t index, std::uint32_t previous_tick, SceneEvent& event) {
    const std::string what = "event " + std::to_string(index);
    const std::size_t start = in_.position();
    event.tick = in_.u32_le();
    event.avatar = in_.u16_le();
    const std::uint8_t text_bytes = in_.u8();
    if (in_.failed()) return cut_short(what, start, layout::kEventFixedBytes);
    const auto text = in_.bytes(text_bytes);
    if (in_.failed()) return cut_short(what + "'s text", start + layout::kEventFixedBytes, text_bytes);
    const std::string where = what + " (byte " + std::to_string(start) + ")";
    if (event.avatar >= h.avatars)
      return fail(where + " names avatar " + std::to_string(event.avatar) + "; the scene has avatars 0 to " +
                  std::to_string(h.avatars - 1));
    if (event.tick >= h.ticks)
      return fail(where + " happens at tick " + std::to_string(event.tick) + "; the scene has ticks 0 to " +
                  std::to_string(h.ticks - 1));
    if (event.tick < previous_tick)
      return fail(where + " at tick " + std::to_string(event.tick) + " follows one at tick " +
                  std::to_string(previous_tick) + "; events go in tick order");
    event.what.assign(text.begin(), text.end());
    return true;
  }

  // ---- End ------------------------------------------------------------------------

  bool check_end(const Header& h) {
    if (in_.remaining() == 0) return true;
    return fail("size does not match " + std::to_string(h.ticks) + " ticks of " + std::to_string(h.avatars) +
                " avatars and " + std::to_string(h.events) + " events: " + std::to_string(in_.remaining()) +
                " bytes follow the last event, from byte " + std::to_string(in_.position()) +
                " (trailing garbage: the file is corrupt)");
  }

  // ---- Errors -----------------------------------------------------------------------

  bool fail(std::string what) {
    error_ = std::move(what);
    return false;
  }

  // `what` needs `bytes` bytes from byte `start`, and the file ends before.
  bool cut_short(const std::string& what, std::size_t start, std::size_t bytes) {
    return fail(what + " is cut short: it takes " + std::to_string(bytes) + " bytes from byte " +
                std::to_string(start) + ", and the file ends at byte " + std::to_string(size_) +
                ": the file is truncated; record or copy it again");
  }

  codec::ByteReader in_;
  std::size_t size_;
  std::string error_;
};

}  // namespace

bool read_scene_bytes(std::span<const std::uint8_t> bytes, Scene& scene, std::string& error) {
  SceneParser parser(bytes);
  if (parser.parse(scene)) return true;
  error = parser.error();
  return false;
}

}  // namespace fw::behavior
