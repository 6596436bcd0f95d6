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
import { pageUntil } from '../support/page_poll.mjs';

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
const until = (page, predicate, what, timeout) => pageUntil(page, state, predicate, what, timeout);

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
  // A room address whose language is not a language code stops the page, saying so.
  await page.goto(new URL('room.html?room=aloud&name=Eve&language=Deutsch!', web.server.url).href);
  await page.locator('#status.error').waitFor();
  assert.match(await page.locator('#status').textContent(), /'Deutsch!' is not a language code .*choose one in the lobby/);
  await page.context().close();
});

// Small pages: SwiftShader draws both on the CPU, and the mouth is timed
// from the frames Ann's page draws, so the more often it draws the better.
const VIEWPORT = { width: 480, height: 320 };
const WRITER_VIEWPORT = { width: 320, height: 240 };  // Bert's page need hardly draw
const LINES = ['Guten Tag, wie geht es Ihnen heute?', 'Morgen fahren wir zusammen nach Berlin.',
  'Das Wetter ist heute wirklich schön.', 'Bitte bringen Sie mir ein Glas Wasser.', 'Wir sehen uns am Montag wieder.'];

test("a German line's speaking comes back in German to its writer's page", { timeout: 120000 }, async () => {
  pages.ann = await web.page(VIEWPORT);
  await pages.ann.addInitScript(() => localStorage.setItem('facewire.readAloud', 'on'));
  await joinFromLobby(pages.ann, 'Ann');
  assert.ok(await pages.ann.locator('#read-aloud').isChecked(), 'read aloud kept on');
  pages.bert = await web.page(WRITER_VIEWPORT);
  const bert = await joinFromLobby(pages.bert, 'Bert', 'de');
  assert.match(pages.bert.url(), /language=de/);
  // Ann's page draws Bert's face before he speaks.
  const ann = await until(pages.ann, (s) => s.names.Bert && s.drawn[s.names.Bert], "Bert's face on Ann's page", 60000);
  pages.bertId = ann.names.Bert;
  pages.measures = [await sayAndMeasure(LINES[0])];
  const said = await until(pages.bert, (s) => s.speaking.length > 0, "the speaking of Bert's line", 30000);
  assert.equal(said.speaking[0].avatar, bert.you);
  assert.equal(said.speaking[0].language, 'de');
  assert.equal(said.speaking[0].text, LINES[0]);
  assert.ok(said.speaking[0].durationMs > 1000, `${said.speaking[0].durationMs} ms`);
});

/**
 * Bert says `text`; Ann's page times, at every frame it draws, Bert's
 * decoded mouth (lips apart AU 25, jaw drop AU 26, mouth stretch AU 27:
 * channels 26-28) in the face it draws, and the sound through the read-aloud
 * analyser. The mouth opens where it crosses its threshold, between the two
 * drawn frames either side (linearly: a page on a loaded machine draws
 * seldom); the sound begins at its first sample above the player's silence
 * level, placed on the page's clock by the analyser's window and
 * getOutputTimestamp. Resolves with both times once the line is over.
 */
async function sayAndMeasure(text) {
  await pages.ann.evaluate((watched) => {
    const { client, readAloud } = window.facewireRoom;
    const watch = { mouthMs: null, soundMs: null, restingMouth: 0, drawnFrames: 0, longestGapMs: 0, done: false };
    window.readAloudWatch = watch;
    // The longest window the analyser keeps (0.7 s at 48 kHz): a page that
    // draws seldom still finds where the sound began.
    readAloud.analyser.fftSize = 32768;
    const samples = new Float32Array(readAloud.analyser.fftSize);
    const level = 328 / 32768;  // the player's silence level (read_aloud.js SILENCE_LEVEL)
    const startMs = performance.now();
    const mouthOf = (now) => Math.max(...(client.face(watched, now)?.au ?? []).slice(26, 29));
    let last = null;
    const step = (now) => {
      if (watch.soundMs === null || watch.mouthMs === null) requestAnimationFrame(step);
      else watch.done = true;
      const mouth = mouthOf(now);
      if (last) watch.longestGapMs = Math.max(watch.longestGapMs, now - last.now);
      ++watch.drawnFrames;
      // For half a second before the line: how far the idle face opens its mouth anyway.
      if (now - startMs < 500) watch.restingMouth = Math.max(watch.restingMouth, mouth);
      const threshold = Math.max(0.12, watch.restingMouth + 0.08);
      if (now - startMs >= 500 && watch.mouthMs === null && mouth > threshold) {
        watch.mouthMs = last && last.mouth < threshold
          ? last.now + ((threshold - last.mouth) / (mouth - last.mouth)) * (now - last.now) : now;
      }
      last = { now, mouth };
      if (watch.soundMs === null) {
        readAloud.analyser.getFloatTimeDomainData(samples);
        const first = samples.findIndex((s) => Math.abs(s) > level);
        if (first >= 0) {
          const context = readAloud.analyser.context;
          const stamp = context.getOutputTimestamp();
          const startS = context.currentTime - (samples.length - first) / context.sampleRate;
          watch.soundMs = stamp.performanceTime + (startS - stamp.contextTime) * 1000;
          watch.soundFilledWindow = first === 0;  // then its start is older than the window
        }
      }
    };
    requestAnimationFrame(step);
  }, pages.bertId);
  await pages.ann.waitForTimeout(600);  // the resting mouth
  await pages.bert.fill('#chat-text', text);
  await pages.bert.click('#chat-form button');
  const start = Date.now();
  let watch;
  for (;;) {
    watch = await pages.ann.evaluate(() => window.readAloudWatch);
    if (watch.done) break;
    if (Date.now() - start > 30000) throw new Error(`no sound or no mouth within 30 s: ${JSON.stringify(watch)}`);
    await pages.ann.waitForTimeout(250);
  }
  const log = await pages.ann.evaluate(() => window.facewireRoom.readAloud.log);
  const line = log.findLast((l) => l.text === text);
  assert.ok(line, `the player scheduled '${text}': ${JSON.stringify(log)}`);
  assert.ok(!watch.soundFilledWindow, 'the sound began inside the analyser\'s window');
  // Before the page showed the line's first frame no frame of it was on the
  // screen: an interpolation across a long gap between drawn frames may not
  // place the opening earlier.
  const mouthMs = Math.max(watch.mouthMs, line.shownMs);
  const apart = watch.soundMs - mouthMs;
  console.log(`'${text}': mouth opened ${mouthMs.toFixed(0)} ms (resting ${watch.restingMouth.toFixed(3)}), ` +
    `sound heard ${watch.soundMs.toFixed(0)} ms (scheduled ${line.soundAtMs?.toFixed(0)}, its frame shown ` +
    `${line.shownMs.toFixed(0)}, leading silence ${line.silenceMs.toFixed(0)} ms, late by ${line.offsetMs.toFixed(0)} ms): ` +
    `${apart.toFixed(0)} ms apart; sound ${line.soundMs.toFixed(0)} ms of the lips' ${line.durationMs} ms; ` +
    `${watch.drawnFrames} frames drawn, longest gap ${watch.longestGapMs.toFixed(0)} ms`);
  // The line over, and a moment of quiet before the next.
  await pages.ann.waitForTimeout(line.durationMs + 800);
  return { apart, line };
}

test("Ann's page hears Bert's lines, in step with his lips", { timeout: 240000 }, async () => {
  for (const text of LINES.slice(1)) pages.measures.push(await sayAndMeasure(text));
  for (const { line } of pages.measures) assert.equal(line.language, 'de');
  // Pooled: the median of five lines, so that a few slow frames on a loaded machine do not decide.
  const aparts = pages.measures.map((m) => m.apart).sort((a, b) => a - b);
  const median = aparts[Math.floor(aparts.length / 2)];
  assert.ok(Math.abs(median) <= IN_STEP_MS,
    `the sound began ${median.toFixed(0)} ms after the mouth opened (median of ${aparts.map((a) => a.toFixed(0)).join(', ')}; at most ${IN_STEP_MS})`);
  assert.deepEqual(web.pageErrors, []);
});

test('turned off, read aloud stops what plays and stays off', { timeout: 60000 }, async () => {
  const page = pages.ann;
  await page.click('#read-aloud');
  assert.equal(await page.evaluate(() => window.facewireRoom.readAloud.lines.size), 0);
  assert.equal(await page.evaluate(() => localStorage.getItem('facewire.readAloud')), 'off');
});
