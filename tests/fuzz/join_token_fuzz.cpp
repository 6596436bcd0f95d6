// Fuzzes check_join_token (server/identity/join_token.hpp), which stands between
// anyone who can reach the server and its rooms when --auth-secret is set.
// The token is the input's own text, a payload of the input's signed here
// with its secret (so that the fuzzer reaches the payload's reader, past a
// signature it could never guess), or mint_join_token's for the input's
// room and name (join_token_fuzz_input.hpp has the layout). Whatever the
// bytes: no crash, and a reason whenever the token is refused. A minted
// token admits its own room and name until it expires, when the name is a
// display name as a hello brings it (in NFC; names are compared so). An admitted token
// admits no other room and no other name (a token binds one person), and
// no other spelling of its signature (PROTOCOL.md, "Join tokens").
// Seeded with admitted tokens of every making (corpus/join_token_fuzz,
// written by fuzz_make_seeds).
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "display_name.hpp"
#include "join_token.hpp"
#include "join_token_fuzz_input.hpp"
#include "seed_check.hpp"

namespace {

using fw::fuzz::JoinTokenInput;
using fw::fuzz::TokenMaking;
using fw::fuzz::kBase64urlAlphabet;

bool admits(const std::string& token, const JoinTokenInput& in, std::string_view room, std::string_view name) {
  return fw::server::check_join_token(token, in.secret, room, name, in.now).empty();
}

/// Whether a hello could bring `name` as it is: a display name, in NFC.
bool hello_name(std::string_view name) {
  std::string normalized;
  return fw::server::normalize_display_name(name, normalized).empty() && normalized == name;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto in = JoinTokenInput::parse({data, size});
  if (!in) return 0;
  std::string token;
  switch (in->making) {
    case TokenMaking::raw: token = in->text; break;
    case TokenMaking::signed_: token = fw::fuzz::signed_token(in->text, in->secret); break;
    case TokenMaking::minted:
      // The payload is JSON, which holds UTF-8 only: mint_join_token throws
      // on other bytes, and its callers check the room and name first.
      try {
        token = fw::server::mint_join_token({std::string(in->room), std::string(in->name), in->expires}, in->secret);
      } catch (const std::exception&) {
        return 0;
      }
      break;
  }
  const std::string why = fw::server::check_join_token(token, in->secret, in->room, in->name, in->now);
  if (!why.empty()) {
    if (in->making == TokenMaking::minted && hello_name(in->name) && in->expires >= in->now) std::abort();
    fw::fuzz::seed_refused(why);
    return 0;
  }
  // Admitted: for this room and this name only.
  if (admits(token, *in, std::string(in->room) + "~", in->name)) std::abort();
  if (admits(token, *in, in->room, std::string(in->name) + "~")) std::abort();
  // One spelling of the signature: any character changed refuses it.
  if (in->change_signature) {
    const auto dot = token.rfind('.');
    if (dot == std::string::npos || dot + 1 == token.size()) std::abort();
    const std::size_t signature_bytes = token.size() - dot - 1;
    std::string changed = token;
    char& c = changed[dot + 1 + in->change_at % signature_bytes];
    const char to = kBase64urlAlphabet[in->change_to % kBase64urlAlphabet.size()];
    if (c != to) {
      c = to;
      if (admits(changed, *in, in->room, in->name)) std::abort();
    }
  }
  return 0;
}
