// Photos uploaded from the lobby: progress, then the prepared avatar and
// the preparation's advice, and deleting it again; the server's own words
// when a photo cannot serve. The server takes at most 200 000 bytes per upload here, so that a
// test portrait is too large.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';

import { openWeb, sourceFile } from '../support/harness.mjs';
import { flatPng } from '../support/test_images.mjs';

const MAX_UPLOAD_BYTES = 200000;
let web;
before(async () => { web = await openWeb(['--max-upload-bytes', String(MAX_UPLOAD_BYTES), '--no-demo-room']); });
after(async () => { await web?.close(); });

// Records every value the progress bar shows, and whether it was visible.
async function watchProgress(page) {
  await page.evaluate(() => {
    window.progressSeen = [];
    const bar = document.getElementById('upload-progress');
    const box = document.getElementById('upload');
    new MutationObserver(() => {
      if (!box.hidden) window.progressSeen.push(bar.hasAttribute('value') ? bar.value : 'preparing');
    }).observe(document.body, { attributes: true, subtree: true, attributeFilter: ['hidden', 'value'] });
  });
}

test('a portrait uploads with progress, then its avatar and advice show, and a reload keeps it', { timeout: 120000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  await watchProgress(page);
  await page.setInputFiles('#photo-file', sourceFile('tests/data/grace_hopper.jpg'));
  const preview = page.locator('#avatar-preview');
  await preview.waitFor({ state: 'visible', timeout: 90000 });
  assert.equal(await page.locator('#upload-error').isHidden(), true, await page.locator('#upload-error').textContent());
  const seen = await page.evaluate(() => window.progressSeen);
  assert.ok(seen.length > 0, 'the progress bar showed');
  assert.ok(seen.includes('preparing') || seen.some((v) => v > 0), `progress moved: ${JSON.stringify(seen)}`);
  assert.equal(await page.locator('#upload').isHidden(), true, 'the progress bar goes when it is done');
  assert.equal(await page.locator('#face').isHidden(), true, 'the generic face gives way');
  // The avatar is drawn: the canvas holds the face's light pixels, not the blank.
  const lit = await page.evaluate(() => {
    const canvas = document.getElementById('avatar-preview');
    const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
    let count = 0;
    for (let i = 0; i < data.length; i += 4) count += data[i] + data[i + 1] + data[i + 2] > 300 ? 1 : 0;
    return count / (canvas.width * canvas.height);
  });
  assert.ok(lit > 0.2, `only ${Math.round(lit * 100)} % of the preview is lit`);
  // Grace Hopper's photo: glasses and a cap; whatever the pipeline says is listed (it may say nothing).
  const advice = await page.locator('#advice li').allTextContents();
  assert.equal(await page.locator('#advice-box').isHidden(), advice.length === 0);

  const asset = await page.evaluate(() => JSON.parse(localStorage.getItem('facewire.identity')).asset);
  assert.match(asset, /^[0-9a-f]{32}$/);
  await page.reload();
  await preview.waitFor({ state: 'visible' });

  // "Delete my photo": gone from the server, forgotten here, the generic face back.
  await page.getByRole('button', { name: 'Delete my photo' }).click();
  await page.locator('#face').waitFor({ state: 'visible', timeout: 10000 });
  assert.equal(await page.locator('#delete-error').isHidden(), true, await page.locator('#delete-error').textContent());
  assert.equal(await preview.isHidden(), true);
  assert.match(await page.locator('#deleted-note').textContent(), /deleted from the server/);
  assert.equal(await page.locator('#deleted-note').isHidden(), false);
  assert.equal(await page.evaluate(() => JSON.parse(localStorage.getItem('facewire.identity')).asset), '');
  const status = await page.evaluate(async (id) => (await fetch(`api/packages/${id}`)).status, asset);
  assert.equal(status, 404, 'the server still serves the deleted avatar');
  await page.context().close();
});

test('a photo without a face shows the server\'s message', { timeout: 120000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  await page.setInputFiles('#photo-file', { name: 'wall.png', mimeType: 'image/png', buffer: flatPng(320, 240, [90, 140, 200]) });
  const error = page.locator('#upload-error');
  await error.waitFor({ state: 'visible', timeout: 90000 });
  assert.match(await error.textContent(), /face/i);
  assert.equal(await page.locator('#avatar-preview').isHidden(), true);
  await page.context().close();
});

test('a photo over the server\'s upload limit shows the 413 message', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(web.server.url);
  // 791 KB, 512x512: small enough in pixels that the lobby sends it as it is.
  await page.setInputFiles('#photo-file', sourceFile('tests/data/astronaut.png'));
  const error = page.locator('#upload-error');
  await error.waitFor({ state: 'visible', timeout: 30000 });
  const text = await error.textContent();
  assert.match(text, /too large/);
  assert.match(text, new RegExp(`at most ${Math.floor(MAX_UPLOAD_BYTES / 1024)} KiB`));
  await page.context().close();
});
