#pragma once
// What must hold across the nodes of a cluster and is counted where people
// connect: the per-address limits and the join tokens in use. Each node
// tells the others over Redis pub/sub (channel cluster_keys::kLimitsChannel)
// twice a second what each address spent of its rates there, how many
// connections each address holds there, and which tokens its connections
// hold; a token taken or let go is told at once. Addresses and token hashes
// only: no token crosses Redis.
//
// One line per item, so that a message is easy to read in `redis-cli
// subscribe` while debugging:
//   node NAME            the sender (first line)
//   beat                 the connection counts below are all the sender's
//   s RATE TOKENS KEY    an address spent TOKENS of AddressRate RATE
//   c COUNT KEY          an address holds COUNT connections
//   t HASH RESUME [FROM] a token held, by the connection with that resume key
//                        (taken over from node FROM)
//   r HASH               a token let go
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "address_limits.hpp"
#include "token_holders.hpp"

namespace fw::server {

struct LimitsNews {
  std::string node;
  bool beat = false;
  std::vector<AddressLimits::Spent> spent;
  std::map<std::string, std::size_t> connections;
  std::vector<TokenNews> tokens;
};

std::string encode_limits(const LimitsNews& news);
/// nullopt for a message that is not one (it is ignored).
std::optional<LimitsNews> decode_limits(std::string_view message);

}  // namespace fw::server
