#include "upload_pace.hpp"

#include <algorithm>
#include <cmath>

namespace fw::server {

UploadPace::UploadPace(std::size_t min_bytes_per_second, Clock::duration window, Clock::time_point start)
    : window_(window), start_(start),
      bytes_per_window_(static_cast<std::size_t>(
          std::ceil(static_cast<double>(min_bytes_per_second) * std::chrono::duration<double>(window).count()))) {}

void UploadPace::record(Clock::time_point now, std::size_t total) {
  if (total <= total_) return;
  total_ = total;
  samples_.push_back({now, total});
  // A sample older than a window before the newest one can no longer be
  // the one a deadline starts from: a later sample is at least as recent.
  while (samples_.size() > 1 && samples_[1].at + window_ <= now) samples_.pop_front();
}

UploadPace::Clock::time_point UploadPace::deadline() const {
  if (bytes_per_window_ == 0) return Clock::time_point::max();
  // The window ending at t holds total_ - (the total at t - window_). With
  // nothing more arriving, the pace is missed from the first t at which the
  // total a window back exceeds total_ - bytes_per_window_: a window after
  // the sample that brought the total past it (or after the start, when
  // everything received is less than a window's worth), and never within
  // the first, free window.
  Clock::time_point from = start_;
  for (const Sample& sample : samples_)
    if (sample.total + bytes_per_window_ > total_) {
      from = sample.at;
      break;
    }
  if (total_ < bytes_per_window_) from = start_;
  return std::max(from, start_) + window_;
}

}  // namespace fw::server
