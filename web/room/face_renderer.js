// Avatars drawn with WebGL2 as avatar/render's FaceRenderer draws them
// natively (face_renderer.cpp): the same GLSL ES 3.00 shaders
// (/shaders/face.vert, face.frag, in the same variants), the skin rebuilt
// every frame by the engine (web/engine: the C++ reconstruction in
// WebAssembly), the package's textures (face, eye layer, mouth, closed lids,
// colour masks), then the eyes, the mouth cavity and the head shell, nearest
// first.

// The key light, above and to the viewer's right, unit length (FaceRenderer's).
const LIGHT = (() => {
  const v = [0.45, 0.6, 0.9];
  const length = Math.hypot(...v);
  return v.map((c) => c / length);
})();
// The eye's sheen and catch-light (face.frag; FaceRenderer's kEyeSpecular).
const EYE_SPECULAR = 1.0;
// The skin's specular lobe on albedo faces (face.frag): the face's skin only, never the head shell.
const SKIN_SPECULAR = 2.5;
const UNIT = { main: 0, closedLid: 1, masksA: 2, masksB: 3 };

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(`a shader does not compile: ${gl.getShaderInfoLog(shader)}`);
  return shader;
}

// Variants are chosen by defines after the #version line of both stages (face.frag's head).
function withDefines(source, defines) {
  const lineEnd = source.indexOf('\n') + 1;
  return source.slice(0, lineEnd) + defines.map((d) => `#define ${d}\n`).join('') + source.slice(lineEnd);
}

function program(gl, vertexSource, fragmentSource, defines) {
  const p = gl.createProgram();
  gl.attachShader(p, compile(gl, gl.VERTEX_SHADER, withDefines(vertexSource, defines)));
  gl.attachShader(p, compile(gl, gl.FRAGMENT_SHADER, withDefines(fragmentSource, defines)));
  gl.linkProgram(p);
  if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(`a shader program does not link: ${gl.getProgramInfoLog(p)}`);
  const names = ['u_model', 'u_view_projection', 'u_camera_position', 'u_light_direction', 'u_texture', 'u_specular',
    'u_closed_lid', 'u_closed_lid_rect', 'u_lid_closure', 'u_masks_a', 'u_masks_b', 'u_blush_a', 'u_blush_sides', 'u_pallor', 'u_skin_specular'];
  return { program: p, u: Object.fromEntries(names.map((n) => [n, gl.getUniformLocation(p, n)])) };
}

function buffer(gl, location, data, size, usage) {
  const b = gl.createBuffer();
  gl.bindBuffer(gl.ARRAY_BUFFER, b);
  gl.bufferData(gl.ARRAY_BUFFER, data, usage);
  gl.enableVertexAttribArray(location);
  gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
  return b;
}

// A mesh with positions, normals, uvs and rest normals (the shader's four
// attributes: the photo's light was seen under the rest normals,
// photoLightNormals where a mesh has them); `dynamic` for the skin, whose
// shape changes every frame.
function uploadMesh(gl, mesh, dynamic = false) {
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  const usage = dynamic ? gl.DYNAMIC_DRAW : gl.STATIC_DRAW;
  const positions = buffer(gl, 0, mesh.positions, 3, usage);
  const normals = buffer(gl, 1, mesh.normals, 3, usage);
  const uvs = buffer(gl, 2, mesh.uvs, 2, usage);
  buffer(gl, 3, mesh.photoLightNormals ?? mesh.normals, 3, gl.STATIC_DRAW);
  gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
  gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, mesh.triangles, gl.STATIC_DRAW);
  gl.bindVertexArray(null);
  return { vao, count: mesh.triangles.length, positions, normals, uvs };
}

/** A texture from an image (ImageBitmap): colour images decode sRGB on lookup, masks are data. */
function uploadImage(gl, image, srgb) {
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.texImage2D(gl.TEXTURE_2D, 0, srgb ? gl.SRGB8_ALPHA8 : gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, image);
  gl.generateMipmap(gl.TEXTURE_2D);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  return t;
}

// "No effect" for a missing closed lid or mask, as the native or_black.
function black(gl) {
  const t = gl.createTexture();
  gl.bindTexture(gl.TEXTURE_2D, t);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA8, 1, 1, 0, gl.RGBA, gl.UNSIGNED_BYTE, Uint8Array.of(0, 0, 0, 255));
  return t;
}

/**
 * Decodes a package's image member (WebP or PNG) in the browser. Flipped
 * here, since WebGL ignores its own flip for an ImageBitmap: image rows run
 * down, v runs up. Colours as stored (no premultiplying, no colour
 * management): the shader decodes sRGB itself.
 */
export async function decodeImage(member) {
  if (!member) return null;
  return createImageBitmap(new Blob([member.bytes], { type: member.type }),
    { imageOrientation: 'flipY', premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
}

export class FaceRenderer {
  /** @param gl a WebGL2 context; vertexSource, fragmentSource: /shaders/face.vert and face.frag */
  constructor(gl, vertexSource, fragmentSource) {
    this.gl = gl;
    // One set for photo textures (their own light, relit where the face
    // turns) and one for albedo (procedural faces: FW_ALBEDO lights them).
    const set = (light) => {
      const make = (defines) => program(gl, vertexSource, fragmentSource, [...defines, ...light]);
      return {
        skin: make(['FW_CLOSED_LID']),
        skinWithBlood: make(['FW_CLOSED_LID', 'FW_BLOOD']),
        eye: make(['FW_SPECULAR']),
        plain: make([]),
      };
    };
    this.programSets = { photo: set([]), albedo: set(['FW_ALBEDO']) };
    this.black = black(gl);
  }

  /**
   * A face to draw: the avatar model (web/engine AvatarModel) and its
   * package's decoded images { faceTexture, eye, mouth, closedLid,
   * colourMasksA, colourMasksB } with closedLidRect, and what its textures
   * hold (AvatarPackage.textureLight: 'photo' or 'albedo'). Returns a handle.
   */
  addFace(avatar, images, closedLidRect, textureLight = 'photo') {
    const gl = this.gl;
    const face = avatar.face;
    const colour = (image) => (image ? uploadImage(gl, image, true) : this.black);
    const data = (image) => (image ? uploadImage(gl, image, false) : this.black);
    const skinTexture = colour(images.faceTexture);
    const skin = uploadMesh(gl, face.skin, true);
    return {
      avatar,
      skin,
      eyes: face.eyes.map((e) => uploadMesh(gl, e.mesh)),
      sockets: face.eyes.map((e) => uploadMesh(gl, e.socket)),
      holeFans: face.eyeHoles.map((hole) => this.shareSkin(skin, fan(hole))),
      mouth: uploadMesh(gl, face.mouthCavity),
      head: uploadMesh(gl, face.head.mesh),
      textures: {
        skin: skinTexture, eye: colour(images.eye), mouth: colour(images.mouth), closedLid: colour(images.closedLid),
        masksA: data(images.colourMasksA), masksB: data(images.colourMasksB),
      },
      closedLidRect: images.closedLid ? Array.from(closedLidRect) : [0, 0, 0, 0],
      eyeLayer: Boolean(images.eye),
      programs: this.programSets[textureLight === 'albedo' ? 'albedo' : 'photo'],
      eyeCovers: images.eye ? null : this.shareSkin(skin, this.eyeCovers(face).triangles),
    };
  }

  // Without an eye layer the face texture keeps the photo's eyes: the eye
  // holes are filled by fans over their rims, on the skin's own vertices.
  eyeCovers(face) {
    return { triangles: Uint32Array.from(face.eyeHoles.flatMap((hole) => Array.from(fan(hole)))) };
  }

  // A mesh of other triangles over the skin's vertex buffers.
  shareSkin(skin, triangles) {
    const gl = this.gl;
    const vao = gl.createVertexArray();
    gl.bindVertexArray(vao);
    for (const [location, b, size] of [[0, skin.positions, 3], [1, skin.normals, 3], [2, skin.uvs, 2], [3, skin.normals, 3]]) {
      gl.bindBuffer(gl.ARRAY_BUFFER, b);
      gl.enableVertexAttribArray(location);
      gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
    }
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, gl.createBuffer());
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, triangles, gl.STATIC_DRAW);
    gl.bindVertexArray(null);
    return { vao, count: triangles.length };
  }

  /** Frees a face's GL objects. */
  removeFace(face) {
    const gl = this.gl;
    for (const mesh of [face.skin, face.mouth, face.head, ...face.eyes, ...face.sockets, ...face.holeFans, face.eyeCovers]) {
      if (mesh) gl.deleteVertexArray(mesh.vao);
    }
    for (const t of Object.values(face.textures)) if (t !== this.black) gl.deleteTexture(t);
  }

  /**
   * Draws faces into the current viewport.
   * @param draws  [{ face, frame }] where frame = AvatarModel.frame(params, place)
   * @param camera { viewProjection: Float32Array(16), position: [x, y, z] }
   */
  draw(draws, camera) {
    const gl = this.gl;
    gl.enable(gl.DEPTH_TEST);
    gl.depthFunc(gl.LESS);
    gl.cullFace(gl.BACK);
    gl.enable(gl.SAMPLE_ALPHA_TO_COVERAGE);
    for (const { program: p, u } of Object.values(this.programSets).flatMap((set) => Object.values(set))) {
      gl.useProgram(p);
      gl.uniformMatrix4fv(u.u_view_projection, false, camera.viewProjection);
      gl.uniform3fv(u.u_camera_position, camera.position);
      gl.uniform3fv(u.u_light_direction, LIGHT);
      gl.uniform1i(u.u_texture, UNIT.main);
      gl.uniform1i(u.u_closed_lid, UNIT.closedLid);
      gl.uniform1i(u.u_masks_a, UNIT.masksA);
      gl.uniform1i(u.u_masks_b, UNIT.masksB);
      gl.uniform1f(u.u_specular, EYE_SPECULAR);
    }
    for (const { face, frame } of draws) this.drawFace(face, frame);
    gl.bindVertexArray(null);
    gl.disable(gl.SAMPLE_ALPHA_TO_COVERAGE);
  }

  drawFace(face, frame) {
    const gl = this.gl;
    // The skin's shape of this frame.
    gl.bindBuffer(gl.ARRAY_BUFFER, face.skin.positions);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, frame.positions);
    gl.bindBuffer(gl.ARRAY_BUFFER, face.skin.normals);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, frame.normals);
    gl.bindBuffer(gl.ARRAY_BUFFER, face.skin.uvs);
    gl.bufferSubData(gl.ARRAY_BUFFER, 0, frame.uvs);
    const bind = (unit, texture) => {
      gl.activeTexture(gl.TEXTURE0 + unit);
      gl.bindTexture(gl.TEXTURE_2D, texture);
    };
    const mesh = (m, texture, u, model) => {
      gl.uniformMatrix4fv(u.u_model, false, model);
      bind(UNIT.main, texture);
      gl.bindVertexArray(m.vao);
      gl.drawElements(gl.TRIANGLES, m.count, gl.UNSIGNED_INT, 0);
    };
    // Nearest first, as natively: what lies behind then fails the depth test.
    const programs = face.programs;
    const skin = frame.blood ? programs.skinWithBlood : programs.skin;
    gl.useProgram(skin.program);
    bind(UNIT.closedLid, face.textures.closedLid);
    gl.uniform4fv(skin.u.u_closed_lid_rect, face.closedLidRect);
    gl.uniform2fv(skin.u.u_lid_closure, frame.lidClosure);
    if (frame.blood) {
      bind(UNIT.masksA, face.textures.masksA);
      bind(UNIT.masksB, face.textures.masksB);
      gl.uniform4fv(skin.u.u_blush_a, frame.blush.slice(0, 4));
      gl.uniform1f(skin.u.u_blush_sides, frame.blush[4]);
      gl.uniform1f(skin.u.u_pallor, frame.pallor);
    }
    gl.uniform1f(skin.u.u_skin_specular, SKIN_SPECULAR);
    mesh(face.skin, face.textures.skin, skin.u, frame.model);
    if (face.eyeCovers) {
      mesh(face.eyeCovers, face.textures.skin, skin.u, frame.model);
    } else {
      const eye = programs.eye;
      gl.useProgram(eye.program);
      face.eyes.forEach((m, side) => {
        if (frame.lidClosure[side] >= 1) return;  // shut: the lids hide it (as natively)
        mesh(m, face.textures.eye, eye.u, frame.eyeModels[side]);
        this.drawSocket(face, side, eye.u, frame.model, mesh);
      });
    }
    const plain = programs.plain;
    gl.useProgram(plain.program);
    gl.uniform1f(plain.u.u_skin_specular, 0);
    mesh(face.mouth, face.textures.mouth, plain.u, frame.model);
    // The shell faces out and is closed where it shows: its far side is culled.
    gl.enable(gl.CULL_FACE);
    mesh(face.head, face.textures.skin, plain.u, frame.model);
    gl.disable(gl.CULL_FACE);
  }

  // The eye socket's far wall where the hole is open, as the native
  // draw_socket (fw/model/eye_socket.hpp): the stencil marks the hole, the
  // socket is drawn from inside there, and the mark is taken out again
  // (no scissor here, so the next hole must not find it).
  drawSocket(face, side, u, model, mesh) {
    const gl = this.gl;
    const markHole = (value) => {
      gl.stencilFunc(gl.ALWAYS, value, 0xff);
      gl.stencilOp(gl.KEEP, gl.KEEP, gl.REPLACE);
      gl.colorMask(false, false, false, false);
      gl.depthMask(false);
      mesh(face.holeFans[side], face.textures.eye, u, model);
      gl.colorMask(true, true, true, true);
      gl.depthMask(true);
    };
    gl.enable(gl.STENCIL_TEST);
    markHole(1);
    gl.stencilFunc(gl.EQUAL, 1, 0xff);
    gl.stencilOp(gl.KEEP, gl.KEEP, gl.KEEP);
    gl.uniform1f(u.u_specular, 0);
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.FRONT);
    mesh(face.sockets[side], face.textures.eye, u, model);
    gl.cullFace(gl.BACK);
    gl.disable(gl.CULL_FACE);
    gl.uniform1f(u.u_specular, EYE_SPECULAR);
    markHole(0);
    gl.disable(gl.STENCIL_TEST);
  }
}

/** A hole spanned by a fan over its rim's vertices (the skin's). */
function fan(hole) {
  const triangles = [];
  for (let i = 1; i + 1 < hole.length; ++i) triangles.push(hole[0], hole[i], hole[i + 1]);
  return Uint32Array.from(triangles);
}
