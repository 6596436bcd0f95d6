#pragma once
// POST /api/avatars: a photo prepared into a package on the photo worker,
// or a prepared package validated; either stored in the avatar store, the
// photo beside its package (so the avatar can be prepared again when the
// package format or the generic face changes). An upload is admitted from
// its header, before its body is read: the address's rate, the bytes in
// flight (its own and the server's) and the photo queue (PROTOCOL.md,
// "Limits").
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <atomic>

#include "abuse_log.hpp"
#include "address_limits.hpp"
#include "avatar_store.hpp"
#include "http_responses.hpp"
#include "metrics.hpp"
#include "server_config.hpp"
#include "upload_reservation.hpp"

namespace fw::server {

class PhotoWorker;

/// What an upload uses of the server besides the photo worker, made once
/// with the listeners (network_server.cpp).
struct UploadServices {
  const ServerConfig& config;  ///< the largest photo
  Metrics& metrics;            ///< uploads stored
  AbuseLog& abuse;             ///< refusals by kind, for the log and /metrics
  AddressLimits& addresses;    ///< uploads per address, bytes in flight, the photo queue's shares
  AvatarStore& store;          ///< where an upload is stored
  const std::string& server_key;  ///< signs the key an upload is answered with
  const std::atomic<bool>& draining;  ///< SIGTERM: no new uploads
};

class PhotoPreparation {
 public:
  PhotoPreparation(const UploadServices& services, PhotoWorker& worker);

  /// Decides from an upload's header alone, before its body is read,
  /// whether the body may come: nullopt, and `reservation` ready to count
  /// the body's bytes as they arrive, when `body_bytes` (its declared
  /// length, or the largest upload for a chunked one) would fit in the
  /// shares now; else the refusal, 429 (this address's rate or bytes in
  /// flight) or 503 (the server's bytes in flight, a full photo queue or
  /// the block's share of it), with Retry-After. Counts an upload of the
  /// address's rate.
  std::optional<Response> admit(unsigned version, std::uint64_t body_bytes, const std::string& peer_address,
                                UploadReservation& reservation);
  /// The refusal of an upload whose `bytes` do not fit in `share` (429 for
  /// the address's, 503 for the server's), with Retry-After; counted.
  Response share_refusal(UploadShare share, unsigned version, std::size_t bytes, const std::string& peer_address);
  /// Handles one upload admitted and read; `done` gets the response, on a
  /// photo worker's thread (or on this one when the queue is full).
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
  /// 413 for a photo (raw, or a form's part 'photo') whose header declares
  /// more than --max-photo-pixels, decided without decoding; counted.
  std::optional<Response> refuse_oversized_photo(const Request& request, const std::string& peer_address);
  /// 503: the photo queue is full, or the uploader's block holds its share
  /// of it; Retry-After when it likely has room.
  Response queue_full(unsigned version, const std::string& peer_address);

  const UploadServices services_;
  PhotoWorker& worker_;
};

}  // namespace fw::server
