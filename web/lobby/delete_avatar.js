// Deleting one's own avatar and the photo it was made from, on the server
// (DELETE /api/avatars/ID with the key its upload answered, in
// X-Avatar-Key: server/PROTOCOL.md, section 8). Anyone in a room with the
// person then sees a face made from their name.

/// Resolves once the avatar is gone from the server (also when it was
/// gone already: 404); throws an Error with the server's reason otherwise.
export async function deleteAvatar(asset, key, fetchImpl = globalThis.fetch) {
  let response;
  try {
    response = await fetchImpl(`api/avatars/${encodeURIComponent(asset)}`, {
      method: 'DELETE',
      headers: { 'X-Avatar-Key': key },
    });
  } catch {
    throw new Error('The request did not reach the server (the connection failed). Check the connection and try again.');
  }
  if (response.status === 204 || response.status === 404) return;
  const said = (await response.text()).trim();
  throw new Error(said || `The server did not delete your photo (HTTP ${response.status}).`);
}
