// Saved looks over HTTP (server/PROTOCOL.md 8.2): the face scripts a person
// keeps with their uploaded avatar, under its key. Shared by the face lab
// (which saves, lists and deletes them) and the room page (which lists
// them to play one by name, command kind 6).

/** What a person reads when a request fails: the server's words, or the status. */
async function problemOf(response) {
  const text = (await response.text()).trim();
  return text || `the server answered ${response.status}`;
}

export class SavedLooksApi {
  /** `asset` and `key`: the uploaded avatar and the key its upload answered. */
  constructor({ asset, key, fetchImpl = (...args) => fetch(...args) }) {
    this.asset = asset;
    this.key = key;
    this.fetch = fetchImpl;
  }

  /** Whether there is an avatar to keep looks with (a procedural face has none). */
  get available() { return Boolean(this.asset && this.key); }

  url(name) {
    const base = `/api/avatars/${encodeURIComponent(this.asset)}/looks`;
    return name === undefined ? base : `${base}/${encodeURIComponent(name)}`;
  }

  /** { looks: [{ name, kinds, bytes, script }], max } or { error }. */
  async list() {
    const response = await this.fetch(this.url(), { headers: { 'X-Avatar-Key': this.key }, cache: 'no-store' });
    if (!response.ok) return { error: await problemOf(response) };
    return response.json();
  }

  /** Saves `script` under `name` (replacing a look of that name): { look } or { error, status }. */
  async save(name, script) {
    const response = await this.fetch(this.url(name), {
      method: 'PUT', headers: { 'X-Avatar-Key': this.key, 'Content-Type': 'text/plain; charset=utf-8' }, body: script,
    });
    if (!response.ok) return { error: await problemOf(response), status: response.status };
    return { look: await response.json() };
  }

  /** {} or { error }. */
  async remove(name) {
    const response = await this.fetch(this.url(name), { method: 'DELETE', headers: { 'X-Avatar-Key': this.key } });
    return response.ok ? {} : { error: await problemOf(response) };
  }
}
