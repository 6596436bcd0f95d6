// A turning preview of the generic face, drawn with WebGL2 from the very files
// the native renderer uses: the asset (/generic_face.json) and the GLSL ES
// 3.00 shaders (/shaders/face.vert, /shaders/face.frag). Textures are painted
// here with the 2-D canvas, since the page has no photo.
import { mat4 } from '../shared/mat4.js';

const LIPS = [48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59];
const EYES = [[36, 37, 38, 39, 40, 41], [42, 43, 44, 45, 46, 47]];
const BROWS = [[17, 18, 19, 20, 21], [22, 23, 24, 25, 26]];

async function fetchText(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.text();
}

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) {
    throw new Error(`shader does not compile: ${gl.getShaderInfoLog(shader)}`);
  }
  return shader;
}

// The fragment shader's variants are chosen by defines after its #version
// line (see the head of face.frag).
function withDefines(source, defines) {
  const lineEnd = source.indexOf('\n') + 1;
  return source.slice(0, lineEnd) + defines.map((name) => `#define ${name}\n`).join('') + source.slice(lineEnd);
}

// A variant: its defines go after the #version line of both stages (face.frag's head).
function buildProgram(gl, vertexSource, fragmentSource, defines) {
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, withDefines(vertexSource, defines)));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, withDefines(fragmentSource, defines)));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
    throw new Error(`program does not link: ${gl.getProgramInfoLog(program)}`);
  }
  return program;
}

// Area-weighted vertex normals, as avatar/model computes them once for a
// mesh (welded_vertex_normals): vertices at one position share a normal, so
// the head shell's texture seams do not crease its shading.
function vertexNormals(positions, triangles) {
  const sums = new Map();
  const key = (p) => p.join(',');
  for (const p of positions) sums.set(key(p), [0, 0, 0]);
  for (const [a, b, c] of triangles) {
    const [pa, pb, pc] = [positions[a], positions[b], positions[c]];
    const u = [pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]];
    const v = [pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]];
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    for (const i of [a, b, c]) for (let k = 0; k < 3; ++k) sums.get(key(positions[i]))[k] += n[k];
  }
  return positions.map((p) => sums.get(key(p))).map(([x, y, z]) => {
    const length = Math.hypot(x, y, z) || 1;
    return [x / length, y / length, z / length];
  });
}

function uploadMesh(gl, mesh) {
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  const attribute = (location, rows, size) => {
    gl.bindBuffer(gl.ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(rows.flat()), gl.STATIC_DRAW);
    gl.enableVertexAttribArray(location);
    gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
  };
  const normals = vertexNormals(mesh.positions, mesh.triangles);
  attribute(0, mesh.positions, 3);
  attribute(1, normals, 3);
  attribute(2, mesh.uvs, 2);
  attribute(3, normals, 3);  // the rest shape's normals: this preview never morphs
  gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint32Array(mesh.triangles.flat()), gl.STATIC_DRAW);
  gl.bindVertexArray(null);
  return { vao, count: mesh.triangles.length * 3 };
}

function uploadCanvas(gl, canvas) {
  const texture = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_FLIP_Y_WEBGL, true);  // canvas rows run down, v runs up
  // Colours are sRGB: decoded to linear light on lookup, as natively.
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.SRGB8_ALPHA8, gl.RGBA, gl.UNSIGNED_BYTE, canvas);
  gl.generateMipmap(gl.TEXTURE_2D);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  return texture;
}

// Skin in the asset's texture frame: skin tone, lips, brows, hair, and
// transparent eye holes.
function paintSkin(face, size) {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const g = canvas.getContext('2d');
  const { origin, size: frame } = face.texture_frame;
  const toPixel = ([x, y]) => [((x - origin[0]) / frame) * size, (1 - (y - origin[1]) / frame) * size];
  const landmark = (i) => toPixel(face.skin.positions[face.landmark_vertices[i]]);
  const path = (indices) => {
    g.beginPath();
    indices.forEach((i, k) => (k ? g.lineTo(...landmark(i)) : g.moveTo(...landmark(i))));
  };
  g.fillStyle = '#dba88c';
  g.fillRect(0, 0, size, size);
  // Hair above the hairline arc, as the native procedural skin has it.
  g.fillStyle = '#3b2617';
  g.beginPath();
  g.moveTo(...toPixel([origin[0], origin[1] + frame]));
  for (let x = origin[0]; x <= origin[0] + frame; x += frame / 64) {
    const across = Math.min(1, Math.abs(x) / 1.18);
    g.lineTo(...toPixel([x, 0.22 + Math.sqrt(1 - across * across)]));
  }
  g.lineTo(...toPixel([origin[0] + frame, origin[1] + frame]));
  g.fill();
  g.fillStyle = '#b86060';
  path(LIPS);
  g.fill();
  g.strokeStyle = '#3b2617';
  g.lineWidth = (0.06 / frame) * size;
  g.lineCap = 'round';
  for (const brow of BROWS) {
    path(brow);
    g.stroke();
  }
  paintHeadBack(g, face, size);
  g.globalCompositeOperation = 'destination-out';
  for (const eye of EYES) {
    path(eye);
    g.fill();
  }
  return canvas;
}

const smoothstep = (a, b, x) => {
  const t = Math.min(1, Math.max(0, (x - a) / (b - a)));
  return t * t * (3 - 2 * t);
};

// The head's back and its sides behind the silhouette take their colour from
// a disc in the texture's lower left corner (avatar/model's head_back.hpp,
// whose uvs the asset's head shell carries): the colour just inside the
// outline on each ray at the disc's rim, turning toward its centre, the back
// pole, into the crown's colour, except on the neck's rays. This painted
// face is uniform between its features, so one texel a ray stands for the
// native painter's smoothed average.
function paintHeadBack(g, face, size) {
  const PATCH = { centre: [0.07, 0.07], radius: 0.055 };  // head_back.hpp's kHeadBackPatch
  const { origin, size: frame } = face.texture_frame;
  const { centre, outline } = face.head;
  const pixels = g.getImageData(0, 0, size, size).data;
  const colourAt = ([x, y]) => {
    const px = Math.min(size - 1, Math.max(0, Math.floor(((x - origin[0]) / frame) * size)));
    const py = Math.min(size - 1, Math.max(0, Math.floor((1 - (y - origin[1]) / frame) * size)));
    return [0, 1, 2].map((c) => pixels[(py * size + px) * 4 + c]);
  };
  const rayColour = (phi) => {
    const at = (((phi / (2 * Math.PI)) % 1) + 1) % 1 * outline.length;
    const k = Math.floor(at) % outline.length;
    const r = outline[k] + (outline[(k + 1) % outline.length] - outline[k]) * (at - Math.floor(at));
    // head_shell.cpp's unseen_colour_radius: 0.32 inside the silhouette; the
    // neck's rays, whose silhouette is off the texture, take the jaw's skin.
    const radius = Math.sin(phi) < -0.6 ? 1.6 : r - 0.32;
    return colourAt([centre[0] + radius * Math.cos(phi), centre[1] + radius * Math.sin(phi)]);
  };
  const crown = rayColour(Math.PI / 2);
  const reach = PATCH.radius * 1.25;
  const x0 = Math.floor((PATCH.centre[0] - reach) * size), x1 = Math.ceil((PATCH.centre[0] + reach) * size);
  const y0 = Math.floor((1 - PATCH.centre[1] - reach) * size), y1 = Math.ceil((1 - PATCH.centre[1] + reach) * size);
  const patch = g.createImageData(x1 - x0, y1 - y0);
  for (let y = y0; y < y1; ++y) {
    for (let x = x0; x < x1; ++x) {
      const dx = ((x + 0.5) / size - PATCH.centre[0]) / PATCH.radius;
      const dy = (1 - (y + 0.5) / size - PATCH.centre[1]) / PATCH.radius;
      const t = Math.min(1, Math.hypot(dx, dy));
      const phi = Math.atan2(dy, dx);
      const edge = rayColour(phi);
      const hair = smoothstep(-0.65, -0.25, Math.sin(phi));
      const front = smoothstep(0.4, 1, t);
      const i = ((y - y0) * (x1 - x0) + (x - x0)) * 4;
      for (let c = 0; c < 3; ++c) {
        const back = edge[c] + (crown[c] - edge[c]) * hair;
        patch.data[i + c] = back + (edge[c] - back) * front;
      }
      patch.data[i + 3] = 255;
    }
  }
  g.putImageData(patch, Math.max(0, x0), Math.max(0, y0));
}

// Eyeball texture: the front pole at the centre, angle linear in radius.
function paintEye(eye, size) {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  const g = canvas.getContext('2d');
  const perRadian = size / 2 / eye.cap_angle_rad;
  const iris = Math.asin(5.85 / 63 / eye.radius) * perRadian;
  g.fillStyle = '#eeeae4';
  g.fillRect(0, 0, size, size);
  const disc = (radius, colour) => {
    g.fillStyle = colour;
    g.beginPath();
    g.arc(size / 2, size / 2, radius, 0, 2 * Math.PI);
    g.fill();
  };
  disc(iris, '#4d73a0');
  disc(iris * 0.35, '#080808');
  return canvas;
}

function paintMouth() {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 16;
  const g = canvas.getContext('2d');
  g.fillStyle = '#3a0f0f';
  g.fillRect(0, 0, 16, 16);
  return canvas;
}

// The native renderer's key light (face_renderer.cpp): above and to the
// viewer's right, unit length.
const KEY_LIGHT = [0.45, 0.6, 0.9].map((c, _, v) => c / Math.hypot(...v));

export async function startFacePreview(canvas, status) {
  // Opaque: the shader's alpha is coverage, not transparency.
  const gl = canvas.getContext('webgl2', { antialias: true, alpha: false });
  if (!gl) throw new Error('this browser has no WebGL2');
  const [face, vertexSource, fragmentSource] = await Promise.all([
    fetch('/generic_face.json').then((r) => r.json()),
    fetchText('/shaders/face.vert'),
    fetchText('/shaders/face.frag'),
  ]);
  // The preview has no closed-lid skin or blood masks (lids open, colour
  // unchanged), so the skin, the mouth and the head shell use the plain
  // variant; its textures are painted albedo, lit by the shader (FW_ALBEDO).
  const plain = buildProgram(gl, vertexSource, fragmentSource, ['FW_ALBEDO']);
  const eye = buildProgram(gl, vertexSource, fragmentSource, ['FW_SPECULAR', 'FW_ALBEDO']);
  // The head shell shares the skin's texture; like the native renderer, the
  // shell (closed wherever it shows, facing out) is drawn with culling.
  const skinTexture = uploadCanvas(gl, paintSkin(face, 512));
  const parts = [
    { mesh: uploadMesh(gl, face.skin), texture: skinTexture, program: plain, cull: false, skinSpecular: 2.5 },
    ...['right', 'left'].map((side) => ({
      mesh: uploadMesh(gl, face.eyes[side].mesh),
      texture: uploadCanvas(gl, paintEye(face.eyes[side], 128)),
      program: eye,
      cull: false,
    })),
    { mesh: uploadMesh(gl, face.mouth_cavity), texture: uploadCanvas(gl, paintMouth()), program: plain, cull: false },
    { mesh: uploadMesh(gl, face.head.mesh), texture: skinTexture, program: plain, cull: true },
  ];

  // The camera and neck pivot of avatar/render's Camera::portrait and head_transform.
  const eyePosition = [0, -0.25, 8.2];
  const viewProjection = mat4.multiply(
    mat4.perspective(Math.PI / 6, canvas.width / canvas.height, 0.5, 100),
    mat4.lookAt(eyePosition, [0, -0.25, 0], [0, 1, 0]));
  const pivot = [0, -1.5, 0.2];

  let frames = 0;
  const draw = (milliseconds) => {
    const yaw = 0.45 * Math.sin(milliseconds / 1500);
    const model = mat4.multiply(mat4.translation(pivot),
      mat4.multiply(mat4.rotationY(yaw), mat4.translation(pivot.map((v) => -v))));
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(0.13, 0.14, 0.17, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.enable(gl.SAMPLE_ALPHA_TO_COVERAGE);
    for (const program of [plain, eye]) {
      const uniform = (name) => gl.getUniformLocation(program, name);
      gl.useProgram(program);
      gl.uniformMatrix4fv(uniform('u_view_projection'), false, viewProjection);
      gl.uniform3fv(uniform('u_camera_position'), eyePosition);
      gl.uniform3fv(uniform('u_light_direction'), KEY_LIGHT);
      gl.uniform1i(uniform('u_texture'), 0);
      gl.uniform1f(uniform('u_specular'), 1.0);
    }
    for (const part of parts) {
      gl.useProgram(part.program);
      gl.uniformMatrix4fv(gl.getUniformLocation(part.program, 'u_model'), false, model);
      // The skin's specular lobe (face.frag) on the face's skin only, never the head shell.
      gl.uniform1f(gl.getUniformLocation(part.program, 'u_skin_specular'), part.skinSpecular ?? 0);
      if (part.cull) gl.enable(gl.CULL_FACE); else gl.disable(gl.CULL_FACE);
      gl.bindTexture(gl.TEXTURE_2D, part.texture);
      gl.bindVertexArray(part.mesh.vao);
      gl.drawElements(gl.TRIANGLES, part.mesh.count, gl.UNSIGNED_INT, 0);
    }
    status.textContent = `generic face: ${face.skin.positions.length} vertices, ` +
      `${face.skin.triangles.length} triangles, drawn with the shared shaders`;
    canvas.dataset.frames = String(++frames);
    requestAnimationFrame(draw);
  };
  requestAnimationFrame(draw);
}
