// ClusterNode (cluster_node.hpp): the per-address limits and the join
// tokens in use, told to and heard from the other nodes (cluster_limits.hpp).
#include <algorithm>

#include "client_session.hpp"
#include "cluster_keys.hpp"
#include "cluster_limits.hpp"
#include "cluster_node.hpp"

namespace fw::server {

namespace keys = cluster_keys;

namespace {
// What another node says of an address counts this long after it said it
// (six beats: a node that misses a beat or two under load loses nothing):
// its connections, unless said again; its spending, as the longest it can
// make the address wait for its next token here.
constexpr auto kRemoteNewsLife = std::chrono::seconds(3);
}  // namespace

void ClusterNode::share_limits() {
  LimitsNews news;
  news.node = node_;
  news.beat = true;
  news.spent = services_.addresses.take_spending();
  // Past a burst, spending says nothing more (a bucket holds no more), and
  // the others refuse a report of more than an address can spend.
  for (auto& spent : news.spent)
    spent.tokens = std::min(spent.tokens, rate_of(services_.config.abuse, spent.rate).burst);
  news.connections = services_.addresses.connection_counts();
  news.tokens = services_.tokens.held_here();
  commands_->command({"PUBLISH", keys::kLimitsChannel, encode_limits(news)});
}

void ClusterNode::apply_limits(LimitsNews news) {
  const auto now = std::chrono::steady_clock::now();
  for (const auto& spent : news.spent)
    services_.addresses.charge(spent.rate, spent.key, spent.tokens, now, kRemoteNewsLife);
  if (news.beat)
    services_.addresses.set_remote_connections(news.node, std::move(news.connections), now, now + kRemoteNewsLife);
  // A hold lasts a few beats unless told again (a node that dies stops telling).
  for (const auto& token : news.tokens) {
    services_.tokens.remote_news(news.node, token, now + kRemoteNewsLife);
    if (token.taken_from != node_) continue;
    if (auto holder = services_.tokens.give_way(token.token_hash))
      holder->close(codec::CloseCode::unauthorized, "replaced by your newer connection");
  }
}


}  // namespace fw::server
