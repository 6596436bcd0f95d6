#include "join_command.hpp"

#include <atomic>
#include <csignal>
#include <cctype>
#include <iostream>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <nlohmann/json.hpp>

#include "avatar_upload.hpp"
#include "fw/model/avatar_package.hpp"
#include "fw/model/file_io.hpp"
#include "fw/render/avatar_appearance.hpp"
#include "photo_downsizer.hpp"
#include "png_sequence_sink.hpp"
#include "room_session.hpp"
#include "room_summary.hpp"
#include "room_view.hpp"
#include "server_url.hpp"
#include "window_sink.hpp"
#include "y4m_sink.hpp"

namespace fw::client {
namespace {

using Clock = std::chrono::steady_clock;

struct JoinArgs {
  std::string url, room, name, photo, avatar, api, token;
  bool window = false;
  std::string out_dir, y4m;
  int frames = 0;
  double seconds = 0;
  double max_kbps = 0;
  std::vector<std::string> say;
  std::string emote;
  bool json = false, quiet = false;
  std::string size = "640x360";
  int fps = 15;
  int samples = 2;
  std::string timestamps = "auto";
  double join_timeout_s = 60;
};

std::atomic<bool> g_interrupted{false};
extern "C" void on_signal(int) { g_interrupted = true; }

[[noreturn]] void fail(int status, const std::string& message) {
  std::cerr << "facewire-client join: " << message << "\n";
  std::exit(status);
}

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

// Where uploads go: --api, or the ws:// URL's own host and port (the
// WebSocket shares the HTTP port).
UploadTarget upload_target(const JoinArgs& args, const ServerUrl& url) {
  if (!args.api.empty()) {
    ServerUrl api;
    std::string error;
    std::string as_ws = args.api;
    if (as_ws.rfind("http://", 0) == 0) as_ws.replace(0, 7, "ws://");
    if (!parse_server_url(as_ws, api, error) || api.scheme != ServerUrl::Scheme::websocket)
      fail(2, "--api must look like http://HOST:PORT (the server's HTTP port), not '" + args.api + "'");
    return {api.host, api.port};
  }
  if (url.scheme == ServerUrl::Scheme::tcp)
    fail(2, "a tcp:// URL names the stream port only: say where the server's HTTP port is with --api http://HOST:PORT "
            "so that the photo or package can be uploaded");
  return {url.host, url.port};
}

// Uploads the photo (downsized) or the package; the asset id for hello, or
// "" when neither was given (the server makes a procedural face). An
// uploaded package is kept in `own_package`: the client draws its own face
// from it.
std::string upload(const JoinArgs& args, const ServerUrl& url, std::size_t& uploaded_bytes,
                   std::shared_ptr<const std::vector<std::uint8_t>>& own_package) {
  if (args.photo.empty() && args.avatar.empty()) return "";
  const UploadTarget target = upload_target(args, url);
  std::vector<std::uint8_t> bytes;
  std::string error, content_type, asset;
  if (!args.photo.empty()) {
    if (!model::read_file(args.photo, kMaxPhotoFileBytes, bytes, error)) fail(2, "--photo: " + error);
    DownsizedPhoto photo;
    if (!downsize_photo(bytes, photo, error)) fail(2, "--photo " + args.photo + ": " + error);
    bytes = std::move(photo.jpeg);
    content_type = "image/jpeg";
  } else {
    if (!model::read_file(args.avatar, model::kMaxPackageBytes, bytes, error)) fail(2, "--avatar: " + error);
    model::AvatarPackage package;
    if (!model::parse_avatar_package(bytes, package, error)) fail(2, "--avatar " + args.avatar + ": " + error);
    content_type = "application/x-facewire-avatar";
  }
  // A photo is prepared on the server before it answers; a slow link needs
  // its time for the bytes: allow both.
  const int timeout_s = 60 + static_cast<int>(args.max_kbps > 0 ? bytes.size() * 8 / (args.max_kbps * 1000) : 0);
  if (!upload_avatar(target, content_type, bytes, timeout_s, asset, error)) fail(2, error);
  uploaded_bytes = bytes.size();
  if (args.photo.empty()) own_package = std::make_shared<const std::vector<std::uint8_t>>(std::move(bytes));
  return asset;
}

struct Outputs {
  std::vector<std::unique_ptr<FrameSink>> sinks;
  bool video_on_stdout = false;
};

Outputs open_outputs(const JoinArgs& args, int width, int height) {
  Outputs outputs;
  std::string error;
  if (args.window) {
    auto sink = WindowSink::create(width, height, "facewire: " + args.room, error);
    if (!sink) fail(2, error);
    outputs.sinks.push_back(std::move(sink));
  }
  if (!args.out_dir.empty()) {
    auto sink = PngSequenceSink::create(args.out_dir, error);
    if (!sink) fail(2, error);
    outputs.sinks.push_back(std::move(sink));
  }
  if (!args.y4m.empty()) {
    auto sink = Y4mSink::create(args.y4m, width, height, args.fps, error);
    if (!sink) fail(2, error);
    outputs.video_on_stdout = args.y4m == "-";
    outputs.sinks.push_back(std::move(sink));
  }
  return outputs;
}

// Turns newly arrived packages into faces for the view (off the lock: a
// package takes milliseconds to decode and fit).
void load_new_packages(RoomState& state, RoomView& view, std::map<std::uint32_t, std::uint64_t>& loaded,
                       std::size_t& with_package) {
  std::vector<std::pair<std::uint32_t, std::shared_ptr<const std::vector<std::uint8_t>>>> fresh;
  {
    std::lock_guard lock(state.mutex);
    with_package = 0;
    for (const auto& [id, avatar] : state.avatars) {
      if (!avatar.package) continue;
      ++with_package;
      auto& serial = loaded[id];
      if (serial == avatar.package_serial) continue;
      serial = avatar.package_serial;
      fresh.emplace_back(id, avatar.package);
    }
  }
  for (const auto& [id, bytes] : fresh) {
    model::AvatarPackage package;
    auto appearance = std::make_shared<render::AvatarAppearance>();
    std::string error;
    if (!model::parse_avatar_package(*bytes, package, error) ||
        !render::load_avatar_appearance(package, *appearance, error)) {
      std::cerr << "avatar " << id << ": its package cannot be shown (" << error << "); drawing the generic face\n";
      continue;
    }
    view.set_appearance(id, std::move(appearance));
  }
}

void run(const JoinArgs& args) {
  ServerUrl url;
  std::string error;
  if (!parse_server_url(args.url, url, error)) fail(2, error);
  if (!room_name_ok(args.room))
    fail(2, "--room must be 1.." + std::to_string(codec::kMaxRoomNameBytes) +
                " characters of A-Z a-z 0-9 _ - . , not '" + args.room + "'");
  if (!display_name_ok(args.name))
    fail(2, "--name must be 1.." + std::to_string(codec::kMaxDisplayNameBytes) + " bytes without control characters");
  for (const std::string& line : args.say)
    if (line.empty() || line.size() > codec::kMaxChatBytes)
      fail(2, "--say: a chat line holds 1.." + std::to_string(codec::kMaxChatBytes) + " bytes");
  if (args.token.size() > codec::kMaxTokenBytes) fail(2, "--token is longer than a join token can be");
  render::RendererOptions render_options;
  {
    const auto x = args.size.find('x');
    try {
      if (x == std::string::npos) throw std::invalid_argument("no x");
      std::size_t used_w = 0, used_h = 0;
      render_options.width = std::stoi(args.size.substr(0, x), &used_w);
      render_options.height = std::stoi(args.size.substr(x + 1), &used_h);
      if (used_w != x || used_h != args.size.size() - x - 1) throw std::invalid_argument("junk");
    } catch (const std::exception&) {
      fail(2, "--size must look like 640x360 (width x height in pixels), not '" + args.size + "'");
    }
    if (render_options.width < 16 || render_options.height < 16 || render_options.width > 4096 ||
        render_options.height > 4096)
      fail(2, "--size: width and height must each be 16..4096 pixels");
    render_options.samples = args.samples;
  }

  std::size_t uploaded_bytes = 0;
  std::shared_ptr<const std::vector<std::uint8_t>> own_package;
  const std::string asset = upload(args, url, uploaded_bytes, own_package);
  Outputs outputs = open_outputs(args, render_options.width, render_options.height);
  std::unique_ptr<RoomView> view;
  if (!outputs.sinks.empty()) {
    view = RoomView::create(render_options, error);
    if (!view) fail(1, "the renderer cannot start: " + error);
  }
  const bool stdout_free = !outputs.video_on_stdout;

  RoomState state;
  SessionOptions options;
  options.url = url;
  options.room = args.room;
  options.name = args.name;
  options.avatar_asset = asset;
  options.own_package = own_package;
  options.token = args.token;
  options.max_bps = static_cast<std::uint32_t>(args.max_kbps * 1000.0);
  // Timestamps cost 10..14 bytes a frame: left off on slow links unless asked.
  options.timestamps = args.timestamps == "on" || (args.timestamps == "auto" && (args.max_kbps == 0 || args.max_kbps >= 32));
  options.say = args.say;
  options.emote = args.emote;
  options.on_event = [](const std::string& text) { std::cerr << text << "\n"; };

  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGPIPE, SIG_IGN);  // a closed video pipe is an error to report, not a reason to die

  boost::asio::io_context io;
  RoomSession session(io, options, state);
  session.start();
  std::thread network([&io] { io.run(); });

  const auto start = Clock::now();
  const auto frame_period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / args.fps));
  auto next_frame = start;
  auto next_line = start + std::chrono::seconds(1);
  std::map<std::uint32_t, std::uint64_t> loaded;
  std::size_t with_package = 0;
  int frames_written = 0;
  bool ever_joined = false;
  int status = 0;
  std::string ending;
  while (true) {
    const auto now = Clock::now();
    if (g_interrupted) {
      ending = "interrupted";
      break;
    }
    if (args.seconds > 0 && now - start >= std::chrono::duration<double>(args.seconds)) break;
    if (args.frames > 0 && frames_written >= args.frames) break;
    bool joined;
    {
      std::lock_guard lock(state.mutex);
      if (state.fatal_error) {
        error = *state.fatal_error;
        status = 2;
        break;
      }
      joined = state.joined;
      ever_joined = ever_joined || joined;
      if (!args.quiet && now >= next_line) {
        std::cerr << state.stats.live_line(now) << "\n";
        next_line += std::chrono::seconds(1);
      }
    }
    if (!ever_joined && now - start >= std::chrono::duration<double>(args.join_timeout_s)) {
      error = "could not join room " + args.room + " at " + args.url + " within " +
              std::to_string(static_cast<int>(args.join_timeout_s)) + " s; is the server running there?";
      status = 1;
      break;
    }
    if (ever_joined) {
      std::vector<AvatarFace> faces;
      if (view) {
        load_new_packages(state, *view, loaded, with_package);
        std::lock_guard lock(state.mutex);
        faces = state.faces(now);
      }
      if (view) {
        const model::RgbaImage image = view->render(faces);
        for (auto& sink : outputs.sinks)
          if (!sink->write(image, error)) status = 1;
        if (status != 0) break;
      }
      ++frames_written;
    }
    next_frame += frame_period;
    if (next_frame < Clock::now()) next_frame = Clock::now();  // rendering fell behind: do not try to catch up
    std::this_thread::sleep_until(next_frame);
  }

  boost::asio::post(io, [&session] { session.stop(); });
  // The session's sockets are closed; give their handlers a moment, then stop.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  io.stop();
  network.join();

  nlohmann::json summary;
  {
    std::lock_guard lock(state.mutex);
    summary = room_summary(state, Clock::now());
    if (!state.fatal_error && status == 0 && !ever_joined) status = 1;
  }
  summary["frames_rendered"] = view ? frames_written : 0;
  summary["upload_bytes"] = uploaded_bytes;
  outputs.sinks.clear();  // flush the video before the summary
  if (args.json) (stdout_free ? std::cout : std::cerr) << summary.dump() << std::endl;
  else if (!args.quiet) std::cerr << summary.dump(2) << "\n";
  if (status != 0) fail(status, error.empty() ? "ended without joining" : error);
  if (!ending.empty()) std::cerr << "facewire-client join: " << ending << "\n";
}

}  // namespace

void add_join_command(CLI::App& app) {
  auto args = std::make_shared<JoinArgs>();
  CLI::App* cmd = app.add_subcommand("join", "Join a room as an avatar and show its faces");
  cmd->add_option("url", args->url, "server: ws://HOST:PORT/ (WebSocket) or tcp://HOST:PORT (native port)")->required();
  cmd->add_option("--room", args->room, "room name (A-Z a-z 0-9 _ - ., created on first join)")->required();
  cmd->add_option("--name", args->name, "your display name")->required();
  auto* photo = cmd->add_option("--photo", args->photo, "a photo of your face (JPEG, PNG or WebP): downsized to ~30 KB and uploaded");
  cmd->add_option("--avatar", args->avatar, "a prepared avatar package (.fwa) to upload")->excludes(photo);
  cmd->add_option("--api", args->api, "the server's HTTP port for uploads, http://HOST:PORT (default: the ws:// URL's)");
  cmd->add_option("--token", args->token, "a join token from the room's host (facewire-server token)");
  cmd->add_flag("--window", args->window, "show the room in a window (needs a display)");
  cmd->add_option("--out", args->out_dir, "write the room's frames as PNG files into this directory");
  cmd->add_option("--y4m", args->y4m, "write the room as a Y4M video to this file, or - for stdout (| ffplay -)");
  auto* frames = cmd->add_option("--frames", args->frames, "stop after this many frames once joined")->check(CLI::Range(1, 10000000));
  cmd->add_option("--seconds", args->seconds, "stop after this many seconds (counted after the upload)")->check(CLI::Range(0.1, 1e7))->excludes(frames);
  cmd->add_option("--max-kbps", args->max_kbps, "downstream budget in kbit/s (the server's default if unset)")
      ->check(CLI::Range(0.001, 100000.0));
  cmd->add_option("--say", args->say, "a chat line to send once joined (repeatable)");
  cmd->add_option("--emote", args->emote, "express an emotion once joined: joy, sadness, anger, fear, surprise, disgust")
      ->check(CLI::IsMember({"joy", "sadness", "anger", "fear", "surprise", "disgust", "neutral"}));
  cmd->add_flag("--json", args->json, "print one JSON summary at the end (on stdout, or stderr when the video is there)");
  cmd->add_flag("-q,--quiet", args->quiet, "no live statistics");
  cmd->add_option("--size", args->size, "frame size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--fps", args->fps, "frames rendered per second")->check(CLI::Range(1, 60))->capture_default_str();
  cmd->add_option("--samples", args->samples, "anti-aliasing samples (0 = off)")->check(CLI::Range(0, 16))->capture_default_str();
  cmd->add_option("--timestamps", args->timestamps, "timed room frames for latency figures: on, off, auto (off below 32 kbit/s)")
      ->check(CLI::IsMember({"on", "off", "auto"}))
      ->capture_default_str();
  cmd->add_option("--join-timeout", args->join_timeout_s, "give up if not in the room after this many seconds")
      ->check(CLI::Range(1.0, 3600.0))
      ->capture_default_str();
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::client
