// Whether, when and where to connect again after a connection ended
// (PROTOCOL.md 5.11), as the native client decides it
// (client/transport/failover_policy.cpp, RoomSession::backoff; the golden file
// tests/vectors/reconnect_policy holds this port to it): a refusal that
// will not change on any server (bad token, room full, bad name, another
// protocol version) stops with its reason; an avatar being prepared again
// is asked for again on the same server (it prepares it); anything else (a
// drop, a server shutting down, an idle time-out, a code of a later
// server) is retried on the next server of the list, round robin. Every
// retry waits the back-off, which grows with the failures since the last
// welcome.
import { CloseCode } from '../protocol/session_types.js';

// The native client's after_closing without a face to upload: the room page
// never uploads one (the lobby did), so "unauthorized" and "bad request"
// are final here.
const FINAL = new Set([
  CloseCode.protocolError, CloseCode.messageTooLarge, CloseCode.unsupportedVersion, CloseCode.unauthorized,
  CloseCode.roomFull, CloseCode.badRequest,
]);

export class ReconnectPolicy {
  /** The back-off doubles from `firstDelayMs` up to `maxDelayMs` (the native client's 0.5 s to 8 s). */
  constructor({ firstDelayMs = 500, maxDelayMs = 8000 } = {}) {
    this.firstDelayMs = firstDelayMs;
    this.maxDelayMs = maxDelayMs;
    this.failures = 0;
  }
  /** The connection was welcomed: the next drop starts the back-off again. */
  welcomed() { this.failures = 0; }
  /**
   * After a connection ended with `closing` (the server's last message, or
   * null when it just dropped): { retry: false } or { retry: true, delayMs,
   * moveOn } (moveOn: to the next server of the list).
   */
  next(closing) {
    if (closing && FINAL.has(closing.code)) return { retry: false };
    this.failures += 1;
    const delayMs = Math.min(this.maxDelayMs, this.firstDelayMs * 2 ** (this.failures - 1));
    const sameServer = Boolean(closing) && closing.code === CloseCode.avatarBeingPrepared;
    return { retry: true, delayMs, moveOn: !sameServer };
  }
}
