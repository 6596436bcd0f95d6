// The words a person sees when an upload fails. The server's own text says
// what was wrong with the photo (server/PROTOCOL.md, section 8); this adds
// what the status alone tells, and when to try again after a 429.

/// Seconds from a Retry-After header (seconds, or an HTTP date); null when absent or unreadable.
export function retryAfterSeconds(header, now = Date.now()) {
  if (!header) return null;
  const trimmed = header.trim();
  if (/^\d+$/.test(trimmed)) return Number(trimmed);
  const date = Date.parse(trimmed);
  return Number.isNaN(date) ? null : Math.max(0, Math.ceil((date - now) / 1000));
}

function inSeconds(seconds) {
  if (seconds <= 1) return 'in a second';
  if (seconds < 90) return `in ${seconds} seconds`;
  return `in ${Math.ceil(seconds / 60)} minutes`;
}

/// The message for a failed upload: `status` 0 means no answer came.
export function uploadErrorMessage(status, body, retryAfterHeader) {
  const said = (body || '').trim();
  switch (status) {
    case 0:
      return 'The upload did not reach the server (the connection failed). Check the connection and try again.';
    case 413:
      return said || 'The photo is too large for this server. Choose a smaller photo.';
    case 415:
      return said || 'That file is not a photo the server takes. Choose a JPEG, PNG or WebP photo.';
    case 422:
      return said || 'No avatar can be made from this photo. Try another photo of your face.';
    case 429: {
      const seconds = retryAfterSeconds(retryAfterHeader);
      const when = seconds === null ? 'in a minute' : inSeconds(seconds);
      return `Too many uploads from here for now: try again ${when}.` + (said ? ` (The server says: ${said})` : '');
    }
    case 503:
      return said || 'The server cannot take photos just now. Try again in a moment.';
    default:
      return said || `The server refused the upload (HTTP ${status}).`;
  }
}
