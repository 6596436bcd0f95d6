#include "join_token.hpp"

#include <gtest/gtest.h>

namespace fw::server {
namespace {

constexpr std::int64_t kNow = 1'800'000'000;

TEST(JoinToken, AdmitsItsRoomAndName) {
  const std::string token = mint_join_token({"a", "Ann", kNow + 60}, "secret");
  EXPECT_EQ(token.rfind("fw1.", 0), 0u);
  EXPECT_EQ(check_join_token(token, "secret", "a", "Ann", kNow), "");
}

TEST(JoinToken, WithoutANameAdmitsAnyName) {
  const std::string token = mint_join_token({"a", "", kNow + 60}, "secret");
  EXPECT_EQ(check_join_token(token, "secret", "a", "Whoever", kNow), "");
}

TEST(JoinToken, RefusesAnotherRoomAnotherNameAndExpiry) {
  const std::string token = mint_join_token({"a", "Ann", kNow + 60}, "secret");
  EXPECT_NE(check_join_token(token, "secret", "b", "Ann", kNow).find("another room"), std::string::npos);
  EXPECT_NE(check_join_token(token, "secret", "a", "Eve", kNow).find("another name"), std::string::npos);
  EXPECT_NE(check_join_token(token, "secret", "a", "Ann", kNow + 61).find("expired"), std::string::npos);
}

TEST(JoinToken, RefusesAnotherSecretAndTampering) {
  const std::string token = mint_join_token({"a", "Ann", kNow + 60}, "secret");
  EXPECT_NE(check_join_token(token, "other", "a", "Ann", kNow).find("signature"), std::string::npos);
  // Swap in a payload for room b, keeping the signature of room a's.
  const std::string for_b = mint_join_token({"b", "Ann", kNow + 60}, "secret");
  const std::string forged = for_b.substr(0, for_b.rfind('.')) + token.substr(token.rfind('.'));
  EXPECT_NE(check_join_token(forged, "secret", "b", "Ann", kNow).find("signature"), std::string::npos);
  for (const char* junk : {"", "fw1.", "fw1..", "x.y.z", "fw1.!!!.???", "fw2.abc.def"})
    EXPECT_NE(check_join_token(junk, "secret", "a", "Ann", kNow), "") << junk;
}

}  // namespace
}  // namespace fw::server
