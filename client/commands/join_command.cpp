#include "join_command.hpp"

#include <atomic>
#include <csignal>
#include <iostream>
#include <memory>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "chat_feeder.hpp"
#include "frame_outputs.hpp"
#include "join_arguments.hpp"
#include "join_loop.hpp"
#include "room_summary.hpp"
#include "room_view.hpp"
#include "self_view.hpp"
#include "session_thread.hpp"
#include "command_failure.hpp"
#include "failover_policy.hpp"

namespace fw::client {
namespace {

std::atomic<bool> g_interrupted{false};
extern "C" void on_signal(int) { g_interrupted = true; }

void watch_signals() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGPIPE, SIG_IGN);  // a closed video pipe is an error to report, not a reason to die
}

// A renderer only when some output wants frames; without one the client
// only receives and measures.
std::unique_ptr<RoomView> start_view(const FrameOutputs& outputs, const render::RendererOptions& options) {
  if (outputs.empty()) return nullptr;
  std::string error;
  auto view = RoomView::create(options, error);
  if (!view) fail_command("join", 1, "the renderer cannot start: " + error);
  return view;
}

// How the session reaches each server of the list, and uploads the face
// again to one that does not know it (it went to the first that answered).
SessionNetwork session_network(const JoinArgs& args, const JoinPlan& plan, const JoinNetwork& network,
                               const UploadedAvatar& uploaded) {
  SessionNetwork session;
  session.open_transport = [open = network.open_transport, servers = plan.servers](boost::asio::io_context& io,
                                                                                   std::size_t server) {
    return open(io, servers.at(server));
  };
  std::vector<UploadTarget> targets;
  std::string error;
  if (!uploaded.body || !network.upload_avatar_async || !upload_targets(args, plan.servers, targets, error))
    return session;
  const int timeout_s = upload_timeout_s(uploaded.body->size(), args.max_kbps);
  session.upload_avatar = [upload = network.upload_avatar_async, targets, type = uploaded.content_type,
                           body = uploaded.body, timeout_s](boost::asio::io_context& io, std::size_t server,
                                                            ReuploadDone done) {
    upload(io, targets.at(server), type, body, timeout_s,
           [done = std::move(done)](bool ok, const UploadAnswer& answer, const std::string& why) {
             done(ReuploadResult{.ok = ok,
                                 .credentials = {answer.asset, answer.key},
                                 .try_elsewhere = !ok && another_server_may_take_it(answer.http_status),
                                 .error = why});
           });
  };
  return session;
}

// --chat: the person's lines go to the session as they come (standard
// input) or at their times (a script).
std::unique_ptr<ChatFeeder> start_chat(const JoinPlan& plan, RoomState& state, SessionThread& session) {
  const auto say = [&session](std::string line) { session.say(std::move(line)); };
  if (plan.chat_from_stdin)
    return std::make_unique<ChatFeeder>(STDIN_FILENO, say, [](const std::string& message) {
      std::cerr << "facewire-client join: " << message << "\n";
    });
  if (plan.chat_script.empty()) return nullptr;
  return std::make_unique<ChatFeeder>(plan.chat_script, [&state] {
    std::lock_guard lock(state.mutex);
    return state.stats.joined_at();
  }, say);
}

// The session runs on its own thread while the render loop runs here; the
// session is stopped before the summary is made.
JoinOutcome play_room(const JoinArgs& args, const JoinPlan& plan, const JoinNetwork& network,
                      const UploadedAvatar& uploaded, RoomState& state, RoomView* view, FrameOutputs& outputs) {
  SessionOptions options = session_options(args, uploaded.asset, uploaded.key, uploaded.own_package);
  options.on_event = [](const std::string& text) { std::cerr << text << "\n"; };
  for (const ServerUrl& server : plan.servers) options.servers.push_back(server.text);
  options.first_server = uploaded.server;
  SessionThread session(std::move(options), state, session_network(args, plan, network, uploaded));
  const std::unique_ptr<ChatFeeder> chat = start_chat(plan, state, session);
  JoinOutcome outcome = JoinLoop(args, state, view, outputs, std::cerr).run(g_interrupted);
  if (chat) chat->stop();
  session.stop();
  return outcome;
}

// The --json summary (on stdout unless the video is there), then the exit.
void finish(const JoinArgs& args, RoomState& state, JoinOutcome outcome, const UploadedAvatar& uploaded,
            FrameOutputs& outputs, bool rendered) {
  nlohmann::json summary;
  {
    std::lock_guard lock(state.mutex);
    summary = room_summary(state, std::chrono::steady_clock::now());
    if (!state.fatal_error && outcome.status == 0 && !outcome.ever_joined) outcome.status = 1;
  }
  summary["frames_rendered"] = rendered ? outcome.frames : 0;
  summary["upload_bytes"] = uploaded.bytes;
  outputs.sinks.clear();  // flush the video before the summary
  if (args.json) (outputs.video_on_stdout ? std::cerr : std::cout) << summary.dump() << std::endl;
  else if (!args.quiet) std::cerr << summary.dump(2) << "\n";
  if (outcome.status != 0) fail_command("join", outcome.status, outcome.error.empty() ? "ended without joining" : outcome.error);
  if (outcome.interrupted) std::cerr << "facewire-client join: interrupted\n";
}

void run(const JoinArgs& args, const JoinNetwork& network) {
  std::string error;
  JoinPlan plan;
  if (!plan_join(args, plan, error)) fail_command("join", 2, error);
  OwnAvatar own;
  std::vector<UploadTarget> targets;
  if (brings_own_avatar(args) &&
      (!upload_targets(args, plan.servers, targets, error) || !prepare_own_avatar(args, own, error)))
    fail_command("join", 2, error);
  FrameOutputs outputs;
  if (!open_frame_outputs(args, plan.render.width, plan.render.height, outputs, error)) fail_command("join", 2, error);
  const std::unique_ptr<RoomView> view = start_view(outputs, plan.render);
  // The self view shows before the upload and before the server says anything.
  if (view) {
    if (!set_self_look(*view, own, error)) std::cerr << "facewire-client join: your own face cannot be shown (" << error << ")\n";
    if (!show_self_view(*view, outputs, args.name, error)) fail_command("join", 1, error);
  }
  UploadedAvatar uploaded;
  if (!upload_prepared_avatar(args, plan.servers, network.upload_avatar, std::move(own), uploaded, error))
    fail_command("join", 2, error);
  // The key is the only way back to the photo the server keeps: said once,
  // here, with the HTTP address the upload went to (also for a tcp:// join).
  if (!uploaded.asset.empty() && !args.quiet && uploaded.server < targets.size())
    std::cerr << "facewire-client join: your avatar is " << uploaded.asset << "; to delete it and your photo from the "
              << "server: facewire-client delete-avatar ws://" << targets[uploaded.server].host << ":"
              << targets[uploaded.server].port << "/ --asset " << uploaded.asset << " --key " << uploaded.key << "\n";
  watch_signals();
  RoomState state;
  state.mutes = MuteList(args.mute);
  const JoinOutcome outcome = play_room(args, plan, network, uploaded, state, view.get(), outputs);
  finish(args, state, outcome, uploaded, outputs, view != nullptr);
}

}  // namespace

void add_join_command(CLI::App& app, JoinNetwork network) {
  auto args = std::make_shared<JoinArgs>();
  CLI::App* cmd = app.add_subcommand("join", "Join a room as an avatar and show its faces");
  cmd->add_option("url", args->url,
                  "server: ws://HOST:PORT/ (WebSocket) or tcp://HOST:PORT (native port); several, comma-separated "
                  "(ws://a:8080/,ws://b:8080/): the first that answers, the next when its link fails")
      ->required();
  cmd->add_option("--room", args->room, "room name (A-Z a-z 0-9 _ - ., created on first join)")->required();
  cmd->add_option("--name", args->name, "your display name")->required();
  cmd->add_option("--photo", args->photo, "a photo of your face (JPEG, PNG or WebP): downsized to ~30 KB and uploaded");
  cmd->add_option("--avatar", args->avatar,
                  "a prepared avatar package (.fwa) to upload; with --photo, the photo it was prepared from goes along");
  cmd->add_option("--api", args->api,
                  "the server's HTTP port for uploads, http://HOST:PORT (default: the ws:// URL's); with several "
                  "servers one for all, or one per server, comma-separated");
  cmd->add_option("--token", args->token, "a join token from the room's host (facewire-server token)");
  cmd->add_flag("--window", args->window, "show the room in a window (needs a display)");
  cmd->add_option("--out", args->out_dir, "write the room's frames as PNG files into this directory");
  cmd->add_option("--y4m", args->y4m, "write the room as a Y4M video to this file, or - for stdout (| ffplay -)");
  auto* frames = cmd->add_option("--frames", args->frames, "stop after this many frames once joined")->check(CLI::Range(1, 10000000));
  cmd->add_option("--seconds", args->seconds, "stop after this many seconds (counted after the upload)")->check(CLI::Range(0.1, 1e7))->excludes(frames);
  cmd->add_option("--max-kbps", args->max_kbps, "downstream budget in kbit/s (the server's default if unset)")
      ->check(CLI::Range(0.001, 100000.0));
  cmd->add_option("--say", args->say, "a chat line to send once joined (repeatable)");
  cmd->add_option("--chat", args->chat,
                  "chat while joined: - sends each line typed on standard input; a FILE sends its lines at their "
                  "times (a line 'SECONDS TEXT' that many seconds after joining, a line of text alone 2 s after "
                  "the one before; # starts a comment)");
  cmd->add_option("--mute", args->mute,
                  "a display name to mute for yourself alone: their chat lines are not printed and their face is "
                  "drawn still and neutral; everyone of that name (repeatable; they are not told)");
  cmd->add_option("--language", args->language,
                  "the language your chat lines are said in by your face (en, en-us, de, fr, es, pt-br, ...; "
                  "GET /api/languages on the server lists them); the server's default if unset");
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
  cmd->callback([args, network = std::move(network)] { run(*args, network); });
}

}  // namespace fw::client
