// server/simulation/face_stepper.cpp: the physics faces of many rooms
// stepped together on a pool give every room the faces it gives alone.
#include "face_stepper.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "fw/model/avatar_model.hpp"
#include "fw/physics/avatar_tissue.hpp"
#include "fw/physics/face_simulation.hpp"
#include "room_simulation.hpp"
#include "step_gate.hpp"

namespace fw::server {
namespace {


constexpr int kRooms = 3;
constexpr int kFaces = 7;  // 21 faces: a batch of 16 and one of 5, across rooms
constexpr int kTicks = 45;

std::vector<RoomSimulation> rooms() {
  std::vector<RoomSimulation> made;
  for (int r = 0; r < kRooms; ++r) {
    RoomSimulationOptions o;
    o.seed = 100 + static_cast<std::uint64_t>(r);
    made.emplace_back(o);
    for (int i = 0; i < kFaces; ++i) made.back().add_avatar({"face " + std::to_string(i), false});
    // Awake from the first tick: a strong expression on one of them.
    EXPECT_EQ(made.back().command(1, ExpressCommand{"surprise", 1, 2}), "");
  }
  return made;
}

// Every room's every face, every tick: their action units, bit for bit.
using Record = std::vector<std::vector<float>>;

void record(const std::vector<RoomSimulation>& made, Record& out) {
  for (const RoomSimulation& room : made) {
    std::vector<float> tick;
    for (const AvatarId id : room.avatars()) tick.insert(tick.end(), room.face(id).au.begin(), room.face(id).au.end());
    out.push_back(std::move(tick));
  }
}

bool same_bits(const Record& a, const Record& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].size() != b[i].size() || std::memcmp(a[i].data(), b[i].data(), a[i].size() * sizeof(float)) != 0)
      return false;
  return true;
}

// Each face stepped alone, room after room: how a room stepped its faces before.
Record one_face_at_a_time() {
  std::vector<RoomSimulation> made = rooms();
  Record out;
  for (int t = 0; t < kTicks; ++t) {
    for (RoomSimulation& room : made) {
      const RoomSimulation::TickFaces faces = room.begin_tick();
      for (physics::FaceSimulation* face : faces.faces) FaceStepper::step_here({face}, faces.dt_s);
      room.finish_tick();
    }
    record(made, out);
  }
  return out;
}

TEST(FaceStepper, RoomsSteppedTogetherOnThePoolGiveTheFacesEachGivesAlone) {
  const Record alone = one_face_at_a_time();

  // RoomSimulation::tick: a room's own faces batched together.
  std::vector<RoomSimulation> ticked = rooms();
  Record by_tick;
  for (int t = 0; t < kTicks; ++t) {
    for (RoomSimulation& room : ticked) room.tick();
    record(ticked, by_tick);
  }
  EXPECT_TRUE(same_bits(alone, by_tick)) << "a room's faces batched together end as each stepped alone";

  // The first room's faces stepped on a worker of their own while the
  // others hand theirs over: those join one batch across the rooms.
  StepGate gate;
  FaceStepper stepper([&gate](double) { gate.pass(); });
  std::vector<RoomSimulation> pooled = rooms();
  Record by_pool;
  std::size_t handed = 0, hand_overs = 0;
  for (int t = 0; t < kTicks; ++t) {
    std::atomic<int> finished{0};
    std::vector<RoomSimulation::TickFaces> out;
    for (RoomSimulation& room : pooled) out.push_back(room.begin_tick());
    for (const auto& faces : out) {
      handed += faces.faces.size();
      hand_overs += faces.faces.empty() ? 0 : 1;
    }
    const std::uint64_t batches_before = stepper.batches();
    const bool first_has_faces = !out[0].faces.empty();
    if (first_has_faces) gate.close();
    std::thread first([&] { stepper.step(std::move(out[0].faces), out[0].dt_s, [&finished] { ++finished; }); });
    while (first_has_faces && stepper.batches() == batches_before) std::this_thread::yield();
    for (std::size_t r = 1; r < kRooms; ++r)
      stepper.step(std::move(out[r].faces), out[r].dt_s, [&finished] { ++finished; });
    gate.open();
    first.join();
    ASSERT_EQ(finished.load(), kRooms) << "every hand-over is done when its stepper returns";
    for (RoomSimulation& room : pooled) room.finish_tick();
    record(pooled, by_pool);
  }
  EXPECT_TRUE(same_bits(alone, by_pool)) << "faces batched with other rooms' end as each stepped alone";
  ASSERT_GT(handed, 0u) << "the faces were awake";
  EXPECT_EQ(stepper.faces_stepped(), handed);
  // Batches of up to 16 across the rooms: fewer solves than hand-overs.
  EXPECT_LT(stepper.batches(), hand_overs);
}

// An avatar's own tissue, fitted to a face stretched by `wide` and sheared.
std::shared_ptr<const physics::TissueModel> fitted_tissue(float wide) {
  std::vector<glm::vec2> xy;
  for (const glm::vec3& p : model::generic_face().skin.positions) xy.emplace_back(wide * p.x + 0.02f * p.y, 0.95f * p.y);
  return physics::build_avatar_tissue_model(model::make_avatar_model(model::generic_face(), xy),
                                            physics::generic_tissue_model());
}

TEST(FaceStepper, TheFacesOfDifferentAvatarsShareASolve) {
  // Two avatars' own faces, each its own tissue model: one solve takes both
  // (they share the generic face's factorisation), and each ends as stepped alone.
  const auto first = fitted_tissue(1.1f), second = fitted_tissue(0.9f);
  ASSERT_NE(first.get(), second.get());
  std::array<float, codec::kAuChannelCount> smile{};
  smile[codec::au_channel(12, codec::AuSide::left)] = smile[codec::au_channel(12, codec::AuSide::right)] = 0.8f;
  const auto made = [&](std::shared_ptr<const physics::TissueModel> tissue) {
    physics::SimulationOptions options;
    options.solver = physics::Solver::projective;
    auto face = std::make_unique<physics::FaceSimulation>(std::move(tissue), options);
    face->set_action_units(smile);
    return face;
  };
  auto a = made(first), b = made(second), a_alone = made(first), b_alone = made(second);
  FaceStepper stepper;
  for (int t = 0; t < 10; ++t) {
    bool done = false;
    stepper.step({a.get(), b.get()}, 1.0 / 30, [&done] { done = true; });
    ASSERT_TRUE(done);
    FaceStepper::step_here({a_alone.get()}, 1.0 / 30);
    FaceStepper::step_here({b_alone.get()}, 1.0 / 30);
  }
  EXPECT_EQ(stepper.batches(), 10u) << "one solve a tick for both";
  const auto same = [](const std::vector<glm::vec3>& x, const std::vector<glm::vec3>& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(glm::vec3)) == 0;
  };
  EXPECT_TRUE(same(a->surface(), a_alone->surface()));
  EXPECT_TRUE(same(b->surface(), b_alone->surface()));
  EXPECT_FALSE(same(a->surface(), b->surface())) << "each on its own face";
}

TEST(FaceStepper, AHandOverOfNoFacesIsDoneAtOnce) {
  FaceStepper stepper([](double) { ADD_FAILURE() << "nothing to step"; });
  bool done = false;
  stepper.step({}, 1.0 / 30, [&done] { done = true; });
  EXPECT_TRUE(done);
}

TEST(FaceStepper, ALineWhoseTrackComesBackMidTickStartsAfterTheTick) {
  // A maker that holds the track until the test hands it back, mid-tick.
  struct HeldMaker : TrackMaker {
    std::function<void()> give_back;
    bool make(LineJob job, std::function<void(LineJob, LineToSay)> done) override {
      give_back = [job = std::move(job), done = std::move(done)]() mutable {
        LineToSay line;
        line.text = job.text;
        done(std::move(job), std::move(line));
      };
      return true;
    }
  };
  auto maker = std::make_shared<HeldMaker>();
  RoomSimulationOptions o;
  o.track_maker = maker;
  RoomSimulation room(o);
  const AvatarId a = room.add_avatar({"a", true});
  room.tick();
  room.chat(a, "hello there");
  ASSERT_TRUE(maker->give_back);
  const RoomSimulation::TickFaces faces = room.begin_tick();
  maker->give_back();  // on the room's strand, between the halves
  FaceStepper::step_here(faces.faces, faces.dt_s);
  room.finish_tick();
  bool chat_seen = false;
  for (const RoomEvent& event : room.take_events())
    if (event.what.find("chat") != std::string::npos) {
      chat_seen = true;
      EXPECT_EQ(event.tick, room.tick_index()) << "its events come after the tick's, as a line arriving then";
    }
  EXPECT_TRUE(chat_seen);
}

}  // namespace
}  // namespace fw::server
