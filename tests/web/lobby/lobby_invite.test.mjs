// An invitation: `facewire-server token --url` prints a link; opening it
// fills in the room, the name and the token, and Join hands them on.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';

import { openWeb, runProgram } from '../support/harness.mjs';

let web;
before(async () => { web = await openWeb(['--auth-secret', 's3cret']); });
after(async () => { await web?.close(); });

test('the invite link fills in the room and the token', { timeout: 60000 }, async () => {
  const { stdout } = await runProgram('facewire-server',
    ['token', '--room', 'team.standup', '--name', 'Ann Lee', '--ttl', '600', '--auth-secret', 's3cret', '--url', web.server.url]);
  const [token, link] = stdout.trim().split('\n');
  assert.match(token, /^fw1\./);
  assert.ok(link.startsWith(web.server.url), link);

  const page = await web.page({ width: 390, height: 844 });
  await page.goto(link);
  assert.equal(await page.inputValue('#room'), 'team.standup');
  assert.equal(await page.inputValue('#name'), 'Ann Lee');
  assert.equal(await page.locator('#room').getAttribute('readonly'), '', 'the token opens this room only');
  assert.match(await page.locator('#invite').textContent(), /team\.standup/);
  await page.click('#join');
  await page.waitForURL(/room\.html/);
  const query = new URL(page.url()).searchParams;
  assert.equal(query.get('room'), 'team.standup');
  assert.equal(query.get('name'), 'Ann Lee');
  assert.equal(query.get('token'), token);
  await page.context().close();
});
