#include "join_arguments.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "fw/codec/messages.hpp"

namespace fw::client {
namespace {

bool room_name_ok(const std::string& room) {
  if (room.empty() || room.size() > codec::kMaxRoomNameBytes) return false;
  for (const char c : room)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') return false;
  return true;
}

bool display_name_ok(const std::string& name) {
  if (name.empty() || name.size() > codec::kMaxDisplayNameBytes) return false;
  for (const char c : name)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return false;
  return true;
}

bool chat_lines_ok(const std::vector<std::string>& lines) {
  for (const std::string& line : lines)
    if (line.empty() || line.size() > codec::kMaxChatBytes) return false;
  return true;
}

// The session's own fields: what goes into hello, and the chat lines.
bool check_session_fields(const JoinArgs& args, std::string& error) {
  if (!room_name_ok(args.room))
    error = "--room must be 1.." + std::to_string(codec::kMaxRoomNameBytes) +
            " characters of A-Z a-z 0-9 _ - . , not '" + args.room + "'";
  else if (!display_name_ok(args.name))
    error = "--name must be 1.." + std::to_string(codec::kMaxDisplayNameBytes) + " bytes without control characters";
  else if (std::any_of(args.mute.begin(), args.mute.end(), [](const std::string& n) { return !display_name_ok(n); }))
    error = "--mute takes a display name as others see it: 1.." + std::to_string(codec::kMaxDisplayNameBytes) +
            " bytes without control characters";
  else if (!chat_lines_ok(args.say))
    error = "--say: a chat line holds 1.." + std::to_string(codec::kMaxChatBytes) + " bytes";
  else if (args.token.size() > codec::kMaxTokenBytes)
    error = "--token is longer than a join token can be";
  else if (!args.language.empty() && !codec::is_language_code(args.language))
    error = "--language takes a language as espeak-ng names it (en, en-us, de, fr, es, pt-br: 1.." +
            std::to_string(codec::kMaxLanguageBytes) + " lowercase letters, digits and -), not '" + args.language +
            "'; GET /api/languages on the server lists the ones it speaks";
  else
    return true;
  return false;
}

bool plan_rendering(const JoinArgs& args, render::RendererOptions& render, std::string& error) {
  if (!parse_frame_size(args.size, render.width, render.height)) {
    error = "--size must look like 640x360 (width x height in pixels), not '" + args.size + "'";
    return false;
  }
  if (render.width < 16 || render.height < 16 || render.width > 4096 || render.height > 4096) {
    error = "--size: width and height must each be 16..4096 pixels";
    return false;
  }
  render.samples = args.samples;
  return true;
}

}  // namespace

bool parse_frame_size(const std::string& text, int& width, int& height) {
  const auto x = text.find('x');
  if (x == std::string::npos) return false;
  try {
    std::size_t used_w = 0, used_h = 0;
    const int w = std::stoi(text.substr(0, x), &used_w);
    const int h = std::stoi(text.substr(x + 1), &used_h);
    if (used_w != x || used_h != text.size() - x - 1) return false;
    width = w;
    height = h;
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

// --chat: standard input, or a script read now so that a mistake in it is
// said before joining.
bool plan_chat(const JoinArgs& args, JoinPlan& plan, std::string& error) {
  plan.chat_from_stdin = args.chat == "-";
  if (args.chat.empty() || plan.chat_from_stdin) return true;
  if (read_chat_script(args.chat, plan.chat_script, error)) return true;
  error = "--chat " + error;
  return false;
}

bool plan_join(const JoinArgs& args, JoinPlan& plan, std::string& error) {
  return parse_server_list(args.url, plan.servers, error) && check_session_fields(args, error) &&
         plan_rendering(args, plan.render, error) && plan_chat(args, plan, error);
}

bool wants_timestamps(const JoinArgs& args) {
  return args.timestamps == "on" || (args.timestamps == "auto" && (args.max_kbps == 0 || args.max_kbps >= 32));
}

SessionOptions session_options(const JoinArgs& args, const std::string& asset, const std::string& key,
                               std::shared_ptr<const std::vector<std::uint8_t>> own_package) {
  SessionOptions options;
  options.room = args.room;
  options.name = args.name;
  options.avatar_asset = asset;
  options.avatar_key = key;
  options.own_package = std::move(own_package);
  options.token = args.token;
  options.max_bps = static_cast<std::uint32_t>(args.max_kbps * 1000.0);
  options.timestamps = wants_timestamps(args);
  options.say = args.say;
  options.emote = args.emote;
  options.language = args.language;
  return options;
}

}  // namespace fw::client
