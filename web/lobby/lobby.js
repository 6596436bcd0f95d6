// The lobby (web/index.html): a name, a photo (file or camera snapshot)
// uploaded with progress and prepared into an avatar, its preview and the
// preparation's advice, the rooms, and Join, which opens the room page.
// Each job lives in its own module; this one wires them to the page.
import { startFacePreview } from './face_preview.js';
import { showAvatarPreview } from './avatar_preview.js';
import { cameraAvailable, snapshot, startCamera } from './camera.js';
import { deleteAvatar } from './delete_avatar.js';
import { loadIdentity, saveIdentity } from './identity.js';
import { labPageUrl, readInvite, roomPageUrl } from './invite.js';
import { DEFAULT_LANGUAGE, chooseLanguage, fetchLanguages, renderLanguages } from './languages.js';
import { displayNameProblem, roomNameProblem } from './names.js';
import { fitPhotoForUpload } from './photo_size.js';
import { fetchRooms, renderRooms } from './room_list.js';
import { uploadPhoto } from './upload.js';
import { parseServers } from '../shared/server_list.js';

const ROOM_REFRESH_MS = 4000;
const $ = (id) => document.getElementById(id);

const invite = readInvite(location.search);
// A list of servers in the lobby's address goes on to the room page; a bad
// one is said here, before anyone waits for a room that cannot start.
const serversProblem = parseServers(invite.servers || null, location).error;
const identity = loadIdentity();
const state = { asset: identity.asset, key: identity.key, uploading: false };

function showError(element, message) {
  element.textContent = message;
  element.hidden = !message;
}

// --- the generic face, until the person's own avatar is there -------------

const status = $('status');
startFacePreview($('face'), status).catch((error) => {
  status.textContent = `cannot draw the face: ${error.message}`;
});

// --- name -----------------------------------------------------------------

const nameField = $('name');
nameField.value = invite.name || identity.name;
if (invite.name && invite.token) {
  // The invitation's token admits only this name.
  nameField.readOnly = true;
}
nameField.addEventListener('input', () => {
  showError($('name-error'), '');
  saveIdentity({ name: nameField.value.trim(), asset: state.asset, key: state.key });
});

// --- language: the server's list, the person's choice kept with the name ----

const languageField = $('language');
languageField.value = identity.language || DEFAULT_LANGUAGE;
fetchLanguages().then((list) => {
  renderLanguages(languageField, list, chooseLanguage(identity.language, list));
  languageField.dataset.loaded = 'true';
}).catch((error) => {
  showError($('language-error'), `${error.message}; your lines are said in the server's default language.`);
});
languageField.addEventListener('change', () => {
  saveIdentity({ name: nameField.value.trim(), asset: state.asset, key: state.key, language: languageField.value });
});

// --- the avatar: preview and advice ----------------------------------------

function showAdvice(advice) {
  const items = (advice || []).map((text) => {
    const item = document.createElement('li');
    item.textContent = text;
    return item;
  });
  $('advice').replaceChildren(...items);
  $('advice-box').hidden = items.length === 0;
}

async function showStoredAvatar(asset, advice) {
  const response = await fetch(`api/packages/${encodeURIComponent(asset)}`);
  if (!response.ok) {
    const why = (await response.text()).trim();
    throw new Error(why || `the avatar cannot be fetched (HTTP ${response.status})`);
  }
  const canvas = $('avatar-preview');
  await showAvatarPreview(canvas, await response.arrayBuffer());
  canvas.hidden = false;
  // The generic face goes on turning (and writing its status) unseen.
  $('face').hidden = true;
  status.hidden = true;
  $('avatar-status').hidden = false;
  $('deleted-note').hidden = true;
  $('delete-box').hidden = false;
  showAdvice(advice);
}

// --- deleting the photo ------------------------------------------------------

$('delete-avatar').addEventListener('click', async () => {
  if (!state.asset) return;
  const button = $('delete-avatar');
  button.disabled = true;
  showError($('delete-error'), '');
  try {
    await deleteAvatar(state.asset, state.key);
    state.asset = '';
    state.key = '';
    saveIdentity({ name: nameField.value.trim(), asset: '', key: '' });
    // Back to the generic face: without a photo one joins with a face made from one's name.
    $('avatar-preview').hidden = true;
    $('face').hidden = false;
    status.hidden = false;
    $('avatar-status').hidden = true;
    $('delete-box').hidden = true;
    showAdvice([]);
    $('deleted-note').hidden = false;
  } catch (error) {
    showError($('delete-error'), error.message);
  } finally {
    button.disabled = false;
  }
});

if (state.asset) {
  showStoredAvatar(state.asset, []).catch(() => {
    // Gone from this server (another server, or it must be uploaded
    // again): forget it; the generic face stays.
    state.asset = '';
    state.key = '';
    saveIdentity({ name: nameField.value.trim(), asset: '', key: '' });
  });
}

// --- the photo: upload with progress --------------------------------------

function setProgress(fraction, label) {
  const bar = $('upload-progress');
  if (fraction === null) bar.removeAttribute('value');
  else bar.value = fraction;
  $('upload-label').textContent = label;
  $('upload').hidden = false;
}

async function upload(photo, name) {
  if (state.uploading) return;
  state.uploading = true;
  showError($('upload-error'), '');
  setProgress(0, 'Uploading your photo…');
  try {
    const fitted = await fitPhotoForUpload(photo, name);
    const answer = await uploadPhoto(fitted.blob, fitted.name, (fraction) => {
      if (fraction !== null && fraction >= 1) setProgress(null, 'Uploaded. Preparing your avatar…');
      else setProgress(fraction, `Uploading your photo… ${fraction === null ? '' : `${Math.round(fraction * 100)} %`}`);
    }, invite.token);
    state.asset = answer.asset;
    state.key = answer.key;
    saveIdentity({ name: nameField.value.trim(), asset: state.asset, key: state.key });
    await showStoredAvatar(answer.asset, answer.advice);
    $('upload').hidden = true;
  } catch (error) {
    $('upload').hidden = true;
    showError($('upload-error'), error.message);
  } finally {
    state.uploading = false;
    $('photo-file').value = '';
  }
}

$('photo-file').addEventListener('change', (event) => {
  const file = event.target.files && event.target.files[0];
  if (file) upload(file, file.name);
});

// --- the camera -------------------------------------------------------------

let stopCamera = null;
function closeCamera() {
  if (stopCamera) stopCamera();
  stopCamera = null;
  $('camera').hidden = true;
  $('snapshot-start').hidden = false;
}
if (cameraAvailable()) {
  $('snapshot-start').hidden = false;
  $('snapshot-start').addEventListener('click', async () => {
    showError($('upload-error'), '');
    try {
      $('camera').hidden = false;
      $('snapshot-start').hidden = true;
      stopCamera = await startCamera($('camera-video'));
    } catch (error) {
      closeCamera();
      showError($('upload-error'), error.message);
    }
  });
  $('snapshot-cancel').addEventListener('click', closeCamera);
  $('snapshot-take').addEventListener('click', async () => {
    try {
      const picture = await snapshot($('camera-video'));
      closeCamera();
      upload(picture, 'snapshot.jpg');
    } catch (error) {
      showError($('upload-error'), error.message);
    }
  });
}

// --- rooms and joining --------------------------------------------------------

const roomField = $('room');
roomField.value = invite.room || 'lobby';
if (invite.token) {
  // The token opens this room only.
  roomField.readOnly = true;
  $('invite').textContent = `You are invited to the room “${invite.room}”.`;
  $('invite').hidden = false;
}

let rooms = [];
function pick(room) {
  if (invite.token) return;
  roomField.value = room;
  showError($('room-error'), '');
  renderRooms($('room-list'), rooms, roomField.value, pick);
}
roomField.addEventListener('input', () => {
  showError($('room-error'), '');
  renderRooms($('room-list'), rooms, roomField.value, pick);
});

async function refreshRooms() {
  try {
    rooms = await fetchRooms(invite.token);
    renderRooms($('room-list'), rooms, roomField.value, pick);
  } catch (error) {
    const item = document.createElement('li');
    item.className = 'empty';
    item.textContent = `${error.message}; trying again.`;
    $('room-list').replaceChildren(item);
  }
}
refreshRooms();
setInterval(refreshRooms, ROOM_REFRESH_MS);
showError($('room-error'), serversProblem);

$('join').addEventListener('click', () => {
  const name = nameField.value.trim();
  const room = roomField.value.trim();
  const nameProblem = displayNameProblem(name);
  const roomProblem = roomNameProblem(room);
  showError($('name-error'), nameProblem);
  showError($('room-error'), roomProblem || serversProblem);
  if (nameProblem) return nameField.focus();
  if (roomProblem) return roomField.focus();
  if (serversProblem) return undefined;
  if (state.uploading) return showError($('upload-error'), 'Wait until your photo is prepared, then join.');
  const language = languageField.value;
  saveIdentity({ name, asset: state.asset, key: state.key, language });
  location.href = roomPageUrl({
    room, name, asset: state.asset, key: state.key, token: invite.token, servers: invite.servers, language,
  });
});

// The face lab: the same face on a private preview, with sliders (lab.html).
$('lab-link').addEventListener('click', (event) => {
  event.preventDefault();
  const name = nameField.value.trim();
  const nameProblem = displayNameProblem(name);
  showError($('name-error'), nameProblem);
  if (nameProblem) return nameField.focus();
  if (state.uploading) return showError($('upload-error'), 'Wait until your photo is prepared, then open the lab.');
  saveIdentity({ name, asset: state.asset, key: state.key, language: languageField.value });
  location.href = labPageUrl({
    room: roomField.value.trim() || 'lobby', name, asset: state.asset, key: state.key, token: invite.token,
    servers: invite.servers,
  });
  return undefined;
});
