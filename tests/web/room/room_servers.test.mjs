// The lobby and the room page in Chromium with a list of servers in the
// address: the lobby hands it on, the room page joins the first that
// answers; a bad list is said in words on both pages.
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:net';

import { openWeb } from '../support/harness.mjs';

let web;
before(async () => { web = await openWeb(['--no-demo-room']); });
after(async () => { await web?.close(); });

async function deadPort() {
  const server = createServer();
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  await new Promise((resolve) => server.close(resolve));
  return port;
}

test('the lobby hands its servers on and the room joins the first that answers', { timeout: 60000 }, async () => {
  const own = `ws://127.0.0.1:${web.server.port}/ws`;
  const servers = `ws://127.0.0.1:${await deadPort()}/ws,${own}`;
  const page = await web.page();
  await page.goto(`${web.server.url}?servers=${encodeURIComponent(servers)}`);
  await page.fill('#name', 'Ann');
  await page.fill('#room', 'hall');
  await page.click('#join');
  await page.waitForURL(/room\.html/);
  assert.equal(new URL(page.url()).searchParams.get('servers'), servers);
  await page.waitForFunction(() => document.getElementById('status').textContent === 'in the room as Ann');
  const { server, moves } = await page.evaluate(() => ({
    server: window.facewireRoom.client.server, moves: window.facewireRoom.client.moves }));
  assert.equal(server, own);
  assert.deepEqual(moves, [{ to: own, why: 'no connection' }]);
  await page.context().close();
});

test('a bad list of servers is said, not tried', { timeout: 60000 }, async () => {
  const page = await web.page();
  await page.goto(`${web.server.url}room.html?room=hall&name=Ann&servers=${encodeURIComponent('http://127.0.0.1:1/')}`);
  await page.waitForFunction(() => document.getElementById('status').classList.contains('error'));
  assert.equal(await page.locator('#status').textContent(),
    "the room cannot start: servers: the server ('http://127.0.0.1:1/') is not a ws:// or wss:// address: list them as servers=wss://a.example/ws,wss://b.example/ws");
  await page.goto(`${web.server.url}?servers=${encodeURIComponent('wss://elsewhere.example/ws')}`);
  await page.waitForSelector('#room-error:not([hidden])');
  assert.match(await page.locator('#room-error').textContent(), /is not on 127\.0\.0\.1 or a host under it/);
  await page.fill('#name', 'Ann');
  await page.click('#join');
  await new Promise((resolve) => setTimeout(resolve, 300));
  assert.ok(!page.url().includes('room.html'), 'no room with a list the page would not use');
  await page.context().close();
});
