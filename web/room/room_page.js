// The room page: joins the room named in its address (room.html?room=R&
// name=N&asset=A&key=K&token=T, as the lobby sends a person here; with
// &servers=wss://a/ws,wss://b/ws on the servers of that list, the next when
// one fails, else on the page's own), draws it from
// the person's own place (room_view.js), and wires the controls: chat, the
// expression and blush buttons, FACS sentences, looking at, snubbing or
// muting a face (for the viewer alone: mute_list.js), the stream budget,
// the meter, and read aloud (the others' lines heard in step with their
// lips: read_aloud_player.js; off until the person turns it on).
import { AttentionTarget, isLanguageCode } from '../protocol/session_types.js';
import { fetchOwnPackage, loadRenderer } from './page_resources.js';
import { startDrawLoop } from './draw_loop.js';
import { RoomClient } from './room_client.js';
import { SavedLooksApi } from './saved_looks_api.js';
import { MuteList } from './mute_list.js';
import { ReadAloudPlayer } from './read_aloud_player.js';
import { RoomView, TILE_BACKGROUND_CSS } from './room_view.js';
import { NECK_FADE_SHARE } from './face_frame.js';
import { parseServers } from '../shared/server_list.js';

const EXPRESSIONS = ['joy', 'sadness', 'anger', 'fear', 'surprise', 'disgust', 'cunning', 'teasing', 'blush'];
const BUDGET_KEY = 'facewire.budget';
const READ_ALOUD_KEY = 'facewire.readAloud';
const $ = (id) => document.getElementById(id);

const query = new URLSearchParams(location.search);
const identity = {
  room: query.get('room') || '', name: query.get('name') || '', asset: query.get('asset') || '', key: query.get('key') || '',
  token: query.get('token') || '', language: query.get('language') || '',
};

function fail(message) {
  $('status').textContent = message;
  $('status').classList.add('error');
}

async function main() {
  if (!identity.room || !identity.name) {
    location.replace('./');
    return;
  }
  const { servers, error: serversProblem } = parseServers(query.get('servers'), location);
  if (serversProblem) return fail(`the room cannot start: ${serversProblem}`);
  if (identity.language && !isLanguageCode(identity.language)) {
    return fail(`the room cannot start: the language '${identity.language}' is not a language code (such as en, de or pt-br); choose one in the lobby`);
  }
  $('room-name').textContent = identity.room;
  document.title = `facewire: ${identity.room}`;
  const canvas = $('room-canvas');
  $('stage').style.setProperty('--tile-background', TILE_BACKGROUND_CSS);
  // Opaque: the shader's alpha is coverage, not transparency. The stencil
  // marks an eye's open hole for its socket (face_renderer.js drawSocket).
  const gl = canvas.getContext('webgl2', { antialias: true, alpha: false, preserveDrawingBuffer: true, stencil: true });
  if (!gl) return fail('this browser has no WebGL2, which the room needs');

  const ownPackage = fetchOwnPackage(identity.asset);
  const { engine, renderer } = await loadRenderer(gl);
  const budget = $('budget');
  budget.value = localStorage.getItem(BUDGET_KEY) ?? budget.value;
  const own = await ownPackage;

  const client = new RoomClient({
    servers, room: identity.room, name: identity.name, asset: identity.asset, avatarKey: identity.key, token: identity.token,
    language: identity.language, maxBps: budgetBps(budget.value), ownPackage: Boolean(own),
    openSocket: (url) => new WebSocket(url), onChange: (what, detail) => changed(what, detail),
  });
  // Whom this person muted in this room, kept across reconnects and visits.
  const mutes = MuteList.load(localStorage, identity.room);
  const view = new RoomView({ gl, engine, renderer, client, mutes });
  if (own) await view.setOwnPackage(own).catch((error) => console.warn(`own package: ${error.message}`));
  const readAloud = new ReadAloudPlayer({
    isMuted: (avatar) => mutes.mutes(avatar, client.nameOf(avatar), client.you),
    onProblem: (message) => { $('read-aloud-note').textContent = message; },
  });
  wireReadAloud(readAloud);
  window.facewireRoom = { client, view, mutes, readAloud };  // for whoever inspects the page (and its tests)
  // Muting changes what this page shows, nothing else: no message goes out.
  const toggleMute = (name) => {
    const muted = mutes.toggle(name);
    mutes.save(localStorage, identity.room);
    if (muted) for (const [id, { info }] of client.avatars) if (info.name === name) readAloud.silence(id);
    $('mute-note').textContent = muteNote(client, name, muted);
    showPeople(client, mutes, toggleMute);
    showChat(client, mutes, true);
    return muted;
  };
  client.start();

  budget.addEventListener('change', () => {
    localStorage.setItem(BUDGET_KEY, budget.value);
    client.setRate(budgetBps(budget.value));
  });
  wireControls(client, mutes, toggleMute);
  wireSavedLooks(client);

  startDrawLoop(canvas, (width, height, ratio, now) => {
    view.draw(width, height, ratio, now);
    readAloud.shown(client.framesReceived, now);
    placeOverlays(client, view);
    canvas.dataset.frames = String(view.frames);
  });
  setInterval(() => showMeter(client), 500);

  function changed(what, detail) {
    if (what === 'speaking') readAloud.heard(detail.line, detail.framesReceived);
    if (what === 'left') readAloud.silence(detail);
    if (what === 'closed') readAloud.disable();
    if (what === 'chat') showChat(client, mutes);
    if (what === 'result') showResults(client);
    if (['welcome', 'presence', 'attention', 'closed', 'reconnecting', 'closing'].includes(what)) showStatus(client);
    if (['welcome', 'presence'].includes(what)) showPeople(client, mutes, toggleMute);
  }
}

/** The read-aloud switch: off unless the person turned it on (kept like the budget). */
function wireReadAloud(readAloud) {
  const toggle = $('read-aloud');
  toggle.checked = localStorage.getItem(READ_ALOUD_KEY) === 'on';
  const apply = () => {
    $('read-aloud-note').textContent = '';
    if (toggle.checked) readAloud.enable();
    else readAloud.disable();
  };
  toggle.addEventListener('change', () => {
    localStorage.setItem(READ_ALOUD_KEY, toggle.checked ? 'on' : 'off');
    apply();
  });
  if (toggle.checked) apply();
  // Kept on from an earlier visit, its sound may wait for a gesture on the page.
  document.addEventListener('pointerdown', () => { if (toggle.checked) readAloud.context?.resume(); });
}

/** 0 asks for "unlimited": the server's own cap. */
const budgetBps = (value) => (Number(value) === 0 ? 100_000_000 : Number(value));

function showStatus(client) {
  const status = $('status');
  status.classList.toggle('error', client.status === 'closed' && Boolean(client.error));
  if (client.status === 'joined') status.textContent = `in the room as ${client.nameOf(client.you)}`;
  else if (client.status === 'reconnecting') {
    const where = client.servers.length > 1 ? ` to ${client.server}` : '';
    status.textContent = `connection lost${client.error ? ` (${client.error})` : ''}; reconnecting${where}…`;
  }
  else if (client.status === 'closed') status.textContent = client.error || 'left the room';
}

function showMeter(client) {
  const reading = client.meter.reading(performance.now());
  $('meter').textContent = `${reading.kbps.toFixed(1)} kbit/s`;
  $('meter').dataset.kbps = reading.kbps.toFixed(3);
  for (const item of document.querySelectorAll('#people li')) {
    const fps = reading.fps.get(Number(item.dataset.avatar)) ?? 0;
    item.querySelector('.fps').textContent = `${fps.toFixed(0)} f/s`;
  }
}

function chatItem(line) {
  const item = document.createElement('li');
  const from = document.createElement('span');
  from.className = 'from';
  from.textContent = line.name;
  item.append(from, document.createTextNode(line.text));
  return item;
}

/**
 * The chat log and the caption, without the lines of muted names (counted
 * instead). A new line is appended (the log is read aloud as it grows);
 * `rebuild` after a mute or unmute lays the whole log out again.
 */
function showChat(client, mutes, rebuild = false) {
  const log = $('chat-log');
  const { shown, hidden } = mutes.filterLines(client.chatLines, client.you);
  const newest = client.chatLines.at(-1);
  if (rebuild) log.replaceChildren(...shown.map(chatItem));
  else if (newest && shown.at(-1) === newest) log.append(chatItem(newest));
  while (log.children.length > 200) log.firstChild.remove();
  log.scrollTop = log.scrollHeight;
  const last = shown.at(-1);
  $('caption').textContent = last ? `${last.name}: ${last.text}` : '';
  $('chat-hidden').textContent = [...hidden].map(([name, n]) => `${n} ${n === 1 ? 'line' : 'lines'} hidden from ${name}`).join(' · ');
}

/** What muting or unmuting `name` did, in words. */
function muteNote(client, name, muted) {
  const avatars = [...client.avatars.values()].map((a) => a.info);
  const wearing = MuteList.wearing(avatars, name, client.you);
  if (!muted) return `${name} is no longer muted.`;
  const who = wearing > 1 ? `All ${wearing} people named ${name} are` : `${name} is`;
  return `${who} muted for you: their lines are hidden and their faces held still. Nobody else is affected, and they are not told.`;
}

function showPeople(client, mutes, toggleMute) {
  const list = $('people');
  list.replaceChildren();
  for (const [id, { info }] of client.avatars) {
    const item = document.createElement('li');
    item.dataset.avatar = String(id);
    const muted = mutes.mutes(id, info.name, client.you);
    item.classList.toggle('muted', muted);
    const who = document.createElement('span');
    who.className = 'who';
    who.textContent = `${info.name}${id === client.you ? ' (you)' : ''}${info.person ? '' : ' · resident'}${muted ? ' · muted' : ''}`;
    const fps = document.createElement('span');
    fps.className = 'fps';
    item.append(who, fps);
    if (id !== client.you) {
      const mute = muted ? 'unmute' : 'mute';
      for (const [label, act] of [['look', () => client.lookAt(id)], ['snub', () => client.snub(id)], [mute, () => toggleMute(info.name)]]) {
        const button = document.createElement('button');
        button.className = `button ${label}`;
        button.type = 'button';
        button.textContent = label;
        button.setAttribute('aria-label', `${label} ${info.name}`);
        button.addEventListener('click', act);
        item.append(button);
      }
    }
    list.append(item);
  }
}

const pending = new Map();  // request id -> button

function showResults(client) {
  for (const [id, button] of pending) {
    if (!client.results.has(id)) continue;
    const error = client.results.get(id);
    pending.delete(id);
    button.classList.remove('sent');
    button.classList.add(error ? 'refused' : 'accepted');
    $('command-result').textContent = error ? `refused: ${error}` : `${button.dataset.label}: on your face now`;
    setTimeout(() => button.classList.remove('accepted', 'refused'), 2500);
  }
}

/**
 * The person's saved looks (kept with their uploaded avatar in the face
 * lab), in a picker that plays one by name (command kind 6). Shown only
 * when there are some.
 */
async function wireSavedLooks(client) {
  const api = new SavedLooksApi({ asset: identity.asset, key: identity.key });
  if (!api.available) return;
  const answer = await api.list().catch((error) => ({ error: error.message }));
  if (answer.error || answer.looks.length === 0) return;
  const pick = $('look-pick');
  pick.replaceChildren(...answer.looks.map((look) => new Option(`${look.name} (${look.kinds.join(', ')})`, look.name)));
  $('saved-looks').hidden = false;
  $('look-play').addEventListener('click', () => {
    const button = $('look-play');
    button.dataset.label = `Look '${pick.value}'`;
    button.classList.remove('accepted', 'refused');
    button.classList.add('sent');
    pending.set(client.playLook(pick.value), button);
  });
}

function wireControls(client, mutes, toggleMute) {
  const buttons = $('expressions');
  for (const name of EXPRESSIONS) {
    const button = document.createElement('button');
    button.className = 'button';
    button.type = 'button';
    button.textContent = name;
    button.dataset.label = name;
    button.dataset.expression = name;
    button.addEventListener('click', () => {
      const id = client.express(name, 1, name === 'blush' ? 8000 : 3000);
      button.classList.remove('accepted', 'refused');
      button.classList.add('sent');
      pending.set(id, button);
    });
    buttons.append(button);
  }
  // A script may run over lines (a vascular emotion, comments), so the box
  // is a text area: Enter starts a new line, Ctrl+Enter (or the button) plays.
  $('facs-form').addEventListener('submit', (event) => {
    event.preventDefault();
    const script = $('facs').value.trim();
    if (!script) return;
    const id = client.facs(script);
    const submit = event.target.querySelector('button');
    submit.dataset.label = 'Face script';
    pending.set(id, submit);
  });
  $('facs').addEventListener('keydown', (event) => {
    if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
      event.preventDefault();
      $('facs-form').requestSubmit();
    }
  });
  $('chat-form').addEventListener('submit', (event) => {
    event.preventDefault();
    const text = $('chat-text').value.trim();
    if (!text) return;
    client.chat(text);
    $('chat-text').value = '';
  });
  const menu = $('face-menu');
  let menuFor = 0;
  $('look-at').addEventListener('click', () => { client.lookAt(menuFor); menu.hidden = true; });
  $('snub').addEventListener('click', () => { client.snub(menuFor); menu.hidden = true; });
  $('mute').addEventListener('click', () => {
    if (client.avatars.has(menuFor)) toggleMute(client.nameOf(menuFor));
    menu.hidden = true;
  });
  $('overlay').addEventListener('click', (event) => {
    const tile = event.target.closest('.tile:not(.self)');
    if (!tile) return;
    menuFor = Number(tile.dataset.avatar);
    $('face-menu-name').textContent = tile.querySelector('.name').textContent;
    $('mute').textContent = mutes.mutes(menuFor, client.nameOf(menuFor), client.you) ? 'Unmute' : 'Mute';
    menu.style.left = `${tile.offsetLeft + 8}px`;
    menu.style.top = `${tile.offsetTop + 8}px`;
    menu.hidden = false;
  });
  document.addEventListener('keydown', (event) => { if (event.key === 'Escape') menu.hidden = true; });
}

/**
 * Names under the faces, each tile clickable, the necks faded out above the
 * names; the self-view's frame.
 */
function placeOverlays(client, view) {
  const overlay = $('overlay');
  const wanted = view.tiles.map((t) => ({ ...t, self: false }));
  // The self view is small (90 px wide on a phone): "You" fits where a name
  // and "(you)" would be cut; the people list gives the name.
  if (view.selfTile) wanted.push({ id: client.you, name: 'You', rect: view.selfTile, drawn: true, self: true });
  while (overlay.children.length > wanted.length) overlay.lastChild.remove();
  while (overlay.children.length < wanted.length) {
    const tile = document.createElement('div');
    tile.className = 'tile';
    tile.tabIndex = 0;
    const name = document.createElement('p');
    name.className = 'name';
    const waiting = document.createElement('p');
    waiting.className = 'waiting';
    const fade = document.createElement('div');
    fade.className = 'fade';
    tile.append(fade, name, waiting);
    overlay.append(tile);
  }
  wanted.forEach((t, i) => {
    const tile = overlay.children[i];
    tile.dataset.avatar = String(t.id);
    tile.classList.toggle('self', t.self);
    tile.classList.toggle('muted', Boolean(t.muted));
    const attention = client.attention.get(t.id);
    tile.classList.toggle('attends-you', !t.self && !t.muted && attention?.target === AttentionTarget.avatar && attention.targetAvatar === client.you);
    Object.assign(tile.style, { left: `${t.rect.x}px`, top: `${t.rect.y}px`, width: `${t.rect.w}px`, height: `${t.rect.h}px` });
    const face = t.rect.h - view.nameBand;
    Object.assign(tile.querySelector('.fade').style, { bottom: `${view.nameBand}px`, height: `${NECK_FADE_SHARE * face}px` });
    if (tile.querySelector('.name').textContent !== t.name) tile.querySelector('.name').textContent = t.name;
    tile.querySelector('.waiting').textContent = t.drawn ? '' : 'arriving…';
  });
}

main().catch((error) => fail(`the room cannot start: ${error.message}`));
