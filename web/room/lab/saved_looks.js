// The face lab's saved looks (server/PROTOCOL.md 8.2): the script in the
// editor saved under a name with the person's avatar, and the list of those
// saved, each loaded back into the editor, played on the preview by its
// name (command kind 6, as a room plays it) or deleted. Without an uploaded
// avatar (a face the room gives the name) there is nothing to keep them
// with, and the section says so.
import { SavedLooksApi } from '../saved_looks_api.js';

const $ = (id) => document.getElementById(id);

/**
 * Wires the saved-looks part of the script editor. `client`: the preview's
 * RoomClient; `editor`: the script's textarea; `identity`: { asset, key }.
 */
export function wireSavedLooks({ client, editor, identity, fetchImpl }) {
  const api = new SavedLooksApi({ asset: identity.asset, key: identity.key, fetchImpl });
  const result = $('looks-result');
  const list = $('looks');
  const nameInput = $('look-name');
  const say = (text, error = false) => {
    result.textContent = text;
    result.classList.toggle('error', error);
  };
  if (!api.available) {
    say('saved looks are kept with an uploaded face: upload your photo in the lobby to keep yours');
    for (const control of [nameInput, $('script-save')]) control.disabled = true;
    return { refresh: async () => {} };
  }

  const playing = new Map();  // request id -> look name
  const previous = client.options.onChange;
  client.options.onChange = (what, detail) => {
    previous?.(what, detail);
    if (what !== 'result') return;
    for (const [id, name] of playing) {
      if (!client.results.has(id)) continue;
      playing.delete(id);
      const error = client.results.get(id);
      say(error ? `'${name}' was not played: ${error}` : `playing '${name}' on your preview`, Boolean(error));
    }
  };

  async function refresh() {
    const answer = await api.list().catch((error) => ({ error: error.message }));
    if (answer.error) return say(`the saved looks could not be listed: ${answer.error}`, true);
    list.replaceChildren(...answer.looks.map((look) => entryOf(look)));
    list.dataset.count = String(answer.looks.length);
    if (answer.looks.length === 0) say('no saved looks yet: write a script, name it and press Save');
    return undefined;
  }

  function entryOf(look) {
    const item = document.createElement('li');
    item.className = 'look';
    item.dataset.name = look.name;
    const title = document.createElement('span');
    title.className = 'look-name';
    title.textContent = look.name;
    const kinds = document.createElement('span');
    kinds.className = 'hint';
    kinds.textContent = `${look.kinds.join(', ')} · ${look.bytes} bytes`;
    const button = (label, action) => {
      const b = document.createElement('button');
      Object.assign(b, { type: 'button', className: 'button', textContent: label });
      b.dataset.action = label.toLowerCase();
      b.setAttribute('aria-label', `${label} ${look.name}`);
      b.addEventListener('click', action);
      return b;
    };
    item.append(title, kinds,
      button('Load', () => {
        editor.value = look.script;
        nameInput.value = look.name;
        say(`loaded '${look.name}' into the editor`);
      }),
      button('Play', () => playing.set(client.playLook(look.name), look.name)),
      button('Delete', async () => {
        const answer = await api.remove(look.name).catch((error) => ({ error: error.message }));
        if (answer.error) return say(`'${look.name}' was not deleted: ${answer.error}`, true);
        say(`deleted '${look.name}'`);
        return refresh();
      }));
    return item;
  }

  $('script-save').addEventListener('click', async () => {
    const name = nameInput.value.trim();
    if (!name) {
      nameInput.focus();
      return say('name the look first (up to 32 letters), then press Save', true);
    }
    say(`saving '${name}'…`);
    const answer = await api.save(name, editor.value).catch((error) => ({ error: error.message }));
    if (answer.error) return say(`'${name}' was not saved: ${answer.error}`, true);
    say(`saved '${answer.look.name}' (${answer.look.kinds.join(', ')}): play it in any room from "Saved looks"`);
    return refresh();
  });
  refresh();
  return { refresh };
}
