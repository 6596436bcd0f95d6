#pragma once
// POST /api/avatars: a photo prepared into a package (dlib and OpenCV, about
// a second of CPU, on its own thread so that neither I/O nor rooms wait), or
// a prepared package validated; either stored in the avatar store.
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <boost/asio/thread_pool.hpp>

#include "http_responses.hpp"
#include "server_context.hpp"

namespace fw::photo {
class AvatarPreparer;
}

namespace fw::server {

class PhotoPreparation {
 public:
  explicit PhotoPreparation(ServerContext& context);
  ~PhotoPreparation();

  /// Handles one upload; `done` gets the response on the preparation thread.
  void upload(Request request, std::string peer_address, std::function<void(Response)> done);

 private:
  Response handle(const Request& request);
  bool allow(const std::string& peer_address);

  ServerContext& context_;
  boost::asio::thread_pool pool_{1};
  std::unique_ptr<photo::AvatarPreparer> preparer_;  ///< used on the pool's thread only
  std::mutex mutex_;
  std::map<std::string, std::vector<std::chrono::steady_clock::time_point>> recent_;
};

}  // namespace fw::server
