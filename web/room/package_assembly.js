// Avatar packages as they arrive in package chunks (PROTOCOL.md 5.7), as the
// native client puts them together (client/room/package_assembler.cpp; the
// golden file tests/vectors/package_assembly holds this port to it): the
// chunks of one package come in order and without gaps, so a package is a
// buffer filled front to back. A chunk at offset 0 starts its package
// (again); a chunk that does not continue it (a gap, another size, past its
// end) drops it, and the rest of that package is ignored until the next
// start, as is the middle of a package whose start was missed.

/** No larger package is read (model::kMaxPackageBytes): refused before anything is buffered. */
export const MAX_ASSEMBLED_BYTES = 512 * 1024;

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
    if (chunk.totalBytes === 0 || chunk.totalBytes > MAX_ASSEMBLED_BYTES) {
      this.pending.delete(key);
      return { problem: `a package of avatar ${chunk.avatar} announced with ${chunk.totalBytes} bytes; this page takes 1 .. ${MAX_ASSEMBLED_BYTES}` };
    }
    if (chunk.offset === 0) this.pending.set(key, { bytes: new Uint8Array(chunk.totalBytes), received: 0 });
    const entry = this.pending.get(key);
    if (!entry) return null;  // the middle of a package whose start was missed
    if (chunk.totalBytes !== entry.bytes.length || chunk.offset !== entry.received ||
        chunk.data.length > entry.bytes.length - entry.received) {
      this.pending.delete(key);
      return { problem: `a package chunk of avatar ${chunk.avatar} out of order or past its end (at ${chunk.offset}, expected ${entry.received}); dropped` };
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
