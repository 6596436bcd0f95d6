#pragma once
// The body bytes of one upload, counted against its address's and the
// server's share (AddressLimits::reserve_upload) as they are received, and
// held until the upload is answered, so that uploads held open cannot hold
// more memory than the shares. Bytes declared but not sent hold nothing: a
// body dribbled a byte at a time holds the bytes it sent, not the
// Content-Length it promised. Given back when it goes, or when emptied.
#include <cstddef>
#include <string>
#include <utility>

#include "address_limits.hpp"

namespace fw::server {

class UploadReservation {
 public:
  UploadReservation() = default;
  /// Counts the bytes of an upload from `key` against `limits`; none yet.
  UploadReservation(AddressLimits& limits, std::string key) : limits_(&limits), key_(std::move(key)) {}
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

  /// Counts `more` bytes received; the share that is full (and nothing
  /// counted) when they do not fit.
  UploadShare grow(std::size_t more) {
    if (!limits_ || more == 0) return UploadShare::granted;
    const UploadShare share = limits_->reserve_upload(key_, more);
    if (share == UploadShare::granted) bytes_ += more;
    return share;
  }
  /// Gives the bytes back now.
  void release() {
    if (limits_) limits_->release_upload(key_, bytes_);
    limits_ = nullptr;
    bytes_ = 0;
  }
  std::size_t bytes() const { return limits_ ? bytes_ : 0; }

 private:
  AddressLimits* limits_ = nullptr;
  std::string key_;
  std::size_t bytes_ = 0;
};

}  // namespace fw::server
