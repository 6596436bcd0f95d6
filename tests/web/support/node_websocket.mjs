// A WebSocket client for node, with the members of a browser's that
// web/room/room_client.js uses (binaryType 'arraybuffer', readyState, send,
// close, onopen, onmessage, onclose): lets a test drive the room client
// against a real server without a browser. Binary messages only; node 20
// has no WebSocket of its own without a flag.
import { randomBytes } from 'node:crypto';
import { request } from 'node:http';

const OPCODE = { continuation: 0, text: 1, binary: 2, close: 8, ping: 9, pong: 10 };

export class NodeWebSocket {
  constructor(url) {
    this.url = url;
    this.binaryType = 'arraybuffer';
    this.readyState = 0;  // connecting
    this.onopen = null;
    this.onmessage = null;
    this.onclose = null;
    this.pending = Buffer.alloc(0);
    this.fragments = [];
    const { hostname, port, pathname } = new URL(url);
    const upgrade = request({
      host: hostname.replace(/^\[|\]$/g, ''), port, path: pathname,
      headers: { Connection: 'Upgrade', Upgrade: 'websocket', 'Sec-WebSocket-Version': '13', 'Sec-WebSocket-Key': randomBytes(16).toString('base64') },
    });
    upgrade.on('upgrade', (response, socket, head) => {
      this.socket = socket;
      socket.setNoDelay(true);
      socket.on('data', (chunk) => this.receive(chunk));
      socket.on('close', () => this.closed());
      socket.on('error', () => {});
      this.readyState = 1;  // open
      this.onopen?.();
      if (head.length) this.receive(head);
    });
    upgrade.on('response', (response) => {  // answered without an upgrade
      response.resume();
      this.closed();
    });
    upgrade.on('error', () => this.closed());
    upgrade.end();
  }

  send(bytes) {
    if (this.readyState === 1) this.socket.write(frame(OPCODE.binary, Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength)));
  }

  close(code = 1000) {
    if (this.readyState !== 1) return;
    this.readyState = 2;  // closing
    const payload = Buffer.alloc(2);
    payload.writeUInt16BE(code);
    this.socket.end(frame(OPCODE.close, payload));
  }

  // Server frames are never masked (RFC 6455 5.1).
  receive(chunk) {
    this.pending = Buffer.concat([this.pending, chunk]);
    for (;;) {
      if (this.pending.length < 2) return;
      const fin = (this.pending[0] & 0x80) !== 0;
      const opcode = this.pending[0] & 0x0f;
      let length = this.pending[1] & 0x7f;
      let offset = 2;
      if (length === 126) {
        if (this.pending.length < 4) return;
        length = this.pending.readUInt16BE(2);
        offset = 4;
      } else if (length === 127) {
        if (this.pending.length < 10) return;
        length = Number(this.pending.readBigUInt64BE(2));
        offset = 10;
      }
      if (this.pending.length < offset + length) return;
      const payload = this.pending.subarray(offset, offset + length);
      this.pending = this.pending.subarray(offset + length);
      this.frameArrived(fin, opcode, Buffer.from(payload));
    }
  }

  frameArrived(fin, opcode, payload) {
    if (opcode === OPCODE.ping) return this.socket.write(frame(OPCODE.pong, payload));
    if (opcode === OPCODE.close) {
      if (this.readyState === 1) this.socket.end(frame(OPCODE.close, payload.subarray(0, 2)));
      this.readyState = 2;
      return undefined;
    }
    if (opcode !== OPCODE.binary && opcode !== OPCODE.continuation) return undefined;
    this.fragments.push(payload);
    if (!fin) return undefined;
    const message = Buffer.concat(this.fragments);
    this.fragments = [];
    const data = message.buffer.slice(message.byteOffset, message.byteOffset + message.byteLength);
    return this.onmessage?.({ data });
  }

  closed() {
    if (this.readyState === 3) return;
    this.readyState = 3;  // closed
    this.onclose?.({});
  }
}

// A client's frame: final, masked (RFC 6455 5.3).
function frame(opcode, payload) {
  const mask = randomBytes(4);
  const header = payload.length < 126 ? Buffer.alloc(2) : Buffer.alloc(payload.length < 65536 ? 4 : 10);
  header[0] = 0x80 | opcode;
  if (payload.length < 126) header[1] = 0x80 | payload.length;
  else if (payload.length < 65536) {
    header[1] = 0x80 | 126;
    header.writeUInt16BE(payload.length, 2);
  } else {
    header[1] = 0x80 | 127;
    header.writeBigUInt64BE(BigInt(payload.length), 2);
  }
  const masked = Buffer.from(payload);
  for (let i = 0; i < masked.length; i += 1) masked[i] ^= mask[i % 4];
  return Buffer.concat([header, mask, masked]);
}
