#pragma once
// Where a room's lines get their lip-sync tracks made. Making one runs
// espeak-ng (make_line, spoken_lines.hpp): a few milliseconds for a short
// line, tens for a 500-byte one, and espeak-ng says one line at a time in
// the whole process. A room that made its lines on its own strand would
// stall its tick for that long, and every room whose tick waits behind it
// too; so the server makes them on a small pool of its own (rooms/
// speech_worker.hpp) and hands each back to the room's strand, and the
// line starts when its track is there. RoomSimulation sees only this seam:
// ImmediateTrackMaker makes the track at once, for tests and `facewire-server
// simulate`, which need no threads.
// Thread-safe: as the implementation says (ImmediateTrackMaker: the caller's).
#include <functional>

#include "spoken_lines.hpp"

namespace fw::server {

class TrackMaker {
 public:
  virtual ~TrackMaker() = default;
  /// Makes the track of `job` and calls `done` with the line on the
  /// caller's strand: at once, or later. False when the maker has no room
  /// for the job now: `done` is never called, and the line is not said.
  virtual bool make(LineJob job, std::function<void(LineJob, LineToSay)> done) = 0;
};

/// Makes the track during the call, on the caller's thread.
class ImmediateTrackMaker final : public TrackMaker {
 public:
  bool make(LineJob job, std::function<void(LineJob, LineToSay)> done) override;
};

}  // namespace fw::server
