// Reads the members of an avatar package (.fwa, avatar/photo/FORMAT.md) as
// far as a preview needs: the manifest and each member's bytes. It checks
// the layout, not the checksums or the fit: the server validated the
// package when it stored it.
import { ByteReader } from '../shared/byte_reader.js';

const MAGIC = 'FWAV';
const HEADER_BYTES = 16;
const MAX_MANIFEST_BYTES = 16 * 1024;

/// { manifest, members: Map(name -> { type, bytes }) } from `bytes`
/// (an ArrayBuffer or Uint8Array); throws an Error that says what is wrong.
export function readPackageMembers(bytes) {
  const data = bytes instanceof Uint8Array ? bytes : new Uint8Array(bytes);
  if (data.length < HEADER_BYTES || String.fromCharCode(...data.subarray(0, 4)) !== MAGIC) {
    throw new Error('this is not an avatar package (no FWAV header)');
  }
  if (data[4] !== 1) throw new Error(`avatar package format ${data[4]}: this page reads format 1; reload the page`);
  const header = new ByteReader(data);
  header.take(8);  // magic, format version, flags, reserved
  const manifestBytes = header.u32();
  if (manifestBytes > MAX_MANIFEST_BYTES || HEADER_BYTES + manifestBytes > data.length) {
    throw new Error('the avatar package is cut off in its manifest');
  }
  const manifest = JSON.parse(new TextDecoder().decode(data.subarray(HEADER_BYTES, HEADER_BYTES + manifestBytes)));
  const members = new Map();
  let at = HEADER_BYTES + manifestBytes;
  for (const member of manifest.members || []) {
    if (at + member.size > data.length) throw new Error(`the avatar package is cut off in member ${member.name}`);
    members.set(member.name, { type: member.type, bytes: data.subarray(at, at + member.size) });
    at += member.size;
  }
  return { manifest, members };
}
