// The lobby in Chromium against a real server: it loads, lists the rooms,
// fits a phone, checks room names, and Join opens the room page.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';

import { openWeb } from '../support/harness.mjs';
import { readPng } from '../support/png_pixels.mjs';

let web;
before(async () => { web = await openWeb(); });
after(async () => { await web?.close(); });

// FW_SCREENSHOT_DIR=DIR keeps pictures of the lobby to look at.
async function keepScreenshot(page, name) {
  const dir = process.env.FW_SCREENSHOT_DIR;
  if (!dir) return;
  mkdirSync(dir, { recursive: true });
  await page.screenshot({ path: join(dir, `${name}.png`), fullPage: true });
}

test('the lobby loads and draws the generic face until there is a photo', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  await page.waitForFunction(() => document.getElementById('status').textContent.includes('drawn with the shared shaders'));
  assert.equal(await page.title(), 'facewire');
  for (const label of ['Your name', 'Room to join, or a new room\'s name']) {
    assert.equal(await page.getByLabel(label, { exact: true }).count(), 1, `a field labelled "${label}"`);
  }
  assert.equal(await page.locator('input[type=file][accept="image/*"]').count(), 1);
  await keepScreenshot(page, 'lobby-desktop');
  assert.deepEqual(web.pageErrors, []);
  await page.context().close();
});

test('the generic face is drawn: its canvas shows skin', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  await page.waitForFunction(() => Number(document.getElementById('face').dataset.frames) >= 2);
  const { width, height, channels, data } = readPng(await page.locator('#face').screenshot());
  // The canvas is dark blue-grey; only the rendered face is warm and light.
  let skin = 0;
  for (let i = 0; i < data.length; i += channels) {
    skin += data[i] > 150 && data[i] > data[i + 2] + 40 && data[i + 1] > 90 ? 1 : 0;
  }
  assert.ok(skin > 0.2 * width * height, `skin covers ${skin} of ${width}x${height} pixels; the face fills about half of it`);
  await page.context().close();
});

test('the room list shows the demo room and how many are in it', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  const lobby = page.locator('#room-list button[data-room="lobby"]');
  await lobby.waitFor();
  assert.match(await lobby.textContent(), /lobby\s*3 faces, 0 people/);
  await page.context().close();
});

test('the page fits a 390x844 phone without sideways scrolling', { timeout: 60000 }, async () => {
  const page = await web.page({ width: 390, height: 844 });
  await page.goto(web.server.url);
  await page.locator('#room-list button[data-room="lobby"]').waitFor();
  const widths = await page.evaluate(() => ({
    scroll: document.documentElement.scrollWidth,
    widest: Math.max(...[...document.querySelectorAll('body *')].map((e) => e.getBoundingClientRect().right)),
  }));
  assert.ok(widths.scroll <= 390, `the page is ${widths.scroll} px wide`);
  assert.ok(widths.widest <= 390, `an element reaches ${widths.widest} px`);
  await keepScreenshot(page, 'lobby-phone');
  await page.context().close();
});

test('a room name the protocol does not allow is refused before joining', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  await page.fill('#name', 'Ann');
  await page.fill('#room', 'my room');
  await page.click('#join');
  const error = page.locator('#room-error');
  await error.waitFor();
  assert.match(await error.textContent(), /no spaces/);
  assert.equal(new URL(page.url()).pathname, '/', 'still in the lobby');
  await page.context().close();
});

test('join opens the room page with the room, the name, and keeps the name for a reload', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  await page.fill('#name', 'Zoë');
  await page.fill('#room', 'new.room-1');
  await page.click('#join');
  await page.waitForURL(/room\.html/);
  const query = new URL(page.url()).searchParams;
  assert.equal(query.get('room'), 'new.room-1');
  assert.equal(query.get('name'), 'Zoë');
  assert.equal(query.get('token'), null);
  await page.goto(web.server.url);
  assert.equal(await page.inputValue('#name'), 'Zoë');
  await page.context().close();
});
