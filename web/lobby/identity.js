// The name, the language (languages.js) and the avatar a person chose, with
// the avatar's key (the secret its upload answered, without which the server
// does not let anyone wear it), kept in localStorage so that a reload (or the next
// visit) keeps them. Storage may be off (private windows, policies): then
// nothing is kept, and nothing fails.

const KEY = 'facewire.identity';

export function loadIdentity(storage = globalThis.localStorage) {
  try {
    const saved = JSON.parse(storage.getItem(KEY) || '{}');
    const text = (value) => (typeof value === 'string' ? value : '');
    // An avatar without its key cannot be worn: it is forgotten.
    const keyed = text(saved.asset) !== '' && text(saved.key) !== '';
    return { name: text(saved.name), asset: keyed ? saved.asset : '', key: keyed ? saved.key : '', language: text(saved.language) };
  } catch {
    return { name: '', asset: '', key: '', language: '' };
  }
}

/** Keeps `identity`; a language left out keeps the one kept before. */
export function saveIdentity(identity, storage = globalThis.localStorage) {
  try {
    const language = identity.language ?? loadIdentity(storage).language;
    storage.setItem(KEY, JSON.stringify({ name: identity.name, asset: identity.asset, key: identity.key, language }));
  } catch {
    // storage is off or full: the page works without it
  }
}
