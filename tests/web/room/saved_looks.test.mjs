// Saved looks in Chromium on a real server: in the face lab a person saves
// the script in the editor under a name with their uploaded face (a bad
// script is refused with its line and column), reloads the page and finds it
// listed, loads it back into the editor and plays it by name, which reddens
// their decoded face; in a room the saved-looks picker plays it too.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

import { openWeb, sourceFile } from '../support/harness.mjs';
import { pageUntil } from '../support/page_poll.mjs';

const FLUSHED = `[emotion flushed
  [stage1 duration 100 [expression flush intensity 1.0]]]
[expression flush
  [mpca cheeks intensity 1.0]
  [mpca forehead intensity 0.8]]
`;
let web;
let owner;

before(async () => {
  web = await openWeb([]);
  // A face of the person's own: a package uploaded as it is (a resident's).
  const upload = await fetch(`${web.server.url}api/avatars`, {
    method: 'POST', headers: { 'Content-Type': 'application/x-facewire-avatar' },
    body: readFileSync(sourceFile('server/avatars/residents/ada.fwa')),
  });
  assert.equal(upload.status, 201, await upload.clone().text());
  owner = await upload.json();
});
after(async () => { await web?.close(); });

/** The largest blush of the person's own face, as their page decodes it. */
const ownBlush = (page, handle) => page.evaluate((h) => {
  const { client } = window[h];
  return Math.max(0, ...(client.face(client.you)?.blush ?? [0]));
}, handle);

test('a look saved in the lab is listed after a reload, loads, plays, and the room picker plays it', { timeout: 180000 }, async () => {
  const page = await web.page({ width: 1280, height: 900 });
  const labUrl = `${web.server.url}lab.html?name=Ada&asset=${owner.asset}&key=${owner.key}`;
  const joined = async () => pageUntil(page, (p) => p.evaluate(() => window.facewireLab?.client.status),
    (s) => s === 'joined', 'the lab joined', 60000);
  await page.goto(labUrl);
  await joined();

  // A bad script is refused where it is wrong, and nothing is saved.
  await page.fill('#script', 'ClearAllFrame\nBeginKeyFrame\n  12 strong\nend\n');
  await page.fill('#look-name', 'oops');
  await page.click('#script-save');
  await pageUntil(page, (p) => p.textContent('#looks-result'), (t) => t.includes('not saved'), 'the refusal shown');
  assert.match(await page.textContent('#looks-result'), /script 3:\d+:/);

  await page.fill('#script', FLUSHED);
  await page.fill('#look-name', 'flushed');
  await page.click('#script-save');
  await pageUntil(page, (p) => p.textContent('#looks-result'), (t) => t.startsWith("saved 'flushed'"), 'the look saved');

  await page.reload();
  await joined();
  const entry = page.locator('#looks li[data-name="flushed"]');
  await pageUntil(page, () => entry.count(), (n) => n === 1, 'the saved look listed after a reload');
  assert.match(await entry.textContent(), /vascular/);
  await page.fill('#script', '');
  await entry.locator('button[data-action="load"]').click();
  assert.equal(await page.inputValue('#script'), FLUSHED);

  const before = await ownBlush(page, 'facewireLab');
  await entry.locator('button[data-action="play"]').click();
  await pageUntil(page, (p) => p.textContent('#looks-result'), (t) => t.includes("playing 'flushed'"), 'the look played');
  const during = await pageUntil(page, (p) => ownBlush(p, 'facewireLab'), (b) => b > before + 0.1,
    'the played look reddening the face', 15000);
  console.log(`lab: blush ${before.toFixed(2)} -> ${during.toFixed(2)}`);
  await page.close();

  // The room page lists the person's looks in a picker that plays one.
  const room = await web.page({ width: 1280, height: 900 });
  await room.goto(`${web.server.url}room.html?room=tea&name=Ada&asset=${owner.asset}&key=${owner.key}`);
  await pageUntil(room, (p) => p.evaluate(() => window.facewireRoom?.client.status), (s) => s === 'joined',
    'the room joined', 60000);
  await pageUntil(room, (p) => p.isVisible('#saved-looks'), Boolean, 'the saved-looks picker shown');
  assert.equal(await room.inputValue('#look-pick'), 'flushed');
  const roomBefore = await ownBlush(room, 'facewireRoom');
  await room.click('#look-play');
  await pageUntil(room, (p) => p.textContent('#command-result'), (t) => t.includes("Look 'flushed': on your face now"),
    'the look accepted in the room');
  const roomDuring = await pageUntil(room, (p) => ownBlush(p, 'facewireRoom'), (b) => b > roomBefore + 0.1,
    'the look reddening the face in the room', 15000);
  console.log(`room: blush ${roomBefore.toFixed(2)} -> ${roomDuring.toFixed(2)}`);
  await room.close();
});
