#include "simulate_command.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>

#include <nlohmann/json.hpp>

#include "fw/behavior/scene_file.hpp"
#include "fw/behavior/seat_layout.hpp"
#include "room_simulation.hpp"
#include "command_failure.hpp"

namespace fw::server {
namespace {

struct SimulateArgs {
  int avatars = 3;
  double seconds = 30;
  std::uint64_t seed = 1;
  int fps = 30;
  double join_interval_s = 2;
  bool no_physics = false;
  std::vector<std::string> chats;  ///< "SECONDS:AVATAR:TEXT"
  std::string output;
};

struct ScheduledChat {
  std::uint32_t tick;
  int avatar;  ///< 1-based, as printed
  std::string text;
};

ScheduledChat parse_chat(const std::string& spec, const SimulateArgs& args) {
  const auto a = spec.find(':');
  const auto b = a == std::string::npos ? a : spec.find(':', a + 1);
  if (b == std::string::npos) fail_command("simulate", "--chat '" + spec + "': write SECONDS:AVATAR:TEXT, e.g. 12.5:2:hahaha :)");
  try {
    const double at = std::stod(spec.substr(0, a));
    const int avatar = std::stoi(spec.substr(a + 1, b - a - 1));
    if (!(at >= 0 && at < args.seconds) || avatar < 1 || avatar > args.avatars)
      fail_command("simulate", "--chat '" + spec + "': the time must lie in the scene and the avatar be 1.." + std::to_string(args.avatars));
    return {static_cast<std::uint32_t>(std::lround(at * args.fps)), avatar, spec.substr(b + 1, 1000)};
  } catch (const std::logic_error&) {
    fail_command("simulate", "--chat '" + spec + "': SECONDS and AVATAR must be numbers");
  }
}

/// The scene being recorded: every avatar's faces and the room's events,
/// with the simulation's ids of the avatars that have joined so far.
class Recording {
 public:
  Recording(const SimulateArgs& args, std::uint32_t ticks)
      : ticks_(ticks), seats_(behavior::seat_layout(args.avatars)) {
    scene_.fps = args.fps;
    ids_.assign(static_cast<std::size_t>(args.avatars), 0);
    for (int i = 0; i < args.avatars; ++i) {
      behavior::SceneAvatar a;
      a.name = std::string("avatar-") + std::to_string(i + 1);
      // Not idle in the codec's sense (a resting face): behavior keeps every face moving.
      a.idle = false;
      a.joined_tick = static_cast<std::uint32_t>(std::lround(i * args.join_interval_s * args.fps));
      a.joined_tick = std::min(a.joined_tick, ticks - 1);
      a.ticks.reserve(ticks);
      scene_.avatars.push_back(std::move(a));
    }
  }

  /// Seats the avatars whose time to join is tick `t`.
  void seat_arrivals(RoomSimulation& room, std::uint32_t t) {
    for (std::size_t i = 0; i < scene_.avatars.size(); ++i) {
      behavior::SceneAvatar& a = scene_.avatars[i];
      if (a.joined_tick != t) continue;
      ids_[i] = room.add_avatar({a.name, false});
      index_of_[ids_[i]] = static_cast<std::uint16_t>(i);
      a.seat = seats_[i];  // nobody leaves, so the i-th to join takes the i-th seat
    }
  }

  /// The chat lines due at tick `t` from avatars already in the room.
  void play_chats(RoomSimulation& room, const std::vector<ScheduledChat>& chats, std::uint32_t t) const {
    for (const ScheduledChat& c : chats) {
      const AvatarId from = ids_[static_cast<std::size_t>(c.avatar - 1)];
      if (c.tick == t && from != 0) room.chat(from, c.text);
    }
  }

  /// Every avatar's face after a tick (a neutral one before it joined), and the tick's events.
  void record_tick(RoomSimulation& room) {
    for (std::size_t i = 0; i < scene_.avatars.size(); ++i) {
      const AvatarId id = ids_[i];
      scene_.avatars[i].ticks.push_back(id ? room.face(id) : codec::FaceParams{});
      if (!id) continue;
      ++present_faces_;
      resting_faces_ += room.resting(id) ? 1 : 0;
    }
    for (RoomEvent& e : room.take_events()) {
      const auto it = index_of_.find(e.avatar);
      if (it == index_of_.end()) continue;
      if (e.what.size() > behavior::kMaxSceneEventBytes) e.what.resize(behavior::kMaxSceneEventBytes);
      scene_.events.push_back({std::min(e.tick, ticks_ - 1), it->second, std::move(e.what)});
    }
  }

  const behavior::Scene& scene() const { return scene_; }
  double resting_fraction() const {
    return present_faces_ ? static_cast<double>(resting_faces_) / static_cast<double>(present_faces_) : 0.0;
  }

 private:
  std::uint32_t ticks_;
  std::vector<behavior::Seat> seats_;
  behavior::Scene scene_;
  std::vector<AvatarId> ids_;  ///< 0 until the avatar joins
  std::map<AvatarId, std::uint16_t> index_of_;
  std::size_t resting_faces_ = 0, present_faces_ = 0;
};

std::uint32_t tick_count(const SimulateArgs& args) {
  const auto ticks = static_cast<std::uint32_t>(std::lround(args.seconds * args.fps));
  if (ticks < 1 || ticks > behavior::kMaxSceneTicks)
    fail_command("simulate", std::string("--seconds gives ") + std::to_string(ticks) + " ticks; a scene holds 1 to " +
         std::to_string(behavior::kMaxSceneTicks));
  return ticks;
}

RoomSimulation room_for(const SimulateArgs& args) {
  RoomSimulationOptions options;
  options.seed = args.seed;
  options.tick_hz = args.fps;
  options.physics = !args.no_physics;
  options.seats = args.avatars;  // the room is laid out for everyone from the start
  return RoomSimulation(options);
}

nlohmann::json summary_json(const SimulateArgs& args, const Recording& recording, std::uint32_t ticks,
                            double wall_s) {
  return {
      {"scene", args.output},
      {"avatars", args.avatars},
      {"seconds", args.seconds},
      {"fps", args.fps},
      {"seed", args.seed},
      {"physics", !args.no_physics},
      {"ticks", ticks},
      {"events", recording.scene().events.size()},
      {"resting_fraction", recording.resting_fraction()},
      {"wall_seconds", std::round(wall_s * 1000) / 1000},
      {"simulated_seconds_per_wall_second", wall_s > 0 ? std::round(args.seconds / wall_s * 10) / 10 : 0.0},
  };
}

void run(const SimulateArgs& args) {
  const std::uint32_t ticks = tick_count(args);
  std::vector<ScheduledChat> chats;
  for (const std::string& c : args.chats) chats.push_back(parse_chat(c, args));
  RoomSimulation room = room_for(args);
  Recording recording(args, ticks);
  const auto started = std::chrono::steady_clock::now();
  for (std::uint32_t t = 0; t < ticks; ++t) {
    recording.seat_arrivals(room, t);
    recording.play_chats(room, chats, t);
    room.tick();
    recording.record_tick(room);
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::string error;
  if (!behavior::write_scene(recording.scene(), args.output, error)) fail_command("simulate", error);
  std::cout << summary_json(args, recording, ticks, wall_s).dump(2) << "\n";
}

}  // namespace

void add_simulate_command(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "Run a room's behavior and faces without a network and record a scene");
  cmd->add_option("--avatars", args->avatars, "avatars in the room; the first leads")->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--seconds", args->seconds, "simulated seconds")->check(CLI::Range(0.04, 3600.0))->capture_default_str();
  cmd->add_option("--seed", args->seed, "same seed, same scene")->capture_default_str();
  cmd->add_option("--fps", args->fps, "ticks per second")->check(CLI::Range(1, 240))->capture_default_str();
  cmd->add_option("--join-interval", args->join_interval_s,
                  "seconds between one avatar joining and the next (0: all at once)")
      ->check(CLI::Range(0.0, 600.0))
      ->capture_default_str();
  cmd->add_option("--chat", args->chats, "a chat line SECONDS:AVATAR:TEXT (repeatable), e.g. 12:2:hahaha :)");
  cmd->add_flag("--no-physics", args->no_physics, "show the behavior's action-unit targets as they are");
  cmd->add_option("-o,--output", args->output, "scene file to write (.fws)")->required();
  cmd->callback([args] { run(*args); });
}

}  // namespace fw::server
