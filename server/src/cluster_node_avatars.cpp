// ClusterNode (cluster_node.hpp): the avatars and the key that signs them,
// shared through Redis so that a face uploaded to any node is worn on all.
#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "cluster_keys.hpp"
#include "cluster_node.hpp"

namespace fw::server {

namespace net = boost::asio;
namespace keys = cluster_keys;

void ClusterNode::keep_avatars_in_redis() {
  // Blocking calls, from the threads that store and look up avatars (never
  // the I/O loop): an upload is answered once its avatar is in Redis.
  context_.store->set_replica(AvatarReplica{
      .share =
          [this](const std::string& asset, std::span<const std::uint8_t> package, std::span<const std::uint8_t> photo) {
            const auto reply = avatars_.command({"HSET", keys::avatar(asset), "package",
                                                 std::string(package.begin(), package.end()), "photo",
                                                 std::string(photo.begin(), photo.end())});
            if (reply && !reply->is_error()) avatars_.command({"SADD", keys::kAvatars, asset});
            else spdlog::warn("avatar {} is kept on this node only until Redis is back", asset);
          },
      .fetch =
          [this](const std::string& asset, std::vector<std::uint8_t>& package, std::vector<std::uint8_t>& photo) {
            const auto reply = avatars_.command({"HMGET", keys::avatar(asset), "package", "photo"});
            if (!reply || reply->elements.size() != 2 || reply->elements[0].type != RedisReply::Type::string)
              return false;
            package.assign(reply->elements[0].text.begin(), reply->elements[0].text.end());
            photo.assign(reply->elements[1].text.begin(), reply->elements[1].text.end());
            spdlog::info("avatar {} fetched from the cluster", asset);
            return true;
          }});
}

void ClusterNode::adopt_server_key() {
  // Avatar keys must open a face on every node: the first node's key is the cluster's.
  if (!avatars_.command({"SET", keys::kServerKey, context_.server_key, "NX"})) {
    spdlog::warn("Redis at {} does not answer: this node signs avatar keys with its own key until it does",
                 to_string(address_));
    return;
  }
  const auto key = avatars_.command({"GET", keys::kServerKey});
  if (key && key->type == RedisReply::Type::string && !key->text.empty()) context_.server_key = key->text;
}

void ClusterNode::reshare_avatars() {
  // On a worker: the blocking connection may wait for Redis.
  net::post(*context_.workers, [this] {
    std::size_t shared = 0;
    for (const std::string& asset : context_.store->stored_assets()) {
      const auto known = avatars_.command({"SISMEMBER", keys::kAvatars, asset});
      if (!known || known->integer == 1) continue;
      std::vector<std::uint8_t> package, photo;
      if (!context_.store->read_files(asset, package, photo)) continue;
      avatars_.command({"HSET", keys::avatar(asset), "package", std::string(package.begin(), package.end()), "photo",
                        std::string(photo.begin(), photo.end())});
      avatars_.command({"SADD", keys::kAvatars, asset});
      ++shared;
    }
    if (shared) spdlog::info("cluster: shared {} avatar(s) Redis did not have", shared);
  });
}

}  // namespace fw::server
