// Where the faces' tiles go (web/room/tile_layout.js): the widest tiles of
// every arrangement, each of the frame's shape, on the stage, apart, and
// clear of the self view.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { FRAME_ASPECT } from '../../../web/room/face_frame.js';
import { tileLayout } from '../../../web/room/tile_layout.js';

const apart = (a, b) => a.x + a.w <= b.x || b.x + b.w <= a.x || a.y + a.h <= b.y || b.y + b.h <= a.y;
const rowsOf = (tiles) => new Set(tiles.map((t) => Math.round(t.y))).size;

function assertSound({ tiles, self, nameBand }, width, height) {
  for (const [i, t] of tiles.entries()) {
    assert.ok(t.x >= 0 && t.y >= 0 && t.x + t.w <= width + 1e-9 && t.y + t.h <= height + 1e-9, `tile ${i} ${JSON.stringify(t)} off a ${width}x${height} stage`);
    assert.ok(Math.abs((t.h - nameBand) / t.w - FRAME_ASPECT) < 1e-9, `tile ${i} is not of the frame's shape`);
    assert.ok(apart(t, self), `tile ${i} ${JSON.stringify(t)} under the self view ${JSON.stringify(self)}`);
    for (const other of tiles.slice(i + 1)) assert.ok(apart(t, other), `tiles overlap: ${JSON.stringify([t, other])}`);
  }
}

test('a desktop stage: three faces in one row, each more than half the stage high', () => {
  const layout = tileLayout(3, 960, 741);
  assertSound(layout, 960, 741);
  assert.equal(rowsOf(layout.tiles), 1);
  assert.ok(layout.tiles[0].h - layout.nameBand > 741 / 2, JSON.stringify(layout.tiles[0]));
});

test('a phone stage: three faces two to a row, wider than three in a row or in a column', () => {
  const layout = tileLayout(3, 390, 591);
  assertSound(layout, 390, 591);
  assert.equal(rowsOf(layout.tiles), 2);
  assert.ok(layout.tiles[0].w > (390 - 4 * 6) / 3, JSON.stringify(layout.tiles[0]));
  // The short last row is centred.
  const last = layout.tiles[2];
  assert.ok(Math.abs(last.x + last.w / 2 - 195) < 1e-6, JSON.stringify(last));
});

test('every count on both stages keeps its tiles sound, and none is left without a tile', () => {
  for (const [w, h] of [[960, 741], [390, 591], [640, 360], [1600, 900]]) {
    for (let count = 0; count <= 9; ++count) {
      const layout = tileLayout(count, w, h);
      assert.equal(layout.tiles.length, count);
      assertSound(layout, w, h);
    }
  }
});

test('one face alone is as large as the stage allows', () => {
  const { tiles, nameBand } = tileLayout(1, 960, 741);
  assert.ok(tiles[0].h - nameBand > 0.9 * 741 - nameBand, JSON.stringify(tiles[0]));
});
