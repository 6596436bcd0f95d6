#include "fw/codec/codec.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <gtest/gtest.h>

#include "frame_reader.hpp"
#include "fw/codec/messages.hpp"
#include "golden_vectors.hpp"
#include "fw/behavior/scene_file.hpp"
#include "test_paths.hpp"

namespace fw::codec {
namespace {

const std::filesystem::path kDir = std::filesystem::path(fw::test::source_dir()) / "tests" / "vectors" / "codec";

std::vector<std::uint8_t> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in, nullptr, false);
}

class GoldenVector : public ::testing::TestWithParam<vectors::VectorSpec> {
 protected:
  // The committed vector: its JSON, its messages, and the faces it encodes.
  void SetUp() override {
    const auto& spec = GetParam();
    json_ = read_json(kDir / (spec.name + ".json"));
    ASSERT_FALSE(json_.is_discarded()) << "missing or broken " << spec.name << ".json: run the codec_vectors target";
    std::vector<std::vector<std::uint8_t>> bytes;
    ASSERT_TRUE(vectors::from_stream_file(read_bytes(kDir / (spec.name + ".fwc")), bytes));
    ASSERT_EQ(bytes.size(), json_["messages"].size());
    for (std::size_t i = 0; i < bytes.size(); ++i) messages_.push_back({json_["messages"][i]["tick"].get<int>(), bytes[i]});
    behavior::Scene scene;
    std::string error;
    ASSERT_TRUE(behavior::read_scene((kDir / (spec.name + ".fwscene")).string(), scene, error)) << error;
    spec_ = spec;
    spec_.inputs.clear();
    for (const auto& a : scene.avatars) spec_.inputs.push_back(a.ticks);
  }
  nlohmann::json json_;
  std::vector<vectors::Message> messages_;
  vectors::VectorSpec spec_;
};

TEST_P(GoldenVector, DecodesToTheCommittedValues) {
  const vectors::Decoded decoded = vectors::decode_vector(spec_, messages_);
  for (std::size_t m = 0; m < messages_.size(); ++m)
    ASSERT_EQ(nlohmann::json(decoded.errors[m]), json_["messages"][m]["errors"]) << "message " << m;
  ASSERT_EQ(decoded.shown.size(), json_["shown"].size());
  for (std::size_t t = 0; t < decoded.shown.size(); ++t)
    for (std::size_t a = 0; a < decoded.shown[t].size(); ++a)
      ASSERT_EQ(nlohmann::json(decoded.shown[t][a]), json_["shown"][t][a]) << "tick " << t << " avatar " << a;
  for (std::size_t a = 0; a < decoded.final_faces.size(); ++a)
    for (std::size_t c = 0; c < kChannelCount; ++c)
      EXPECT_EQ(channel_value(decoded.final_faces[a], c), json_["final_faces"][a][c].get<float>()) << c;
}

TEST_P(GoldenVector, TheEncoderStillProducesItByteForByte) {
  EXPECT_EQ(json_["encoder"]["target_bps"].get<double>(), spec_.options.target_bps);
  EXPECT_EQ(json_["encoder"]["loss_tolerant"].get<bool>(), spec_.options.stream.loss_tolerant);
  EXPECT_EQ(json_["dropped_frames"], nlohmann::json(spec_.dropped_frames));
  const auto fresh = vectors::encode_vector(spec_);
  ASSERT_EQ(fresh.size(), messages_.size()) << "a change to a vector is a change of format version (FORMAT.md)";
  for (std::size_t m = 0; m < fresh.size(); ++m) {
    ASSERT_EQ(fresh[m].tick, messages_[m].tick) << "message " << m;
    ASSERT_EQ(fresh[m].bytes, messages_[m].bytes) << "message " << m;
  }
}

INSTANTIATE_TEST_SUITE_P(Codec, GoldenVector, ::testing::ValuesIn(vectors::vector_specs()),
                         [](const auto& param_info) { return param_info.param.name; });

TEST(GoldenVectors, CoverEveryFrameTypeErrorAndCodingTool) {
  std::set<int> types, levels, dampings;
  std::set<std::string> errors;
  bool velocity = false, partner_same = false;
  for (const auto& spec : vectors::vector_specs()) {
    const auto json = read_json(kDir / (spec.name + ".json"));
    ASSERT_FALSE(json.is_discarded());
    for (const auto& m : json["messages"])
      for (const auto& e : m["errors"]) errors.insert(e.get<std::string>());
    std::vector<std::vector<std::uint8_t>> messages;
    ASSERT_TRUE(vectors::from_stream_file(read_bytes(kDir / (spec.name + ".fwc")), messages));
    CodingState state(spec.options.stream.max_extrapolation_ticks);
    for (std::size_t i = 0; i < messages.size(); ++i) {
      types.insert(messages[i][0] & 0x0F);
      if (spec.room || i == 0) continue;
      const auto type = static_cast<FrameType>(messages[i][0] & 0x0F);
      CodingState next = state;
      std::uint32_t delta = 0;
      if (read_frame_payload(next, type, std::span(messages[i]).subspan(spec.options.stream.loss_tolerant ? 2 : 1), delta) !=
          DecodeError::ok)
        continue;  // a frame after a gap: the decoder refused it too
      state = next;
      levels.insert(state.level);
      for (std::size_t c = 0; c < kChannelCount; ++c) {
        dampings.insert(state.reconstruction.damping(c));
        velocity = velocity || state.reconstruction.velocity(c) != 0;
      }
      const QuantisedParams fields = fields_from_coded(state.reconstruction.shown_all());
      partner_same = partner_same || (fields[1] == fields[0] && fields[0] != 0);
    }
  }
  EXPECT_EQ(types, (std::set<int>{0, 1, 2, 3})) << "stream header, key, predicted, room";
  for (const char* e : {"ok", "sequence_gap", "awaiting_key_frame", "stale_frame"}) EXPECT_TRUE(errors.count(e)) << e;
  EXPECT_GE(levels.size(), 3u);
  EXPECT_GE(dampings.size(), 3u) << "linear and damped velocities";
  EXPECT_TRUE(velocity);
  EXPECT_TRUE(partner_same);
}

TEST(GoldenVectors, AVersionOneStreamIsRefusedWithASentenceSayingWhatToDo) {
  // The committed stream of format version 1 (before the corrective
  // channels): its header and every frame are refused, never misread.
  std::vector<std::vector<std::uint8_t>> messages;
  ASSERT_TRUE(vectors::from_stream_file(read_bytes(kDir / "version1" / "avatar_basic.fwc"), messages));
  ASSERT_GT(messages.size(), 2u);
  StreamOptions options;
  EXPECT_EQ(read_stream_header(messages.front(), options), DecodeError::unsupported_version);
  EXPECT_EQ(classify(messages.front()), MessageKind::stream_header) << "refused by the codec, which says why";
  Decoder decoder(options);
  for (std::size_t i = 1; i < messages.size(); ++i)
    EXPECT_EQ(decoder.decode(messages[i]), DecodeError::unsupported_version) << "message " << i;
  EXPECT_TRUE(decoder.needs_key_frame());
  const std::string why(describe(DecodeError::unsupported_version));
  EXPECT_NE(why.find("reload"), std::string::npos) << why;
  EXPECT_NE(why.find("update"), std::string::npos) << why;
}

TEST(GoldenVectors, ErrorCasesStillGiveTheirCommittedCodes) {
  const auto committed = read_json(kDir / "errors.json");
  ASSERT_FALSE(committed.is_discarded());
  EXPECT_EQ(vectors::error_cases(), committed) << "a change here is a change of format version";
  std::set<std::string> seen;
  for (const auto& c : committed) seen.insert(c["error"].get<std::string>());
  for (int e = 0; e <= 18; ++e) {
    const std::string name = vectors::error_name(static_cast<DecodeError>(e));
    // awaiting_key_frame, sequence_gap and stale_frame also come from the stream vectors.
    if (name == "too_many_avatars" || name == "duplicate_avatar") {
      EXPECT_TRUE(seen.count(name)) << name;
    }
  }
  EXPECT_GE(seen.size(), 17u) << "nearly every code is exercised";
}

}  // namespace
}  // namespace fw::codec
