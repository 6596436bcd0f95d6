// The rooms on this server (GET /api/rooms), as a list of buttons that pick
// a room. `persons` are people connected; `avatars` every face in the room,
// the demo room's own included.

/// `token`: the invitation's; a server with join tokens lists the room it opens.
export async function fetchRooms(token = '') {
  const headers = token ? { Authorization: `Bearer ${token}` } : {};
  const response = await fetch('api/rooms', { cache: 'no-store', headers });
  if (!response.ok) throw new Error(`the room list is unavailable (HTTP ${response.status})`);
  return (await response.json()).rooms || [];
}

function plural(count, one, many) {
  return `${count} ${count === 1 ? one : many}`;
}

/// One line of the list, e.g. "3 faces, 1 person".
export function describeRoom(room) {
  return `${plural(room.avatars, 'face', 'faces')}, ${plural(room.persons, 'person', 'people')}`;
}

/// Replaces the items of `list` (a <ul>) with `rooms`; `onPick(name)` when one is chosen.
export function renderRooms(list, rooms, selected, onPick) {
  const items = [...rooms].sort((a, b) => b.persons - a.persons || a.name.localeCompare(b.name)).map((room) => {
    const item = document.createElement('li');
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'room';
    button.dataset.room = room.name;
    button.setAttribute('aria-pressed', String(room.name === selected));
    const name = document.createElement('span');
    name.className = 'room-name';
    name.textContent = room.name;
    const count = document.createElement('span');
    count.className = 'room-count';
    count.textContent = describeRoom(room);
    button.append(name, count);
    button.addEventListener('click', () => onPick(room.name));
    item.append(button);
    return item;
  });
  if (items.length === 0) {
    const empty = document.createElement('li');
    empty.className = 'empty';
    empty.textContent = 'No rooms yet: name one below to open it.';
    items.push(empty);
  }
  list.replaceChildren(...items);
}
