// One person's connection to a room (server/PROTOCOL.md): hello, then the
// welcome, the codec stream, presence, seats, attention, chat and packages
// kept as the room's state; commands, chat and the stream budget going up;
// pings to stay alive; and a new connection after a drop, to the next
// server of the list when it was given several (reconnect_policy.js). No DOM and no
// WebGL here: the page (room_page.js) reads the state and draws it, and the
// socket is whatever `openSocket(url)` returns (a browser WebSocket, or a
// test's stand-in with the same few members).
import { DecodeError, FORMAT_VERSION, RoomDecoder, errorName, readStreamHeader, writeResyncRequest } from '../codec/decoder.js';
import { readMessage, sessionType } from '../protocol/session_read.js';
import { CommandKind, MessageError, MessageType, PresenceChange, classify, messageErrorName } from '../protocol/session_types.js';
import { writeMessage } from '../protocol/session_write.js';
import { LinkMeter } from './link_meter.js';
import { PackageAssembly } from './package_assembly.js';
import { ReconnectPolicy } from './reconnect_policy.js';

/** A silent client pings this often; the server closes after 60 s of silence. */
const PING_EVERY_MS = 15000;
const MAX_CHAT_LINES = 200;

export class RoomClient {
  /**
   * @param options.servers      ws:// or wss:// URLs (shared/server_list.js): the first, then the next after a failure
   * @param options.url          or one URL, or several comma-separated
   * @param options.room, options.name, options.asset, options.avatarKey, options.token   the hello's fields
   * @param options.language     the language the person's lines are said in ('' = the server's default)
   * @param options.maxBps       downstream budget, 0: the server's default
   * @param options.ownPackage   the page holds its own avatar's package (the server sends it none)
   * @param options.preview      a face-lab preview (PROTOCOL.md 5.17): a private room of one, `room` unused
   * @param options.openSocket   url -> WebSocket-like ({binaryType, send, close, onopen, onmessage, onclose})
   * @param options.onChange     (what, detail) => void, after every change of state ('welcome', 'chat', 'frame', ...);
   *                             'speaking' with { line, framesReceived } (the line starts with the next room
   *                             frame), 'left' with the avatar id
   * @param options.now          clock in ms (performance.now)
   */
  constructor(options) {
    this.resume = '';
    this.options = { maxBps: 0, ownPackage: false, preview: false, asset: '', avatarKey: '', token: '', language: '', now: () => performance.now(), ...options };
    this.servers = this.options.servers ?? String(this.options.url).split(',').map((u) => u.trim()).filter(Boolean);
    this.serverIndex = 0;
    /** Where the client moved and why, newest last (for the page and whoever inspects it). */
    this.moves = [];
    this.policy = new ReconnectPolicy();
    this.meter = new LinkMeter();
    this.status = 'connecting';  // connecting, joined, reconnecting, closed
    this.error = '';             // why the client stopped, or the last refusal, for a person
    this.you = 0;
    this.tickHz = 30;
    this.avatars = new Map();    // id -> { info, package: {quality, bytes} | null, lastFrameMs }
    this.attention = new Map();  // id -> { target, targetAvatar }
    this.chatLines = [];         // { from, name, text }
    this.previewSurface = null;  // a face-lab preview's skin beyond its action units (PROTOCOL.md 5.18), newest
    this.unitMorphs = new Map();  // avatar id -> its redefined units (PROTOCOL.md 5.17), newest version; the view draws the face with them
    this.speakingLines = [];     // the speaking messages (avatar, tick, durationMs, language, text), newest last
    this.results = new Map();    // request id -> error ('' accepted)
    this.requestId = 0;
    this.decoder = null;
    /** Room frames received so far: a speaking line starts with the frame after its message. */
    this.framesReceived = 0;
    this.packages = new PackageAssembly();
    this.socket = null;
    this.stopped = false;
    this.pingTimer = null;
    this.retryTimer = null;
    /** When things first happened (the clock's ms): welcome, a face's first frame, every full package. */
    this.timeline = { welcomeMs: null, firstFrameMs: null, fullPackagesMs: null };
  }

  start() {
    this.stopped = false;
    this.connect();
  }

  stop() {
    this.stopped = true;
    clearTimeout(this.retryTimer);
    clearInterval(this.pingTimer);
    this.status = 'closed';
    if (this.socket) this.socket.close(1000);
    this.socket = null;
  }

  // --- What a person does ---------------------------------------------------

  chat(text) { this.send(writeMessage(MessageType.chat, { from: 0, text })); }
  express(emotion, intensity = 1, durationMs = 3000) {
    return this.command({ kind: CommandKind.express, emotion, intensity, durationMs });
  }
  lookAt(target, durationMs = 5000) { return this.command({ kind: CommandKind.lookAt, target, durationMs }); }
  snub(target, durationMs = 10000) { return this.command({ kind: CommandKind.snub, target, durationMs }); }
  facs(sentence) { return this.command({ kind: CommandKind.facs, sentence }); }
  /** A face-lab preview's override ({ part, index, side, value }, PROTOCOL.md 5.17). */
  override(fields) { return this.command({ kind: CommandKind.override, override: fields }); }
  /** Plays a look the person saved with their avatar, by its name (PROTOCOL.md 8.2). */
  playLook(name) { return this.command({ kind: CommandKind.playLook, sentence: name }); }
  /** Asks the server to parse a face script without playing it. */
  check(script) { return this.command({ kind: CommandKind.check, sentence: script }); }
  setRate(maxBps) {
    this.options.maxBps = maxBps;
    this.send(writeMessage(MessageType.setRate, { maxBps }));
  }
  /** Sends a command; returns its request id (its result lands in `results`). */
  command(fields) {
    const requestId = ++this.requestId;
    this.send(writeMessage(MessageType.command, {
      requestId, emotion: '', intensity: 1, target: 0, durationMs: 3000, sentence: '', ...fields,
    }));
    return requestId;
  }

  // --- What the page reads -------------------------------------------------

  /** The avatar's face now: its last decoded frame carried forward (the decoder extrapolates). */
  face(avatar, nowMs = this.options.now()) {
    const entry = this.avatars.get(avatar);
    const decoder = this.decoder?.avatar(avatar);
    if (!entry || !decoder || decoder.framesDecoded === 0) return null;
    const ticks = Math.max(0, ((nowMs - entry.lastFrameMs) / 1000) * this.tickHz);
    return decoder.face(ticks);
  }
  nameOf(avatar) { return this.avatars.get(avatar)?.info.name ?? `avatar ${avatar}`; }
  /** The server the client is connected to, or tries next. */
  get server() { return this.servers[this.serverIndex]; }

  // --- The connection ------------------------------------------------------

  connect() {
    const socket = this.options.openSocket(this.server);
    this.socket = socket;
    this.closing = null;
    socket.binaryType = 'arraybuffer';
    socket.onopen = () => {
      const o = this.options;
      socket.send(writeMessage(MessageType.hello, {
        room: o.room, name: o.name, avatar: o.asset, avatarKey: o.avatarKey, token: o.token, maxBps: o.maxBps,
        ownPackage: o.ownPackage, preview: o.preview, timestamps: false, noPackages: false, language: o.language,
        // After a drop: the server may still hold the token for the old
        // connection; the last welcome's key shows this is the same person.
        resume: this.resume,
      }));
      this.pingTimer = setInterval(() => this.ping(), PING_EVERY_MS);
    };
    socket.onmessage = (event) => {
      if (socket !== this.socket) return;
      this.receive(new Uint8Array(event.data));
    };
    socket.onclose = () => {
      if (socket !== this.socket) return;
      this.ended();
    };
  }

  ping() {
    this.send(writeMessage(MessageType.ping, { nonce: this.requestId, clientTimeUs: Math.round(this.options.now() * 1000) }));
  }

  send(bytes) {
    if (this.socket && this.socket.readyState === 1) this.socket.send(bytes);
  }

  ended() {
    clearInterval(this.pingTimer);
    this.socket = null;
    if (this.stopped) return;
    const next = this.policy.next(this.closing);
    if (this.closing?.reason) this.error = this.closing.reason;
    if (!next.retry) {
      this.status = 'closed';
      this.notify('closed');
      return;
    }
    if (next.moveOn && this.servers.length > 1) {
      this.serverIndex = (this.serverIndex + 1) % this.servers.length;
      const why = this.closing?.reason || (this.status === 'joined' ? 'the connection dropped' : 'no connection');
      this.moves.push({ to: this.server, why });
      console.info(`${why}; moving to ${this.server} (server ${this.serverIndex + 1} of ${this.servers.length}) in ${next.delayMs} ms`);
    }
    this.status = 'reconnecting';
    this.notify('reconnecting');
    this.retryTimer = setTimeout(() => this.connect(), next.delayMs);
  }

  notify(what, detail) { this.options.onChange?.(what, detail); }

  /** One message from the server. */
  receive(bytes) {
    const now = this.options.now();
    this.meter.received(now, bytes.length);
    switch (classify(bytes)) {
      case 'streamHeader': {
        const header = readStreamHeader(bytes);
        if (header.error === DecodeError.unsupportedVersion)
          return this.protocolProblem(`a face stream of format version ${bytes[0] >> 4}, and this page decodes version ${FORMAT_VERSION}: reload the page`);
        if (header.error) return this.protocolProblem(`a bad stream header (${errorName(header.error)})`);
        this.decoder = new RoomDecoder(header.options);
        return;
      }
      case 'roomFrame': return this.roomFrame(bytes, now);
      case 'session': return this.session(bytes, now);
      default: return this.protocolProblem(`a message no server sends (first byte ${bytes[0]})`);
    }
  }

  protocolProblem(what) {
    this.error = `the server sent ${what}; reconnecting`;
    if (this.socket) this.socket.close(1002);
  }

  roomFrame(bytes, now) {
    if (!this.decoder) return this.protocolProblem('a room frame before its stream header');
    const result = this.decoder.decode(bytes);
    this.framesReceived += 1;
    for (const [avatar, error] of result.avatars) {
      const entry = this.avatars.get(avatar);
      if (error === 0 && entry) {
        entry.lastFrameMs = now;
        this.timeline.firstFrameMs ??= now;
        this.meter.frameDecoded(now, avatar);
      }
    }
    const needing = this.decoder.needingKeyFrames();
    if (needing.length) this.send(writeResyncRequest(needing.slice(0, 64)));
    this.notify('frame');
  }

  session(bytes, now) {
    const type = sessionType(bytes);
    const read = readMessage(bytes, type);
    if (read.error !== MessageError.ok) return this.protocolProblem(`a malformed message (${messageErrorName(read.error)})`);
    const m = read.message;
    switch (type) {
      case MessageType.welcome: return this.welcomed(m, now);
      case MessageType.presence: return this.presence(m);
      case MessageType.seats:
        for (const { avatar, seat } of m.seats) if (this.avatars.has(avatar)) this.avatars.get(avatar).info.seat = seat;
        return this.notify('seats');
      case MessageType.attention:
        for (const e of m.entries) if (this.avatars.has(e.avatar)) this.attention.set(e.avatar, e);
        return this.notify('attention');
      case MessageType.chat:
        this.chatLines.push({ from: m.from, name: this.nameOf(m.from), text: m.text });
        if (this.chatLines.length > MAX_CHAT_LINES) this.chatLines.shift();
        return this.notify('chat');
      case MessageType.commandResult:
        this.results.set(m.requestId, m.error);
        return this.notify('result');
      case MessageType.packageChunk: return this.packageChunk(m);
      case MessageType.closing:
        this.closing = m;
        this.error = m.reason;
        return this.notify('closing');
      case MessageType.linkStats:
        this.serverLink = m;
        return this.notify('link');
      case MessageType.speaking:
        this.speakingLines.push(m);
        if (this.speakingLines.length > MAX_CHAT_LINES) this.speakingLines.shift();
        return this.notify('speaking', { line: m, framesReceived: this.framesReceived });
      case MessageType.unitMorphs: {
        const held = this.unitMorphs.get(m.avatar);
        if (held && held.version >= m.version) return undefined;  // not newer
        this.unitMorphs.set(m.avatar, m);
        return this.notify('unitMorphs', m.avatar);
      }
      case MessageType.previewSurface:
        // A face-lab preview's own face only (PROTOCOL.md 5.18): the whole
        // residual each time; the lab view adds it to the face it draws.
        this.previewSurface = m;
        return this.notify('previewSurface', m.avatar);
      case MessageType.pong: return undefined;
      default: return this.protocolProblem(`a message of type ${type} a client never receives`);
    }
  }

  welcomed(m, now) {
    this.policy.welcomed();
    this.resume = m.resume;
    this.timeline.welcomeMs ??= now;
    this.status = 'joined';
    this.error = '';
    this.you = m.you;
    this.tickHz = m.tickHz;
    const before = this.avatars;
    this.avatars = new Map();
    for (const info of m.avatars) {
      // An avatar still here in the same face keeps its package.
      const old = before.get(info.id);
      const keep = old && old.info.asset === info.asset && info.asset !== '';
      this.avatars.set(info.id, { info, package: keep ? old.package : null, lastFrameMs: now });
    }
    this.attention.clear();
    this.packages = new PackageAssembly();
    this.notify('welcome');
  }

  presence(m) {
    if (m.change === PresenceChange.joined) {
      this.avatars.set(m.avatar.id, { info: m.avatar, package: null, lastFrameMs: 0 });
    } else {
      this.avatars.delete(m.avatar.id);
      this.attention.delete(m.avatar.id);
      this.decoder?.remove(m.avatar.id);
      this.packages.forget(m.avatar.id);
      this.unitMorphs.delete(m.avatar.id);
      this.meter.forget(m.avatar.id);
      this.notify('left', m.avatar.id);
    }
    this.notify('presence');
  }

  packageChunk(chunk) {
    const done = this.packages.add(chunk);
    if (!done || done.problem) return;
    const entry = this.avatars.get(done.avatar);
    // A late preview never replaces the full package.
    if (!entry || (entry.package && entry.package.quality > done.quality)) return;
    entry.package = { quality: done.quality, bytes: done.bytes };
    const everyone = [...this.avatars.values()].every((a) => a.package?.quality === 1 || (a.info.id === this.you && this.options.ownPackage));
    if (everyone) this.timeline.fullPackagesMs ??= this.options.now();
    this.notify('package');
  }
}
