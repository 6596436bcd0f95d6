#include "fw/codec/messages.hpp"

#include <random>

#include <gtest/gtest.h>

#include "fw/codec/codec.hpp"
#include "sample_messages.hpp"
#include "test_seed.hpp"

namespace fw::codec {
namespace {

template <class M>
std::vector<std::uint8_t> bytes_of(const M& message) {
  std::vector<std::uint8_t> out;
  write_message(message, out);
  return out;
}

TEST(Messages, HelloRoundTrips) {
  const Hello hello = fw::test::sample_hello();
  const auto bytes = bytes_of(hello);
  EXPECT_EQ(bytes[0], 0x81);
  EXPECT_EQ(classify(bytes), MessageKind::session);
  EXPECT_EQ(session_type(bytes), MessageType::hello);
  Hello back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.room, "lobby");
  EXPECT_EQ(back.name, "Zoë");
  EXPECT_EQ(back.avatar, hello.avatar);
  EXPECT_EQ(back.token, hello.token);
  EXPECT_EQ(back.max_bps, 9600u);
  EXPECT_TRUE(back.timestamps);
  EXPECT_FALSE(back.no_packages);
  EXPECT_TRUE(back.own_package);
  EXPECT_EQ(back.avatar_key, hello.avatar_key);
  EXPECT_EQ(back.resume, hello.resume);
  EXPECT_EQ(back.protocol_version, 5);
  EXPECT_EQ(back.language, "pt-br");
  EXPECT_EQ(bytes_of(back), bytes);
}

TEST(Messages, HelloOfAnotherVersionIsRefusedBeforeItsFields) {
  Hello back;
  for (const std::uint8_t version : {1, 2, 6, 0xFF}) {  // versions whose layout this reader does not know
    std::vector<std::uint8_t> bytes = {0x81, version, 0x00, 0xFF};
    EXPECT_EQ(read_message(bytes, back), MessageError::unsupported_version) << int{version};
  }
}

TEST(Messages, HelloOfVersionThreeStillReadsWithoutALanguage) {
  const Hello v3 = fw::test::sample_hello_v3();
  const auto bytes = bytes_of(v3);
  EXPECT_EQ(bytes[1], 3);
  Hello back;
  back.language = "de";  // the reader clears what an earlier message left
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.protocol_version, 3);
  EXPECT_EQ(back.language, "");
  EXPECT_EQ(back.resume, v3.resume);
  EXPECT_EQ(bytes_of(back), bytes) << "written back in version 3's layout";
  // A version-4 hello is the version-3 one plus the language.
  Hello v4 = v3;
  v4.protocol_version = 4;
  v4.language = "de";
  const auto v4_bytes = bytes_of(v4);
  ASSERT_EQ(v4_bytes.size(), bytes.size() + 3);
  EXPECT_TRUE(std::equal(bytes.begin() + 3, bytes.end(), v4_bytes.begin() + 3));
  EXPECT_EQ(v4_bytes[v4_bytes.size() - 3], 2);
  // A version-3 hello with a language field after its last: trailing bytes.
  auto v3_with_language = bytes;
  v3_with_language.insert(v3_with_language.end(), {2, 'd', 'e'});
  EXPECT_EQ(read_message(v3_with_language, back), MessageError::trailing_bytes);
  // A version-4 hello without its language is cut short.
  auto v4_cut = bytes;
  v4_cut[1] = 4;
  EXPECT_EQ(read_message(v4_cut, back), MessageError::truncated);
}

TEST(Messages, HelloLanguageIsEmptyOrAVoiceName) {
  Hello hello;
  hello.room = "r";
  hello.name = "A";
  Hello back;
  for (const char* language : {"", "en", "en-us", "pt-br", "zh-yue", "sit-can-1", "abcdefghijklmnop"}) {
    hello.language = language;
    ASSERT_EQ(read_message(bytes_of(hello), back), MessageError::ok) << language;
    EXPECT_EQ(back.language, language);
  }
  hello.language.clear();
  const auto plain = bytes_of(hello);
  ASSERT_EQ(plain.back(), 0) << "an empty language is its length alone";
  const auto with_language = [&](std::string_view text) {
    auto bytes = plain;
    bytes.back() = static_cast<std::uint8_t>(text.size());
    bytes.insert(bytes.end(), text.begin(), text.end());
    return bytes;
  };
  for (const char* bad : {"EN", "en_us", "en us", "de.", "fr/", "é"})
    EXPECT_EQ(read_message(with_language(bad), back), MessageError::bad_text) << bad;
  EXPECT_EQ(read_message(with_language("abcdefghijklmnopq"), back), MessageError::string_too_long);
  EXPECT_EQ(read_message(with_language(std::string_view("d\0", 2)), back), MessageError::bad_text);
}

TEST(Messages, LanguageCodesHaveOneShape) {
  EXPECT_TRUE(is_language_code("en"));
  EXPECT_TRUE(is_language_code("pt-br"));
  EXPECT_TRUE(is_language_code("x"));
  EXPECT_TRUE(is_language_code("1234567890123456"));
  EXPECT_FALSE(is_language_code(""));
  EXPECT_FALSE(is_language_code("12345678901234567"));
  EXPECT_FALSE(is_language_code("De"));
  EXPECT_FALSE(is_language_code("en_GB"));
  EXPECT_FALSE(is_language_code("de "));
}

TEST(Messages, SpeakingRoundTrips) {
  const Speaking speaking = fw::test::sample_speaking();
  const auto bytes = bytes_of(speaking);
  EXPECT_EQ(bytes[0], 0x90);
  EXPECT_EQ(classify(bytes), MessageKind::session);
  EXPECT_EQ(session_type(bytes), MessageType::speaking);
  Speaking back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.avatar, 300u);
  EXPECT_EQ(back.tick, 70000u);
  EXPECT_EQ(back.duration_ms, 2140u);
  EXPECT_EQ(back.language, "de");
  EXPECT_EQ(back.text, speaking.text);
  EXPECT_EQ(bytes_of(back), bytes);
  const Speaking longest{.avatar = kMaxAvatarIdValue, .tick = 0xFFFFFFFFu, .duration_ms = kMaxSpeakingMs,
                         .language = "abcdefghijklmnop", .text = std::string(kMaxChatBytes, 'x')};
  ASSERT_EQ(read_message(bytes_of(longest), back), MessageError::ok);
  EXPECT_EQ(back.tick, 0xFFFFFFFFu);
  EXPECT_EQ(back.text.size(), kMaxChatBytes);
}

TEST(Messages, SpeakingRefusesWhatNoServerSends) {
  Speaking back;
  // avatar 1, tick 2, 20 001 ms (0xA1 0x9C 0x01): past kMaxSpeakingMs
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0xA1, 0x9C, 0x01, 0x02, 'e', 'n', 0x01, 'a'},
                         back),
            MessageError::value_out_of_range);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0xA0, 0x9C, 0x01, 0x02, 'e', 'n', 0x01, 'a'},
                         back),
            MessageError::ok)
      << "20 000 ms is the longest";
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0x03, 0x00, 0x01, 'a'}, back),
            MessageError::value_out_of_range)
      << "a line is said in some language";
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0x03, 0x02, 'e', 'n', 0x00}, back),
            MessageError::value_out_of_range)
      << "and says something";
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0x03, 0x02, 'E', 'N', 0x01, 'a'}, back),
            MessageError::bad_text);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0x03, 0x02, 'e', 'n', 0x01, 0x07}, back),
            MessageError::bad_text);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0x03, 0x02, 'e', 'n', 0x02, 'a'}, back),
            MessageError::truncated);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x01, 0x02, 0x03, 0x02, 'e', 'n', 0x01, 'a', 0x00}, back),
            MessageError::trailing_bytes);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x90, 0x81, 0x81, 0x81, 0x01, 0x02, 0x03, 0x02, 'e', 'n', 0x01, 'a'},
                         back),
            MessageError::bad_number)
      << "an avatar id takes at most 3 bytes";
  std::vector<std::uint8_t> long_text = {0x90, 0x01, 0x02, 0x03, 0x02, 'e', 'n', 0xF5, 0x03};  // 501 bytes
  long_text.resize(long_text.size() + 501, 'x');
  EXPECT_EQ(read_message(long_text, back), MessageError::string_too_long);
  std::vector<std::uint8_t> long_language = {0x90, 0x01, 0x02, 0x03, 17};
  long_language.resize(long_language.size() + 17, 'a');
  long_language.insert(long_language.end(), {0x01, 'a'});
  EXPECT_EQ(read_message(long_language, back), MessageError::string_too_long);
  Chat chat;
  EXPECT_EQ(read_message(bytes_of(fw::test::sample_speaking()), chat), MessageError::wrong_type);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x93, 0x00}, back), MessageError::unknown_type)
      << "0x93 is no message of version 5";
  EXPECT_EQ(classify(std::vector<std::uint8_t>{0x93, 0x00}), MessageKind::invalid);
}

TEST(Messages, UnitMorphsRoundTrip) {
  const UnitMorphs morphs = fw::test::sample_unit_morphs();
  const auto bytes = bytes_of(morphs);
  EXPECT_EQ(bytes[0], 0x91);
  EXPECT_EQ(classify(bytes), MessageKind::session);
  UnitMorphs back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.avatar, 300u);
  EXPECT_EQ(back.version, 3u);
  EXPECT_EQ(back.units, morphs.units);
  EXPECT_EQ(bytes_of(back), bytes);
  const UnitMorphs restored{.avatar = 1, .version = 9, .units = {}};
  ASSERT_EQ(read_message(bytes_of(restored), back), MessageError::ok);
  EXPECT_TRUE(back.units.empty());
}

TEST(Messages, PreviewSurfaceRoundTrip) {
  const PreviewSurface surface = fw::test::sample_preview_surface();
  const auto bytes = bytes_of(surface);
  EXPECT_EQ(bytes[0], 0x92);
  EXPECT_EQ(classify(bytes), MessageKind::session);
  PreviewSurface back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back, surface);
  EXPECT_EQ(bytes_of(back), bytes);
  const PreviewSurface none{.avatar = 2097151, .moves = {}};
  ASSERT_EQ(read_message(bytes_of(none), back), MessageError::ok);
  EXPECT_EQ(back, none) << "no residual: the face is what its action units rebuild";
  UnitMorphs other;
  EXPECT_EQ(read_message(bytes, other), MessageError::wrong_type);
}

TEST(Messages, PreviewSurfaceRefusesWhatNoServerSends) {
  PreviewSurface back;
  // avatar 1, then the moves.
  const auto with_moves = [](std::vector<std::uint8_t> moves) {
    std::vector<std::uint8_t> bytes = {0x92, 0x01};
    bytes.insert(bytes.end(), moves.begin(), moves.end());
    return bytes;
  };
  EXPECT_EQ(read_message(with_moves({2, 7, 1, 0, 0, 0, 0, 0, 7, 1, 0, 0, 0, 0, 0}), back),
            MessageError::value_out_of_range)
      << "a vertex given twice";
  EXPECT_EQ(read_message(with_moves({2, 8, 1, 0, 0, 0, 0, 0, 7, 1, 0, 0, 0, 0, 0}), back),
            MessageError::value_out_of_range)
      << "vertices not increasing";
  EXPECT_EQ(read_message(with_moves({0x81, 0x08}), back), MessageError::too_many_entries) << "1025 moves";
  EXPECT_EQ(read_message(with_moves({1, 0x80, 0x08, 0, 0, 0, 0, 0, 0}), back), MessageError::value_out_of_range)
      << "vertex 1024";
  EXPECT_EQ(read_message(with_moves({1, 7, 1, 0}), back), MessageError::truncated);
  EXPECT_EQ(read_message(with_moves({0, 0}), back), MessageError::trailing_bytes);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x92, 0x80, 0x80, 0x80, 0x01, 0}, back), MessageError::bad_number)
      << "an avatar id in 4 bytes";
}

TEST(Messages, UnitMorphsRefuseWhatNoServerSends) {
  UnitMorphs back;
  // avatar 1, version 1, then the units.
  const auto with_units = [](std::vector<std::uint8_t> units) {
    std::vector<std::uint8_t> bytes = {0x91, 0x01, 0x01};
    bytes.insert(bytes.end(), units.begin(), units.end());
    return bytes;
  };
  EXPECT_EQ(read_message(with_units({9}), back), MessageError::too_many_entries) << "at most 8 channels";
  EXPECT_EQ(read_message(with_units({1, 29, 0}), back), MessageError::value_out_of_range) << "29 channels: 0 .. 28";
  EXPECT_EQ(read_message(with_units({2, 4, 0, 4, 0}), back), MessageError::value_out_of_range)
      << "a channel given twice";
  EXPECT_EQ(read_message(with_units({1, 4, 2, 7, 1, 0, 0, 0, 0, 0, 7, 1, 0, 0, 0, 0, 0}), back),
            MessageError::value_out_of_range)
      << "a vertex given twice";
  EXPECT_EQ(read_message(with_units({1, 4, 0x81, 0x08}), back), MessageError::too_many_entries) << "1025 moves";
  EXPECT_EQ(read_message(with_units({1, 4, 1, 0x80, 0x08, 0, 0, 0, 0, 0, 0}), back), MessageError::value_out_of_range)
      << "vertex 1024";
  EXPECT_EQ(read_message(with_units({1, 4, 1, 7, 1, 0}), back), MessageError::truncated);
  EXPECT_EQ(read_message(with_units({0, 0}), back), MessageError::trailing_bytes);
}

TEST(Messages, WelcomeOfVersionThreeAnswersAVersionThreeHello) {
  Welcome welcome;
  welcome.protocol_version = 3;
  welcome.you = 7;
  welcome.room = "lobby";
  welcome.resume = "k";
  const auto bytes = bytes_of(welcome);
  Welcome back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.protocol_version, 3);
  EXPECT_EQ(bytes_of(back), bytes);
  welcome.protocol_version = 4;
  auto v4 = bytes_of(welcome);
  v4[1] = 3;
  EXPECT_EQ(v4, bytes) << "the two versions' welcomes differ in the version alone";
  v4[1] = 2;
  EXPECT_EQ(read_message(v4, back), MessageError::unsupported_version);
}

TEST(Messages, WelcomeAndPresenceCarryAvatars) {
  Welcome welcome;
  welcome.you = 7;
  welcome.room = "lobby";
  welcome.max_bps = 12000;
  welcome.avatars = {{0, "Ada", "abc", 1100, 40000, false, {-420.0f, 0.0f, 112.6f, 0.8726646f}},
                     {7, "Bo", "def", 0, 50000, true, {}}};
  Welcome back;
  ASSERT_EQ(read_message(bytes_of(welcome), back), MessageError::ok);
  EXPECT_EQ(back.you, 7u);
  ASSERT_EQ(back.avatars.size(), 2u);
  EXPECT_EQ(back.avatars[0].name, "Ada");
  EXPECT_FALSE(back.avatars[0].person);
  EXPECT_EQ(back.avatars[0].preview_bytes, 1100u);
  EXPECT_EQ(back.avatars[1].full_bytes, 50000u);
  // Seats travel as whole millimetres and ten-thousandths of a radian.
  EXPECT_EQ(back.avatars[0].seat.x_mm, -420.0f);
  EXPECT_EQ(back.avatars[0].seat.z_mm, 113.0f);
  EXPECT_NEAR(back.avatars[0].seat.facing_yaw_rad, 0.8726646f, 0.5e-4f);
  EXPECT_EQ(back.avatars[1].seat, SeatInfo{});

  Presence left{Presence::Change::left, {7, "Bo", "", 0, 0, true, {}}};
  Presence presence_back;
  ASSERT_EQ(read_message(bytes_of(left), presence_back), MessageError::ok);
  EXPECT_EQ(presence_back.change, Presence::Change::left);
  EXPECT_EQ(presence_back.avatar.id, 7u);
}

TEST(Messages, SeatsRoundTripAndRefuseAFacingPastPi) {
  Seats seats;
  seats.seats = {{1, {0.0f, 0.0f, 0.0f, 0.0f}}, {2, {300.0f, -5.0f, 90.0f, -3.14159f}}};
  const auto bytes = bytes_of(seats);
  EXPECT_EQ(bytes[0], 0x8E);
  EXPECT_EQ(classify(bytes), MessageKind::session);
  Seats back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  ASSERT_EQ(back.seats.size(), 2u);
  EXPECT_EQ(back.seats[1].avatar, 2u);
  EXPECT_EQ(back.seats[1].seat.y_mm, -5.0f);
  EXPECT_NEAR(back.seats[1].seat.facing_yaw_rad, -3.1416f, 1e-4f);
  // 31417 ten-thousandths (0x7AB9) is past pi.
  const std::vector<std::uint8_t> past_pi = {0x8E, 0x01, 0x01, 0, 0, 0, 0, 0, 0, 0xB9, 0x7A};
  EXPECT_EQ(read_message(past_pi, back), MessageError::value_out_of_range);
  std::vector<std::uint8_t> cut = bytes;
  cut.pop_back();
  EXPECT_EQ(read_message(cut, back), MessageError::truncated);
}

TEST(Messages, AttentionRoundTripsEveryTarget) {
  Attention attention;
  attention.entries = {{1, AttentionTarget::avatar, 2}, {2, AttentionTarget::room, 0}, {3, AttentionTarget::nobody, 0}};
  const auto bytes = bytes_of(attention);
  // Only an avatar target carries an id: 0x8F, count, (1, 2, 2), (2, 1), (3, 0).
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0x8F, 0x03, 0x01, 0x02, 0x02, 0x02, 0x01, 0x03, 0x00}));
  Attention back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.entries, attention.entries);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x8F, 0x01, 0x01, 0x03}, back), MessageError::value_out_of_range);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x8F, 0x41}, back), MessageError::too_many_entries);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x8F, 0x01, 0x01, 0x01, 0x00}, back), MessageError::trailing_bytes);
}

TEST(Messages, CommandsOfEveryKindRoundTrip) {
  Command express{.request_id = 3, .kind = Command::Kind::express, .emotion = "joy", .intensity = 0.7f,
                  .target = 0, .duration_ms = 2500, .sentence = "", .override_face = {}};
  Command back;
  ASSERT_EQ(read_message(bytes_of(express), back), MessageError::ok);
  EXPECT_EQ(back.emotion, "joy");
  EXPECT_FLOAT_EQ(back.intensity, 0.7f);
  EXPECT_EQ(back.duration_ms, 2500u);

  Command snub{.request_id = 4, .kind = Command::Kind::snub, .emotion = "", .intensity = 1, .target = 12,
               .duration_ms = 10000, .sentence = "", .override_face = {}};
  ASSERT_EQ(read_message(bytes_of(snub), back), MessageError::ok);
  EXPECT_EQ(back.kind, Command::Kind::snub);
  EXPECT_EQ(back.target, 12u);

  Command facs{.request_id = 5, .kind = Command::Kind::facs, .emotion = "", .intensity = 1, .target = 0,
               .duration_ms = 0, .sentence = "ClearAllFrame\nBeginKeyFrame\n\tAU12 0.8\n", .override_face = {}};
  ASSERT_EQ(read_message(bytes_of(facs), back), MessageError::ok);
  EXPECT_EQ(back.sentence, facs.sentence);
}

TEST(Messages, FaceLabCommandsAndPreviewHelloRoundTrip) {
  Command set{.request_id = 8, .kind = Command::Kind::override_face, .emotion = "", .intensity = 1, .target = 0,
              .duration_ms = 3000, .sentence = "", .override_face = {OverridePart::head_roll, 0, 0, -6000}};
  Command back;
  ASSERT_EQ(read_message(bytes_of(set), back), MessageError::ok);
  EXPECT_EQ(back.kind, Command::Kind::override_face);
  EXPECT_EQ(back.override_face, set.override_face);
  for (const OverridePart part : {OverridePart::muscle, OverridePart::skin_age, OverridePart::skin_looseness}) {
    Command physics = set;
    physics.override_face = {part, part == OverridePart::muscle ? std::uint8_t{41} : std::uint8_t{0}, 0, 10000};
    ASSERT_EQ(read_message(bytes_of(physics), back), MessageError::ok);
    EXPECT_EQ(back.override_face, physics.override_face);
  }

  // A part past the skin's looseness, or a side past right, means nothing.
  std::vector<std::uint8_t> bytes = bytes_of(set);
  bytes[bytes.size() - 5] = kLastOverridePart + 1;
  EXPECT_EQ(read_message(bytes, back), MessageError::value_out_of_range);
  bytes = bytes_of(set);
  bytes[bytes.size() - 3] = 3;
  EXPECT_EQ(read_message(bytes, back), MessageError::value_out_of_range);

  Command check{.request_id = 9, .kind = Command::Kind::check, .emotion = "", .intensity = 1, .target = 0,
                .duration_ms = 3000, .sentence = "ClearAllFrame\n\tBeginKeyFrame", .override_face = {}};
  ASSERT_EQ(read_message(bytes_of(check), back), MessageError::ok);
  EXPECT_EQ(back.sentence, check.sentence);

  // A saved look by its name: 1 .. 32 bytes of text without layout.
  Command play{.request_id = 10, .kind = Command::Kind::play_look, .emotion = "", .intensity = 1, .target = 0,
               .duration_ms = 3000, .sentence = "blush slowly", .override_face = {}};
  ASSERT_EQ(read_message(bytes_of(play), back), MessageError::ok);
  EXPECT_EQ(back.kind, Command::Kind::play_look);
  EXPECT_EQ(back.sentence, "blush slowly");
  std::vector<std::uint8_t> unnamed = bytes_of(play);
  unnamed.resize(3);
  unnamed.push_back(0);  // an empty name
  EXPECT_EQ(read_message(unnamed, back), MessageError::value_out_of_range);
  std::vector<std::uint8_t> long_name = bytes_of(play);
  long_name.resize(3);
  long_name.push_back(kMaxLookNameBytes + 1);
  long_name.insert(long_name.end(), kMaxLookNameBytes + 1, 'a');
  EXPECT_EQ(read_message(long_name, back), MessageError::string_too_long);
  std::vector<std::uint8_t> past = bytes_of(play);
  past[2] = 7;  // no kind 7
  EXPECT_EQ(read_message(past, back), MessageError::value_out_of_range);

  Hello hello;
  hello.room = "lab";
  hello.name = "Ada";
  hello.preview = true;
  Hello hello_back;
  ASSERT_EQ(read_message(bytes_of(hello), hello_back), MessageError::ok);
  EXPECT_TRUE(hello_back.preview);
}

TEST(Messages, SmallMessagesRoundTrip) {
  Chat chat{3, "hello, room"};
  Chat chat_back;
  ASSERT_EQ(read_message(bytes_of(chat), chat_back), MessageError::ok);
  EXPECT_EQ(chat_back.text, "hello, room");
  EXPECT_EQ(chat_back.from, 3u);

  CommandResult result{9, "unknown emotion 'glee'"};
  CommandResult result_back;
  ASSERT_EQ(read_message(bytes_of(result), result_back), MessageError::ok);
  EXPECT_EQ(result_back.error, result.error);

  Ping ping{42, 123456789012ull};
  Pong pong{42, 123456789012ull, 987654321ull};
  Pong pong_back;
  ASSERT_EQ(read_message(bytes_of(pong), pong_back), MessageError::ok);
  EXPECT_EQ(pong_back.server_time_us, 987654321ull);
  Ping ping_back;
  ASSERT_EQ(read_message(bytes_of(ping), ping_back), MessageError::ok);
  EXPECT_EQ(ping_back.client_time_us, 123456789012ull);

  LinkStats stats{9600, 8000, 12, 3};
  LinkStats stats_back;
  ASSERT_EQ(read_message(bytes_of(stats), stats_back), MessageError::ok);
  EXPECT_EQ(stats_back.drain_bps, 8000u);

  Closing closing{CloseCode::unauthorized, "token is for room 'a'"};
  Closing closing_back;
  ASSERT_EQ(read_message(bytes_of(closing), closing_back), MessageError::ok);
  EXPECT_EQ(closing_back.code, CloseCode::unauthorized);

  SetRate rate{4800};
  SetRate rate_back;
  ASSERT_EQ(read_message(bytes_of(rate), rate_back), MessageError::ok);
  EXPECT_EQ(rate_back.max_bps, 4800u);
}

TEST(Messages, PackageChunksStayInsideTheirPackage) {
  PackageChunk chunk{.avatar = 2, .quality = PackageChunk::Quality::full, .total_bytes = 10, .offset = 6,
                     .data = {1, 2, 3, 4}};
  auto bytes = bytes_of(chunk);
  PackageChunk back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.offset, 6u);
  EXPECT_EQ(back.data, chunk.data);
  bytes.push_back(5);  // now offset + size > total
  EXPECT_EQ(read_message(bytes, back), MessageError::value_out_of_range);
}

TEST(Messages, TimedRoomFrameWrapsACodecRoomFrame) {
  const std::vector<std::uint8_t> frame = {0x21, 0xAB, 0xCD};  // not decoded here
  std::vector<std::uint8_t> room;
  const RoomEntry entry{5, frame};
  write_room_frame({&entry, 1}, room);
  TimedRoomFrame timed{1234, 5555, room};
  const auto bytes = bytes_of(timed);
  TimedRoomFrame back;
  ASSERT_EQ(read_message(bytes, back), MessageError::ok);
  EXPECT_EQ(back.tick, 1234u);
  EXPECT_EQ(back.server_time_us, 5555u);
  std::vector<RoomEntry> entries;
  ASSERT_EQ(read_room_frame(back.room_frame, entries), DecodeError::ok);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].avatar_id, 5u);
}

TEST(Messages, ClassifyTellsCodecMessagesFromSessionMessages) {
  std::vector<std::uint8_t> resync;
  write_resync_request({}, resync);
  EXPECT_EQ(classify(resync), MessageKind::resync_request);
  EXPECT_EQ(classify(write_stream_header({})), MessageKind::stream_header);
  EXPECT_EQ(classify(std::vector<std::uint8_t>{0x23, 0x00, 0x01}), MessageKind::room_frame);
  EXPECT_EQ(classify(std::vector<std::uint8_t>{0x21}), MessageKind::invalid);  // bare key frames do not travel alone
  EXPECT_EQ(classify(std::vector<std::uint8_t>{0x80}), MessageKind::invalid);
  EXPECT_EQ(classify(std::vector<std::uint8_t>{0xFF}), MessageKind::invalid);
  EXPECT_EQ(classify(std::vector<std::uint8_t>{}), MessageKind::invalid);
}

TEST(Messages, BadBytesGiveTheirError) {
  Chat chat;
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{}, chat), MessageError::empty);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x23}, chat), MessageError::not_session_message);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0xF0}, chat), MessageError::unknown_type);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x81}, chat), MessageError::wrong_type);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x01, 0x05, 'a'}, chat), MessageError::truncated);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x81}, chat), MessageError::truncated) << "a number cut short";
  // The same numbers written in more bytes than they need, or than the
  // field allows: the bytes are all there, so the message is not cut short.
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x81, 0x00, 0x01, 'a'}, chat), MessageError::bad_number);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x01, 0x81, 0x80, 0x00, 'a'}, chat), MessageError::bad_number);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x81, 0x81, 0x81, 0x01, 0x01, 'a'}, chat),
            MessageError::bad_number)
      << "an avatar id takes at most 3 bytes";
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x01, 0x01, 'a', 'b'}, chat), MessageError::trailing_bytes);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x01, 0x01, 0x07}, chat), MessageError::bad_text);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x84, 0x01, 0x02, 0xC0, 0x80}, chat), MessageError::bad_text);
  std::vector<std::uint8_t> long_chat = {0x84, 0x01, 0xF5, 0x03};  // 501 bytes
  long_chat.resize(long_chat.size() + 501, 'x');
  EXPECT_EQ(read_message(long_chat, chat), MessageError::string_too_long);
  std::vector<std::uint8_t> huge(kMaxUpstreamMessageBytes + 1, 'x');
  huge[0] = 0x81;
  Hello hello;
  EXPECT_EQ(read_message(huge, hello), MessageError::too_large);
  Command command;
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x85, 0x01, 0x09}, command), MessageError::value_out_of_range);
  EXPECT_EQ(read_message(std::vector<std::uint8_t>{0x85, 0x01, 0x00, 0x03, 'j', 'o', 'y', 101, 0x00}, command),
            MessageError::value_out_of_range);
  for (int e = 0; e <= 14; ++e) EXPECT_FALSE(describe(static_cast<MessageError>(e)).empty());
}

TEST(Messages, EveryReaderSurvivesRandomBytes) {
  std::mt19937_64 rng(test::seed("Messages.EveryReaderSurvivesRandomBytes"));
  std::vector<std::uint8_t> bytes;
  for (int i = 0; i < 20000; ++i) {
    bytes.resize(rng() % 64);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    if (!bytes.empty()) bytes[0] = static_cast<std::uint8_t>(0x80 | (1 + rng() % 16));
    Hello a; Welcome b; Presence c; Chat d; Command e; CommandResult f; PackageChunk g;
    SetRate h; Ping k; Pong l; LinkStats m; Closing n; TimedRoomFrame o; Seats p; Attention q; Speaking s;
    (void)read_message(bytes, a); (void)read_message(bytes, b); (void)read_message(bytes, c);
    (void)read_message(bytes, d); (void)read_message(bytes, e); (void)read_message(bytes, f);
    (void)read_message(bytes, g); (void)read_message(bytes, h); (void)read_message(bytes, k);
    (void)read_message(bytes, l); (void)read_message(bytes, m); (void)read_message(bytes, n);
    (void)read_message(bytes, o); (void)read_message(bytes, p); (void)read_message(bytes, q);
    (void)read_message(bytes, s);
    EXPECT_LE(s.language.size(), kMaxLanguageBytes);
    EXPECT_LE(a.language.size(), kMaxLanguageBytes);
    EXPECT_LE(b.avatars.size(), kMaxWelcomeAvatars);
    EXPECT_LE(p.seats.size(), kMaxWelcomeAvatars);
    EXPECT_LE(q.entries.size(), kMaxWelcomeAvatars);
  }
}

TEST(TcpFraming, SplitsAStreamFedByteByByte) {
  std::vector<std::uint8_t> stream;
  const std::vector<std::uint8_t> small = {0x84, 0x00, 0x01, 'x'};
  std::vector<std::uint8_t> large(300, 0x42);
  write_tcp_frame(small, stream);
  write_tcp_frame(large, stream);
  EXPECT_EQ(stream[0], 4);
  EXPECT_EQ(stream[5], 0xAC);  // 300 = 0b10'0101100 -> 0xAC 0x02
  EXPECT_EQ(stream[6], 0x02);
  TcpDeframer deframer(kMaxUpstreamMessageBytes);
  std::vector<std::vector<std::uint8_t>> got;
  for (const std::uint8_t b : stream) {
    deframer.feed({&b, 1});
    std::span<const std::uint8_t> message;
    while (deframer.next(message) == TcpDeframer::Status::message) got.emplace_back(message.begin(), message.end());
  }
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0], small);
  EXPECT_EQ(got[1], large);
  EXPECT_EQ(deframer.buffered(), 0u);
}

TEST(TcpFraming, RefusesOversizedEmptyAndOverlongLengths) {
  std::span<const std::uint8_t> message;
  {
    TcpDeframer deframer(100);
    std::vector<std::uint8_t> prefix;
    write_length_prefix(101, prefix);
    deframer.feed(prefix);
    EXPECT_EQ(deframer.next(message), TcpDeframer::Status::error);
    EXPECT_EQ(deframer.error(), MessageError::too_large);
  }
  {
    TcpDeframer deframer(100);
    const std::uint8_t zero = 0;
    deframer.feed({&zero, 1});
    EXPECT_EQ(deframer.next(message), TcpDeframer::Status::error);
    EXPECT_EQ(deframer.error(), MessageError::empty);
  }
  {
    TcpDeframer deframer(100);
    const std::vector<std::uint8_t> overlong = {0x85, 0x00};
    deframer.feed(overlong);
    EXPECT_EQ(deframer.next(message), TcpDeframer::Status::error);
  }
  {
    TcpDeframer deframer(kMaxDownstreamMessageBytes);
    const std::vector<std::uint8_t> four_bytes = {0xFF, 0xFF, 0xFF, 0x01};
    deframer.feed(four_bytes);
    EXPECT_EQ(deframer.next(message), TcpDeframer::Status::error);
    EXPECT_EQ(deframer.error(), MessageError::too_large);
  }
}

}  // namespace
}  // namespace fw::codec
