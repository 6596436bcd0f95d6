// What the protocol allows in a hello (server/PROTOCOL.md, 5.1), checked
// before joining so that a person learns it here rather than from a refusal.

const ROOM_PATTERN = /^[A-Za-z0-9_.-]{1,64}$/;

/// '' when `room` is a valid room name, else what is wrong and what to do.
export function roomNameProblem(room) {
  if (room.length === 0) return 'Pick a room, or type the name of a new one.';
  if (room.length > 64) return `A room name has at most 64 characters; this one has ${room.length}.`;
  if (!ROOM_PATTERN.test(room)) {
    return 'A room name may only hold letters A-Z and a-z, digits, and _ - . (no spaces).';
  }
  return '';
}

/// '' when `name` is a valid display name (1 to 32 bytes of UTF-8), else what to do.
export function displayNameProblem(name) {
  const bytes = new TextEncoder().encode(name.trim()).length;
  if (bytes === 0) return 'Type the name the others will see.';
  if (bytes > 32) return 'That name is too long: at most 32 bytes (about 32 letters, fewer with accents or emoji).';
  return '';
}
