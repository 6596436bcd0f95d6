// The face lab's contact sheet without a browser: every view once in each
// arrangement, panels that neither overlap nor leave the sheet, rows
// centred, the arrangement that shows the panels largest on a desktop and
// on a phone, and a file name that is safe whatever the avatar is called.
import { test } from 'node:test';
import assert from 'node:assert/strict';

import { ARRANGEMENTS, PANEL_SIZE, SHEET_VIEWS, arrangementFor, sheetFileName, sheetLayout } from '../../../web/room/lab/contact_sheet.js';

test('each arrangement holds every view once, panels apart and inside the sheet', () => {
  for (const [name, arrangement] of Object.entries(ARRANGEMENTS)) {
    const layout = sheetLayout(arrangement);
    assert.deepEqual(layout.cells.map((c) => c.view.key).sort(), SHEET_VIEWS.map((v) => v.key).sort(), name);
    for (const [i, a] of layout.cells.entries()) {
      assert.equal(a.size, PANEL_SIZE);
      assert.ok(a.x >= 0 && a.y >= 0 && a.x + a.size <= layout.width && a.y + a.size + layout.labelHeight <= layout.height,
        `${name}: ${a.view.key} leaves the sheet`);
      for (const b of layout.cells.slice(i + 1)) {
        const apart = a.x + a.size <= b.x || b.x + b.size <= a.x || a.y + a.size + layout.labelHeight <= b.y || b.y + b.size + layout.labelHeight <= a.y;
        assert.ok(apart, `${name}: ${a.view.key} and ${b.view.key} overlap`);
      }
    }
  }
});

test('rows are centred, the front in the middle of the turns', () => {
  const wide = sheetLayout(ARRANGEMENTS.wide);
  const centre = (key) => { const c = wide.cells.find((cell) => cell.view.key === key); return c.x + c.size / 2; };
  assert.equal(centre('front'), wide.width / 2);
  assert.equal((centre('above-20') + centre('below-20')) / 2, wide.width / 2);
  assert.ok(centre('right-60') < centre('right-30') && centre('left-30') < centre('left-60'), 'seen from the front, the person\'s right is on the left');
  const views = Object.fromEntries(SHEET_VIEWS.map((v) => [v.key, v]));
  assert.deepEqual([views['left-30'].yawDeg, views['right-60'].yawDeg, views['above-20'].pitchDeg], [30, -60, 20]);
});

test('a desktop gets the wide sheet, an upright phone the tall one', () => {
  // What the dialog leaves for the image (sheet_dialog.js) at 1280x800 and 390x844.
  assert.equal(arrangementFor(0.96 * 1280 - 32, 0.94 * 800 - 150), 'wide');
  assert.equal(arrangementFor(0.96 * 390 - 32, 0.94 * 844 - 150), 'tall');
  assert.equal(arrangementFor(10000, 10000), 'wide', 'room for either at full size: the wide one');
});

test('the file name holds the avatar\'s name and the time, and nothing else', () => {
  const at = new Date(Date.UTC(2026, 10, 28, 22, 41, 1, 250));
  assert.equal(sheetFileName('Ada', at), 'facewire-sheet-Ada-20261128-224101.png');
  assert.equal(sheetFileName('Ada Lovelace', at), 'facewire-sheet-Ada-Lovelace-20261128-224101.png');
  assert.equal(sheetFileName('../../etc/passwd', at), 'facewire-sheet-etc-passwd-20261128-224101.png');
  assert.equal(sheetFileName('Zoë', at), 'facewire-sheet-Zoë-20261128-224101.png');
  assert.equal(sheetFileName('', at), 'facewire-sheet-face-20261128-224101.png');
  assert.equal(sheetFileName('<>:"|?*', at), 'facewire-sheet-face-20261128-224101.png');
  assert.equal(sheetFileName('x'.repeat(500), at), `facewire-sheet-${'x'.repeat(40)}-20261128-224101.png`);
  assert.equal(sheetFileName(`${'x'.repeat(39)} y`, at), `facewire-sheet-${'x'.repeat(39)}-20261128-224101.png`, 'no dash left at the cut');
  assert.equal(sheetFileName('𠀀'.repeat(41), at), `facewire-sheet-${'𠀀'.repeat(40)}-20261128-224101.png`, 'whole characters');
});
