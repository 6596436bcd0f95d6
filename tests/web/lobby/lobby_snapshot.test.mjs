// A camera snapshot in the lobby: Chromium's fake camera plays a portrait
// (made into a video at test time with ffmpeg), the person takes a
// snapshot, and it is uploaded and prepared like a chosen photo.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { openWeb, sourceFile } from '../support/harness.mjs';

let web;
let dir;
before(async () => {
  dir = mkdtempSync(join(tmpdir(), 'facewire-camera-'));
  const video = join(dir, 'portrait.y4m');
  // Two seconds of the still portrait, in the format Chromium's fake camera reads.
  execFileSync('ffmpeg', ['-loglevel', 'error', '-loop', '1', '-i', sourceFile('tests/data/astronaut.png'), '-t', '2',
    '-r', '10', '-vf', 'scale=480:-2', '-pix_fmt', 'yuv420p', video]);
  web = await openWeb(['--no-demo-room'], {
    browserArgs: ['--use-fake-device-for-media-stream', '--use-fake-ui-for-media-stream', `--use-file-for-fake-video-capture=${video}`],
  });
});
after(async () => {
  await web?.close();
  if (dir) rmSync(dir, { recursive: true, force: true });
});

test('a snapshot from the camera becomes the avatar', { timeout: 120000 }, async () => {
  const page = await web.page();
  await page.context().grantPermissions(['camera'], { origin: web.server.url });
  await page.goto(web.server.url);
  await page.fill('#name', 'Camera');
  await page.click('#snapshot-start');
  await page.locator('#camera-video').waitFor({ state: 'visible' });
  await page.waitForFunction(() => document.getElementById('camera-video').videoWidth > 0);
  await page.click('#snapshot-take');
  await page.locator('#avatar-preview').waitFor({ state: 'visible', timeout: 90000 });
  assert.equal(await page.locator('#upload-error').isHidden(), true, await page.locator('#upload-error').textContent());
  const asset = await page.evaluate(() => JSON.parse(localStorage.getItem('facewire.identity')).asset);
  assert.match(asset, /^[0-9a-f]{32}$/, 'the snapshot was prepared into an avatar');
  assert.equal(await page.locator('#camera').isHidden(), true, 'the camera closes after the snapshot');
});
