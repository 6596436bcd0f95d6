// SubscriberStream, ticked by the test on a clock of its own (a simulated
// second takes milliseconds), writing into an in-memory connection whose
// peer decodes everything: the stream header, previews before packages and
// frames after previews, the budget kept, thin budgets bundled, and latest
// value wins when the peer stops reading.
#include "subscriber_stream.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "in_memory_server.hpp"

namespace fw::server {
namespace {

using test::eventually;
using test::InMemoryPeer;
using test::InMemoryServer;
using namespace std::chrono_literals;

constexpr int kTickHz = 30;
constexpr std::uint64_t kTickUs = 1'000'000 / kTickHz;

/// A face in quick motion: a smile that comes and goes, a jaw that talks,
/// a head that turns, eyes that dart; enough to use a thin budget.
codec::FaceParams moving_face(std::uint32_t tick) {
  codec::FaceParams face;
  const float t = static_cast<float>(tick);
  face.set_au(12, 0.4f + 0.3f * std::sin(t * 0.7f));
  face.set_au(26, 0.3f + 0.3f * std::sin(t * 1.3f));
  face.set_au(1, 0.3f + 0.3f * std::sin(t * 0.9f));
  face.head_yaw_rad = 0.3f * std::sin(t * 0.4f);
  face.head_pitch_rad = 0.1f * std::sin(t * 0.6f);
  face.eye_left.yaw_rad = face.eye_right.yaw_rad = 0.3f * std::sin(t * 1.1f);
  return face;
}

/// A face unlike anything moving_face shows: a broad smile, the head turned far away.
codec::FaceParams newest_face() {
  codec::FaceParams face;
  face.set_au(12, 1.0f);
  face.set_au(6, 0.9f);
  face.head_yaw_rad = -0.9f;
  return face;
}

/// Hands everything on to the session and counts what the stream delivers,
/// so that the test sees the backlog from outside the session's own
/// bookkeeping (which is what the stream reads and what a bug could hide).
class CountingConnection : public RoomConnection {
 public:
  explicit CountingConnection(std::shared_ptr<InMemorySession> session) : session_(std::move(session)) {}
  void deliver(SharedBytes message) override {
    delivered_ += message->size();
    session_->deliver(std::move(message));
  }
  std::size_t queued_bytes() const override { return session_->queued_bytes(); }
  std::uint64_t bytes_written() const override { return session_->bytes_written(); }
  std::size_t framing_bytes(std::size_t message_bytes) const override { return session_->framing_bytes(message_bytes); }
  void close(codec::CloseCode code, std::string reason) override { session_->close(code, std::move(reason)); }
  void joined(std::uint32_t avatar, SharedBytes welcome) override { session_->joined(avatar, std::move(welcome)); }
  /// Bytes of every message delivered so far (the stream ticks on the test's thread).
  std::uint64_t delivered() const { return delivered_; }

 private:
  std::shared_ptr<InMemorySession> session_;
  std::uint64_t delivered_ = 0;
};

/// One subscriber stream over an in-memory connection, ticked by hand.
class StreamHarness {
 public:
  /// `packages`: demo faces made for the test to stream as avatars' packages.
  /// `version`: the protocol version of the subscriber's hello.
  explicit StreamHarness(std::uint32_t budget_bps, std::uint32_t packages = 1, bool timestamps = false,
                         std::uint16_t version = codec::kProtocolVersion)
      : server_(quiet_config(packages)), peer_(server_.connect()),
        connection_(std::make_shared<CountingConnection>(peer_->shared_session())),
        stream_(settings(budget_bps, timestamps, version), connection_, server_.core().metrics()) {
    drain();  // the stream header, which a room sends after its welcome
  }

  InMemoryPeer& peer() { return *peer_; }
  InMemorySession& session() { return peer_->session(); }
  SubscriberStream& stream() { return stream_; }
  Metrics& metrics() { return server_.core().metrics(); }
  /// The demo faces' packages, to stream as if avatars of the room.
  const std::vector<StoredAvatar>& packages() { return server_.core().demo_avatars(); }
  std::uint32_t ticks() const { return tick_; }

  /// One tick with these faces, then (while the peer reads) waits until it
  /// has everything, so that the stream never sees a backlog it did not cause.
  void tick(const std::vector<std::pair<std::uint32_t, codec::FaceParams>>& faces, bool wait = true) {
    std::vector<AvatarFace> view;
    for (const auto& [id, face] : faces) view.push_back({id, &face});
    ++tick_;
    now_us_ += kTickUs;
    stream_.tick(tick_, now_us_, view);
    if (wait) drain();
  }
  void tick_moving(std::initializer_list<std::uint32_t> ids, bool wait = true) {
    std::vector<std::pair<std::uint32_t, codec::FaceParams>> faces;
    for (const std::uint32_t id : ids) faces.emplace_back(id, moving_face(tick_ + id * 7));
    tick(faces, wait);
  }
  /// Waits until the peer has read everything the stream delivered.
  void drain() {
    EXPECT_TRUE(eventually(
        [&] {
          peer_->read();
          return peer_->bytes_received >= connection_->delivered();
        },
        2s));
  }
  /// Delivered by the stream and not read by the peer yet: what waits.
  std::uint64_t backlog() const { return connection_->delivered() - peer_->bytes_received; }

 private:
  static ServerConfig quiet_config(std::uint32_t packages) {
    ServerConfig config = InMemoryServer::test_config(packages);
    config.timeouts.handshake = std::chrono::minutes(10);  // the peer never says hello here
    return config;
  }
  static StreamSettings settings(std::uint32_t budget_bps, bool timestamps, std::uint16_t version) {
    StreamSettings s;
    s.tick_hz = kTickHz;
    s.budget_bps = budget_bps;
    s.timestamps = timestamps;
    s.protocol_version = version;
    return s;
  }

  InMemoryServer server_;
  std::unique_ptr<InMemoryPeer> peer_;
  std::shared_ptr<CountingConnection> connection_;
  SubscriberStream stream_;
  std::uint32_t tick_ = 0;
  std::uint64_t now_us_ = 1'000'000;
};

TEST(SubscriberStream, TheStreamHeaderComesFirst) {
  StreamHarness h(64000);
  h.drain();
  EXPECT_TRUE(h.peer().stream_header);
  EXPECT_EQ(h.peer().messages_read, 1u);
}

TEST(SubscriberStream, PreviewsComeBeforeAnyFullPackageAndFramesAfterTheirPreview) {
  StreamHarness h(64000, /*packages=*/2);
  const auto& demo = h.packages();
  h.stream().add_avatar(1, demo[0].preview, demo[0].full);
  h.stream().add_avatar(2, demo[1].preview, demo[1].full);
  bool frames_before_preview = false;
  for (int i = 0; i < 30 * 20 && h.peer().package_order.size() < 4; ++i) {
    h.tick_moving({1, 2});
    for (const auto& [id, frames] : h.peer().frames_per_avatar)
      if (frames > 0 && !h.peer().packages[{id, 0}].complete()) frames_before_preview = true;
  }
  ASSERT_EQ(h.peer().package_order.size(), 4u);
  EXPECT_EQ(h.peer().package_order[0].second, 0);
  EXPECT_EQ(h.peer().package_order[1].second, 0);
  EXPECT_FALSE(frames_before_preview) << "a face the client cannot draw yet is not streamed";
  EXPECT_EQ(h.peer().packages[std::pair(1u, 1)].bytes, *demo[0].full);
  EXPECT_GT(h.peer().frames_per_avatar[1], 0u);
  EXPECT_TRUE(h.peer().errors.empty()) << h.peer().errors.front();
}

TEST(SubscriberStream, APackageTheSubscriberHoldsIsNotSentAndItsFaceStreamsAtOnce) {
  StreamHarness h(64000);
  h.stream().add_avatar(1, nullptr, nullptr);
  for (int i = 0; i < 10; ++i) h.tick_moving({1});
  EXPECT_GT(h.peer().frames_per_avatar[1], 0u);
  EXPECT_EQ(h.peer().package_bytes, 0u);
}

TEST(SubscriberStream, EverythingItSendsStaysWithinTheBudget) {
  // Five seconds: the packages (about 30 KB) outlast them on each budget.
  for (const std::uint32_t budget : {8000u, 16000u, 32000u}) {
    StreamHarness h(budget, /*packages=*/3);
    const auto& demo = h.packages();
    for (std::uint32_t id = 1; id <= 3; ++id) h.stream().add_avatar(id, demo[id - 1].preview, demo[id - 1].full);
    for (int i = 0; i < kTickHz * 5; ++i) h.tick_moving({1, 2, 3});
    // Written bytes include the framing, as a TCP link carries them.
    const double seconds = 5.0, allowed = budget / 8.0 * seconds;
    const auto written = static_cast<double>(h.session().bytes_written());
    EXPECT_LE(written, allowed) << budget << " bit/s";
    EXPECT_GE(written, 0.8 * allowed) << budget << " bit/s: packages use what the faces leave";
    EXPECT_EQ(h.metrics().skipped_ticks.load(), 0u) << budget << " bit/s: a peer that reads is never skipped";
  }
}

TEST(SubscriberStream, AThinBudgetBundlesTheFramesOnEverySecondTick) {
  StreamHarness h(2400);
  h.stream().add_avatar(1, nullptr, nullptr);
  h.stream().add_avatar(2, nullptr, nullptr);
  for (int i = 0; i < kTickHz * 4; ++i) h.tick_moving({1, 2});
  EXPECT_GT(h.peer().room_frames, 10u);
  EXPECT_LE(h.peer().room_frames, static_cast<std::uint64_t>(kTickHz * 4 / 2));
}

TEST(SubscriberStream, AStillFaceCostsNothingButAResyncGetsItsKeyFrame) {
  StreamHarness h(64000);
  h.stream().add_avatar(1, nullptr, nullptr);
  const codec::FaceParams still = newest_face();
  for (int i = 0; i < kTickHz * 2; ++i) h.tick({{1, still}});
  const auto frames = h.peer().room_frames;
  for (int i = 0; i < kTickHz; ++i) h.tick({{1, still}});
  EXPECT_EQ(h.peer().room_frames, frames) << "nothing to say";
  const std::uint32_t lost[] = {1};
  h.stream().force_key_frames(lost);
  h.tick({{1, still}});
  EXPECT_EQ(h.peer().room_frames, frames + 1);
}

TEST(SubscriberStream, ARemovedAvatarIsNoLongerStreamedNorItsPackagesSent) {
  StreamHarness h(8000);
  const auto& demo = h.packages();
  h.stream().add_avatar(1, nullptr, nullptr);
  h.stream().add_avatar(2, demo[0].preview, demo[0].full);
  h.stream().remove_avatar(2);
  for (int i = 0; i < kTickHz * 3; ++i) h.tick_moving({1, 2});
  EXPECT_EQ(h.peer().package_bytes, 0u);
  EXPECT_EQ(h.peer().frames_per_avatar.count(2), 0u);
  EXPECT_GT(h.peer().frames_per_avatar[1], 0u);
}

TEST(SubscriberStream, LinkStatisticsComeOnceASecond) {
  StreamHarness h(16000);
  h.stream().add_avatar(1, nullptr, nullptr);
  for (int i = 0; i < kTickHz * 3 + 1; ++i) h.tick_moving({1});
  ASSERT_TRUE(h.peer().link);
  EXPECT_NEAR(h.peer().link->target_bps, 16000 * 0.97, 1);
  EXPECT_EQ(h.peer().link->skipped_ticks, 0u);
  EXPECT_GT(h.peer().link->drain_bps, 0u);
}

// Latest value wins. While the peer reads nothing, the stream skips ticks
// instead of queueing frames (the encoders hold, so nothing is lost); when
// it reads again it gets the face of now, coded against what it last
// decoded, and not the seconds it missed.
TEST(SubscriberStream, APeerThatStopsReadingIsSkippedAndThenGetsTheNewestFace) {
  constexpr std::uint32_t kBudget = 16000;
  StreamHarness h(kBudget);
  // Avatar 1 streams at once; avatar 2's packages fill what its frames leave.
  h.stream().add_avatar(1, nullptr, nullptr);
  h.stream().add_avatar(2, h.packages()[0].preview, h.packages()[0].full);
  for (int i = 0; i < kTickHz * 2; ++i) h.tick_moving({1});
  ASSERT_GT(h.peer().room_frames, 0u);
  const auto frames_before_stall = h.peer().room_frames;

  h.session().set_reading(false);
  std::uint64_t most_waiting = 0;
  for (int i = 0; i < kTickHz * 10; ++i) {  // ten seconds of a peer that reads nothing
    h.tick_moving({1}, /*wait=*/false);
    most_waiting = std::max(most_waiting, h.backlog());
  }
  const codec::FaceParams newest = newest_face();
  for (int i = 0; i < kTickHz; ++i) {  // and a second of the face it should see next
    h.tick({{1, newest}}, /*wait=*/false);
    most_waiting = std::max(most_waiting, h.backlog());
  }
  const auto stalled_ticks = static_cast<std::uint64_t>(kTickHz * 11);
  EXPECT_GE(h.metrics().skipped_ticks.load(), stalled_ticks - kTickHz) << "ticks are skipped, not queued";
  // The stream stops once half a second of budget waits (1 KB here).
  EXPECT_LE(most_waiting, kBudget / 8) << "no growing queue";

  h.session().set_reading(true);
  h.drain();
  const auto stale_frames = h.peer().room_frames - frames_before_stall;
  EXPECT_LE(stale_frames, 30u) << "what waited is about half a second of budget, not " << stalled_ticks << " ticks";
  for (int i = 0; i < kTickHz * 3; ++i) h.tick({{1, newest}});
  EXPECT_TRUE(h.peer().errors.empty()) << h.peer().errors.front();
  const codec::Decoder* decoder = h.peer().decoder.avatar(1);
  ASSERT_NE(decoder, nullptr);
  const codec::FaceParams shown = decoder->face();
  EXPECT_NEAR(shown.au_intensity(12), 1.0f, 0.1f) << "the newest face wins";
  EXPECT_NEAR(shown.head_yaw_rad, -0.9f, 0.05f);
}

TEST(SubscriberStream, TheBudgetFallsToWhatDrainsAndClimbsBackWhenTheLinkRecovers) {
  constexpr std::uint32_t kBudget = 32000;
  StreamHarness h(kBudget);
  h.stream().add_avatar(1, nullptr, nullptr);
  h.stream().add_avatar(2, h.packages()[0].preview, h.packages()[0].full);  // fills the budget
  for (int i = 0; i < kTickHz * 2; ++i) h.tick_moving({1});
  EXPECT_NEAR(h.stream().target_bps(), kBudget * 0.97, 1);
  h.session().set_reading(false);
  for (int i = 0; i < kTickHz * 3; ++i) h.tick_moving({1}, /*wait=*/false);
  EXPECT_LE(h.stream().target_bps(), 2400u + 1) << "nothing drained: the floor";
  h.session().set_reading(true);
  h.drain();
  for (int i = 0; i < kTickHz * 20; ++i) h.tick_moving({1});
  EXPECT_NEAR(h.stream().target_bps(), kBudget * 0.97, 1) << "back to the client's own budget";
}

// --- the room's messages, within the budget ----------------------------------

SharedBytes presence(codec::Presence::Change change, std::uint32_t id) {
  codec::AvatarInfo info;
  info.id = id;
  info.name = "Flood " + std::to_string(id);
  info.person = true;
  return encode_shared(codec::Presence{change, info});
}

/// A flood as one address could make it before the per-address limits: a
/// face joins, says five long lines and leaves, every tick.
void flood_tick(StreamHarness& h, std::uint32_t id) {
  using Change = codec::Presence::Change;
  h.stream().post_presence(Change::joined, id, presence(Change::joined, id));
  h.stream().add_avatar(id, nullptr, nullptr);
  for (int line = 0; line < 5; ++line) h.stream().post_chat(encode_shared(codec::Chat{id, std::string(200, 'x')}));
  h.stream().remove_avatar(id);
  h.stream().post_presence(Change::left, id, presence(Change::left, id));
  h.tick_moving({1});
}

TEST(SubscriberStream, ChatAndPresenceUnderAFloodStayWithinTheBudget) {
  constexpr std::uint32_t kBudget = 9600;
  StreamHarness h(kBudget);
  h.stream().add_avatar(1, nullptr, nullptr);
  for (int i = 0; i < kTickHz * 5; ++i) flood_tick(h, 100 + static_cast<std::uint32_t>(i));
  // Five seconds of budget, and the half second a burst of messages may
  // overdraw it by.
  const double allowed = kBudget / 8.0 * 5.5;
  EXPECT_LE(static_cast<double>(h.session().bytes_written()), allowed)
      << "750 chat lines (150 KB) were posted in 5 s";
  EXPECT_TRUE(h.peer().errors.empty()) << h.peer().errors.front();
  EXPECT_GT(h.peer().frames_per_avatar[1], 30u) << "the face still moves";
  ASSERT_FALSE(h.peer().chat.empty());
  EXPECT_LT(h.peer().chat.size(), 100u);
  const bool told = std::any_of(h.peer().chat.begin(), h.peer().chat.end(), [](const codec::Chat& c) {
    return c.from == 0 && c.text.find("chat lines skipped") != std::string::npos;
  });
  EXPECT_TRUE(told) << "the client hears that lines were dropped";
  EXPECT_GT(h.stream().dropped_chat_lines(), 600u);
  EXPECT_EQ(h.metrics().skipped_ticks.load(), 0u) << "what waits, waits in the stream, not in the socket";
}

TEST(SubscriberStream, AFaceThatComesAndGoesBeforeItIsMentionedIsNeverMentioned) {
  using Change = codec::Presence::Change;
  StreamHarness h(9600);
  h.stream().charge(2000);  // the budget is overdrawn: messages wait
  h.stream().post_presence(Change::joined, 5, presence(Change::joined, 5));
  h.stream().post_presence(Change::left, 5, presence(Change::left, 5));
  h.stream().post_presence(Change::joined, 6, presence(Change::joined, 6));
  for (int i = 0; i < kTickHz * 3; ++i) h.tick({});
  h.stream().post_presence(Change::left, 6, presence(Change::left, 6));  // 6 was mentioned: its leaving is too
  for (int i = 0; i < kTickHz; ++i) h.tick({});
  ASSERT_EQ(h.peer().presence.size(), 2u);
  EXPECT_EQ(h.peer().presence[0].avatar.id, 6u);
  EXPECT_EQ(h.peer().presence[0].change, Change::joined);
  EXPECT_EQ(h.peer().presence[1].change, Change::left);
}

TEST(SubscriberStream, AFacesFramesNeverOvertakeThePresenceThatIntroducesIt) {
  using Change = codec::Presence::Change;
  StreamHarness h(2400);
  h.stream().charge(2000);  // a large welcome: the budget is overdrawn for a while
  h.stream().post_presence(Change::joined, 7, presence(Change::joined, 7));
  h.stream().add_avatar(7, nullptr, nullptr);
  bool overtaken = false;
  for (int i = 0; i < kTickHz * 10 && h.peer().frames_per_avatar[7] == 0; ++i) {
    h.tick_moving({7});
    overtaken = overtaken || (h.peer().frames_per_avatar[7] > 0 && h.peer().presence.empty());
  }
  EXPECT_FALSE(overtaken);
  EXPECT_EQ(h.peer().presence.size(), 1u);
  EXPECT_GT(h.peer().frames_per_avatar[7], 0u);
}

TEST(SubscriberStream, AMessageGoesAtOnceWhileTheBudgetAllows) {
  using Change = codec::Presence::Change;
  StreamHarness h(64000);
  h.stream().post_presence(Change::joined, 5, presence(Change::joined, 5));
  h.stream().post_chat(encode_shared(codec::Chat{5, "hello"}));
  h.stream().post_presence(Change::left, 5, presence(Change::left, 5));
  h.drain();  // no tick
  ASSERT_EQ(h.peer().presence.size(), 2u);
  ASSERT_EQ(h.peer().chat.size(), 1u);
}

TEST(SubscriberStream, WaitingSeatsAndAttentionAreCoalesced) {
  StreamHarness h(2400);
  h.stream().add_avatar(1, nullptr, nullptr);
  h.stream().add_avatar(2, nullptr, nullptr);
  h.stream().charge(1000);
  for (std::uint32_t i = 0; i < 20; ++i) {
    codec::Seats seats;
    seats.seats.push_back({1, codec::SeatInfo{static_cast<float>(i), 0, 0, 0}});
    h.stream().post_seats(encode_shared(seats));
    codec::Attention attention;
    attention.entries.push_back({i % 2 == 0 ? 1u : 2u, codec::AttentionTarget::avatar, i % 2 == 0 ? 2u : 1u});
    h.stream().post_attention(attention);
  }
  for (int i = 0; i < kTickHz * 6; ++i) h.tick({});  // the budget pays the charge back in about 3.5 s
  ASSERT_EQ(h.peer().seats.size(), 1u);
  EXPECT_FLOAT_EQ(h.peer().seats[0].seats[0].seat.x_mm, 19);
  ASSERT_EQ(h.peer().attention.size(), 1u);
  EXPECT_EQ(h.peer().attention[0].entries.size(), 2u);
}

TEST(SubscriberStream, SpeakingGoesBeforeTheLinesFramesAndOnlyTheNewestWaitOnAThinLink) {
  StreamHarness h(2400, 1, /*timestamps=*/true);
  h.stream().add_avatar(7, nullptr, nullptr);
  h.stream().charge(1500);  // overdrawn: what is posted now waits
  for (std::uint32_t i = 1; i <= 12; ++i)
    h.stream().post_speaking(encode_shared(codec::Speaking{7, 100 + i, 900, "de", "Zeile " + std::to_string(i)}));
  for (int i = 0; i < kTickHz * 10 && h.peer().speaking.size() < SubscriberStream::kMaxWaitingSpeaking; ++i)
    h.tick_moving({7});
  ASSERT_EQ(h.peer().speaking.size(), SubscriberStream::kMaxWaitingSpeaking) << "the oldest four went";
  EXPECT_EQ(h.peer().speaking.front().text, "Zeile 5");
  EXPECT_EQ(h.peer().speaking.back().text, "Zeile 12");
  EXPECT_EQ(h.peer().last_tick_before_speaking.back(), 0u) << "no frame overtook them";
  EXPECT_TRUE(h.peer().errors.empty());
}

TEST(SubscriberStream, AVersion3SubscriberIsSentNoSpeaking) {
  StreamHarness h(64000, 1, /*timestamps=*/true, /*version=*/3);
  h.stream().add_avatar(7, nullptr, nullptr);
  h.stream().post_speaking(encode_shared(codec::Speaking{7, 1, 900, "de", "Hallo"}));
  h.stream().post_chat(encode_shared(codec::Chat{7, "Hallo"}));
  h.tick_moving({7});
  EXPECT_TRUE(h.peer().speaking.empty());
  EXPECT_EQ(h.peer().chat.size(), 1u);
}

}  // namespace
}  // namespace fw::server
