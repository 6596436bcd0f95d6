// What the room page and the face lab both fetch before they draw: the
// renderer (the engine, the shared shaders) and the person's own package.
import { loadEngineFromServer } from '../engine/engine.js';
import { FaceRenderer } from './face_renderer.js';

async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.text();
}

/** The page's own package, when the person uploaded a photo: shown at once, never sent back down. */
export async function fetchOwnPackage(asset) {
  if (!asset) return null;
  const response = await fetch(`/api/packages/${encodeURIComponent(asset)}`);
  if (!response.ok) return null;
  return new Uint8Array(await response.arrayBuffer());
}

/** The avatar engine and a FaceRenderer on `gl` with /shaders/face.vert and face.frag. */
export async function loadRenderer(gl) {
  const [engine, vertexSource, fragmentSource] = await Promise.all([
    loadEngineFromServer(), fetchText('/shaders/face.vert'), fetchText('/shaders/face.frag')]);
  return { engine, renderer: new FaceRenderer(gl, vertexSource, fragmentSource) };
}
