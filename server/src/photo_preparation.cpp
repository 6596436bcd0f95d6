#include "photo_preparation.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "fw/model/avatar_package.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "photo_worker.hpp"
#include "rest_api.hpp"
#include "server_limits.hpp"

namespace fw::server {

namespace http = boost::beast::http;

PhotoPreparation::PhotoPreparation(ServerContext& context, PhotoWorker& worker) : context_(context), worker_(worker) {}

bool PhotoPreparation::allow(const std::string& peer_address) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  auto& times = recent_[peer_address];
  std::erase_if(times, [&](auto t) { return now - t > std::chrono::minutes(1); });
  if (recent_.size() > 10000) recent_.clear();  // bounded: a flood of addresses forgets the old ones
  if (static_cast<int>(times.size()) >= limits::kUploadsPerMinute) return false;
  times.push_back(now);
  return true;
}

void PhotoPreparation::upload(Request request, std::string peer_address, std::function<void(Response)> done) {
  const auto error = [&](http::status status, const std::string& message) {
    return error_response(status, request.version(), message);
  };
  if (context_.draining.load())
    return done(error(http::status::service_unavailable, "the server is shutting down; upload again in a moment"));
  if (!allow(peer_address))
    return done(error(http::status::too_many_requests, "at most 6 uploads a minute; wait a little"));
  worker_.post([this, request = std::move(request), done = std::move(done)] { done(handle(request)); });
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

Response PhotoPreparation::handle(const Request& request) {
  const auto error = [&](http::status status, const std::string& message) {
    return error_response(status, request.version(), message);
  };
  const std::string type(request[http::field::content_type].substr(0, request[http::field::content_type].find(';')));
  const auto& body = request.body();
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(body.data()), body.size());
  if (bytes.empty()) return error(http::status::bad_request, "the upload is empty; send a photo or a .fwa package");
  std::vector<std::uint8_t> package;
  std::span<const std::uint8_t> photo_kept;
  if (type == "image/jpeg" || type == "image/png") {
    photo::PrepError prep_error;
    if (!photo::AvatarPreparer::check_photo(bytes, prep_error)) return prep_refusal(request, prep_error);
    photo::AvatarPreparer* preparer = worker_.preparer(prep_error);
    if (!preparer)
      return error(http::status::service_unavailable, "this server cannot prepare photos: " + prep_error.message +
                                                          "; upload a prepared .fwa package instead");
    const auto prepared = preparer->prepare(bytes, photo::PrepOptions{}, prep_error);
    if (!prepared) return prep_refusal(request, prep_error);
    package = model::serialize_avatar_package(prepared->package);
    photo_kept = bytes;
  } else if (type == "application/x-facewire-avatar" || type == "application/octet-stream") {
    package.assign(bytes.begin(), bytes.end());
  } else {
    return error(http::status::unsupported_media_type,
                 "send a photo (Content-Type image/jpeg or image/png) or a package (application/x-facewire-avatar)");
  }
  std::string why;
  const auto stored = context_.store->put(package, photo_kept, why);
  if (!stored) return error(http::status::unprocessable_entity, "the package is not valid: " + why);
  context_.metrics.uploads.fetch_add(1);
  spdlog::info("stored avatar {} ({} bytes, preview {} bytes)", stored->asset, stored->full->size(),
               stored->preview->size());
  const nlohmann::json answer = {
      {"asset", stored->asset}, {"bytes", stored->full->size()}, {"preview_bytes", stored->preview->size()}};
  return json_response(http::status::created, request.version(), false, answer.dump() + "\n");
}

}  // namespace fw::server
