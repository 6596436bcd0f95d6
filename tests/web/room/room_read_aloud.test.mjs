// Read aloud and the language, end to end on a real server, in Chromium:
// the lobby lists the server's languages (GET /api/languages) and keeps the
// choice; Bert joins in German and Ann, with read aloud on, in the default
// language. Bert's own page is told his line is said in German (the hello
// carried his choice); Ann's page hears the line (its sound passes through
// the player's AnalyserNode), starting within 150 ms of Bert's mouth first
// opening in the frames her page draws. Both times are taken in Ann's page
// (performance.now; the analyser's sound mapped to the page's clock by
// AudioContext.getOutputTimestamp), so a loaded machine's slow round trips
// do not enter them.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';

import { openWeb } from '../support/harness.mjs';

const ROOM = 'aloud';
/** How far apart the sound's start and the mouth's opening may be. */
const IN_STEP_MS = 150;
let web;
const pages = {};

// Headless Chromium starts sound without a gesture only when told so.
before(async () => { web = await openWeb(['--no-demo-room'], { browserArgs: ['--autoplay-policy=no-user-gesture-required'] }); });
after(async () => { await web?.close(); });

const state = (page) => page.evaluate(() => {
  if (!window.facewireRoom) return null;  // the page is still starting
  const { client } = window.facewireRoom;
  return {
    you: client.you, status: client.status, error: client.error, speaking: client.speakingLines,
    names: Object.fromEntries([...client.avatars].map(([id, a]) => [a.info.name, id])),
    drawn: Object.fromEntries([...client.avatars].map(([id]) => [id, Boolean(client.face(id))])),
  };
});
async function until(page, predicate, what, timeout = 30000) {
  const start = Date.now();
  for (;;) {
    const s = await state(page);
    if (s && predicate(s)) return s;
    if (Date.now() - start > timeout) throw new Error(`${what} did not happen within ${timeout / 1000} s: ${JSON.stringify(s)}`);
    await page.waitForTimeout(200);
  }
}

async function joinFromLobby(page, name, language) {
  await page.goto(web.server.url);
  await page.locator('#language[data-loaded="true"]').waitFor();
  await page.fill('#name', name);
  if (language) await page.selectOption('#language', language);
  await page.fill('#room', ROOM);
  await page.click('#join');
  await page.waitForURL(/room\.html/);
  return until(page, (s) => s.status === 'joined', `${name} joining`);
}

test("the lobby lists the server's languages and keeps the choice", { timeout: 60000 }, async () => {
  const served = await (await fetch(new URL('/api/languages', web.server.url))).json();
  assert.ok(served.languages.some((l) => l.code === 'de'), 'the server speaks German');
  const page = await web.page();
  await page.goto(web.server.url);
  await page.locator('#language[data-loaded="true"]').waitFor();
  const listed = await page.locator('#language option').evaluateAll((options) => options.map((o) => o.value));
  assert.deepEqual(listed, served.languages.map((l) => l.code));
  assert.equal(await page.locator('#language').inputValue(), served.default, 'the default before any choice');
  await page.selectOption('#language', 'de');
  await page.reload();
  await page.locator('#language[data-loaded="true"]').waitFor();
  assert.equal(await page.locator('#language').inputValue(), 'de', 'kept across a reload, as the name is');
  await page.context().close();
});

test("a German line's speaking comes back in German to its writer's page", { timeout: 120000 }, async () => {
  pages.ann = await web.page();
  await pages.ann.addInitScript(() => localStorage.setItem('facewire.readAloud', 'on'));
  await joinFromLobby(pages.ann, 'Ann');
  assert.ok(await pages.ann.locator('#read-aloud').isChecked(), 'read aloud kept on');
  pages.bert = await web.page();
  const bert = await joinFromLobby(pages.bert, 'Bert', 'de');
  assert.match(pages.bert.url(), /language=de/);
  // Ann's page draws Bert's face before he speaks.
  const ann = await until(pages.ann, (s) => s.names.Bert && s.drawn[s.names.Bert], "Bert's face on Ann's page", 60000);
  pages.bertId = ann.names.Bert;
  await watchMouthAndSound(pages.ann, pages.bertId);
  await pages.bert.fill('#chat-text', 'Guten Tag, wie geht es Ihnen heute?');
  await pages.bert.click('#chat-form button');
  const said = await until(pages.bert, (s) => s.speaking.length > 0, "the speaking of Bert's line", 30000);
  assert.equal(said.speaking[0].avatar, bert.you);
  assert.equal(said.speaking[0].language, 'de');
  assert.ok(said.speaking[0].durationMs > 1000, `${said.speaking[0].durationMs} ms`);
});

/**
 * Watches, in Ann's page at every animation frame, Bert's decoded mouth
 * (lips apart AU 25, jaw drop AU 26, mouth stretch AU 27: channels 26-28)
 * in the face the page draws, and the sound through the read-aloud
 * analyser; keeps the first time each crosses its threshold.
 */
function watchMouthAndSound(page, avatar) {
  return page.evaluate((watched) => {
    const { client, readAloud } = window.facewireRoom;
    const watch = { mouthMs: null, soundMs: null, restingMouth: 0, frames: 0 };
    window.readAloudWatch = watch;
    const samples = new Float32Array(2048);
    const startMs = performance.now();
    const mouthOf = (now) => Math.max(...(client.face(watched, now)?.au ?? []).slice(26, 29));
    const step = (now) => {
      if (watch.soundMs === null || watch.mouthMs === null) requestAnimationFrame(step);
      ++watch.frames;
      const mouth = mouthOf(now);
      // Before the line: how far the idle face opens its mouth anyway.
      if (now - startMs < 500) watch.restingMouth = Math.max(watch.restingMouth, mouth);
      else if (watch.mouthMs === null && mouth > Math.max(0.12, watch.restingMouth + 0.08)) watch.mouthMs = now;
      const analyser = readAloud.analyser;
      if (watch.soundMs === null && analyser) {
        analyser.getFloatTimeDomainData(samples);
        let peak = 0;
        for (const s of samples) peak = Math.max(peak, Math.abs(s));
        if (peak > 0.02) {
          // The analyser holds the last fftSize samples the context rendered:
          // the sound began at most that long ago, and is heard after the
          // output's latency. getOutputTimestamp maps context time to page time.
          const stamp = analyser.context.getOutputTimestamp();
          const renderedMs = stamp.performanceTime + (analyser.context.currentTime - stamp.contextTime) * 1000;
          let first = 0;
          while (first < samples.length && Math.abs(samples[first]) <= 0.02) ++first;
          const backMs = ((samples.length - first) / analyser.context.sampleRate) * 1000;
          watch.soundMs = renderedMs - backMs;
          watch.soundSeenMs = now;
        }
      }
    };
    requestAnimationFrame(step);
  }, avatar);
}

test("Ann's page hears Bert's line, in step with his lips", { timeout: 120000 }, async () => {
  const page = pages.ann;
  const start = Date.now();
  let watch;
  for (;;) {
    watch = await page.evaluate(() => ({ ...window.readAloudWatch, log: window.facewireRoom.readAloud.log }));
    if (watch.soundMs !== null && watch.mouthMs !== null) break;
    if (Date.now() - start > 30000) throw new Error(`no sound or no mouth within 30 s: ${JSON.stringify(watch)}`);
    await page.waitForTimeout(250);
  }
  const line = watch.log.find((l) => l.avatar === pages.bertId);
  assert.ok(line, `the player scheduled Bert's line: ${JSON.stringify(watch.log)}`);
  assert.equal(line.language, 'de');
  const apart = watch.soundMs - watch.mouthMs;
  console.log(`mouth opened ${watch.mouthMs.toFixed(0)} ms (resting ${watch.restingMouth.toFixed(3)}), sound heard ` +
    `${watch.soundMs.toFixed(0)} ms (scheduled ${line.soundAtMs?.toFixed(0)}, frame shown ${line.shownMs.toFixed(0)}, ` +
    `leading silence ${line.silenceMs.toFixed(0)} ms, late by ${line.offsetMs.toFixed(0)} ms): ${apart.toFixed(0)} ms apart; ` +
    `sound ${line.soundMs.toFixed(0)} ms of the lips' ${line.durationMs} ms`);
  assert.ok(Math.abs(apart) <= IN_STEP_MS, `sound ${apart.toFixed(0)} ms after the mouth opened (at most ${IN_STEP_MS})`);
  assert.deepEqual(web.pageErrors, []);
});

test('turned off, read aloud stops what plays and stays off after a reload', { timeout: 60000 }, async () => {
  const page = pages.ann;
  await page.click('#read-aloud');
  assert.equal(await page.evaluate(() => window.facewireRoom.readAloud.lines.size), 0);
  assert.equal(await page.evaluate(() => localStorage.getItem('facewire.readAloud')), 'off');
});
