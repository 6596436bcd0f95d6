// Avatar packages as they arrive in package chunks (PROTOCOL.md 5.7): the
// chunks of one package come in order and without gaps, so a package is a
// buffer filled front to back. A chunk that does not continue its package
// (a gap, another size) starts it again rather than mixing two packages.

export class PackageAssembly {
  constructor() {
    /** key `${avatar}:${quality}` -> { bytes, received } */
    this.pending = new Map();
  }

  /**
   * Adds a chunk. Returns { avatar, quality, bytes } when it completed a
   * package, { problem } when the chunk did not fit, else null.
   */
  add(chunk) {
    const key = `${chunk.avatar}:${chunk.quality}`;
    let entry = this.pending.get(key);
    if (chunk.offset === 0 || !entry || entry.bytes.length !== chunk.totalBytes) {
      entry = { bytes: new Uint8Array(chunk.totalBytes), received: 0 };
      this.pending.set(key, entry);
    }
    if (chunk.offset !== entry.received) {
      this.pending.delete(key);
      return { problem: `a package chunk of avatar ${chunk.avatar} left a gap (at ${chunk.offset}, expected ${entry.received})` };
    }
    entry.bytes.set(chunk.data, chunk.offset);
    entry.received += chunk.data.length;
    if (entry.received < entry.bytes.length) return null;
    this.pending.delete(key);
    return { avatar: chunk.avatar, quality: chunk.quality, bytes: entry.bytes };
  }

  /** An avatar left: its half-received packages go. */
  forget(avatar) {
    for (const key of [...this.pending.keys()]) if (key.startsWith(`${avatar}:`)) this.pending.delete(key);
  }
}
