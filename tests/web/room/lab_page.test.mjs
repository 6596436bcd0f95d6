// The face lab (lab.html) on a real server in Chromium: its preview is drawn
// by the room's renderer, the joy slider moves the mouth, a muscle's slider
// the region the muscle pulls (the skin age and looseness are taken), the cheeks' blush
// sliders redden the cheeks, and so does the blushing example loaded and
// played from the editor, a script with a syntax error is shown at its
// line and column, and the lobby links the lab. Pixels are read from the
// canvas where the page's own landmarks put the mouth and the cheeks. The
// contact sheet, downloaded as a person would, shows the face in each of its
// panels, turned where it says, smiling when the preview smiles, and fits a
// phone's screen as the page does. FW_LAB_SHOTS=DIR keeps screenshots of the
// page and of the sheet at desktop and at phone size.
import { readFileSync } from 'node:fs';
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';

import { openWeb, sourceFile } from '../support/harness.mjs';
import { pageUntil } from '../support/page_poll.mjs';
import { readPng } from '../support/png_pixels.mjs';
import {
  canvasPixels, faceShare, imageMouthSamples, imageRegion, lumas, meanAbsDifference, mouthSamples,
} from '../support/room_pixels.mjs';

/** Long enough for an override to reach the server, its face to settle through the physics face and come back. */
const SETTLE_MS = 2000;
let web;

before(async () => { web = await openWeb([]); });
after(async () => { await web?.close(); });

async function openLab(viewport = { width: 1280, height: 800 }) {
  const page = await web.page(viewport);
  await page.goto(`${web.server.url}lab.html?name=Ada`);
  await pageUntil(page, (p) => p.evaluate(() => window.facewireLab && {
    status: window.facewireLab.client.status, frames: window.facewireLab.view.frames,
  }), (s) => s.status === 'joined' && s.frames > 10, 'the preview drawn', 60000);
  await page.waitForTimeout(SETTLE_MS);
  return page;
}

const landmarks = (page, indices) => page.evaluate((i) => window.facewireLab.view.landmarksOnScreen(i), indices);

async function slide(page, key, value) {
  const slider = page.locator(`input[data-key="${key}"]`);
  await slider.evaluate((input, v) => {
    input.value = String(v);
    input.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
}

/** Mean R/G of a square around each cheek: between the lower lid, the mouth's corner and the jaw. */
async function cheekRedness(page) {
  const [l2, l14, l41, l46, l48, l54, l36, l45] = await landmarks(page, [2, 14, 41, 46, 48, 54, 36, 45]);
  const side = 0.12 * Math.hypot(l45[0] - l36[0], l45[1] - l36[1]);
  const centre = (...ps) => [0, 1].map((k) => ps.reduce((s, p) => s + p[k], 0) / ps.length);
  let ratio = 0;
  for (const [x, y] of [centre(l2, l41, l48), centre(l14, l46, l54)]) {
    const { data } = await canvasPixels(page, { x: x - side / 2, y: y - side / 2, w: side, h: side });
    let r = 0;
    let g = 0;
    for (let i = 0; i < data.length; i += 4) [r, g] = [r + data[i], g + data[i + 1]];
    ratio += r / Math.max(1, g) / 2;
  }
  return ratio;
}

test('the joy slider changes the mouth', async () => {
  const page = await openLab();
  const corners = await landmarks(page, [36, 45]);
  const before = await mouthSamples(page, corners);
  await page.waitForTimeout(500);
  const still = await mouthSamples(page, corners);
  await slide(page, 'emotion-joy', 100);
  await page.waitForTimeout(SETTLE_MS);
  const after = await mouthSamples(page, await landmarks(page, [36, 45]));
  const unchanged = meanAbsDifference(before, still);
  const changed = meanAbsDifference(before, after);
  assert.ok(unchanged < 1.5, `the held face moved by itself: ${unchanged.toFixed(2)}`);
  assert.ok(changed > 3 && changed > 4 * unchanged, `joy at 100 %: the mouth changed by ${changed.toFixed(2)} (still: ${unchanged.toFixed(2)})`);
  await page.close();
});

test('the cheeks redden with their blush sliders', async () => {
  const page = await openLab();
  const before = await cheekRedness(page);
  await slide(page, 'blush-1', 100);
  await slide(page, 'blush-2', 100);
  await page.waitForTimeout(SETTLE_MS);
  const after = await cheekRedness(page);
  assert.ok(after > before * 1.04, `R/G in the cheeks: ${before.toFixed(3)} before, ${after.toFixed(3)} with blush`);
  await page.close();
});

test('a vascular script loaded from a file and played reddens the cheeks', async () => {
  const page = await openLab();
  const before = await cheekRedness(page);
  // Loaded as a person would: the example file through the editor's Load.
  await page.setInputFiles('#script-file', sourceFile('avatar/behavior/script/examples/blushing.fws'));
  await pageUntil(page, (p) => p.inputValue('#script'), (t) => t.includes('[emotion blushing'), 'the file in the editor');
  await page.click('#script-play');
  // Its stages rise over the 20 s episode: the most R/G seen within 8 s.
  let most = before;
  for (let i = 0; i < 16 && most <= before * 1.04; ++i) {
    await page.waitForTimeout(500);
    most = Math.max(most, await cheekRedness(page));
  }
  assert.ok(most > before * 1.04, `R/G in the cheeks: ${before.toFixed(3)} before, at most ${most.toFixed(3)} with the script`);
  await page.close();
});

/** The canvas pixels of a square of `side` CSS pixels around `centre`. */
async function squareAround(page, centre, side) {
  const { data } = await canvasPixels(page, { x: centre[0] - side / 2, y: centre[1] - side / 2, w: side, h: side });
  return Array.from(data);
}

test('a muscle slider moves the region that muscle pulls, and the skin sliders are taken', async (t) => {
  const page = await openLab();
  // The left zygomatic major (muscle 22, PROTOCOL.md 5.16) pulls the left
  // mouth corner (landmark 54) up and out; the right brow (19) is far from it.
  const [corner, brow, l36, l45] = await landmarks(page, [54, 19, 36, 45]);
  const side = 0.35 * Math.hypot(l45[0] - l36[0], l45[1] - l36[1]);
  const before = { corner: await squareAround(page, corner, side), brow: await squareAround(page, brow, side) };
  const slider = page.locator('input[data-key="muscle-22"]');
  assert.equal(await slider.getAttribute('aria-label'), 'Muscles: zygomatic major (left)');
  await slide(page, 'muscle-22', 100);
  await page.waitForTimeout(SETTLE_MS);
  const after = { corner: await squareAround(page, corner, side), brow: await squareAround(page, brow, side) };
  const near = meanAbsDifference(before.corner, after.corner);
  const far = meanAbsDifference(before.brow, after.brow);
  t.diagnostic(`mouth corner changed by ${near.toFixed(2)}, far brow by ${far.toFixed(2)}`);
  assert.ok(near > 3 && near > 4 * far, `the mouth corner changed by ${near.toFixed(2)}, the far brow by ${far.toFixed(2)}`);
  const surface = await page.evaluate(() => window.facewireLab.client.previewSurface);
  assert.ok(surface && surface.moves.length > 0, 'the page was sent the simulated surface (5.18)');
  t.diagnostic(`preview surface: ${surface.moves.length} vertices`);

  // The page draws the simulated skin, not only its action units: the left
  // zygomatic minor (20) is no unit's muscle alone, and the face drawn
  // without the surface it was sent differs where that muscle pulls.
  await slide(page, 'muscle-22', 0);
  await slide(page, 'muscle-20', 100);
  await page.waitForTimeout(SETTLE_MS);
  const [lip, l36b, l45b] = await landmarks(page, [52, 36, 45]);
  const lipSide = 0.35 * Math.hypot(l45b[0] - l36b[0], l45b[1] - l36b[1]);
  const drawn = await squareAround(page, lip, lipSide);
  await page.waitForTimeout(200);
  const still = meanAbsDifference(drawn, await squareAround(page, lip, lipSide));
  const stripped = await page.evaluate(() => {
    const { view, client } = window.facewireLab;
    const face = view.room.ownFace ?? view.room.faces.get(client.you);
    face.model.setSurface([]);  // until the next message or the next showSurface: held while the face rests
    return client.previewSurface.moves.length;
  });
  await page.waitForTimeout(200);
  const without = await squareAround(page, lip, lipSide);
  const residual = meanAbsDifference(drawn, without);
  t.diagnostic(`zygomatic minor: surface of ${stripped} vertices; the upper lip drawn without it differs by ${residual.toFixed(2)} (held: ${still.toFixed(2)})`);
  assert.ok(residual > 0.5 && residual > 3 * still, `the surface changed the drawn lip by ${residual.toFixed(2)} only (held: ${still.toFixed(2)})`);

  await slide(page, 'skin-age', 100);
  await slide(page, 'skin-looseness', 50);
  await page.waitForTimeout(SETTLE_MS);
  const results = await page.evaluate(() => [...window.facewireLab.client.results.values()]);
  assert.ok(results.length >= 3, `${results.length} overrides answered`);
  assert.deepEqual(results.filter((error) => error !== ''), [], 'the server refused an override');
  assert.equal(await page.textContent('#control-result'), '');
  await page.close();
});

test('a script with a syntax error is shown at its line and column', async () => {
  const page = await openLab();
  await page.fill('#script', 'ClearAllFrame\nBeginKeyFrame\n  12 oops\nend\n');
  await page.click('#script-check');
  const shown = await pageUntil(page, (p) => p.evaluate(() => {
    const result = document.getElementById('script-result');
    return result.dataset.line ? { line: result.dataset.line, column: result.dataset.column, text: result.textContent } : null;
  }), () => true, 'the check answered');
  assert.equal(shown.line, '3');
  assert.match(shown.text, new RegExp(`^line 3, column ${shown.column}: `));
  const caret = await page.evaluate(() => document.getElementById('script').selectionStart);
  assert.equal(caret, 'ClearAllFrame\nBeginKeyFrame\n'.length + Number(shown.column) - 1, 'the caret is put at the error');

  await page.fill('#script', 'ClearAllFrame\nBeginKeyFrame\nBeginKeyFrame\n 12 1.0\nAnimate 5 "Texture"\nend\n');
  await page.click('#script-check');
  await pageUntil(page, (p) => p.textContent('#script-result'), (t) => t.includes('no errors'), 'a good script checked');
  await page.close();
});

/**
 * Presses "Contact sheet" and downloads it by its link: { image (the PNG
 * read), layout, arrangement, fileName, suggested (the download's name),
 * front (landmarks 36 and 45 in the sheet's pixels) }.
 */
async function takeSheet(page) {
  const last = () => page.evaluate(() => window.facewireLab.sheet.last?.url ?? null);
  const before = await last();
  await page.click('#contact-sheet');
  await pageUntil(page, last, (url) => url !== before, 'the contact sheet drawn');
  const sheet = await page.evaluate(() => {
    const { layout, arrangement, fileName } = window.facewireLab.sheet.last;
    return { layout, arrangement, fileName, front: window.facewireLab.view.landmarksOnScreen([36, 45], 'sheet:front') };
  });
  const cell = sheet.layout.cells.find((c) => c.view.key === 'front');
  sheet.front = sheet.front.map(([x, y]) => [cell.x + x, cell.y + y]);
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#sheet-download')]);
  return { ...sheet, suggested: download.suggestedFilename(), image: readPng(readFileSync(await download.path())) };
}

const panelOf = (sheet, key) => {
  const { x, y, size } = sheet.layout.cells.find((c) => c.view.key === key);
  return imageRegion(sheet.image, { x, y, w: size, h: size });
};

/** The share of the sheet outside its panels and their labels that is face: none, where no panel is. */
function faceOutsidePanels({ image, layout }) {
  const inside = (x, y) => layout.cells.some((c) => x >= c.x && x < c.x + c.size && y >= c.y && y < c.y + c.size + layout.labelHeight);
  const outside = [];
  for (let y = 0; y < image.height; ++y) {
    for (let x = 0; x < image.width; ++x) {
      const at = (y * image.width + x) * image.channels;
      if (!inside(x, y)) outside.push(image.data[at], image.data[at + 1], image.data[at + 2], 255);
    }
  }
  return faceShare({ data: outside });
}

const dialogOpen = (page) => page.evaluate(() => document.getElementById('sheet-dialog').open);

test('the contact sheet shows the face as the preview does now, from seven views', async () => {
  const page = await openLab();
  const liveBefore = await page.evaluate(() => {
    const { view } = window.facewireLab;
    const canvas = document.getElementById('room-canvas');
    return { width: canvas.width, height: canvas.height, yaw: view.cameraYawRad, frames: view.frames };
  });
  const liveCorners = await landmarks(page, [36, 45]);
  const liveStill = await mouthSamples(page, liveCorners);
  const still = await takeSheet(page);
  await page.keyboard.press('Escape');
  await pageUntil(page, async (p) => ({ open: await dialogOpen(p) }), (s) => !s.open, 'Escape closing the sheet', 5000);

  // The preview is as it was: same canvas, same camera, still drawing, the same face.
  await page.waitForTimeout(500);
  const liveAfter = await page.evaluate(() => {
    const { view } = window.facewireLab;
    const canvas = document.getElementById('room-canvas');
    return { width: canvas.width, height: canvas.height, yaw: view.cameraYawRad, frames: view.frames };
  });
  assert.deepEqual([liveAfter.width, liveAfter.height, liveAfter.yaw], [liveBefore.width, liveBefore.height, liveBefore.yaw]);
  assert.ok(liveAfter.frames > liveBefore.frames + 3, `the preview kept drawing (${liveBefore.frames} -> ${liveAfter.frames} frames)`);
  const liveUndisturbed = meanAbsDifference(liveStill, await mouthSamples(page, await landmarks(page, [36, 45])));
  assert.ok(liveUndisturbed < 1.5, `the preview's mouth moved by ${liveUndisturbed.toFixed(2)} after the sheet`);

  // Seven panels, each a face, nothing drawn elsewhere, the PNG as big as the sheet.
  const keys = still.layout.cells.map((c) => c.view.key).sort();
  assert.deepEqual(keys, ['above-20', 'below-20', 'front', 'left-30', 'left-60', 'right-30', 'right-60']);
  assert.equal(still.arrangement, 'wide', 'a desktop gets the wide sheet');
  assert.deepEqual([still.image.width, still.image.height], [still.layout.width, still.layout.height], 'the PNG is the sheet');
  assert.match(still.suggested, /^facewire-sheet-Ada-\d{8}-\d{6}\.png$/);
  assert.equal(still.suggested, still.fileName);
  for (const key of keys) {
    const share = faceShare(panelOf(still, key));
    assert.ok(share > 0.2, `the ${key} panel shows a face (${share.toFixed(3)} of it is face)`);
  }
  const stray = faceOutsidePanels(still);
  assert.ok(stray < 0.01, `${stray.toFixed(3)} of the sheet outside the panels is face`);

  // A second sheet of the same state is the same; every other view differs from the front.
  const again = await takeSheet(page);
  await page.click('#sheet-close');
  assert.equal(await dialogOpen(page), false, 'Close closes the sheet');
  const front = lumas(panelOf(still, 'front'));
  const repeat = meanAbsDifference(front, lumas(panelOf(again, 'front')));
  const turns = {};
  for (const key of keys.filter((k) => k !== 'front')) {
    const turned = meanAbsDifference(front, lumas(panelOf(still, key)));
    turns[key] = turned.toFixed(1);
    assert.ok(turned > 4 && turned > 4 * repeat, `the ${key} panel differs from the front by ${turned.toFixed(2)} (a second sheet: ${repeat.toFixed(2)})`);
  }

  // With joy at 100 % the sheet's front smiles as the preview does.
  await slide(page, 'emotion-joy', 100);
  await page.waitForTimeout(SETTLE_MS);
  const liveJoy = await mouthSamples(page, await landmarks(page, [36, 45]));
  const joy = await takeSheet(page);
  if (process.env.FW_LAB_SHOTS) await page.screenshot({ path: `${process.env.FW_LAB_SHOTS}/lab-sheet-joy.png` });
  await page.keyboard.press('Escape');
  const stillMouth = imageMouthSamples(still.image, still.front);
  const noise = meanAbsDifference(stillMouth, imageMouthSamples(again.image, again.front));
  const smiled = meanAbsDifference(stillMouth, imageMouthSamples(joy.image, joy.front));
  assert.ok(smiled > 3 && smiled > 4 * noise, `joy at 100 %: the front panel's mouth changed by ${smiled.toFixed(2)} (a second sheet: ${noise.toFixed(2)})`);
  // ...and is nearer the preview's mouth at joy than the sheet at rest is.
  const nearJoy = meanAbsDifference(liveJoy, imageMouthSamples(joy.image, joy.front));
  const nearRest = meanAbsDifference(liveJoy, stillMouth);
  assert.ok(nearJoy < 0.3 * nearRest, `the sheet's mouth to the preview's at joy: ${nearJoy.toFixed(2)}; the sheet at rest: ${nearRest.toFixed(2)}`);
  console.log(`sheet measures: panels vs front ${JSON.stringify(turns)}, repeat ${repeat.toFixed(2)}; mouth smiled ${smiled.toFixed(2)}, noise ${noise.toFixed(2)}; `
    + `to the preview at joy ${nearJoy.toFixed(2)} vs at rest ${nearRest.toFixed(2)}`);
  await page.close();
});

test('the lab and its contact sheet work at desktop and phone size, and the lobby links it', async () => {
  for (const [width, height, label] of [[1280, 800, 'desktop'], [390, 844, 'phone']]) {
    const page = await openLab({ width, height });
    const box = await page.locator('#room-canvas').boundingBox();
    assert.ok(box.width > 0.6 * width && box.width <= width, `${label}: the preview is ${box.width} px wide`);
    assert.ok(box.height > 0.4 * height, `${label}: the preview is ${box.height} px high`);
    assert.ok(box.y < 0.15 * height, `${label}: the preview starts ${box.y} px down`);
    const overflow = await page.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
    assert.ok(overflow <= 0, `${label}: the page is ${overflow} px wider than the screen`);
    if (process.env.FW_LAB_SHOTS) await page.screenshot({ path: `${process.env.FW_LAB_SHOTS}/lab-${label}.png` });
    // The sliders are there to be moved: brought into view, nothing covers them.
    for (const key of ['emotion-joy', 'pallor']) {
      const slider = page.locator(`input[data-key="${key}"]`);
      await slider.scrollIntoViewIfNeeded();
      const reachable = await slider.evaluate((input) => {
        const r = input.getBoundingClientRect();
        return r.top >= 0 && r.bottom <= window.innerHeight && document.elementFromPoint(r.x + r.width / 2, r.y + r.height / 2) === input;
      });
      assert.ok(reachable, `${label}: the ${key} slider cannot be reached`);
    }
    // The sheet and its buttons fit the screen, its panels shown large enough to see.
    const sheet = await takeSheet(page);
    assert.equal(sheet.arrangement, width > height ? 'wide' : 'tall', `${label}: the sheet's arrangement`);
    for (const selector of ['#sheet-dialog', '#sheet-dialog img', '#sheet-download', '#sheet-close']) {
      const b = await page.locator(selector).boundingBox();
      assert.ok(b && b.x >= 0 && b.y >= 0 && b.x + b.width <= width && b.y + b.height <= height,
        `${label}: ${selector} at ${JSON.stringify(b)} is not within the ${width}x${height} screen`);
    }
    const shown = await page.locator('#sheet-dialog img').boundingBox();
    const panel = (shown.width / sheet.layout.width) * sheet.layout.cells[0].size;
    assert.ok(panel >= 120, `${label}: each panel is shown ${panel.toFixed(0)} px wide`);
    const sheetOverflow = await page.evaluate(() => document.scrollingElement.scrollWidth - window.innerWidth);
    assert.ok(sheetOverflow <= 0, `${label}: with the sheet open the page is ${sheetOverflow} px wider than the screen`);
    if (process.env.FW_LAB_SHOTS) await page.screenshot({ path: `${process.env.FW_LAB_SHOTS}/lab-sheet-${label}.png` });
    await page.close();
  }
  const lobby = await web.page();
  await lobby.goto(web.server.url);
  await lobby.fill('#name', 'Ada');
  await lobby.click('#lab-link');
  await lobby.waitForURL(/lab\.html\?/);
  assert.match(lobby.url(), /name=Ada/);
  await lobby.close();
  assert.deepEqual(web.pageErrors, []);
});
