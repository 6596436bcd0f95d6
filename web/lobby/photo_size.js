// A photo from a phone's camera is often several megabytes, more than a
// server takes (--max-upload-bytes, 4 MiB by default) and far more than
// preparation needs (the face texture is 320 px). Large photos are redrawn
// smaller, as JPEG, before the upload; small ones go as they are, so that
// the server sees the original. The browser turns the photo upright (EXIF)
// as it decodes it.

const MAX_SIDE = 1600;
const MAX_BYTES = 1.5 * 1024 * 1024;

function toJpeg(canvas, quality) {
  return new Promise((resolve) => canvas.toBlob(resolve, 'image/jpeg', quality));
}

/// `{ blob, name }`: `file` itself when it is small enough or cannot be
/// decoded here (the server then says what is wrong with it), else a JPEG
/// of at most MAX_SIDE pixels on its longer side.
export async function fitPhotoForUpload(file, name) {
  let bitmap;
  try {
    bitmap = await createImageBitmap(file);
  } catch {
    return { blob: file, name };
  }
  const longer = Math.max(bitmap.width, bitmap.height);
  if (file.size <= MAX_BYTES && longer <= MAX_SIDE) return { blob: file, name };
  const scale = Math.min(1, MAX_SIDE / longer);
  const canvas = document.createElement('canvas');
  canvas.width = Math.round(bitmap.width * scale);
  canvas.height = Math.round(bitmap.height * scale);
  canvas.getContext('2d').drawImage(bitmap, 0, 0, canvas.width, canvas.height);
  const blob = await toJpeg(canvas, 0.9);
  return blob ? { blob, name: name.replace(/\.[^.]*$/, '') + '.jpg' } : { blob: file, name };
}
