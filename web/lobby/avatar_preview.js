// The prepared avatar, shown in the lobby from its package. For now a still
// image: the package's face texture (320 px, the photo aligned to the
// generic face) over its 48 px preview thumbnail, whose eyes show through
// the texture's eye holes. The live WebGL avatar (web/engine/) can take this
// function's place without the lobby changing.
import { readPackageMembers } from './package_members.js';

// The generic face's texture frame (avatar/model/assets/generic_face.json,
// "texture_frame": origin (-2.7, -3), 5.4 model units across, v up) and the
// region the preview thumbnail covers (make_preview in
// avatar/photo/src/prepare_avatar.cpp: x -1.3..1.3, y 1.3..-1.95): the face
// without much hair, at the thumbnail's proportions.
const FRAME = { x0: -2.7, y0: -3, size: 5.4 };
const CROP = { left: -1.3, right: 1.3, top: 1.3, bottom: -1.95 };

/// The crop in texture fractions (0..1, rows from the top).
function cropFractions() {
  const u = (x) => (x - FRAME.x0) / FRAME.size;
  const row = (y) => 1 - (y - FRAME.y0) / FRAME.size;
  return { x: u(CROP.left), y: row(CROP.top), width: u(CROP.right) - u(CROP.left), height: row(CROP.bottom) - row(CROP.top) };
}

/// The width / height the preview is drawn at (the canvas should have it).
export const PREVIEW_ASPECT = (CROP.right - CROP.left) / (CROP.top - CROP.bottom);

async function decode(member) {
  if (!member) return null;
  return createImageBitmap(new Blob([member.bytes], { type: member.type }));
}

/// Draws the avatar in `packageBytes` (an ArrayBuffer of a .fwa) on the 2-D
/// `canvas`; throws an Error with a message for the person when it cannot.
export async function showAvatarPreview(canvas, packageBytes) {
  const { members } = readPackageMembers(packageBytes);
  const [thumbnail, texture] = await Promise.all([decode(members.get('preview')), decode(members.get('face_texture'))]);
  if (!thumbnail && !texture) throw new Error('the avatar package holds no image to show');
  const g = canvas.getContext('2d');
  g.clearRect(0, 0, canvas.width, canvas.height);
  g.imageSmoothingQuality = 'high';
  if (thumbnail) g.drawImage(thumbnail, 0, 0, canvas.width, canvas.height);
  if (texture) {
    const crop = cropFractions();
    g.drawImage(texture, crop.x * texture.width, crop.y * texture.height, crop.width * texture.width,
      crop.height * texture.height, 0, 0, canvas.width, canvas.height);
  }
  canvas.dataset.drawn = 'avatar';
}
