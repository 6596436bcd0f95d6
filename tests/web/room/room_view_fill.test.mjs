// The room's faces fill the stage, on a desktop and on a phone: in the demo
// room (three residents), each face, found from the pixels of a screenshot
// of the stage, is whole in its tile (background above its hair), the faces
// together are at least half the stage's height, and each name sits below
// its face's lowest drawn pixel. FW_ROOM_SHOTS=DIR keeps the screenshots.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';

import { openWeb } from '../support/harness.mjs';
import { pageUntil } from '../support/page_poll.mjs';
import { faceRows, stageBoxes, stageShotWithoutText } from '../support/stage_faces.mjs';

const RESIDENTS = 3;
/** Looks at each size, 400 ms apart: a face's height is their median (one look may catch a nod or a turn). */
const LOOKS = 3;
/** Background rows (CSS px) between a face's lowest drawn row and its name. */
const NAME_CLEARANCE = 2;
let web;

before(async () => { web = await openWeb([]); });
after(async () => { await web?.close(); });

const joinedWithFaces = (page) => pageUntil(page, (p) => p.evaluate(() => {
  if (!window.facewireRoom) return null;
  const { client, view } = window.facewireRoom;
  return { status: client.status, drawn: view.tiles.filter((t) => t.drawn).length };
}), (s) => s.status === 'joined' && s.drawn === RESIDENTS, `the ${RESIDENTS} residents drawn`, 90000);

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

/** Per face: its drawn rows in each look, and its name's box (CSS px, from the stage's top). */
async function look(page, label) {
  const boxes = await stageBoxes(page);
  const looks = [];
  for (let i = 0; i < LOOKS; ++i) {
    if (i > 0) await page.waitForTimeout(400);
    const png = await stageShotWithoutText(page);
    if (process.env.FW_ROOM_SHOTS && i === 0) writeFileSync(`${process.env.FW_ROOM_SHOTS}/view-${label}.png`, await page.locator('#stage').screenshot());
    const scale = png.width / boxes.stage.w;
    looks.push(boxes.tiles.map((t) => {
      const rows = faceRows(png, t.tile, scale);
      return rows && { top: rows.top / scale, bottom: (rows.bottom + 1) / scale };
    }));
  }
  return { boxes, faces: boxes.tiles.map((t, i) => ({ ...t, looks: looks.map((l) => l[i]) })) };
}

/** The faces' rows together (a row of two faces side by side counts once), CSS px. */
function unionHeight(spans) {
  const sorted = [...spans].sort((a, b) => a.top - b.top);
  let total = 0;
  let end = -Infinity;
  for (const { top, bottom } of sorted) {
    total += Math.max(0, bottom - Math.max(top, end));
    end = Math.max(end, bottom);
  }
  return total;
}

/** How many rows the faces stand in: faces whose rows overlap stand in one. */
function rowsOf(spans) {
  let rows = 0;
  let end = -Infinity;
  for (const { top, bottom } of [...spans].sort((a, b) => a.top - b.top)) {
    if (top >= end) rows += 1;
    end = Math.max(end, bottom);
  }
  return rows;
}

for (const [label, viewport] of [['desktop', { width: 1280, height: 800 }], ['phone', { width: 390, height: 844 }]]) {
  test(`${label} ${viewport.width}x${viewport.height}: the faces fill the stage, whole, their names under their chins`, { timeout: 150000 }, async (t) => {
    const page = await web.page(viewport);
    // Leaves the room at the end, pass or fail: the next size's viewer sees the residents alone.
    t.after(() => page.context().close());
    await page.goto(`${web.server.url}room.html?room=lobby&name=Viewer`);
    await joinedWithFaces(page);
    await page.waitForTimeout(1500);  // the faces' first frames and the view's re-aims settle
    const { boxes, faces } = await look(page, label);
    assert.equal(faces.length, RESIDENTS);
    const spans = faces.map((face) => {
      assert.ok(face.looks.every(Boolean), `${face.nameText}: no face drawn in its tile ${JSON.stringify(face.tile)}`);
      return { top: median(face.looks.map((l) => l.top)), bottom: median(face.looks.map((l) => l.bottom)) };
    });
    const stageHeight = boxes.stage.h;
    const filled = unionHeight(spans) / stageHeight;
    console.log(`${label}: stage ${boxes.stage.w}x${stageHeight}; faces ` + faces.map((f, i) =>
      `${f.nameText} rows ${spans[i].top.toFixed(0)}-${spans[i].bottom.toFixed(0)} (${((spans[i].bottom - spans[i].top) / stageHeight * 100).toFixed(0)} %), ` +
      `tile top ${f.tile.y.toFixed(0)}, name top ${f.name.y.toFixed(0)}`).join('; ') + `; together ${(filled * 100).toFixed(0)} % of the stage's height`);
    for (const [i, face] of faces.entries()) {
      const span = spans[i];
      // Whole: the head is not cut by its tile's top.
      assert.ok(span.top >= face.tile.y + 2, `${face.nameText}: the head is cut by its tile's top (face from ${span.top}, tile from ${face.tile.y})`);
      // Under the chin: the face ends before its name's box begins (a neck that
      // runs on into the name reads as a label on the neck), and the name
      // stays in the tile and on the stage.
      assert.ok(face.name.y >= span.bottom + NAME_CLEARANCE, `${face.nameText}: the name (from ${face.name.y.toFixed(1)}) is not clear of the face (drawn down to ${span.bottom.toFixed(1)})`);
      assert.ok(face.name.x >= face.tile.x - 0.5 && face.name.x + face.name.w <= face.tile.x + face.tile.w + 0.5, `${face.nameText}: the name leaves its tile`);
      assert.ok(face.name.y + face.name.h <= stageHeight + 0.5, `${face.nameText}: the name is below the stage`);
    }
    // Large: the faces' rows together fill half the stage's height, and no face
    // is smaller than its share of that half (a row of faces shares it).
    assert.ok(filled >= 0.5, `the faces fill ${(filled * 100).toFixed(0)} % of the stage's height, not half`);
    const faceRowsCount = rowsOf(spans);
    for (const [i, span] of spans.entries()) {
      const share = (span.bottom - span.top) / stageHeight;
      assert.ok(share >= 0.5 / faceRowsCount, `${faces[i].nameText} fills ${(share * 100).toFixed(0)} % of the stage's height, under its share of half in ${faceRowsCount} rows`);
    }
    assert.deepEqual(web.pageErrors, []);
  });
}
