#pragma once
// What `facewire-client join` was asked to do (its command line, parsed by
// CLI11 in join_command.cpp), the checks CLI11 cannot make, and what follows
// from it for the session and the renderer.
#include <string>
#include <vector>

#include "fw/render/face_renderer.hpp"
#include "chat_script.hpp"
#include "room_session.hpp"
#include "server_list.hpp"

namespace fw::client {

struct JoinArgs {
  std::string url;  ///< one server URL, or several separated by commas (server_list.hpp)
  std::string room, name, photo, avatar, api, token;
  bool window = false;
  std::string out_dir, y4m;
  int frames = 0;
  double seconds = 0;
  double max_kbps = 0;
  std::vector<std::string> say;
  std::string chat;  ///< --chat: a file of timed chat lines (chat_script.hpp), or "-" for standard input
  std::vector<std::string> mute;  ///< display names muted for this person alone (--mute, repeatable)
  std::string emote;
  std::string language;  ///< --language: the espeak-ng language the person's lines are said in ("": the server's)
  bool json = false, quiet = false;
  std::string size = "640x360";
  int fps = 15;
  int samples = 2;
  std::string timestamps = "auto";
  double join_timeout_s = 60;
};

/// What the checked arguments come to.
struct JoinPlan {
  std::vector<ServerUrl> servers;  ///< in the order given: the first that answers is used
  render::RendererOptions render;  ///< frame size and anti-aliasing
  std::vector<ScriptedLine> chat_script;  ///< --chat FILE, read
  bool chat_from_stdin = false;           ///< --chat -
};

/// Checks what CLI11 does not (the server URLs, room and display name,
/// chat lines, token, frame size). @return false and `error`, which says what to change.
bool plan_join(const JoinArgs& args, JoinPlan& plan, std::string& error);

/// "WIDTHxHEIGHT" as two whole numbers around an x; false if it is not.
bool parse_frame_size(const std::string& text, int& width, int& height);

/// Whether to ask for timed room frames: they cost 10..14 bytes a frame,
/// so `auto` leaves them off below 32 kbit/s.
bool wants_timestamps(const JoinArgs& args);

/// The session's options for these arguments (without on_event, and the
/// servers, which join_command fills in).
/// @param asset        the uploaded avatar's asset id, or ""
/// @param key          the key the upload answered, or ""
/// @param own_package  the uploaded package, when it was one
SessionOptions session_options(const JoinArgs& args, const std::string& asset, const std::string& key,
                               std::shared_ptr<const std::vector<std::uint8_t>> own_package);

}  // namespace fw::client
