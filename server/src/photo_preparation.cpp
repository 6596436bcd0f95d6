#include "photo_preparation.hpp"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "fw/model/avatar_package.hpp"
#include "fw/photo/prepare_avatar.hpp"
#include "multipart_body.hpp"
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

std::optional<Response> PhotoPreparation::prepare_photo(const Request& request, std::span<const std::uint8_t> photo,
                                                        Upload& upload) {
  photo::PrepError prep_error;
  if (!photo::AvatarPreparer::check_photo(photo, prep_error)) return prep_refusal(request, prep_error);
  photo::AvatarPreparer* preparer = worker_.preparer(prep_error);
  if (!preparer)
    return error_response(http::status::service_unavailable, request.version(),
                          "this server cannot prepare photos: " + prep_error.message +
                              "; upload a prepared .fwa package instead");
  const auto prepared = preparer->prepare(photo, photo::PrepOptions{}, prep_error);
  if (!prepared) return prep_refusal(request, prep_error);
  upload.package = model::serialize_avatar_package(prepared->package);
  upload.photo = photo;
  return std::nullopt;
}

namespace {

// A package and the photo it was prepared from, in one multipart body: the
// photo is only checked (a photo's format and size), not prepared; the
// package is validated by the store.
std::optional<Response> read_package_and_photo(const Request& request, std::span<const std::uint8_t> body,
                                               PhotoPreparation::Upload& upload) {
  const auto refuse = [&](http::status status, const std::string& message) {
    return error_response(status, request.version(), message);
  };
  std::map<std::string, MultipartPart> parts;
  std::string why;
  const auto content_type = request[http::field::content_type];
  if (!read_multipart(body, multipart_boundary({content_type.data(), content_type.size()}), parts, why))
    return refuse(http::status::bad_request, why);
  if (!parts.contains("package"))
    return refuse(http::status::bad_request,
                  "a multipart upload needs a part named 'package' (the .fwa) and may add one named 'photo'");
  upload.package.assign(parts["package"].data.begin(), parts["package"].data.end());
  if (!parts.contains("photo")) return std::nullopt;
  const MultipartPart& photo = parts["photo"];
  if (photo.content_type != "image/jpeg" && photo.content_type != "image/png")
    return refuse(http::status::unsupported_media_type, "the part 'photo' must be image/jpeg or image/png");
  photo::PrepError prep_error;
  if (!photo::AvatarPreparer::check_photo(photo.data, prep_error)) return prep_refusal(request, prep_error);
  upload.photo = photo.data;
  return std::nullopt;
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
  Upload upload;
  std::optional<Response> refusal;
  if (type == "image/jpeg" || type == "image/png") {
    refusal = prepare_photo(request, bytes, upload);
  } else if (type == "application/x-facewire-avatar" || type == "application/octet-stream") {
    upload.package.assign(bytes.begin(), bytes.end());
  } else if (type == "multipart/form-data") {
    refusal = read_package_and_photo(request, bytes, upload);
  } else {
    return error(http::status::unsupported_media_type,
                 "send a photo (Content-Type image/jpeg or image/png), a package (application/x-facewire-avatar), "
                 "or both (multipart/form-data, parts 'package' and 'photo')");
  }
  if (refusal) return *refusal;
  std::string why;
  const auto stored = context_.store->put(upload.package, upload.photo, why);
  if (!stored) return error(http::status::unprocessable_entity, "the package is not valid: " + why);
  context_.metrics.uploads.fetch_add(1);
  spdlog::info("stored avatar {} ({} bytes, preview {} bytes{})", stored->asset, stored->full->size(),
               stored->preview->size(), upload.photo.empty() ? "" : ", with its photo");
  const nlohmann::json answer = {
      {"asset", stored->asset}, {"bytes", stored->full->size()}, {"preview_bytes", stored->preview->size()}};
  return json_response(http::status::created, request.version(), false, answer.dump() + "\n");
}

}  // namespace fw::server
