// The name and the avatar a person chose, kept in localStorage so that a
// reload (or the next visit) keeps them. Storage may be off (private
// windows, policies): then nothing is kept, and nothing fails.

const KEY = 'facewire.identity';

export function loadIdentity(storage = globalThis.localStorage) {
  try {
    const saved = JSON.parse(storage.getItem(KEY) || '{}');
    return { name: typeof saved.name === 'string' ? saved.name : '', asset: typeof saved.asset === 'string' ? saved.asset : '' };
  } catch {
    return { name: '', asset: '' };
  }
}

export function saveIdentity(identity, storage = globalThis.localStorage) {
  try {
    storage.setItem(KEY, JSON.stringify({ name: identity.name, asset: identity.asset }));
  } catch {
    // storage is off or full: the page works without it
  }
}
