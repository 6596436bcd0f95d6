// The viewer's own view of the room (web/room/view_geometry.js) and the
// re-aiming of faces into it (gaze_reaim.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { aimAt, headShare, reaim, reaimAtViewer } from '../../../web/room/gaze_reaim.js';
import { rotateY, screenOrder, serverSeat, viewSeats } from '../../../web/room/view_geometry.js';

const EYE_MID = [0, 0, 20];  // a head's eyes, mm, in front of its origin
const DEG = Math.PI / 180;
const near = (a, b, tolerance, what) => assert.ok(Math.abs(a - b) <= tolerance, `${what}: ${a} vs ${b}`);

// A server room: four seats on an arc facing its centre (as avatar/behavior lays one out).
function serverRoom() {
  return [-60, -20, 20, 60].map((deg, i) => {
    const a = deg * DEG;
    const centreDistance = 600;
    const origin = [centreDistance * Math.sin(a), 0, centreDistance * (1 - Math.cos(a)) - centreDistance];
    return { id: i + 1, seat: { xMm: origin[0], yMm: 0, zMm: origin[2], facingYawRad: -a } };
  });
}

test('every face of the view looks at the viewer when its head is at rest', () => {
  for (const count of [1, 2, 3, 6]) {
    const seats = viewSeats(count, EYE_MID);
    for (const seat of seats) {
      const aim = aimAt(seat, EYE_MID, [0, 0, 0]);
      near(aim.yaw, 0, 1e-9, 'yaw');
      near(aim.pitch, 0, 1e-9, 'pitch');
    }
    for (let i = 1; i < count; ++i) assert.ok(seats[i].eyes[0] > seats[i - 1].eyes[0], 'left to right');
  }
});

test('neighbours at the table stay neighbours on the screen, the viewer left out', () => {
  const room = serverRoom();
  const order = screenOrder(room, 2).map((a) => a.id);
  assert.equal(order.length, 3);
  assert.ok(!order.includes(2));
  assert.deepEqual(order, [3, 4, 1]);
});

test('a face attending the viewer ends with head and eyes on the viewer; its fine motion stays; a neighbour turns it', () => {
  const room = serverRoom();
  const face = serverSeat(room[0].seat);
  const target = serverSeat(room[3].seat);
  const serverAim = aimAt(face, EYE_MID, [...target.origin.map((v, i) => v + rotateY(target.facingYawRad, EYE_MID)[i])]);
  assert.ok(Math.abs(serverAim.yaw) > 20 * DEG, 'the server turned it well away');
  const saccade = 0.03;
  const settled = (a) => ({ head: headShare(a), eye: a - headShare(a) });
  const decoded = {
    head_yaw_rad: settled(serverAim.yaw).head, head_pitch_rad: settled(serverAim.pitch).head,
    eye_left: { yaw_rad: settled(serverAim.yaw).eye + saccade, pitch_rad: settled(serverAim.pitch).eye },
    eye_right: { yaw_rad: settled(serverAim.yaw).eye + saccade, pitch_rad: settled(serverAim.pitch).eye },
  };
  const view = viewSeats(3, EYE_MID)[0];
  const viewAim = aimAt(view, EYE_MID, [0, 0, 0]);
  // However the server split the gaze between head and eyes (here its
  // settled split, and a head lagging by 0.1 rad), the head ends on the
  // viewer and the eyes keep only the saccade, converged on the viewer.
  const vergence = 0.03;
  for (const lag of [0, 0.1]) {
    const lagging = { ...decoded, head_yaw_rad: decoded.head_yaw_rad - lag,
      eye_left: { ...decoded.eye_left, yaw_rad: decoded.eye_left.yaw_rad + lag },
      eye_right: { ...decoded.eye_right, yaw_rad: decoded.eye_right.yaw_rad + lag } };
    const out = reaimAtViewer(lagging, serverAim, viewAim, vergence);
    near(out.head_yaw_rad, viewAim.yaw, 1e-9, 'head on the viewer');
    near(out.eye_left.yaw_rad, saccade - vergence, 1e-9, 'left eye: the saccade, turned in');
    near(out.eye_right.yaw_rad, saccade + vergence, 1e-9, 'right eye: the saccade, turned in');
    near(out.eye_right.pitch_rad, 0, 1e-9, 'eye pitch');
  }
  assert.equal(decoded.head_yaw_rad, settled(serverAim.yaw).head, 'the decoded face is left alone');

  // Toward a neighbour on the screen's right: eyes and head turn to the
  // viewer's right, which is the face's own left (+yaw).
  const neighbour = viewSeats(3, EYE_MID)[1].eyes;
  const toNeighbour = reaim(decoded, serverAim, aimAt(view, EYE_MID, neighbour));
  assert.ok(toNeighbour.head_yaw_rad > 5 * DEG);
  assert.ok(toNeighbour.eye_left.yaw_rad - saccade > 2 * DEG);
  // Half weight: half way.
  const half = reaimAtViewer(decoded, serverAim, viewAim, 0, 0.5);
  near(half.head_yaw_rad, (decoded.head_yaw_rad + viewAim.yaw) / 2, 1e-9, 'half way');
});
