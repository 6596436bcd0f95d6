// ClusterNode (cluster_node.hpp): the avatars and the key that signs them,
// shared through Redis so that a face uploaded to any node is worn on all.
#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include "avatar_deletion.hpp"
#include "cluster_keys.hpp"
#include "cluster_node.hpp"

namespace fw::server {

namespace net = boost::asio;
namespace keys = cluster_keys;

namespace {

}  // namespace

std::vector<std::string> avatar_key_expiry(const ServerConfig& config, const std::string& key) {
  if (config.avatar_retention_days == 0) return {"PERSIST", key};
  return {"EXPIRE", key, std::to_string(std::uint64_t{config.avatar_retention_days} * 86400)};
}

namespace {

/// Redis forgets its copy of an avatar unused for --avatar-retention-days
/// on every node: each use here starts its expiry again (at most hourly),
/// and its saved looks' with it.
std::vector<std::string> expiry_of(const ServerConfig& config, const std::string& asset) {
  return avatar_key_expiry(config, keys::avatar(asset));
}

}  // namespace

void ClusterNode::keep_avatars_in_redis() {
  // Blocking calls, from the threads that store and look up avatars (never
  // the I/O loop): an upload is answered once its avatar is in Redis.
  services_.store.set_replica(AvatarReplica{
      .share =
          [this](const std::string& asset, std::span<const std::uint8_t> package, std::span<const std::uint8_t> photo) {
            const auto reply = avatars_.command({"HSET", keys::avatar(asset), "package",
                                                 std::string(package.begin(), package.end()), "photo",
                                                 std::string(photo.begin(), photo.end())});
            if (reply && !reply->is_error()) {
              avatars_.command({"SADD", keys::kAvatars, asset});
              avatars_.command(expiry_of(services_.config, asset));
            } else {
              spdlog::warn("avatar {} is kept on this node only until Redis is back", asset);
            }
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
          },
      .touch =
          [this](const std::string& asset) {
            avatars_.command(expiry_of(services_.config, asset));
            avatars_.command(avatar_key_expiry(services_.config, keys::avatar_looks(asset)));
          },
      .remove =
          [this](const std::string& asset) {
            // The mark first: a node that misses the message finds it when it comes back.
            const auto marked = avatars_.command({"SADD", keys::kDeletedAvatars, asset});
            avatars_.command({"DEL", keys::avatar(asset), keys::avatar_looks(asset)});
            avatars_.command({"SREM", keys::kAvatars, asset});
            avatars_.command({"PUBLISH", keys::kAvatarDeletions, asset});
            if (!marked || marked->is_error())
              spdlog::warn("avatar {} was deleted on this node only: Redis does not answer; other nodes keep their "
                           "copies until it is deleted again",
                           asset);
          }});
}

void ClusterNode::adopt_server_key() {
  // Avatar keys must open a face on every node: the first node's key is the cluster's.
  if (!avatars_.command({"SET", keys::kServerKey, services_.server_key, "NX"})) {
    spdlog::warn("Redis at {} does not answer: this node signs avatar keys with its own key until it does",
                 to_string(address_));
    return;
  }
  const auto key = avatars_.command({"GET", keys::kServerKey});
  if (key && key->type == RedisReply::Type::string && !key->text.empty()) services_.server_key = key->text;
}

void ClusterNode::forget_deleted_avatar(std::string_view payload) {
  const std::string asset(payload);
  if (!is_asset_id(asset)) return;
  // On a worker: files are removed, and rooms told, off the node's strand.
  // The node that deleted it hears its own message too: by then it has
  // nothing left to drop.
  net::post(services_.workers, [this, asset] {
    services_.store.forget(asset);
    replace_deleted_avatar_in_rooms(services_.rooms, asset);
  });
}

void ClusterNode::reshare_avatars() {
  // On a worker: the blocking connection may wait for Redis.
  net::post(services_.workers, [this] {
    std::size_t shared = 0;
    for (const std::string& asset : services_.store.stored_assets()) {
      // Deleted on another node while this one could not hear it.
      const auto deleted = avatars_.command({"SISMEMBER", keys::kDeletedAvatars, asset});
      if (deleted && deleted->integer == 1) {
        services_.store.forget(asset);
        replace_deleted_avatar_in_rooms(services_.rooms, asset);
        continue;
      }
      reshare_looks(asset);
      const auto known = avatars_.command({"SISMEMBER", keys::kAvatars, asset});
      if (!known || known->integer == 1) continue;
      std::vector<std::uint8_t> package, photo;
      if (!services_.store.read_files(asset, package, photo)) continue;
      avatars_.command({"HSET", keys::avatar(asset), "package", std::string(package.begin(), package.end()), "photo",
                        std::string(photo.begin(), photo.end())});
      avatars_.command({"SADD", keys::kAvatars, asset});
      avatars_.command(expiry_of(services_.config, asset));
      ++shared;
    }
    if (shared) spdlog::info("cluster: shared {} avatar(s) Redis did not have", shared);
  });
}

}  // namespace fw::server
