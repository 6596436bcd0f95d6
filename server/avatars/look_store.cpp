#include "look_store.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

#include <spdlog/spdlog.h>

#include "avatar_store.hpp"
#include "durable_file.hpp"

namespace fw::server {

namespace {

std::vector<SavedLook>::iterator named(std::vector<SavedLook>& looks, const std::string& name) {
  return std::find_if(looks.begin(), looks.end(), [&](const SavedLook& look) { return look.name == name; });
}

/// The file's largest size: every look at its bounds, with its counts.
constexpr std::size_t kMaxLooksFileBytes = kMaxLooksPerAvatar * (kMaxLookNameBytes + kMaxLookScriptBytes + 16) + 64;

}  // namespace

std::vector<SavedLook> LookStore::read_here(const std::string& asset) const {
  std::vector<SavedLook> looks;
  if (!is_asset_id(asset)) return looks;
  const std::filesystem::path path = directory_ / (asset + ".looks");
  std::ifstream in(path, std::ios::binary);
  if (!in) return looks;
  std::string bytes;
  bytes.resize(kMaxLooksFileBytes + 1);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  if (!decode_looks(bytes, looks)) spdlog::warn("the saved looks in {} are damaged: they are ignored", path.string());
  return looks;
}

std::vector<SavedLook> LookStore::current(const std::string& asset) {
  if (replica_.list) {
    if (auto looks = replica_.list(asset)) return std::move(*looks);
    spdlog::warn("saved looks of avatar {}: Redis does not answer; this node's copy is used", asset);
  }
  return read_here(asset);
}

bool LookStore::write_here(const std::string& asset, const std::vector<SavedLook>& looks, std::string& error) {
  const std::filesystem::path path = directory_ / (asset + ".looks");
  if (looks.empty()) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return true;
  }
  const std::string bytes = encode_looks(looks);
  std::string why;
  if (write_file_durably(path, std::span(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), why))
    return true;
  spdlog::error("saved looks of avatar {} not written: {}", asset, why);
  error = "the server could not store the look (its disk refused); try again later";
  return false;
}

std::vector<SavedLook> LookStore::list(const std::string& asset) {
  if (!is_asset_id(asset)) return {};
  std::lock_guard lock(mutex_);
  std::vector<SavedLook> looks = current(asset);
  // By name: a Redis hash keeps no order, and a picker reads better so.
  std::sort(looks.begin(), looks.end(), [](const SavedLook& a, const SavedLook& b) { return a.name < b.name; });
  return looks;
}

std::optional<SavedLook> LookStore::find(const std::string& asset, const std::string& name) {
  std::vector<SavedLook> looks = list(asset);
  const auto it = named(looks, name);
  if (it == looks.end()) return std::nullopt;
  return std::move(*it);
}

LookChange LookStore::put(const std::string& asset, const SavedLook& look, std::string& error) {
  if (!is_asset_id(asset)) return LookChange::failed;
  std::lock_guard lock(mutex_);
  std::vector<SavedLook> looks = current(asset);
  if (const auto it = named(looks, look.name); it != looks.end()) {
    it->script = look.script;
  } else if (looks.size() >= kMaxLooksPerAvatar) {
    error = "the avatar keeps " + std::to_string(looks.size()) + " looks, at most " +
            std::to_string(kMaxLooksPerAvatar) + ": delete one (DELETE /api/avatars/ID/looks/NAME) or save under the "
            "name of one to replace it";
    return LookChange::full;
  } else {
    looks.push_back(look);
  }
  if (!write_here(asset, looks, error)) return LookChange::failed;
  if (replica_.put && !replica_.put(asset, look))
    spdlog::warn("saved look of avatar {} is kept on this node only until Redis is back", asset);
  return LookChange::done;
}

LookChange LookStore::remove(const std::string& asset, const std::string& name, std::string& error) {
  if (!is_asset_id(asset)) return LookChange::unknown_look;
  std::lock_guard lock(mutex_);
  std::vector<SavedLook> looks = current(asset);
  const auto it = named(looks, name);
  if (it == looks.end()) {
    error = "the avatar has no look named '" + name + "' (GET /api/avatars/ID/looks lists them)";
    return LookChange::unknown_look;
  }
  looks.erase(it);
  if (!write_here(asset, looks, error)) return LookChange::failed;
  if (replica_.remove && !replica_.remove(asset, name))
    spdlog::warn("saved look of avatar {} deleted on this node only: Redis does not answer", asset);
  return LookChange::done;
}

}  // namespace fw::server
