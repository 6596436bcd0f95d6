// POST /api/avatars as a browser form would: multipart/form-data with one
// part named `photo`. XMLHttpRequest rather than fetch, because only it
// reports how much of the body has gone (upload progress events).
import { uploadErrorMessage } from './upload_errors.js';

/// Uploads `photo` (a Blob) named `fileName`; `onProgress(fraction)` is
/// called as it goes (fraction 0..1, or null when the size is unknown).
/// Resolves with the server's answer ({asset, key, package, bytes, advice, ...});
/// rejects with an Error whose message is for the person. `token`: the
/// invitation's, which a server with join tokens wants for uploads too.
export function uploadPhoto(photo, fileName, onProgress = () => {}, token = '') {
  return new Promise((resolve, reject) => {
    const form = new FormData();
    form.append('photo', photo, fileName);
    const request = new XMLHttpRequest();
    request.open('POST', '/api/avatars');
    if (token) request.setRequestHeader('Authorization', `Bearer ${token}`);
    request.upload.addEventListener('progress', (event) => {
      onProgress(event.lengthComputable ? event.loaded / event.total : null);
    });
    request.addEventListener('load', () => {
      if (request.status === 201) {
        try {
          resolve(JSON.parse(request.responseText));
        } catch {
          reject(new Error('The server answered, but not in a way this page understands. Reload the page.'));
        }
        return;
      }
      reject(new Error(uploadErrorMessage(request.status, request.responseText,
        request.getResponseHeader('Retry-After'))));
    });
    request.addEventListener('error', () => reject(new Error(uploadErrorMessage(0, ''))));
    request.addEventListener('timeout', () => reject(new Error(uploadErrorMessage(0, ''))));
    request.timeout = 60000;  // preparation takes about a second, more when uploads queue
    request.send(form);
  });
}
