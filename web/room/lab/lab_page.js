// The face lab (lab.html?name=N&asset=A&key=K[&room=R&token=T][&servers=...],
// as the lobby links it): a private preview of the person's own face (or of
// the face a room gives their name), simulated by the server as a room
// would, with its own behaviour off until turned on. Sliders set overrides
// that hold until changed (lab_controls.js, override_sender.js); the face is
// drawn as the room draws it (lab_view.js); a script editor checks and plays
// FACS sentences (script_result.js) and keeps them with the person's avatar
// as saved looks (saved_looks.js); the contact sheet shows the face as it is
// now from several views (sheet_dialog.js, contact_sheet.js).
import { Limits } from '../../protocol/session_types.js';
import { parseServers } from '../../shared/server_list.js';
import { fetchOwnPackage, loadRenderer } from '../page_resources.js';
import { startDrawLoop } from '../draw_loop.js';
import { RoomClient } from '../room_client.js';
import { GROUPS, SLIDERS, Side, RESET_OVERRIDE, behaviourOverride, overrideOf } from './lab_controls.js';
import { LabView } from './lab_view.js';
import { OverrideSender } from './override_sender.js';
import { wireContactSheet } from './sheet_dialog.js';
import { wireSavedLooks } from './saved_looks.js';
import { offsetOf, readScriptResult } from './script_result.js';

const $ = (id) => document.getElementById(id);
const query = new URLSearchParams(location.search);
const identity = {
  room: query.get('room') || 'lab', name: query.get('name') || '', asset: query.get('asset') || '',
  key: query.get('key') || '', token: query.get('token') || '',
};

function fail(message) {
  $('status').textContent = message;
  $('status').classList.add('error');
}

async function main() {
  if (!identity.name) {
    location.replace('./');
    return;
  }
  const { servers, error: serversProblem } = parseServers(query.get('servers'), location);
  if (serversProblem) return fail(`the lab cannot start: ${serversProblem}`);
  const canvas = $('room-canvas');
  const gl = canvas.getContext('webgl2', { antialias: true, alpha: false, preserveDrawingBuffer: true, stencil: true });
  if (!gl) return fail('this browser has no WebGL2, which the lab needs');
  const ownPackage = fetchOwnPackage(identity.asset);
  const { engine, renderer } = await loadRenderer(gl);
  const own = await ownPackage;
  const client = new RoomClient({
    servers, room: identity.room, name: identity.name, asset: identity.asset, avatarKey: identity.key,
    token: identity.token, ownPackage: Boolean(own), preview: true,
    openSocket: (url) => new WebSocket(url), onChange: (what) => changed(what),
  });
  const view = new LabView({ gl, engine, renderer, client });
  if (own) await view.setOwnPackage(own).catch((error) => console.warn(`own package: ${error.message}`));
  const refused = new Map();  // request id -> what the control was
  const sender = new OverrideSender({ send: (override) => refused.set(client.override(override), override) });
  window.facewireLab = { client, view, sender };  // for whoever inspects the page (and its tests)
  const controls = buildSliders(sender);
  wireBehaviourAndReset(sender, controls);
  wireCamera(view, canvas);
  window.facewireLab.sheet = wireContactSheet({ button: $('contact-sheet'), view, name: identity.name });
  wireScript(client);
  wireSavedLooks({ client, editor: $('script'), identity });
  client.start();

  startDrawLoop(canvas, (width, height, ratio, now) => {
    view.draw(width, height, ratio, now);
    canvas.dataset.frames = String(view.frames);
  });

  function changed(what) {
    if (what === 'result') showResults(client, refused);
    if (['welcome', 'closed', 'reconnecting', 'closing'].includes(what)) showStatus(client);
    // A new connection is a new preview: the page's controls say what it holds.
    if (what === 'welcome') controls.resend();
  }
}

function showStatus(client) {
  const status = $('status');
  status.classList.toggle('error', client.status !== 'joined' && Boolean(client.error));
  if (client.status === 'joined') status.textContent = `your private preview, as ${client.nameOf(client.you)}`;
  else if (client.status === 'reconnecting') status.textContent = `${client.error || 'connection lost'}; trying again…`;
  else status.textContent = client.error || 'the preview ended';
}

/** Overrides the server refused (the controls keep to its ranges, so this is rare) are shown. */
function showResults(client, refused) {
  for (const [id, what] of refused) {
    if (!client.results.has(id)) continue;
    refused.delete(id);
    const error = client.results.get(id);
    if (error) $('control-result').textContent = `refused (${JSON.stringify(what)}): ${error}`;
  }
}

/** The slider groups; returns { reset(), resend() } over all of them. */
function buildSliders(sender) {
  const inputs = [];
  const auSide = () => Number(document.querySelector('input[name="au-side"]:checked')?.value ?? Side.both);
  for (const [group, title] of GROUPS) {
    const box = $(`group-${group}`);
    for (const slider of SLIDERS.filter((s) => s.group === group)) {
      const label = document.createElement('label');
      label.className = 'slider';
      const name = document.createElement('span');
      name.textContent = slider.label;
      const shown = document.createElement('output');
      const input = document.createElement('input');
      Object.assign(input, { type: 'range', min: slider.min, max: slider.max, step: 1, value: slider.rest });
      input.dataset.key = slider.key;
      input.setAttribute('aria-label', `${title}: ${slider.label}`);
      const show = () => { shown.textContent = `${input.value}${slider.unit}`; };
      input.addEventListener('input', () => {
        show();
        sender.set(overrideOf(slider, input.value, auSide()));
      });
      show();
      label.append(name, input, shown);
      box.append(label);
      inputs.push({ slider, input, show });
    }
  }
  return {
    reset() {
      for (const { slider, input, show } of inputs) {
        input.value = slider.rest;
        show();
      }
    },
    resend() {
      for (const { slider, input } of inputs)
        if (Number(input.value) !== slider.rest) sender.set(overrideOf(slider, input.value, auSide()));
      if ($('behaviour').checked) sender.set(behaviourOverride(true));
    },
  };
}

function wireBehaviourAndReset(sender, controls) {
  $('behaviour').addEventListener('change', (event) => sender.set(behaviourOverride(event.target.checked)));
  $('reset').addEventListener('click', () => {
    controls.reset();
    $('behaviour').checked = false;
    $('control-result').textContent = '';
    sender.sendInstead(RESET_OVERRIDE);
  });
}

/** The camera turns with the yaw slider, or by dragging across the face. */
function wireCamera(view, canvas) {
  const slider = $('camera-yaw');
  const apply = (degrees) => {
    const clamped = Math.max(-90, Math.min(90, degrees));
    slider.value = String(Math.round(clamped));
    $('camera-yaw-shown').textContent = `${slider.value}°`;
    view.cameraYawRad = (clamped * Math.PI) / 180;
  };
  slider.addEventListener('input', () => apply(Number(slider.value)));
  let drag = null;
  canvas.addEventListener('pointerdown', (event) => {
    drag = { x: event.clientX, degrees: Number(slider.value) };
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (drag) apply(drag.degrees - ((event.clientX - drag.x) / Math.max(1, canvas.clientWidth)) * 180);
  });
  const end = () => { drag = null; };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
  apply(0);
}

/** The script editor: load a file, check and play on the server, download a copy. */
function wireScript(client) {
  const text = $('script');
  const result = $('script-result');
  const pending = new Map();  // request id -> 'check' or 'play'
  const byteLength = (s) => new TextEncoder().encode(s).length;
  const ask = (what) => {
    const script = text.value;
    const bytes = byteLength(script);
    if (bytes === 0) return show({ message: 'the script is empty: write a FACS sentence, or load one' }, what);
    if (bytes > Limits.sentenceBytes)
      return show({ message: `the script is ${bytes} bytes; the server takes ${Limits.sentenceBytes} at most: shorten it` }, what);
    result.textContent = what === 'check' ? 'checking…' : 'playing…';
    pending.set(what === 'check' ? client.check(script) : client.facs(script), what);
    return undefined;
  };
  function show(error, what) {
    result.classList.toggle('error', Boolean(error));
    delete result.dataset.line;
    delete result.dataset.column;
    if (!error) {
      result.textContent = what === 'check' ? 'the script parses: no errors' : 'playing on your preview';
      return;
    }
    if (error.line === null || error.line === undefined) {
      result.textContent = error.message;
      return;
    }
    result.dataset.line = String(error.line);
    result.dataset.column = String(error.column);
    result.textContent = `line ${error.line}, column ${error.column}: ${error.message}`;
    const at = offsetOf(text.value, error.line, error.column);
    text.focus();
    text.setSelectionRange(at, Math.min(text.value.length, at + 1));
  }
  const previous = client.options.onChange;
  client.options.onChange = (what, detail) => {
    previous?.(what, detail);
    if (what !== 'result') return;
    for (const [id, kind] of pending) {
      if (!client.results.has(id)) continue;
      pending.delete(id);
      show(readScriptResult(client.results.get(id)), kind);
    }
  };
  $('script-check').addEventListener('click', () => ask('check'));
  $('script-play').addEventListener('click', () => ask('play'));
  $('script-file').addEventListener('change', async (event) => {
    const file = event.target.files?.[0];
    if (!file) return;
    text.value = await file.text();
    result.textContent = `loaded ${file.name}`;
    result.classList.remove('error');
  });
  $('script-download').addEventListener('click', () => {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([text.value], { type: 'text/plain' }));
    link.download = 'expression.facs';
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  });
}

main().catch((error) => fail(`the lab cannot start: ${error.message}`));
