#pragma once
// What the session does when a connection ends, and which server comes
// next: the decisions of failover, apart from sockets and timers so that
// they can be tested as they are. A link that fails (no connection, a drop,
// a time-out, a server shutting down) moves on to the next server of the
// list, round robin; a refusal that no server would answer otherwise (a bad
// or expired token, a bad name, a face that is not the person's own, a full
// room, another protocol version) ends the session; a server that does not
// know the person's face (or its key: another server key) gets it uploaded
// once, then the hello again.
#include <cstddef>

#include "fw/codec/messages.hpp"

namespace fw::client {

enum class NextStep {
  same_server,  ///< say hello to the same server again after the back-off (it prepares the face)
  next_server,  ///< move on to the next server after the back-off
  upload_here,  ///< upload the face to this server, then say hello to it again
  stop,         ///< end the session with the server's reason
};

/// After the server's closing message. `could_upload_here`: the person
/// brings a face of their own (--photo, --avatar) and has not uploaded it
/// to this server yet, so an unknown face or a key of another server may
/// be the cause of a refusal and an upload its cure.
NextStep after_closing(codec::CloseCode code, bool could_upload_here);

/// After a connection that could not be made, or ended without a closing
/// message (the server died, the network went away, a malformed message).
inline NextStep after_drop() { return NextStep::next_server; }

/// Whether an upload that failed with `http_status` (0: no answer came)
/// might succeed on another server: no answer, too many uploads from this
/// address (429), or a server that is draining or full (5xx). Other
/// answers (the photo has no face, the token is bad) are the same anywhere.
bool another_server_may_take_it(int http_status);

/// Round robin over a list of servers.
class ServerRotation {
 public:
  /// `count` servers (at least one), starting at `first`.
  explicit ServerRotation(std::size_t count, std::size_t first = 0);
  std::size_t current() const { return current_; }
  std::size_t count() const { return count_; }
  /// The current server's link failed: the next one (after the last, the first).
  std::size_t move_on();

 private:
  std::size_t count_;
  std::size_t current_;
};

}  // namespace fw::client
