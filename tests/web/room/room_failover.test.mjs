// The browser's room client (web/room/room_client.js) given two real
// servers, without a browser (support/node_websocket.mjs stands in for its
// WebSocket): it joins the first that answers, and when its server is
// killed (SIGKILL) it is back in the room on the other within seconds,
// under its name.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:net';

import { RoomClient } from '../../../web/room/room_client.js';
import { startServer } from '../support/harness.mjs';
import { NodeWebSocket } from '../support/node_websocket.mjs';

// A loopback port nobody listens on.
async function deadPort() {
  const server = createServer();
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const { port } = server.address();
  await new Promise((resolve) => server.close(resolve));
  return port;
}

function joinWith(servers) {
  const client = new RoomClient({
    servers, room: 'hall', name: 'Ann', openSocket: (url) => new NodeWebSocket(url),
  });
  client.start();
  return client;
}

// Resolves once `done()` holds (checked every 50 ms) with the ms it took; rejects after `timeoutMs`.
async function waitFor(done, timeoutMs, what) {
  const start = performance.now();
  while (!done()) {
    if (performance.now() - start > timeoutMs) throw new Error(`${what}: not within ${timeoutMs / 1000} s`);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
  return performance.now() - start;
}

const wsUrl = (server) => `ws://127.0.0.1:${server.port}/ws`;

test('joins the first server of the list that answers', async (t) => {
  const b = await startServer(['--no-demo-room']);
  const client = joinWith([`ws://127.0.0.1:${await deadPort()}/ws`, wsUrl(b)]);
  t.after(() => {
    client.stop();
    return b.stop();
  });
  await waitFor(() => client.status === 'joined', 20000, 'joined on the second server');
  assert.equal(client.server, wsUrl(b));
  assert.equal(client.moves[0].why, 'no connection');
  assert.equal(client.nameOf(client.you), 'Ann');
});

test('a killed server\'s client is back in the room on the other, under its name', async (t) => {
  const a = await startServer(['--no-demo-room']);
  const b = await startServer(['--no-demo-room']);
  const client = joinWith([wsUrl(a), wsUrl(b)]);
  t.after(() => {
    client.stop();
    return Promise.all([a.stop(), b.stop()]);
  });
  await waitFor(() => client.status === 'joined', 20000, 'joined on the first server');
  assert.equal(client.server, wsUrl(a));

  await a.kill();
  const backMs = await waitFor(() => client.status === 'joined' && client.server === wsUrl(b), 20000,
    'back in the room on the second server');
  console.log(`back in the room on B ${(backMs / 1000).toFixed(2)} s after A was killed`);
  assert.ok(backMs < 10000, `${backMs} ms`);
  assert.equal(client.nameOf(client.you), 'Ann', 'the welcome of B names her as before');
  assert.deepEqual(client.moves.map((m) => m.to), [wsUrl(b)]);
  const rooms = await (await fetch(`${b.url}api/rooms`)).json();
  assert.deepEqual(rooms.rooms.map((r) => [r.name, r.persons]), [['hall', 1]]);
});
