#pragma once
// POST /api/avatars: a photo prepared into a package on the photo worker,
// or a prepared package validated; either stored in the avatar store, the
// photo beside its package (so the avatar can be prepared again when the
// package format or the generic face changes).
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "http_responses.hpp"
#include "server_context.hpp"

namespace fw::server {

class PhotoWorker;

class PhotoPreparation {
 public:
  PhotoPreparation(ServerContext& context, PhotoWorker& worker);

  /// Handles one upload; `done` gets the response on the photo worker's thread.
  void upload(Request request, std::string peer_address, std::function<void(Response)> done);

  /// What an upload stores: the package, and the photo to keep beside it
  /// (empty when none came; a view into the request); and the preparation's
  /// advice on the photo (empty for an uploaded package), for the answer.
  struct Upload {
    std::vector<std::uint8_t> package;
    std::span<const std::uint8_t> photo;
    std::vector<std::string> advice;
  };

 private:
  Response handle(const Request& request);
  /// The photo prepared into `upload`; the refusal when it makes no avatar.
  std::optional<Response> prepare_photo(const Request& request, std::span<const std::uint8_t> photo, Upload& upload);
  /// A multipart body: a package (and the photo it was prepared from), or a
  /// photo alone, as a browser's form sends it.
  std::optional<Response> read_multipart_upload(const Request& request, std::span<const std::uint8_t> body,
                                                Upload& upload);
  /// Counts an upload from `peer_address`; nullopt when it may go ahead,
  /// else the seconds until it may (the rate limit is a sliding minute).
  std::optional<int> wait_before_upload(const std::string& peer_address);

  ServerContext& context_;
  PhotoWorker& worker_;
  std::mutex mutex_;
  std::map<std::string, std::vector<std::chrono::steady_clock::time_point>> recent_;
};

}  // namespace fw::server
