// ClusterNode (cluster_node.hpp): who may say what on the cluster's
// channels. Anyone who reaches Redis can publish there, so a message is
// believed only when it reads as one a node of this build sends
// (cluster_message_check.hpp) and comes from a node in a position to send
// it: a room's news from the holder of its lease, requests and limits news
// from a node alive in Redis. The rest is dropped, counted in /metrics
// (refusals of kind cluster_message) and logged at a bounded rate.
#include "cluster_keys.hpp"
#include "cluster_message_check.hpp"
#include "cluster_node.hpp"
#include "log_text.hpp"
#include "room.hpp"
#include "room_registry.hpp"

namespace fw::server {

namespace keys = cluster_keys;

namespace {
// Messages held while a lease or a node's liveness is read again (a
// millisecond or two): a room's faces for a few ticks, say. Past this they
// are refused, so that a flood of forged ones costs bounded memory.
constexpr std::size_t kMaxHeld = 64;
constexpr std::size_t kMaxNodesHeld = 64;
// A lease read this recently is not read again for news from another
// node: a flood of forged news costs Redis at most this many reads a second.
constexpr auto kLeaseReread = std::chrono::milliseconds(100);
}  // namespace

void ClusterNode::refuse(std::string_view sender, std::string_view why) {
  services_.abuse.note(Abuse::cluster_message, "node " + printable(sender, cluster_check::kMaxNodeNameBytes), why);
}

void ClusterNode::on_down(const std::string& room, bridge::Down message) {
  if (message.owner == node_) return;  // its own news, from before it took the room
  if (auto why = cluster_check::refusal_of(message)) return refuse(message.owner, "room " + room + ": " + *why);
  auto deliver = [this, room](bridge::Down& news) {
    if (auto target = services_.rooms.find(room)) target->on_down(std::move(news));
  };
  const auto held = held_down_.find(room);
  const auto lease = leases_.find(room);
  const auto now = Clock::now();
  if (held == held_down_.end() && lease != leases_.end()) {
    if (lease->second.holder == message.owner) return deliver(message);
    if (now - lease->second.read < kLeaseReread)
      return refuse(message.owner, "room " + room + ": news from a node that does not hold the room's lease");
  }
  // From another node than the holder last read (or none read yet): the
  // room may have been taken over. The lease is read again before the news
  // is believed; what comes meanwhile waits behind it, in order.
  auto& queue = held_down_[room];
  if (queue.size() >= kMaxHeld)
    return refuse(message.owner, "room " + room + ": too much news while the room's lease is read");
  queue.push_back(std::move(message));
  if (queue.size() > 1 || !commands_) return;
  commands_->command({"GET", keys::room_owner(room)}, [this, room, deliver](const RedisReply* reply) {
    auto waiting = std::move(held_down_[room]);
    held_down_.erase(room);
    if (!reply) return;  // Redis went away: the room asks for a roster when it is back
    const bool known = leases_.count(room) != 0;
    Lease& read_lease = leases_[room];
    const std::string before = read_lease.holder;
    read_lease.holder = reply->type == RedisReply::Type::string ? reply->text : "";
    read_lease.read = Clock::now();
    bool from_holder = false;
    for (bridge::Down& news : waiting) {
      if (!read_lease.holder.empty() && news.owner == read_lease.holder) {
        from_holder = true;
        deliver(news);
      } else if (news.owner != before || before.empty()) {
        refuse(news.owner, "room " + room + ": news from a node that does not hold the room's lease");
      }  // else: the old owner's last words, after the room moved on
    }
    // A new owner, whose first news (its roster) may have been refused
    // before its lease was read: its roster is asked for again.
    if (from_holder && known && before != read_lease.holder)
      if (auto target = services_.rooms.find(room)) target->ask_roster();
  });
}

void ClusterNode::on_up(const std::string& room, bridge::Up message) {
  if (message.node == node_) return;  // its own request, from before it took the room
  if (auto why = cluster_check::refusal_of(message)) return refuse(message.node, "room " + room + ": " + *why);
  const std::string node = message.node;
  when_alive(node, "room " + room + ": a request", [this, room, message = std::move(message)]() mutable {
    if (auto target = services_.rooms.find(room)) target->on_up(std::move(message));
  });
}

void ClusterNode::on_limits(std::string_view payload) {
  auto news = decode_limits(payload);
  if (!news) return refuse("unknown", "limits news this build cannot read");
  if (news->node == node_) return;
  if (auto why = cluster_check::refusal_of(*news, services_.config.abuse)) return refuse(news->node, *why);
  const std::string node = news->node;
  when_alive(node, "limits news", [this, news = std::move(*news)]() mutable { apply_limits(std::move(news)); });
}

void ClusterNode::when_alive(const std::string& node, const std::string& what, std::function<void()> then) {
  const auto held = held_from_.find(node);
  if (held == held_from_.end() && live_.count(node)) return then();
  // Not alive at the last look (a node that just started, or none at all):
  // its liveness key is read before it is heard.
  if (held == held_from_.end() && held_from_.size() >= kMaxNodesHeld)
    return refuse(node, what + " from a node not seen alive, among too many such");
  auto& queue = held_from_[node];
  if (queue.size() >= kMaxHeld) return refuse(node, what + ": too many while its node's liveness is read");
  queue.emplace_back(what, std::move(then));
  if (queue.size() > 1 || !commands_) return;
  commands_->command({"EXISTS", keys::node_alive(node)}, [this, node](const RedisReply* reply) {
    auto waiting = std::move(held_from_[node]);
    held_from_.erase(node);
    const bool alive = reply && reply->type == RedisReply::Type::integer && reply->integer == 1;
    for (auto& [said, run] : waiting) {
      if (alive) run();
      else refuse(node, said + " from a node that is not alive");
    }
  });
}

}  // namespace fw::server
