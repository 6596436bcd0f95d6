// Whether, when and where to connect again after a connection ended
// (PROTOCOL.md 5.11): a refusal that will not change on any server (bad
// token, room full, bad name, another protocol version) stops with its
// reason; an avatar being prepared again is asked for again on the same
// server (it prepares it) in a few seconds; anything else (a drop, a
// server shutting down, an idle time-out) is retried with a growing
// back-off on the next server of the list, round robin.
import { CloseCode } from '../protocol/session_types.js';

const FINAL = new Set([
  CloseCode.protocolError, CloseCode.messageTooLarge, CloseCode.unsupportedVersion, CloseCode.unauthorized,
  CloseCode.roomFull, CloseCode.badRequest,
]);

export class ReconnectPolicy {
  constructor({ firstDelayMs = 500, maxDelayMs = 10000 } = {}) {
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
    if (closing && closing.code === CloseCode.avatarBeingPrepared) return { retry: true, delayMs: 3000, moveOn: false };
    const delayMs = Math.min(this.maxDelayMs, this.firstDelayMs * 2 ** this.failures);
    this.failures += 1;
    return { retry: true, delayMs, moveOn: true };
  }
}
