// The lobby's address carries an invitation (`facewire-server token` prints
// it): ?room=R&name=N&token=T. The token opens only that room, for that
// name, so the lobby fills them in and keeps them.

/// { room, name, token } from a query string such as location.search ('' where absent).
export function readInvite(search) {
  const query = new URLSearchParams(search);
  return { room: query.get('room') || '', name: query.get('name') || '', token: query.get('token') || '' };
}

/// The room page's address for joining `room` as `name`, wearing `asset`
/// (empty: a face made from the name) with its `key`, with the invitation's `token`.
export function roomPageUrl({ room, name, asset, key, token }) {
  const query = new URLSearchParams({ room, name });
  if (asset) query.set('asset', asset);
  if (asset && key) query.set('key', key);
  if (token) query.set('token', token);
  return `room.html?${query}`;
}
