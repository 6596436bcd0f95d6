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

TEST(JoinToken, ANameIsComparedInNfcHoweverTheTokenSpellsIt) {
  // Minted elsewhere with a decomposed "é"; hellos' names arrive in NFC.
  const std::string token = mint_join_token({"a", "Zoe\u0301", kNow + 60}, "secret");
  EXPECT_EQ(check_join_token(token, "secret", "a", "Zo\u00e9", kNow), "");
  const std::string bidi = mint_join_token({"a", "\u202Eevil", kNow + 60}, "secret");
  EXPECT_NE(check_join_token(bidi, "secret", "a", "\u202Eevil", kNow).find("cannot be a display name"),
            std::string::npos);
}

TEST(JoinToken, WithoutANameAdmitsNobody) {
  // Signed and in date, but it names nobody: it would admit anyone who saw it.
  const std::string token = mint_join_token({"a", "", kNow + 60}, "secret");
  EXPECT_NE(check_join_token(token, "secret", "a", "Whoever", kNow).find("names nobody"), std::string::npos);
  std::string why;
  EXPECT_FALSE(verify_join_token(token, "secret", kNow, why));
  EXPECT_NE(why.find("--name"), std::string::npos) << why;
}

TEST(JoinToken, TheSignatureHasOneSpelling) {
  // A 32-byte signature is 43 base64url characters: the last carries 4
  // bits of it and 2 unused bits. Setting an unused bit spells the same
  // bytes another way; a second spelling would let a token be altered and
  // still pass, so it is refused.
  const std::string token = mint_join_token({"a", "Ann", kNow + 60}, "secret");
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
  std::string other = token;
  const auto last = alphabet.find(other.back());
  ASSERT_EQ(last % 4, 0u) << "the unused bits are zero in the canonical spelling";
  other.back() = alphabet[last + 1];
  EXPECT_NE(check_join_token(other, "secret", "a", "Ann", kNow), "");
  EXPECT_NE(check_join_token(token + "A", "secret", "a", "Ann", kNow), "") << "a dangling character";
  EXPECT_EQ(check_join_token(token, "secret", "a", "Ann", kNow), "");
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
