// The room as one viewer sees it (server/PROTOCOL.md 6.1): the others on an
// arc in front of the viewer, each seat turned toward the viewer's eyes, and
// the server's own seats (from the welcome and seats messages) in the same
// conventions, so that a face's aim can be moved from one to the other.
//
// Frames as in avatar/behavior's seat_layout.hpp: millimetres, y up; a head's
// own frame has x toward the person's left and z out of the face; a seat
// turns it by `facingYawRad` about y and moves it to `origin`. The view's
// frame has the viewer's eyes at the origin, looking down -z.

/** Millimetres per model unit (model::kMillimetresPerUnit). */
export const MM_PER_UNIT = 63;
/** Where the others' eyes sit from the viewer's, and the widest the arc gets. */
export const VIEW_DISTANCE_MM = 1100;
const MAX_STEP_RAD = (25 * Math.PI) / 180;
const MAX_SPAN_RAD = (100 * Math.PI) / 180;

export const rotateY = (angle, [x, y, z]) => [
  Math.cos(angle) * x + Math.sin(angle) * z, y, -Math.sin(angle) * x + Math.cos(angle) * z];
const add = (a, b) => a.map((v, i) => v + b[i]);
const sub = (a, b) => a.map((v, i) => v - b[i]);
const scale = (a, s) => a.map((v) => v * s);

/** A point of a head's rest frame (mm) in the room, for a seat { origin, facingYawRad }. */
export const seatToRoom = (seat, p) => add(seat.origin, rotateY(seat.facingYawRad, p));
/** A point of the room in the seat's frame. */
export const roomToSeat = (seat, p) => rotateY(-seat.facingYawRad, sub(p, seat.origin));

/** Yaw and pitch of direction `d` (FaceParams' signs: yaw toward the person's left, pitch up). */
export function directionAngles([x, y, z]) {
  return { yaw: Math.atan2(x, z), pitch: Math.atan2(y, Math.hypot(x, z)) };
}

/** The midpoint of the eyes' rotation centres of a face (model units, [right, left] centres) in mm. */
export const eyeMidMm = (eyeCentres) => scale(add(eyeCentres[0], eyeCentres[1]), 0.5 * MM_PER_UNIT);

/** A seat of the protocol (avatar_info.seat) as { origin, facingYawRad }. */
export const serverSeat = (s) => ({ origin: [s.xMm, s.yMm, s.zMm], facingYawRad: s.facingYawRad });

/**
 * The others' seats in the viewer's view, in the given order (left to right
 * on screen): on an arc VIEW_DISTANCE_MM from the viewer's eyes, neighbours
 * at most 25 degrees apart and 100 degrees in all, each turned to face the
 * viewer so that its eyes (at `eyeMid`, head frame) look at the viewer's
 * when its head is at rest.
 */
export function viewSeats(count, eyeMid) {
  const step = count > 1 ? Math.min(MAX_STEP_RAD, MAX_SPAN_RAD / (count - 1)) : 0;
  return Array.from({ length: count }, (_, i) => {
    const angle = (i - (count - 1) / 2) * step;  // negative: the viewer's left
    const eyes = [VIEW_DISTANCE_MM * Math.sin(angle), 0, -VIEW_DISTANCE_MM * Math.cos(angle)];
    const facingYawRad = -angle;  // the face's +z toward the viewer
    return { origin: sub(eyes, rotateY(facingYawRad, eyeMid)), facingYawRad, eyes };
  });
}

/**
 * The others in screen order: the server's seats ordered by where they sit
 * around the table as the viewer would see them from their own seat, so
 * that neighbours at the table stay neighbours on the screen.
 */
export function screenOrder(avatars, viewerId) {
  const viewer = avatars.find((a) => a.id === viewerId);
  const others = avatars.filter((a) => a.id !== viewerId);
  if (!viewer) return others.sort((a, b) => a.seat.xMm - b.seat.xMm);
  const seat = serverSeat(viewer.seat);
  const bearing = (a) => {
    const p = roomToSeat(seat, [a.seat.xMm, a.seat.yMm, a.seat.zMm]);
    // In the viewer's seat frame +x is the viewer's own left: the screen's left.
    return Math.atan2(p[0], p[2]);
  };
  return others.sort((a, b) => bearing(b) - bearing(a));
}
