#pragma once
// This node's part in a cluster on Redis (--redis; server/CLUSTER.md).
//
// Rooms are owned by one node, which simulates them; ownership is a lease
// in Redis that the owner renews twice a second. A node that holds clients
// of a room it does not own bridges them over pub/sub (bridged_room.hpp).
// Every half second each node reports that it lives and its load, renews
// its leases (and gives up a room another node took meanwhile), tells its
// rooms which nodes died, and takes over any room whose owner's lease ran
// out, restoring it from the owner's record (owned_room_cluster.cpp). New rooms
// go to the least-loaded live node.
//
// Without Redis a node keeps serving the rooms it owns and opens new ones
// on its own, reports not ready (/readyz), and rejoins the cluster when
// Redis is back: it reclaims its leases (or hands its rooms to whoever took
// them), writes its records again and shares its avatars again.
//
// Everything runs on one strand of the node's I/O loop; the RoomBus calls
// rooms make from their own strands are posted to it.
#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <boost/asio/any_io_executor.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>

#include "cluster_limits.hpp"
#include "redis_blocking.hpp"
#include "redis_connection.hpp"
#include "room_bus.hpp"
#include "cluster_services.hpp"

namespace fw::server {

class ClusterNode : public RoomBus {
 public:
  /// `executor`: the node's I/O loop. Takes the cluster's server key (or
  /// gives it this node's) before it returns, when Redis answers in time.
  ClusterNode(const ClusterServices& services, boost::asio::any_io_executor executor, RedisAddress address,
              std::string node);
  ~ClusterNode() override;

  /// Connects and starts the heartbeat; the rooms' bus (services.room_bus)
  /// forwards here from now on until stop().
  void start();
  /// Gives up this node's rooms (their leases go, so others take them over
  /// at once) and leaves the cluster. Blocking; call once rooms stopped.
  void stop();

  // RoomBus
  /// A room opened here is a bridge until the node finds or places its owner.
  RoomRoleKind role_of_new_room() const override { return RoomRoleKind::bridge; }
  const std::string& node() const override { return node_; }
  void room_opened(const std::string& room) override;
  void send_down(const std::string& room, bridge::Bytes message) override;
  void send_up(const std::string& room, bridge::Bytes message) override;
  void keep_member(const std::string& room, const bridge::MemberRecord& member) override;
  void forget_member(const std::string& room, std::uint32_t avatar) override;
  void keep_state(const std::string& room, bridge::Bytes state) override;
  void keep_chat(const std::string& room, bridge::Bytes chat_message) override;
  void room_closed(const std::string& room) override;

  /// Connected to Redis (both connections).
  bool connected() const { return up_.load(); }

 private:
  void connect();
  void on_connected();
  void lost(const std::string& why);
  void heartbeat();
  void schedule_heartbeat();
  void report_alive();
  void renew_leases();
  void watch_nodes();
  void adopt_orphans();
  /// Finds or places the owner of `room` (a bridge room opened here).
  void place(const std::string& room);
  /// Tries to take `room` (SET NX): restores it here, or bridges it when
  /// another node was first.
  void acquire(const std::string& room);
  void restore(const std::string& room, const RedisReply& members, const RedisReply& state);
  /// Owns `room` without Redis (it is away): records are written when it returns.
  void own_locally(const std::string& room);
  void own_unplaced();
  void bridge(const std::string& room);
  void on_message(std::string_view channel, std::string_view payload);
  // Who may say what (cluster_node_checks.cpp): every message is checked
  // (cluster_message_check.hpp); a room's news is believed from the holder
  // of its lease only, requests and limits news from live nodes only.
  void on_down(const std::string& room, bridge::Down message);
  void on_up(const std::string& room, bridge::Up message);
  void on_limits(std::string_view payload);
  /// Runs `then` once `node` is known to be alive (at once when it was at
  /// the last look), or refuses `what` from it; in the order they came.
  void when_alive(const std::string& node, const std::string& what, std::function<void()> then);
  /// Counts and logs (rate-limited) a message refused from `sender`.
  void refuse(std::string_view sender, std::string_view why);
  /// The per-address limits and tokens in use, to and from the others
  /// (cluster_limits.hpp; cluster_node_limits.cpp).
  void share_limits();
  void apply_limits(LimitsNews news);
  std::string least_loaded() const;
  void publish(const std::string& channel, bridge::Bytes message);
  // cluster_node_avatars.cpp
  void keep_avatars_in_redis();
  /// The saved looks likewise (cluster_node_looks.cpp).
  void keep_looks_in_redis();
  /// Shares `asset`'s saved looks from this node's copy when Redis has none.
  void reshare_looks(const std::string& asset);
  void reshare_avatars();
  void adopt_server_key();
  /// Another node deleted the avatar `payload` names: this node drops its copy.
  void forget_deleted_avatar(std::string_view payload);

  const ClusterServices services_;
  boost::asio::strand<boost::asio::any_io_executor> strand_;
  RedisAddress address_;
  std::string node_;
  std::shared_ptr<RedisConnection> commands_, subscriber_;
  std::atomic<bool> up_{false};
  bool connecting_ = false;
  bool stopped_ = false;
  boost::asio::steady_timer timer_;
  std::uint64_t beats_ = 0;
  std::set<std::string> owned_;    ///< rooms this node owns
  std::set<std::string> bridged_;  ///< rooms this node bridges to their owner
  std::set<std::string> acquiring_;
  using Clock = std::chrono::steady_clock;
  std::set<std::string> unplaced_;  ///< opened while Redis was away, waiting for it
  Clock::time_point waiting_since_ = Clock::now();  ///< Redis away since (or the start)
  Clock::time_point connected_since_ = Clock::now();
  std::map<std::string, double> loads_;  ///< live nodes and their load, as last seen
  std::set<std::string> live_;           ///< nodes alive at the last look
  RedisBlocking avatars_;                ///< avatar copies (redis_blocking.hpp)
  struct Lease {
    std::string holder;     ///< empty: none
    Clock::time_point read;
  };
  std::map<std::string, Lease> leases_;  ///< bridged rooms: their lease holder, as last read
  /// A room's news from a node that is not the lease holder last read
  /// waits here (in order, with what comes after it) while the lease is read again.
  std::map<std::string, std::deque<bridge::Down>> held_down_;
  /// What nodes not (yet) seen alive said, while their liveness is read.
  std::map<std::string, std::deque<std::pair<std::string, std::function<void()>>>> held_from_;
};

/// The command that starts the expiry of `key`, a part of an avatar's copy
/// in Redis, again: --avatar-retention-days, or none when that is 0.
std::vector<std::string> avatar_key_expiry(const ServerConfig& config, const std::string& key);

}  // namespace fw::server
