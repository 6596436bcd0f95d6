#include "photo_preparation.hpp"

#include <algorithm>

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

std::optional<int> PhotoPreparation::wait_before_upload(const std::string& peer_address) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  constexpr auto kWindow = std::chrono::minutes(1);
  auto& times = recent_[peer_address];
  std::erase_if(times, [&](auto t) { return now - t > kWindow; });
  if (recent_.size() > 10000) recent_.clear();  // bounded: a flood of addresses forgets the old ones
  if (static_cast<int>(times.size()) >= limits::kUploadsPerMinute) {
    // The oldest upload in the window leaves it first; round up, so that
    // an uploader who waits as told is not refused again.
    const auto wait = std::chrono::ceil<std::chrono::seconds>(times.front() + kWindow - now);
    return std::max<int>(1, static_cast<int>(wait.count()));
  }
  times.push_back(now);
  return std::nullopt;
}

void PhotoPreparation::upload(Request request, std::string peer_address, std::function<void(Response)> done) {
  const auto error = [&](http::status status, const std::string& message) {
    return error_response(status, request.version(), message);
  };
  if (context_.draining.load())
    return done(error(http::status::service_unavailable, "the server is shutting down; upload again in a moment"));
  if (const auto wait = wait_before_upload(peer_address)) {
    Response refusal = error(http::status::too_many_requests,
                             "at most " + std::to_string(limits::kUploadsPerMinute) +
                                 " uploads a minute from one address; try again in " + std::to_string(*wait) +
                                 (*wait == 1 ? " second" : " seconds"));
    refusal.set(http::field::retry_after, std::to_string(*wait));
    return done(std::move(refusal));
  }
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
  if (!photo::AvatarPreparer::check_photo(photo.data, prep_error)) return prep_refusal(request, prep_error);
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
  const auto stored = context_.store->put(upload.package, upload.photo, why);
  if (!stored) return error(http::status::unprocessable_entity, "the package is not valid: " + why);
  context_.metrics.uploads.fetch_add(1);
  spdlog::info("stored avatar {} ({} bytes, preview {} bytes{})", stored->asset, stored->full->size(),
               stored->preview->size(), upload.photo.empty() ? "" : ", with its photo");
  const nlohmann::json answer = {{"asset", stored->asset},
                                 {"package", "/api/packages/" + stored->asset},
                                 {"bytes", stored->full->size()},
                                 {"preview_bytes", stored->preview->size()},
                                 {"advice", upload.advice}};
  return json_response(http::status::created, request.version(), false, answer.dump() + "\n");
}

}  // namespace fw::server
