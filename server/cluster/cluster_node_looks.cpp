// ClusterNode (cluster_node.hpp): the avatars' saved looks, a Redis hash
// per avatar (name -> script) beside the avatar's copy, so that a look
// saved on any node plays on all. Deleted with the avatar's copy, and
// expiring with it (cluster_node_avatars.cpp).
#include <spdlog/spdlog.h>

#include "cluster_keys.hpp"
#include "cluster_node.hpp"

namespace fw::server {

namespace keys = cluster_keys;

void ClusterNode::keep_looks_in_redis() {
  // Blocking calls, from the worker threads that answer the looks' HTTP
  // requests and read a look a person plays (never the I/O loop nor a room).
  services_.looks.set_replica(LookReplica{
      .list = [this](const std::string& asset) -> std::optional<std::vector<SavedLook>> {
        const auto reply = avatars_.command({"HGETALL", keys::avatar_looks(asset)});
        if (!reply || reply->type != RedisReply::Type::array) return std::nullopt;
        std::vector<SavedLook> looks;
        for (std::size_t i = 0; i + 1 < reply->elements.size() && looks.size() < kMaxLooksPerAvatar; i += 2)
          looks.push_back({reply->elements[i].text, reply->elements[i + 1].text});
        return looks;
      },
      .put =
          [this](const std::string& asset, const SavedLook& look) {
            const auto reply = avatars_.command({"HSET", keys::avatar_looks(asset), look.name, look.script});
            if (!reply || reply->is_error()) return false;
            avatars_.command(avatar_key_expiry(services_.config, keys::avatar_looks(asset)));
            return true;
          },
      .remove =
          [this](const std::string& asset, const std::string& name) {
            const auto reply = avatars_.command({"HDEL", keys::avatar_looks(asset), name});
            return reply && !reply->is_error();
          }});
}

void ClusterNode::reshare_looks(const std::string& asset) {
  const std::vector<SavedLook> looks = services_.looks.read_here(asset);
  if (looks.empty()) return;
  const auto known = avatars_.command({"EXISTS", keys::avatar_looks(asset)});
  if (!known || known->integer == 1) return;
  std::vector<std::string> command{"HSET", keys::avatar_looks(asset)};
  for (const SavedLook& look : looks) {
    command.push_back(look.name);
    command.push_back(look.script);
  }
  avatars_.command(command);
  avatars_.command(avatar_key_expiry(services_.config, keys::avatar_looks(asset)));
  spdlog::info("cluster: shared {} saved look(s) of avatar {} Redis did not have", looks.size(), asset);
}

}  // namespace fw::server
