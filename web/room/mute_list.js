// Whom the viewer has muted for themselves (server/PROTOCOL.md 6.3): display
// names whose chat lines the page does not show and whose faces it draws
// still and neutral. Only this page filters; the server sends everything and
// the muted person is not told. A name, not an avatar id: ids change when
// someone reconnects, and a muted person who uploads another photo is still
// the name everyone sees. Everyone wearing a muted name is muted, the
// viewer's own avatar never. No DOM here: the page (room_page.js) shows it.

/** A face at rest: no action units, eyes and head straight ahead, no colour. */
export const NEUTRAL_FACE = Object.freeze({
  head_yaw_rad: 0, head_pitch_rad: 0, head_roll_rad: 0, head_translation_mm: [0, 0, 0],
  eye_left: { yaw_rad: 0, pitch_rad: 0 }, eye_right: { yaw_rad: 0, pitch_rad: 0 },
  lid_left: 0, lid_right: 0, blush: [0, 0, 0, 0, 0], pallor: 0, au: [],
});

const STORAGE_PREFIX = 'facewire.muted.';

export class MuteList {
  /** @param names display names muted from the start (say, those kept for the room) */
  constructor(names = []) {
    this.muted = new Set(names.filter((n) => typeof n === 'string' && n !== ''));
  }

  has(name) { return this.muted.has(name); }
  get names() { return [...this.muted]; }
  mute(name) { this.muted.add(name); }
  unmute(name) { this.muted.delete(name); }
  /** Mutes a name not muted, unmutes one that is; returns whether it is muted now. */
  toggle(name) {
    if (this.has(name)) this.unmute(name);
    else this.mute(name);
    return this.has(name);
  }

  /** Whether avatar `id` named `name` is muted for the viewer `you`: never the
   * viewer's own avatar nor the server (0), as the native client's MuteList::mutes. */
  mutes(id, name, you) { return id !== 0 && id !== you && this.has(name); }

  /**
   * The chat lines to show and how many of each muted name's are hidden.
   * Lines from the server (avatar 0) and the viewer's own always show.
   * @param lines [{ from, name, text }] as RoomClient keeps them
   * @returns { shown: [line], hidden: Map(name -> count) }
   */
  filterLines(lines, you) {
    const shown = [];
    const hidden = new Map();
    for (const line of lines) {
      if (line.from !== 0 && this.mutes(line.from, line.name, you)) hidden.set(line.name, (hidden.get(line.name) ?? 0) + 1);
      else shown.push(line);
    }
    return { shown, hidden };
  }

  /** The face to draw for avatar `id`: as decoded, or at rest when muted. */
  faceOf(id, name, you, decoded) { return this.mutes(id, name, you) ? NEUTRAL_FACE : decoded; }

  /** How many avatars of `avatars` ([{ id, name }]) wear `name`, the viewer aside. */
  static wearing(avatars, name, you) { return avatars.filter((a) => a.id !== you && a.name === name).length; }

  /** The list kept for room `room` in `storage` (localStorage), or an empty one. */
  static load(storage, room) {
    try {
      const names = JSON.parse(storage?.getItem(STORAGE_PREFIX + room) ?? '[]');
      return new MuteList(Array.isArray(names) ? names : []);
    } catch {
      return new MuteList();  // a damaged entry mutes nobody rather than stopping the page
    }
  }

  /** Keeps the list for room `room` (removes the entry when nobody is muted). */
  save(storage, room) {
    if (!storage) return;
    if (this.muted.size === 0) storage.removeItem(STORAGE_PREFIX + room);
    else storage.setItem(STORAGE_PREFIX + room, JSON.stringify(this.names));
  }
}
