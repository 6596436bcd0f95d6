// Writes the seed corpora of the fuzz targets whose inputs this version's
// code makes: session_message_fuzz (one message of every type),
// tcp_framing_fuzz (framed conversations, whole and in pieces),
// join_token_fuzz (admitted tokens of every making) and photo_header_fuzz
// (small photos of each format). Run it after a change to what they read,
// from the clone:
//   build/bin/fuzz_make_seeds tests/fuzz/corpus
// Each of the four folders is made anew (whatever else was in it goes).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "fw/codec/codec.hpp"
#include "fw/codec/messages.hpp"
#include "join_token_fuzz_input.hpp"
#include "sample_messages.hpp"
#include "tcp_framing_fuzz_input.hpp"

namespace fs = std::filesystem;

namespace {

using namespace fw::codec;
using Bytes = std::vector<std::uint8_t>;

class Folder {
 public:
  Folder(const fs::path& corpus, const std::string& target) : dir_(corpus / target) {
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void write(const std::string& name, const Bytes& bytes) {
    std::ofstream out(dir_ / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + (dir_ / name).string());
    ++count_;
  }
  ~Folder() { std::cout << dir_.string() << ": " << count_ << " seeds\n"; }

 private:
  fs::path dir_;
  int count_ = 0;
};

template <class M>
Bytes bytes_of(const M& message) {
  Bytes out;
  write_message(message, out);
  return out;
}

/// A room frame with one key frame of a face at rest, as a room sends it.
Bytes room_frame_bytes() {
  EncoderOptions options;
  options.target_bps = 100000;
  Encoder encoder(options);
  Bytes key;
  if (!encoder.encode(FaceParams{}, key)) throw std::logic_error("the encoder made no key frame");
  Bytes other = key;
  const RoomEntry entries[] = {{7, key}, {300, other}};
  Bytes out;
  write_room_frame(entries, out);
  return out;
}

struct Messages {
  Bytes hello, hello_v3, hello_minimal, welcome, welcome_v3, presence_joined, presence_left, chat_up, chat_down, command_express,
      command_look_at, command_snub, command_facs, command_override, command_check, hello_preview, command_accepted, command_refused, package_chunk, package_chunk_large,
      set_rate, ping, pong, link_stats, closing, timed_room_frame, seats, attention, speaking, unit_morphs, unit_morphs_restored, preview_surface, stream_header,
      stream_header_loss_tolerant, resync_request, room_frame;
};

Messages make_messages() {
  Messages m;
  m.hello = bytes_of(fw::test::sample_hello());
  m.hello_v3 = bytes_of(fw::test::sample_hello_v3());
  Hello minimal;
  minimal.room = "r";
  minimal.name = "A";
  minimal.no_packages = true;
  m.hello_minimal = bytes_of(minimal);
  Welcome welcome;
  welcome.you = 300;
  welcome.room = "r-1.x";
  welcome.max_bps = 56000;
  welcome.avatars = {{1, "Ada", "", 0, 0, false, {-364.0f, 0.0f, 210.0f, 1.0471f}},
                     {300, "Bo 🙂", "ffeeddccbbaa99887766554433221100", 1100, 19652, true, {0, 0, -40.0f, -3.1415f}}};
  m.welcome = bytes_of(welcome);
  welcome.protocol_version = 3;
  m.welcome_v3 = bytes_of(welcome);
  m.presence_joined = bytes_of(Presence{Presence::Change::joined, welcome.avatars[1]});
  m.presence_left = bytes_of(Presence{Presence::Change::left, {300, "", "", 0, 0, true, {}}});
  m.chat_up = bytes_of(Chat{0, "hello, room — ça va?"});
  m.chat_down = bytes_of(Chat{300, "hi"});
  m.command_express = bytes_of(Command{.request_id = 70000, .kind = Command::Kind::express, .emotion = "joy",
                                       .intensity = 0.7f, .target = 0, .duration_ms = 2500, .sentence = ""});
  m.command_look_at = bytes_of(Command{.request_id = 2, .kind = Command::Kind::look_at, .emotion = "", .intensity = 1,
                                       .target = 2097151, .duration_ms = 600000, .sentence = ""});
  m.command_snub = bytes_of(Command{.request_id = 3, .kind = Command::Kind::snub, .emotion = "", .intensity = 1,
                                    .target = 5, .duration_ms = 0, .sentence = ""});
  m.command_facs = bytes_of(Command{.request_id = 4, .kind = Command::Kind::facs, .emotion = "", .intensity = 1,
                                    .target = 0, .duration_ms = 3000, .sentence = "AU12 0.8\n\tAU6 0.5"});
  m.command_override = bytes_of(Command{.request_id = 5, .kind = Command::Kind::override_face, .emotion = "",
                                        .intensity = 1, .target = 0, .duration_ms = 3000, .sentence = "",
                                        .override_face = {OverridePart::action_unit, 12, 2, -3}});
  m.command_check = bytes_of(Command{.request_id = 6, .kind = Command::Kind::check, .emotion = "", .intensity = 1,
                                     .target = 0, .duration_ms = 3000, .sentence = "ClearAllFrame\nBeginKeyFrame"});
  Hello preview = minimal;
  preview.preview = true;
  m.hello_preview = bytes_of(preview);
  m.command_accepted = bytes_of(CommandResult{4, ""});
  m.command_refused = bytes_of(CommandResult{5, "no such action unit"});
  m.package_chunk = bytes_of(PackageChunk{7, PackageChunk::Quality::preview, 20000, 16000, {1, 2, 3, 250, 0}});
  m.package_chunk_large = bytes_of(
      PackageChunk{7, PackageChunk::Quality::full, 40000, 0, Bytes(kMaxChunkBytes, 0x5A)});
  m.set_rate = bytes_of(SetRate{2400});
  m.ping = bytes_of(Ping{0xDEADBEEF, 1234567890123ull});
  m.pong = bytes_of(Pong{1, 2, 4503599627370495ull});
  m.link_stats = bytes_of(LinkStats{9600, 9100, 312, 4000000000u});
  m.closing = bytes_of(Closing{CloseCode::room_full, "room 'x' is full (16 avatars); try another room"});
  m.room_frame = room_frame_bytes();
  m.timed_room_frame = bytes_of(TimedRoomFrame{77, 99999999, m.room_frame});
  Seats seats;
  seats.seats = {{1, {-420.0f, 0.0f, 113.0f, 0.8727f}}, {2, {420.0f, 12.0f, 113.0f, -0.8727f}}};
  m.seats = bytes_of(seats);
  Attention attention;
  attention.entries = {{1, AttentionTarget::avatar, 2}, {2, AttentionTarget::room, 0}, {3, AttentionTarget::nobody, 0}};
  m.attention = bytes_of(attention);
  m.speaking = bytes_of(fw::test::sample_speaking());
  m.unit_morphs = bytes_of(fw::test::sample_unit_morphs());
  m.unit_morphs_restored = bytes_of(UnitMorphs{.avatar = 2097151, .version = 4294967295u, .units = {}});
  m.preview_surface = bytes_of(fw::test::sample_preview_surface());
  m.stream_header = write_stream_header(StreamOptions{});
  m.stream_header_loss_tolerant = write_stream_header(StreamOptions{true, 20, 0});
  const std::uint32_t ids[] = {1, 2, 300};
  write_resync_request(ids, m.resync_request);
  return m;
}

void session_messages(const fs::path& corpus, const Messages& m) {
  Folder f(corpus, "session_message_fuzz");
  f.write("hello", m.hello);
  f.write("hello_v3", m.hello_v3);
  f.write("hello_minimal", m.hello_minimal);
  f.write("welcome", m.welcome);
  f.write("welcome_v3", m.welcome_v3);
  f.write("presence_joined", m.presence_joined);
  f.write("presence_left", m.presence_left);
  f.write("chat_up", m.chat_up);
  f.write("chat_down", m.chat_down);
  f.write("command_express", m.command_express);
  f.write("command_look_at", m.command_look_at);
  f.write("command_snub", m.command_snub);
  f.write("command_facs", m.command_facs);
  f.write("command_override", m.command_override);
  f.write("command_check", m.command_check);
  f.write("hello_preview", m.hello_preview);
  f.write("command_accepted", m.command_accepted);
  f.write("command_refused", m.command_refused);
  f.write("package_chunk", m.package_chunk);
  f.write("set_rate", m.set_rate);
  f.write("ping", m.ping);
  f.write("pong", m.pong);
  f.write("link_stats", m.link_stats);
  f.write("closing", m.closing);
  f.write("timed_room_frame", m.timed_room_frame);
  f.write("seats", m.seats);
  f.write("attention", m.attention);
  f.write("speaking", m.speaking);
  f.write("unit_morphs", m.unit_morphs);
  f.write("unit_morphs_restored", m.unit_morphs_restored);
  f.write("preview_surface", m.preview_surface);
  f.write("stream_header", m.stream_header);
  f.write("stream_header_loss_tolerant", m.stream_header_loss_tolerant);
  f.write("resync_request", m.resync_request);
  f.write("room_frame", m.room_frame);
}

Bytes framed(const std::vector<const Bytes*>& messages) {
  Bytes stream;
  for (const Bytes* m : messages) write_tcp_frame(*m, stream);
  return stream;
}

void tcp_framing(const fs::path& corpus, const Messages& m) {
  using fw::fuzz::TcpFramingInput;
  constexpr std::uint8_t all = TcpFramingInput::kAllAtOnce;
  Folder f(corpus, "tcp_framing_fuzz");
  const Bytes up = framed({&m.hello, &m.ping, &m.chat_up, &m.command_express, &m.command_facs, &m.set_rate,
                           &m.resync_request});
  f.write("client_to_server", TcpFramingInput::make(false, {all, all, all, all}, up));
  f.write("client_to_server_in_pieces", TcpFramingInput::make(false, {0, 2, 6, 30}, up));
  const Bytes down = framed({&m.welcome, &m.stream_header, &m.attention, &m.timed_room_frame, &m.presence_joined,
                             &m.seats, &m.speaking, &m.unit_morphs, &m.preview_surface, &m.chat_down, &m.package_chunk_large, &m.room_frame, &m.link_stats, &m.pong,
                             &m.closing});
  f.write("server_to_client", TcpFramingInput::make(true, {all, all, all, all}, down));
  f.write("server_to_client_in_pieces", TcpFramingInput::make(true, {254, 0, 127, 9}, down));
  // One message as long as a client may send.
  Bytes longest(kMaxUpstreamMessageBytes, 'x');
  longest[0] = 0x84;
  f.write("longest_upstream", TcpFramingInput::make(false, {all, all, all, all}, framed({&longest, &m.ping})));
}

void join_tokens(const fs::path& corpus) {
  using fw::fuzz::JoinTokenInput;
  using fw::fuzz::TokenMaking;
  Folder f(corpus, "join_token_fuzz");
  constexpr std::int64_t now = 1'700'000'000;
  f.write("minted", JoinTokenInput::make(TokenMaking::minted, true, now, 100, "s3cret", "lobby", "Zoë", "", 10, 5));
  f.write("minted_expiring_now",
          JoinTokenInput::make(TokenMaking::minted, true, now, 0, "a much longer secret, of 40 bytes or so",
                               "r-1.x", "Bo 🙂", "", 42, 63));
  f.write("signed", JoinTokenInput::make(TokenMaking::signed_, true, now, 0, "s3cret", "lobby", "Ada",
                                         R"({"room":"lobby","exp":1700000100,"name":"Ada"})", 0, 1));
  f.write("signed_more_fields",
          JoinTokenInput::make(TokenMaking::signed_, false, now, 0, "", "r", "Z\xc3\xb6" "e",
                               R"( {"name":"Z\u00f6e", "exp":1700000000, "room":"r", "x":[1,2.5,{"y":null}]} )"));
  const std::string token =
      fw::fuzz::signed_token(R"({"room":"lobby","exp":1700000100,"name":"Ada"})", "s3cret");
  f.write("raw", JoinTokenInput::make(TokenMaking::raw, true, now, 0, "s3cret", "lobby", "Ada", token, 7, 7));
}

void photos(const fs::path& corpus) {
  Folder f(corpus, "photo_header_fuzz");
  cv::Mat colour(12, 16, CV_8UC3), grey(9, 7, CV_8UC1), alpha(10, 10, CV_8UC4);
  cv::randu(colour, 0, 255);
  cv::randu(grey, 0, 255);
  cv::randu(alpha, 0, 255);
  const auto encoded = [&](const std::string& name, const cv::Mat& image, const std::string& extension,
                           const std::vector<int>& parameters) {
    std::vector<uchar> bytes;
    if (!cv::imencode(extension, image, bytes, parameters)) throw std::runtime_error("cannot encode " + name);
    f.write(name, Bytes(bytes.begin(), bytes.end()));
  };
  encoded("colour.png", colour, ".png", {});
  encoded("grey.png", grey, ".png", {});
  encoded("alpha.png", alpha, ".png", {});
  encoded("colour.jpg", colour, ".jpg", {cv::IMWRITE_JPEG_QUALITY, 50});
  encoded("grey.jpg", grey, ".jpg", {});
  encoded("progressive.jpg", colour, ".jpg", {cv::IMWRITE_JPEG_PROGRESSIVE, 1});
  encoded("lossy.webp", colour, ".webp", {cv::IMWRITE_WEBP_QUALITY, 50});
  encoded("lossless.webp", colour, ".webp", {cv::IMWRITE_WEBP_QUALITY, 101});
  encoded("alpha.webp", alpha, ".webp", {cv::IMWRITE_WEBP_QUALITY, 50});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: fuzz_make_seeds CORPUS_DIR (tests/fuzz/corpus in the clone)\n";
    return 2;
  }
  try {
    const fs::path corpus = argv[1];
    const Messages messages = make_messages();
    session_messages(corpus, messages);
    tcp_framing(corpus, messages);
    join_tokens(corpus);
    photos(corpus);
  } catch (const std::exception& e) {
    std::cerr << "fuzz_make_seeds: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
