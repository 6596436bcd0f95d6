// The room servers a page may use: by default its own, or the list in its
// address (`servers=wss://a.example/ws,wss://b.example/ws`), the nodes of one
// community, tried in turn when one fails (room/reconnect_policy.js). The page
// sends a server the person's name, the key of their face and their
// invitation, so a list is taken only of ws:// or wss:// addresses on the
// page's own host or a host under it: a link cannot send them elsewhere.

export const MAX_SERVERS = 16;

/** The page's own server: wss:// on an https page. */
export function ownServer(location) {
  const scheme = location.protocol === 'https:' ? 'wss:' : 'ws:';
  return `${scheme}//${location.host}/ws`;
}

const EXAMPLE = 'list them as servers=wss://a.example/ws,wss://b.example/ws';

/**
 * The servers named by `text` (comma-separated; null or blank: the page's
 * own), checked against the page's `location`.
 * @returns {{servers: string[], error: string}} the servers and '' when all
 *   are fine; else no servers and what is wrong, for the person.
 */
export function parseServers(text, location) {
  if (text == null || text.trim() === '') return { servers: [ownServer(location)], error: '' };
  const parts = text.split(',').map((part) => part.trim());
  if (parts.length > MAX_SERVERS) return refused(`at most ${MAX_SERVERS} servers, not ${parts.length}`);
  const servers = [];
  for (const [index, part] of parts.entries()) {
    const which = parts.length > 1 ? `server ${index + 1} of ${parts.length}` : 'the server';
    const problem = serverProblem(part, location);
    if (problem) return refused(`${which}${part ? ` ('${part}')` : ''} ${problem}`);
    const url = new URL(part).href;
    if (servers.includes(url)) return refused(`${which} ('${part}') is listed twice; name each server once`);
    servers.push(url);
  }
  return { servers, error: '' };
}

function refused(error) {
  return { servers: [], error: `servers: ${error}` };
}

// What is wrong with one address of the list, or ''.
function serverProblem(text, location) {
  if (!text) return `is missing: ${EXAMPLE}`;
  let url;
  try {
    url = new URL(text);
  } catch {
    return `is not an address: ${EXAMPLE}`;
  }
  if (url.protocol !== 'ws:' && url.protocol !== 'wss:') return `is not a ws:// or wss:// address: ${EXAMPLE}`;
  if (location.protocol === 'https:' && url.protocol === 'ws:') return 'is ws://, which an https page may not reach: use wss://';
  if (url.username || url.password) return 'carries a user name or password: leave them out';
  const host = url.hostname;
  if (host !== location.hostname && !host.endsWith(`.${location.hostname}`))
    return `is not on ${location.hostname} or a host under it: the page sends your name, your face's key and your invitation only there`;
  return '';
}
