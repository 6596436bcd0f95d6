// The browser's room frames (web/room/view_geometry.js: seatToRoom,
// roomToSeat, directionAngles; gaze_reaim.js: aimAt) against
// avatar/behavior's seat_layout as the C++ wrote it in
// tests/vectors/seat_frames. The C++ computes in float32 and the browser in
// float64: points agree within 1e-3 mm over a few metres (float32 keeps
// about 7 digits), angles within 2e-5 rad.
import { test } from 'node:test';

import { aimAt } from '../../../web/room/gaze_reaim.js';
import { directionAngles, roomToSeat, seatToRoom } from '../../../web/room/view_geometry.js';
import { assertAngleClose, assertClose, readGolden } from '../support/golden.mjs';

const golden = readGolden('seat_frames');
const MM = 1e-3;
const RAD = 2e-5;
const seatOf = (s) => ({ origin: s.origin_mm, facingYawRad: s.facing_yaw_rad });

test('seat to room and back, as the server places heads', () => {
  for (const [i, frame] of golden.frames.entries()) {
    const seat = seatOf(frame.seat);
    for (const [k, c] of frame.points.entries()) {
      assertClose(seatToRoom(seat, c.point_mm), c.seat_to_room, MM, `seat ${i} point ${k} seatToRoom`);
      assertClose(roomToSeat(seat, c.point_mm), c.room_to_seat, MM, `seat ${i} point ${k} roomToSeat`);
    }
  }
});

test('yaw and pitch of a direction, FaceParams signs', () => {
  for (const [k, c] of golden.direction_angles.entries()) {
    const a = directionAngles(c.direction);
    assertAngleClose(a.yaw, c.yaw_rad, RAD, `direction ${k} yaw`);
    assertAngleClose(a.pitch, c.pitch_rad, RAD, `direction ${k} pitch`);
  }
});

test("a face's aim from its eyes at every other seat's eyes", () => {
  let aims = 0;
  for (const [i, frame] of golden.frames.entries()) {
    const seat = seatOf(frame.seat);
    for (const [k, c] of frame.aims.entries()) {
      const a = aimAt(seat, golden.eye_mid_mm, c.target_mm);
      assertAngleClose(a.yaw, c.yaw_rad, RAD, `seat ${i} aim ${k} yaw`);
      assertAngleClose(a.pitch, c.pitch_rad, RAD, `seat ${i} aim ${k} pitch`);
      ++aims;
    }
  }
  if (aims < 100) throw new Error(`only ${aims} aims in the golden file`);
});
