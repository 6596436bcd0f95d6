// The lobby's address carries an invitation (`facewire-server token` prints
// it): ?room=R&name=N&token=T. The token opens only that room, for that
// name, so the lobby fills them in and keeps them. A community on several
// servers adds &servers=wss://a/ws,wss://b/ws, which the lobby hands on to
// the room page (shared/server_list.js checks it).

/// { room, name, token, servers } from a query string such as location.search ('' where absent).
export function readInvite(search) {
  const query = new URLSearchParams(search);
  return {
    room: query.get('room') || '', name: query.get('name') || '', token: query.get('token') || '',
    servers: query.get('servers') || '',
  };
}

/// The room page's address for joining `room` as `name`, wearing `asset`
/// (empty: a face made from the name) with its `key`, with the invitation's
/// `token`, on the `servers` of the lobby's own address (empty: the page's own),
/// the person's lines said in `language` (empty: the server's default).
export function roomPageUrl(fields) {
  return `room.html?${pageQuery(fields)}`;
}

/// The face lab's address (lab.html): the same fields, for a private preview
/// of the same face (the room stays in it for a token, which names the room).
export function labPageUrl(fields) {
  return `lab.html?${pageQuery(fields)}`;
}

function pageQuery({ room, name, asset, key, token, servers = '', language = '' }) {
  const query = new URLSearchParams({ room, name });
  if (language) query.set('language', language);
  if (asset) query.set('asset', asset);
  if (asset && key) query.set('key', key);
  if (token) query.set('token', token);
  if (servers) query.set('servers', servers);
  return query;
}
