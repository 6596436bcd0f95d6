#pragma once
// The body bytes of one upload, reserved against its address's and the
// server's share (AddressLimits::reserve_upload) from its header until it is
// answered, so that uploads held open cannot hold more memory than the
// shares. Given back when it goes, or when emptied.
#include <cstddef>
#include <string>
#include <utility>

#include "address_limits.hpp"

namespace fw::server {

class UploadReservation {
 public:
  UploadReservation() = default;
  /// Takes over `bytes` that `limits` granted to `key`.
  UploadReservation(AddressLimits& limits, std::string key, std::size_t bytes)
      : limits_(&limits), key_(std::move(key)), bytes_(bytes) {}
  UploadReservation(UploadReservation&& other) noexcept
      : limits_(std::exchange(other.limits_, nullptr)), key_(std::move(other.key_)), bytes_(other.bytes_) {}
  UploadReservation& operator=(UploadReservation&& other) noexcept {
    if (this != &other) {
      release();
      limits_ = std::exchange(other.limits_, nullptr);
      key_ = std::move(other.key_);
      bytes_ = other.bytes_;
    }
    return *this;
  }
  UploadReservation(const UploadReservation&) = delete;
  UploadReservation& operator=(const UploadReservation&) = delete;
  ~UploadReservation() { release(); }

  /// Gives the bytes back now.
  void release() {
    if (limits_) limits_->release_upload(key_, bytes_);
    limits_ = nullptr;
  }
  std::size_t bytes() const { return limits_ ? bytes_ : 0; }

 private:
  AddressLimits* limits_ = nullptr;
  std::string key_;
  std::size_t bytes_ = 0;
};

}  // namespace fw::server
