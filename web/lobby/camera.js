// A snapshot from the camera, where the browser has one (getUserMedia needs
// a secure context: https, or http on localhost).

export function cameraAvailable() {
  return Boolean(navigator.mediaDevices && navigator.mediaDevices.getUserMedia);
}

/// Shows the front camera in `video`; resolves with a function that stops it.
export async function startCamera(video) {
  let stream;
  try {
    stream = await navigator.mediaDevices.getUserMedia({ video: { facingMode: 'user' }, audio: false });
  } catch (error) {
    const denied = error && (error.name === 'NotAllowedError' || error.name === 'SecurityError');
    throw new Error(denied
      ? 'The camera was not allowed. Allow it in the browser, or choose a photo instead.'
      : 'No camera could be opened here. Choose a photo instead.');
  }
  video.srcObject = stream;
  await video.play();
  return () => {
    for (const track of stream.getTracks()) track.stop();
    video.srcObject = null;
  };
}

/// The video's current frame as a JPEG Blob.
export function snapshot(video) {
  const canvas = document.createElement('canvas');
  canvas.width = video.videoWidth;
  canvas.height = video.videoHeight;
  canvas.getContext('2d').drawImage(video, 0, 0);
  return new Promise((resolve, reject) => canvas.toBlob(
    (blob) => (blob ? resolve(blob) : reject(new Error('The snapshot could not be taken; try again.'))),
    'image/jpeg', 0.9));
}
