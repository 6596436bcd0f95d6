#include "fw/facegen/generate_generic_face.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "fw/model/face_asset.hpp"
#include "test_paths.hpp"

namespace fw::facegen {
namespace {

std::string committed_asset() {
  std::ifstream in(fw::test::source_path("avatar/model/assets/generic_face.json"), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(GenerateGenericFace, IsSound) {
  const auto problems = model::validate_generic_face(generate_generic_face());
  for (const auto& p : problems) ADD_FAILURE() << p;
}

TEST(GenerateGenericFace, IsDeterministic) {
  EXPECT_EQ(model::serialize_face_asset(generate_generic_face()), model::serialize_face_asset(generate_generic_face()));
}

// The committed asset is what every binary embeds and the web client loads:
// it must be what the generator makes now. After changing the generator, run
// `make facegen` and commit the result. The action units' vertex fields are
// the physics face's (facewire-aubasis, checked by tests/physics); everything
// else, the texture slides included, must be this generator's.
TEST(GenerateGenericFace, MatchesTheCommittedAsset) {
  const std::string committed = committed_asset();
  ASSERT_FALSE(committed.empty()) << "avatar/model/assets/generic_face.json is missing";
  model::GenericFace committed_face;
  std::string error;
  ASSERT_TRUE(model::parse_face_asset(committed, committed_face, error)) << error;
  model::GenericFace face = generate_generic_face();
  for (std::size_t c = 0; c < face.action_units.size(); ++c)
    face.action_units[c].vertex_delta = committed_face.action_units[c].vertex_delta;
  face.correctives = committed_face.correctives;  // facewire-correctives' (tests/physics checks them)
  const std::string generated = model::serialize_face_asset(face);
  if (generated == committed) return;
  // Report where they part, so a stale asset is easy to recognise.
  std::size_t line = 1, at = 0;
  while (at < generated.size() && at < committed.size() && generated[at] == committed[at]) line += generated[at++] == '\n';
  FAIL() << "the committed generic face differs from the generator's output from line " << line
         << "; run `make facegen` and commit avatar/model/assets/generic_face.json";
}

}  // namespace
}  // namespace fw::facegen
