// ClusterNode (cluster_node.hpp): the per-address limits and the join
// tokens in use, told to and heard from the other nodes (cluster_limits.hpp).
#include "client_session.hpp"
#include "cluster_keys.hpp"
#include "cluster_limits.hpp"
#include "cluster_node.hpp"

namespace fw::server {

namespace keys = cluster_keys;

void ClusterNode::share_limits() {
  LimitsNews news;
  news.node = node_;
  news.beat = true;
  news.spent = context_.addresses->take_spending();
  news.connections = context_.addresses->connection_counts();
  news.tokens = context_.tokens.held_here();
  commands_->command({"PUBLISH", keys::kLimitsChannel, encode_limits(news)});
}

void ClusterNode::apply_limits(std::string_view message) {
  auto news = decode_limits(message);
  if (!news || news->node == node_) return;
  const auto now = std::chrono::steady_clock::now();
  for (const auto& spent : news->spent) context_.addresses->charge(spent.rate, spent.key, spent.tokens, now);
  if (news->beat) context_.addresses->set_remote_connections(news->node, std::move(news->connections));
  // A hold lasts a few beats unless told again (a node that dies stops telling).
  for (const auto& token : news->tokens) {
    context_.tokens.remote_news(news->node, token, now + std::chrono::seconds(3));
    if (token.taken_from != node_) continue;
    if (auto holder = context_.tokens.give_way(token.token_hash))
      holder->close(codec::CloseCode::unauthorized, "replaced by your newer connection");
  }
}


}  // namespace fw::server
