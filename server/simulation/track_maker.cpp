#include "track_maker.hpp"

namespace fw::server {

bool ImmediateTrackMaker::make(LineJob job, std::function<void(LineJob, LineToSay)> done) {
  LineToSay line = make_line(job.text, job.language);
  done(std::move(job), std::move(line));
  return true;
}

}  // namespace fw::server
