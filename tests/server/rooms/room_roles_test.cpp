// A room's roles behind Room, without sockets and without Redis: the owner
// (OwnedRoom) seats and simulates and tells its bus what it keeps; a bridge
// (BridgedRoom) relays its people to an owner elsewhere and becomes the
// owner when that one dies, its people keeping their seats. The bus is a
// recording one; the local bus and the relay rooms hold are checked too.
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "in_memory_server.hpp"
#include "room.hpp"
#include "room_bus_relay.hpp"
#include "room_registry.hpp"
#include "sample_messages.hpp"
#include "step_gate.hpp"

namespace fw::server {
namespace {

using test::eventually;
using test::InMemoryServer;

/// A bus that writes down what rooms tell it, as the other nodes would read it.
class RecordingBus : public RoomBus {
 public:
  explicit RecordingBus(RoomRoleKind new_rooms) : new_rooms_(new_rooms) {}

  RoomRoleKind role_of_new_room() const override { return new_rooms_; }
  void room_opened(const std::string& room) override { note(opened_, room); }
  const std::string& node() const override { return node_; }
  void send_down(const std::string&, bridge::Bytes message) override {
    auto down = bridge::decode_down(message.data(), message.size());
    ASSERT_TRUE(down);
    std::lock_guard lock(mutex_);
    downs_.push_back(std::move(*down));
  }
  void send_up(const std::string&, bridge::Bytes message) override {
    auto up = bridge::decode_up(message.data(), message.size());
    ASSERT_TRUE(up);
    std::lock_guard lock(mutex_);
    ups_.push_back(std::move(*up));
  }
  void keep_member(const std::string&, const bridge::MemberRecord& member) override {
    note(kept_, std::to_string(member.info.id));
    if (!member.unit_morphs.empty()) note(kept_sets_, std::to_string(member.info.id));
  }
  void forget_member(const std::string&, std::uint32_t avatar) override { note(forgotten_, std::to_string(avatar)); }
  void keep_state(const std::string&, bridge::Bytes) override {}
  void keep_chat(const std::string&, bridge::Bytes) override { note(chats_kept_, "line"); }
  void room_closed(const std::string& room) override { note(closed_, room); }

  std::vector<bridge::Up> ups() const { return copy(ups_); }
  std::vector<bridge::Down> downs() const { return copy(downs_); }
  std::vector<std::string> opened() const { return copy(opened_); }
  std::vector<std::string> kept() const { return copy(kept_); }
  /// The avatars whose record was kept with a set of unit morphs, each time.
  std::vector<std::string> kept_sets() const { return copy(kept_sets_); }
  std::vector<std::string> forgotten() const { return copy(forgotten_); }
  std::size_t chats_kept() const { return copy(chats_kept_).size(); }
  std::vector<std::string> closed() const { return copy(closed_); }
  /// The last up message of `kind`, if any.
  std::optional<bridge::Up> last_up(bridge::UpKind kind) const {
    std::optional<bridge::Up> found;
    for (const auto& up : ups())
      if (up.kind == kind) found = up;
    return found;
  }
  bool sent_down(bridge::DownKind kind) const {
    for (const auto& down : downs())
      if (down.kind == kind) return true;
    return false;
  }

 private:
  void note(std::vector<std::string>& list, const std::string& what) {
    std::lock_guard lock(mutex_);
    list.push_back(what);
  }
  template <class T>
  std::vector<T> copy(const std::vector<T>& list) const {
    std::lock_guard lock(mutex_);
    return list;
  }

  RoomRoleKind new_rooms_;
  std::string node_ = "here";
  mutable std::mutex mutex_;
  std::vector<bridge::Up> ups_;
  std::vector<bridge::Down> downs_;
  std::vector<std::string> opened_, kept_, kept_sets_, forgotten_, chats_kept_, closed_;
};

/// A person's connection as a room sees it, writing down its welcome and its close.
class RecordingConnection : public RoomConnection {
 public:
  void deliver(SharedBytes message) override {
    written_ += message->size();
    codec::UnitMorphs set;
    if (codec::classify(*message) == codec::MessageKind::session &&
        codec::session_type(*message) == codec::MessageType::unit_morphs &&
        codec::read_message(*message, set) == codec::MessageError::ok) {
      std::lock_guard lock(mutex_);
      unit_morphs_.push_back(set);
    }
  }
  /// The unit morphs messages delivered, in order.
  std::vector<codec::UnitMorphs> unit_morphs() const {
    std::lock_guard lock(mutex_);
    return unit_morphs_;
  }
  std::size_t queued_bytes() const override { return 0; }
  std::uint64_t bytes_written() const override { return written_.load(); }
  std::size_t framing_bytes(std::size_t) const override { return 0; }
  void close(codec::CloseCode code, std::string) override { closed_with_ = static_cast<int>(code); }
  void joined(std::uint32_t avatar, SharedBytes welcome) override {
    written_ += welcome->size();
    avatar_ = avatar;
  }
  std::uint32_t avatar() const { return avatar_.load(); }
  bool closed() const { return closed_with_.load() >= 0; }

 private:
  std::atomic<std::uint64_t> written_{0};
  std::atomic<std::uint32_t> avatar_{0};
  std::atomic<int> closed_with_{-1};
  mutable std::mutex mutex_;
  std::vector<codec::UnitMorphs> unit_morphs_;
};

/// Rooms made by a registry of their own, over `bus`, with the services of
/// an in-memory server (its face stepper and worker pool, or `stepper` and `workers`).
class RoomsOver {
 public:
  explicit RoomsOver(RoomBus& bus, FaceStepper* stepper = nullptr, boost::asio::thread_pool* workers = nullptr)
      : services_{core().config(), core().metrics(),      core().physics_lod(), core().abuse(),
                  workers ? *workers : core().workers(), core().store(), core().demo_avatars(), bus,
                  core().state().draining,
                  core().speech(), stepper ? *stepper : core().face_stepper()},
        registry_(services_, core().addresses()) {}
  ~RoomsOver() {
    // The rooms hold the registry and the bus: they go first.
    registry_.close_all_rooms();
    for (const auto& room : made_) EXPECT_TRUE(eventually([&] { return room.expired(); }));
  }

  std::shared_ptr<Room> open(const std::string& name) {
    auto room = registry_.find_or_create(name);
    made_.push_back(room);
    return room;
  }
  JoinRequest person(const std::string& name, std::shared_ptr<RecordingConnection> connection) {
    JoinRequest request;
    request.name = name;
    request.avatar = core().demo_avatars()[0];
    request.connection = std::move(connection);
    request.resume = name + "-resume";
    request.address = "192.0.2.1";
    return request;
  }
  /// `name` seated in `room`, owned here: the connection once welcomed.
  std::shared_ptr<RecordingConnection> seated(Room& room, const std::string& name) {
    auto connection = std::make_shared<RecordingConnection>();
    room.join(person(name, connection));
    EXPECT_TRUE(eventually([&] { return connection->avatar() != 0; })) << name << " was not seated";
    return connection;
  }
  /// A person's record as the owner tells it: `name`, seated as `id`, a client of `node`.
  bridge::MemberRecord member(std::uint32_t id, const std::string& name, const std::string& node) {
    bridge::MemberRecord record;
    record.info.id = id;
    record.info.name = name;
    record.info.asset = face().asset;
    record.info.person = true;
    record.node = node;
    return record;
  }
  RoomRegistry& registry() { return registry_; }
  const StoredAvatar& face() { return core().demo_avatars()[0]; }

 private:
  ServerCore& core() { return server_.core(); }

  InMemoryServer server_;
  RoomServices services_;
  RoomRegistry registry_;
  std::vector<std::weak_ptr<Room>> made_;
};

TEST(RoomRoles, AnOwnerSeatsAPersonAndTellsItsBusWhatItKeepsAndForgets) {
  RecordingBus bus(RoomRoleKind::owner);
  RoomsOver rooms(bus);
  auto room = rooms.open("r");
  ASSERT_TRUE(room);
  EXPECT_EQ(room->role(), RoomRoleKind::owner);
  EXPECT_EQ(bus.opened(), std::vector<std::string>{"r"});
  auto ann = std::make_shared<RecordingConnection>();
  room->join(rooms.person("Ann", ann));
  ASSERT_TRUE(eventually([&] { return ann->avatar() != 0; }));
  const std::string id = std::to_string(ann->avatar());
  EXPECT_TRUE(eventually([&] { return bus.kept() == std::vector<std::string>{id}; }));
  EXPECT_TRUE(eventually([&] { return bus.sent_down(bridge::DownKind::joined); }));
  EXPECT_EQ(room->person_count(), 1u);
  room->chat(ann->avatar(), "hello");
  EXPECT_TRUE(eventually([&] { return bus.chats_kept() == 1; }));
  room->leave(ann->avatar());
  EXPECT_TRUE(eventually([&] { return bus.forgotten() == std::vector<std::string>{id}; }));
  EXPECT_TRUE(eventually([&] { return bus.closed() == std::vector<std::string>{"r"}; })) << "nobody keeps it open";
  EXPECT_TRUE(eventually([&] { return rooms.registry().find("r") == nullptr; }));
  EXPECT_FALSE(ann->closed()) << "a person who left is not thrown out";
}

TEST(RoomRoles, ABridgeRelaysItsPersonToTheOwnerAndTakesTheRoomOverWhenTheOwnerDies) {
  RecordingBus bus(RoomRoleKind::bridge);
  RoomsOver rooms(bus);
  auto room = rooms.open("r");
  ASSERT_TRUE(room);
  EXPECT_EQ(room->role(), RoomRoleKind::bridge);
  auto ann = std::make_shared<RecordingConnection>();
  room->join(rooms.person("Ann", ann));
  // No roster yet: the join waits, and the owner is asked for it.
  ASSERT_TRUE(eventually([&] { return bus.last_up(bridge::UpKind::sync).has_value(); }));
  EXPECT_FALSE(bus.last_up(bridge::UpKind::join));
  bridge::Down roster = bridge::down_roster();
  roster.owner = "there";
  room->on_down(roster);
  ASSERT_TRUE(eventually([&] { return bus.last_up(bridge::UpKind::join).has_value(); }));
  const bridge::Up join = *bus.last_up(bridge::UpKind::join);
  EXPECT_EQ(join.name, "Ann");
  EXPECT_EQ(join.node, "here");
  EXPECT_EQ(ann->avatar(), 0u) << "seated by the owner's answer only";

  bridge::MemberRecord record = rooms.member(7, "Ann", "here");
  record.address = "192.0.2.1";
  record.order = 1;
  bridge::Down joined = bridge::down_joined(join.join_ref, record);
  joined.owner = "there";
  room->on_down(joined);
  ASSERT_TRUE(eventually([&] { return ann->avatar() == 7; }));
  EXPECT_EQ(room->person_count(), 1u);
  room->chat(7, "hi");
  ASSERT_TRUE(eventually([&] { return bus.last_up(bridge::UpKind::chat).has_value(); }));
  EXPECT_EQ(bus.last_up(bridge::UpKind::chat)->text, "hi");
  EXPECT_EQ(bus.chats_kept(), 0u) << "a bridge keeps no record";

  // The owner died: this node takes the room over from its record.
  room->take_over({record}, std::nullopt, {"here"});
  ASSERT_TRUE(eventually([&] { return room->role() == RoomRoleKind::owner; }));
  EXPECT_TRUE(eventually([&] { return bus.sent_down(bridge::DownKind::roster); })) << "the bridges learn the new owner";
  room->chat(7, "still here");
  EXPECT_TRUE(eventually([&] { return bus.chats_kept() == 1; })) << "Ann's seat is the owner's now";
  EXPECT_FALSE(ann->closed()) << "Ann keeps her connection through the takeover";
  EXPECT_EQ(room->person_count(), 1u);
}

/// An encoded set of unit morphs for `avatar` at `version`, one unit moving one vertex.
bridge::Bytes set_of(std::uint32_t avatar, std::uint32_t version) {
  bridge::Bytes bytes;
  codec::write_message(codec::UnitMorphs{avatar, version, {{.channel = 3, .moves = {{10, {0, 40, 0}}}}}}, bytes);
  return bytes;
}

TEST(RoomRoles, AnOwnersRedefinitionGoesDownAndIntoTheMembersRecord) {
  RecordingBus bus(RoomRoleKind::owner);
  RoomsOver rooms(bus);
  auto room = rooms.open("r");
  auto ann = rooms.seated(*room, "Ann");
  EXPECT_TRUE(bus.kept_sets().empty());
  room->command(ann->avatar(), test::facs_command(1, "AU 9 nose 0 0 3 0 end"));
  ASSERT_TRUE(eventually([&] { return bus.sent_down(bridge::DownKind::unit_morphs); }));
  for (const auto& down : bus.downs())
    if (down.kind == bridge::DownKind::unit_morphs) {
      EXPECT_EQ(down.avatar, ann->avatar());
      codec::UnitMorphs set;
      ASSERT_EQ(codec::read_message(down.message, set), codec::MessageError::ok);
      EXPECT_EQ(set.version, 1u);
    }
  EXPECT_TRUE(eventually([&] { return bus.kept_sets() == std::vector<std::string>{std::to_string(ann->avatar())}; }))
      << "a successor finds the set in the member's record";
  EXPECT_TRUE(eventually([&] { return ann->unit_morphs().size() == 1; })) << "and Ann is told, here";
}

/// News from the owner, on the node "there".
bridge::Down from_there(bridge::Down news) {
  news.owner = "there";
  return news;
}

TEST(RoomRoles, ABridgeKeepsEachAvatarsNewestSetForItsPeopleAndDropsItWhenTheAvatarLeaves) {
  RecordingBus bus(RoomRoleKind::bridge);
  RoomsOver rooms(bus);
  auto room = rooms.open("r");
  auto ann = std::make_shared<RecordingConnection>();
  room->join(rooms.person("Ann", ann));
  // The roster: Zed, on the owner, redefined a unit already.
  bridge::MemberRecord zed = rooms.member(3, "Zed", "there");
  zed.unit_morphs = set_of(3, 1);
  bridge::Down roster = from_there(bridge::down_roster());
  roster.members = {zed};
  room->on_down(roster);
  ASSERT_TRUE(eventually([&] { return bus.last_up(bridge::UpKind::join).has_value(); }));
  const bridge::MemberRecord record = rooms.member(7, "Ann", "here");
  room->on_down(from_there(bridge::down_joined(bus.last_up(bridge::UpKind::join)->join_ref, record)));
  ASSERT_TRUE(eventually([&] { return ann->avatar() == 7; }));
  // After her welcome, Ann hears of Zed's set as the roster gave it.
  ASSERT_TRUE(eventually([&] { return ann->unit_morphs().size() == 1; }));
  EXPECT_EQ(ann->unit_morphs()[0].avatar, 3u);
  EXPECT_EQ(ann->unit_morphs()[0].version, 1u);
  // A newer set comes down: Ann hears it.
  const bridge::Down newer = from_there(bridge::down_message(bridge::DownKind::unit_morphs, 3, set_of(3, 2)));
  room->on_down(bridge::Down(newer));
  ASSERT_TRUE(eventually([&] { return ann->unit_morphs().size() == 2; }));
  EXPECT_EQ(ann->unit_morphs()[1].version, 2u);
  // A roster repeats every set (another bridge asked for it): nothing new for Ann.
  zed.unit_morphs = set_of(3, 2);
  roster.members = {zed, record};
  room->on_down(roster);
  room->on_down(bridge::Down(newer));
  // Zed leaves; a set of his that comes late is nobody's here.
  room->on_down(from_there(bridge::down_left(3)));
  room->on_down(from_there(bridge::down_message(bridge::DownKind::unit_morphs, 3, set_of(3, 3))));
  // A newcomer here is told of no set: Zed's went with him.
  auto bea = std::make_shared<RecordingConnection>();
  room->join(rooms.person("Bea", bea));
  ASSERT_TRUE(eventually([&] { return bus.last_up(bridge::UpKind::join)->name == "Bea"; }));
  room->on_down(from_there(bridge::down_joined(bus.last_up(bridge::UpKind::join)->join_ref, rooms.member(8, "Bea", "here"))));
  ASSERT_TRUE(eventually([&] { return bea->avatar() == 8; }));
  // Ann redefines a unit: once both hear of it, whatever came before it
  // has been delivered (a stream keeps its order).
  room->on_down(from_there(bridge::down_message(bridge::DownKind::unit_morphs, 7, set_of(7, 1))));
  ASSERT_TRUE(eventually([&] { return !bea->unit_morphs().empty() && ann->unit_morphs().size() >= 3; }));
  const auto anns = ann->unit_morphs();
  ASSERT_EQ(anns.size(), 3u) << "a repeated or late set reached Ann again";
  EXPECT_EQ(anns[2].avatar, 7u);
  ASSERT_EQ(bea->unit_morphs().size(), 1u) << "a set of an avatar that left was kept";
  EXPECT_EQ(bea->unit_morphs()[0].avatar, 7u);
}

TEST(RoomRoles, AnOwnerThatStepsDownAsksItsPeopleBackAndBridges) {
  RecordingBus bus(RoomRoleKind::owner);
  RoomsOver rooms(bus);
  auto room = rooms.open("r");
  auto ann = rooms.seated(*room, "Ann");
  room->step_down();
  EXPECT_TRUE(eventually([&] { return ann->closed(); }));
  EXPECT_TRUE(eventually([&] { return room->role() == RoomRoleKind::bridge; }));
  EXPECT_EQ(room->person_count(), 0u);
}


codec::Command joy() {
  codec::Command command;
  command.emotion = "joy";
  return command;
}

TEST(RoomTick, RoomsThatCloseWhileTheirFacesAreOnThePoolEndTheirTicksFirstAndThenGo) {
  RecordingBus bus(RoomRoleKind::owner);
  StepGate gate;
  FaceStepper stepper([&gate](double) { gate.pass(); });
  boost::asio::thread_pool workers(2);  // one waits at the gate, the other runs the other room
  RoomsOver rooms(bus, &stepper, &workers);
  std::vector<std::weak_ptr<Room>> gone;
  {
    auto a = rooms.open("a"), b = rooms.open("b");
    ASSERT_TRUE(a && b);
    gone = {a, b};
    auto ann = rooms.seated(*a, "Ann"), bob = rooms.seated(*b, "Bob");
    a->command(ann->avatar(), joy());
    b->command(bob->avatar(), joy());
    // One room's worker steps and waits at the gate; the other room hands
    // its faces over meanwhile and waits for them, its strand free.
    gate.close();
    ASSERT_TRUE(eventually([&] { return stepper.waiting() > 0; }));
    a->leave(ann->avatar());  // the last people: each room closes, once its tick has ended
    b->leave(bob->avatar());
    a->chat(ann->avatar(), "still here?");
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(bus.forgotten().empty()) << "the leaves wait for the ticks";
  EXPECT_FALSE(gone[0].expired() || gone[1].expired()) << "the ticks under way hold the rooms";
  gate.open();
  EXPECT_TRUE(eventually([&] { return bus.forgotten().size() == 2; })) << "the leaves ran after the ticks";
  EXPECT_TRUE(eventually([&] { return gone[0].expired() && gone[1].expired(); }))
      << "the rooms went, their simulations with them";
  workers.join();
}

TEST(RoomTick, AnOwnerThatStepsDownMidTickFinishesTheTickAsOwnerFirst) {
  RecordingBus bus(RoomRoleKind::owner);
  StepGate gate;
  FaceStepper stepper([&gate](double) { gate.pass(); });
  boost::asio::thread_pool workers(2);
  RoomsOver rooms(bus, &stepper, &workers);
  auto a = rooms.open("a"), b = rooms.open("b");
  ASSERT_TRUE(a && b);
  auto ann = rooms.seated(*a, "Ann"), bob = rooms.seated(*b, "Bob");
  a->command(ann->avatar(), joy());
  b->command(bob->avatar(), joy());
  gate.close();
  ASSERT_TRUE(eventually([&] { return stepper.waiting() > 0; }));
  a->step_down();
  b->step_down();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(a->role(), RoomRoleKind::owner) << "the role stays while its tick is under way";
  EXPECT_EQ(b->role(), RoomRoleKind::owner);
  gate.open();
  EXPECT_TRUE(eventually([&] { return a->role() == RoomRoleKind::bridge && b->role() == RoomRoleKind::bridge; }));
  // A bridge simulates nothing: its ticks hand nothing over.
  const std::uint64_t stepped = stepper.faces_stepped();
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(stepper.faces_stepped(), stepped);
  rooms.registry().close_all_rooms();
  a.reset();
  b.reset();
  workers.join();
}

TEST(RoomBuses, ARoomAloneIsOwnedHereAndTheRelayForwardsToAnAttachedCluster) {
  LocalRoomBus local;
  EXPECT_EQ(local.role_of_new_room(), RoomRoleKind::owner);
  EXPECT_EQ(local.node(), "");

  RoomBusRelay relay;
  EXPECT_EQ(relay.role_of_new_room(), RoomRoleKind::owner);
  relay.send_up("r", bridge::encode(bridge::up_sync("here")));  // nobody to tell: dropped
  RecordingBus cluster(RoomRoleKind::bridge);
  relay.attach(cluster);
  EXPECT_EQ(relay.role_of_new_room(), RoomRoleKind::bridge);
  EXPECT_EQ(relay.node(), "here");
  relay.send_up("r", bridge::encode(bridge::up_leave("here", 3)));
  relay.room_closed("r");
  ASSERT_EQ(cluster.ups().size(), 1u);
  EXPECT_EQ(cluster.ups()[0].kind, bridge::UpKind::leave);
  EXPECT_EQ(cluster.closed(), std::vector<std::string>{"r"});
  relay.detach();
  relay.room_closed("s");
  EXPECT_EQ(relay.role_of_new_room(), RoomRoleKind::owner);
  EXPECT_EQ(cluster.closed(), std::vector<std::string>{"r"}) << "detached: nothing more reaches the cluster";
}

}  // namespace
}  // namespace fw::server
