#include "photo_preparation.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "fw/model/avatar_package.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "multipart_body.hpp"
#include "peer_address.hpp"
#include "photo_worker.hpp"
#include "rest_api.hpp"
#include "server_keys.hpp"
#include "server_limits.hpp"

namespace fw::server {

namespace http = boost::beast::http;

PhotoPreparation::PhotoPreparation(const UploadServices& services, PhotoWorker& worker)
    : services_(services), worker_(worker) {}

namespace {

std::string seconds_text(int seconds) { return std::to_string(seconds) + (seconds == 1 ? " second" : " seconds"); }

/// A refusal that says when to try again, in its Retry-After header and in
/// its text alike.
Response try_again_later(http::status status, unsigned version, const std::string& why, int seconds) {
  Response refusal = error_response(status, version, why + "; try again in " + seconds_text(seconds));
  refusal.set(http::field::retry_after, std::to_string(seconds));
  return refusal;
}

}  // namespace

std::optional<Response> PhotoPreparation::admit(unsigned version, std::uint64_t body_bytes,
                                                const std::string& peer_address, UploadReservation& reservation) {
  if (services_.draining.load())
    return error_response(http::status::service_unavailable, version,
                          "the server is shutting down; upload again in a moment");
  const std::string key = address_key(peer_address);
  // A full queue first: an upload refused for it costs no token of the rate.
  if (worker_.full_for(key)) return queue_full(version, peer_address);
  if (const auto wait = services_.addresses.take(AddressRate::upload, key)) {
    // Rounded up, so that an uploader who waits as told is not refused again.
    const int seconds = std::max(1, static_cast<int>(std::ceil(*wait)));
    const int per_minute = static_cast<int>(std::lround(services_.addresses.limits().uploads.per_second * 60));
    services_.abuse.note(Abuse::upload_rate, peer_address, "over " + std::to_string(per_minute) + " uploads a minute");
    return try_again_later(http::status::too_many_requests, version,
                           "at most " + std::to_string(per_minute) + " uploads a minute from one address",
                           seconds);
  }
  // The declared length decides from the header whether the body would
  // fit; only what arrives is counted (HttpSession grows the reservation),
  // so an upload that promises much and sends little holds little.
  const auto bytes = static_cast<std::size_t>(body_bytes);
  const UploadShare share = services_.addresses.upload_fits(key, bytes);
  if (share == UploadShare::granted) {
    reservation = UploadReservation(services_.addresses, key);
    return std::nullopt;
  }
  return share_refusal(share, version, bytes, peer_address);
}

Response PhotoPreparation::share_refusal(UploadShare share, unsigned version, std::size_t bytes,
                                         const std::string& peer_address) {
  // Bytes in flight are given back when uploads are answered, or when their
  // body stops coming at the pace the server asks.
  const int seconds = static_cast<int>(limits::kUploadTimeout.count());
  if (share == UploadShare::address_full) {
    services_.abuse.note(Abuse::upload_bytes, peer_address,
                        "another " + std::to_string(bytes / 1024) +
                            " KiB would take its uploads in flight past its share");
    return try_again_later(http::status::too_many_requests, version,
                           "your other uploads are still being received or prepared; send one photo at a time",
                           seconds);
  }
  services_.abuse.note(Abuse::upload_bytes, peer_address, "the server's uploads in flight are at their limit");
  return try_again_later(http::status::service_unavailable, version,
                         "the server is receiving as many uploads as it can", seconds);
}

Response PhotoPreparation::queue_full(unsigned version, const std::string& peer_address) {
  const int seconds = worker_.expected_wait_seconds();
  if (!worker_.full()) {
    // Room in the queue, but not for this network block: its addresses
    // together hold their share of the places.
    services_.abuse.note(Abuse::photo_queue_full, peer_address,
                        "photos waiting from its network " + address_group(peer_address) + " are at their share");
    return try_again_later(http::status::service_unavailable, version,
                           "the server has as many photos waiting from your network (" +
                               address_group(peer_address) + ") as it takes from one",
                           seconds);
  }
  services_.abuse.note(Abuse::photo_queue_full, peer_address,
                      "photos waiting to be prepared are at the limit of " +
                          std::to_string(services_.addresses.limits().photo_queue));
  return try_again_later(http::status::service_unavailable, version,
                         "the server has as many photos waiting to be prepared as it takes", seconds);
}

void PhotoPreparation::upload(Request request, std::string peer_address, std::function<void(Response)> done) {
  if (services_.draining.load())
    return done(error_response(http::status::service_unavailable, request.version(),
                               "the server is shutting down; upload again in a moment"));
  // A photo whose header declares too many pixels is refused here, on the
  // connection's thread, before it takes a place in the queue or a
  // decoder's memory and time.
  if (auto refusal = refuse_oversized_photo(request, peer_address)) return done(std::move(*refusal));
  // The queue may have filled while the body came: it decides now.
  const unsigned version = request.version();
  auto job = [this, request = std::move(request), done] { done(handle(request)); };
  if (!worker_.try_post(address_key(peer_address), std::move(job))) done(queue_full(version, peer_address));
}

std::optional<Response> PhotoPreparation::refuse_oversized_photo(const Request& request,
                                                                 const std::string& peer_address) {
  const auto& body = request.body();
  std::span<const std::uint8_t> photo(reinterpret_cast<const std::uint8_t*>(body.data()), body.size());
  const auto content_type = request[http::field::content_type];
  const std::string_view type(content_type.data(), content_type.size());
  if (type.substr(0, type.find(';')) == "multipart/form-data") {
    // The photo part of a form; a malformed form is answered by handle().
    std::map<std::string, MultipartPart> parts;
    std::string why;
    if (!read_multipart(photo, multipart_boundary(type), parts, why) || !parts.contains("photo")) return std::nullopt;
    photo = parts["photo"].data;
  }
  photo::PrepError prep_error;
  if (photo::AvatarPreparer::check_photo(photo, prep_error, services_.config.max_photo_pixels) ||
      prep_error.code != photo::PrepErrorCode::too_many_pixels)
    return std::nullopt;  // other faults are answered by handle(), with the same check
  services_.abuse.note(Abuse::photo_too_large, peer_address, "refused from its header: " + prep_error.message);
  return error_response(http::status::payload_too_large, request.version(), prep_error.message);
}

namespace {

// A photo that cannot make an avatar: 413 when it is too large, else 422,
// with the preparation's message for the person.
Response prep_refusal(const Request& request, const photo::PrepError& prep_error) {
  const bool too_big = prep_error.code == photo::PrepErrorCode::too_many_bytes ||
                       prep_error.code == photo::PrepErrorCode::too_many_pixels;
  return error_response(too_big ? http::status::payload_too_large : http::status::unprocessable_entity,
                        request.version(), prep_error.message);
}

}  // namespace

std::optional<Response> PhotoPreparation::prepare_photo(const Request& request, std::span<const std::uint8_t> photo,
                                                        Upload& upload) {
  photo::PrepError prep_error;
  if (!photo::AvatarPreparer::check_photo(photo, prep_error, services_.config.max_photo_pixels))
    return prep_refusal(request, prep_error);
  photo::AvatarPreparer* preparer = worker_.preparer(prep_error);
  if (!preparer)
    return error_response(http::status::service_unavailable, request.version(),
                          "this server cannot prepare photos: " + prep_error.message +
                              "; upload a prepared .fwa package instead");
  const auto prepared = preparer->prepare(photo, photo::PrepOptions{}, prep_error);
  if (!prepared) return prep_refusal(request, prep_error);
  upload.package = model::serialize_avatar_package(prepared->package);
  upload.photo = photo;
  upload.advice = prepared->report.warnings;
  return std::nullopt;
}

namespace {

bool is_photo_type(std::string_view type) { return type == "image/jpeg" || type == "image/png" || type == "image/webp"; }

}  // namespace

std::optional<Response> PhotoPreparation::read_multipart_upload(const Request& request,
                                                                std::span<const std::uint8_t> body, Upload& upload) {
  const auto refuse = [&](http::status status, const std::string& message) {
    return error_response(status, request.version(), message);
  };
  std::map<std::string, MultipartPart> parts;
  std::string why;
  const auto content_type = request[http::field::content_type];
  if (!read_multipart(body, multipart_boundary({content_type.data(), content_type.size()}), parts, why))
    return refuse(http::status::bad_request, why);
  if (!parts.contains("package")) {
    // A photo alone, as a browser's form or FormData sends a file: the
    // browser names the type from the file's name, or gives none (or
    // octet-stream) when it does not know it; the photo's own first bytes
    // then decide.
    if (!parts.contains("photo"))
      return refuse(http::status::bad_request,
                    "a multipart upload needs a part named 'photo' (a JPEG, PNG or WebP photo), or one named "
                    "'package' (a .fwa) and may add the photo it was prepared from");
    const MultipartPart& photo = parts["photo"];
    if (!is_photo_type(photo.content_type) && photo.content_type != "application/octet-stream" &&
        !photo.content_type.empty())
      return refuse(http::status::unsupported_media_type,
                    "the photo is " + photo.content_type.substr(0, 64) +
                        "; send a JPEG, PNG or WebP photo (take a snapshot, or save the photo as JPEG)");
    if (photo.data.empty()) return refuse(http::status::bad_request, "the photo is empty; choose a photo file");
    return prepare_photo(request, photo.data, upload);
  }
  // A package and the photo it was prepared from: the photo is only checked
  // (a photo's format and size), not prepared; the store validates the package.
  upload.package.assign(parts["package"].data.begin(), parts["package"].data.end());
  if (!parts.contains("photo")) return std::nullopt;
  const MultipartPart& photo = parts["photo"];
  if (photo.content_type != "image/jpeg" && photo.content_type != "image/png")
    return refuse(http::status::unsupported_media_type, "the part 'photo' must be image/jpeg or image/png");
  photo::PrepError prep_error;
  if (!photo::AvatarPreparer::check_photo(photo.data, prep_error, services_.config.max_photo_pixels))
    return prep_refusal(request, prep_error);
  upload.photo = photo.data;
  return std::nullopt;
}

Response PhotoPreparation::handle(const Request& request) {
  const auto error = [&](http::status status, const std::string& message) {
    return error_response(status, request.version(), message);
  };
  const std::string type(request[http::field::content_type].substr(0, request[http::field::content_type].find(';')));
  const auto& body = request.body();
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(body.data()), body.size());
  if (bytes.empty()) return error(http::status::bad_request, "the upload is empty; send a photo or a .fwa package");
  Upload upload;
  std::optional<Response> refusal;
  if (is_photo_type(type)) {
    refusal = prepare_photo(request, bytes, upload);
  } else if (type == "application/x-facewire-avatar" || type == "application/octet-stream") {
    upload.package.assign(bytes.begin(), bytes.end());
  } else if (type == "multipart/form-data") {
    refusal = read_multipart_upload(request, bytes, upload);
  } else {
    return error(http::status::unsupported_media_type,
                 "send a photo (Content-Type image/jpeg, image/png or image/webp, or multipart/form-data with a "
                 "part 'photo'), a package (application/x-facewire-avatar), or both (multipart/form-data, parts "
                 "'package' and 'photo')");
  }
  if (refusal) return *refusal;
  std::string why;
  const auto stored = services_.store.put(upload.package, upload.photo, why);
  if (!stored) return error(http::status::unprocessable_entity, "the package is not valid: " + why);
  services_.metrics.uploads.fetch_add(1);
  // One line an upload, which many addresses can make: held to the
  // connection log's rate (AbuseLog::event).
  services_.abuse.event("upload", "stored avatar " + stored->asset + " (" + std::to_string(stored->full->size()) +
                                     " bytes, preview " + std::to_string(stored->preview->size()) + " bytes" +
                                     (upload.photo.empty() ? "" : ", with its photo") + ")");
  // The key is what lets its holder wear the face (PROTOCOL.md 8.1): it
  // goes to the uploader alone, never to the room.
  const nlohmann::json answer = {{"asset", stored->asset},
                                 {"key", avatar_key(services_.server_key, stored->asset)},
                                 {"package", "/api/packages/" + stored->asset},
                                 {"bytes", stored->full->size()},
                                 {"preview_bytes", stored->preview->size()},
                                 {"advice", upload.advice}};
  return json_response(http::status::created, request.version(), false, answer.dump() + "\n");
}

}  // namespace fw::server
