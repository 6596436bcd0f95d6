// The 4x4 matrices of every page: column-major like GLSL and glm. Results
// are Float32Array(16), what WebGL takes, unless the caller asks for
// another array type: the engine's head and eye matrices keep float64 all
// the way (`Float64Array`), since tests hold them to what the C++ wrote.

export function identity(Type = Float32Array) {
  return new Type([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
}

/** a times b. */
export function multiply(a, b, Type = Float32Array) {
  const out = new Type(16);
  for (let column = 0; column < 4; ++column) {
    for (let row = 0; row < 4; ++row) {
      let sum = 0;
      for (let k = 0; k < 4; ++k) sum += a[k * 4 + row] * b[column * 4 + k];
      out[column * 4 + row] = sum;
    }
  }
  return out;
}

export function translation([x, y, z], Type = Float32Array) {
  const out = identity(Type);
  out[12] = x;
  out[13] = y;
  out[14] = z;
  return out;
}

/** A turn by `angle` about the y axis. */
export function rotationY(angle, Type = Float32Array) {
  const out = identity(Type);
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  out[0] = c;
  out[2] = -s;
  out[8] = s;
  out[10] = c;
  return out;
}

/** A turn by `angle` about the unit axis [x, y, z], as glm::rotate makes it. */
export function rotation(angle, [x, y, z], Type = Float32Array) {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const r = identity(Type);
  r[0] = c + (1 - c) * x * x;
  r[1] = (1 - c) * x * y + s * z;
  r[2] = (1 - c) * x * z - s * y;
  r[4] = (1 - c) * y * x - s * z;
  r[5] = c + (1 - c) * y * y;
  r[6] = (1 - c) * y * z + s * x;
  r[8] = (1 - c) * z * x + s * y;
  r[9] = (1 - c) * z * y - s * x;
  r[10] = c + (1 - c) * z * z;
  return r;
}

export function perspective(fovY, aspect, near, far) {
  const f = 1 / Math.tan(fovY / 2);
  const out = new Float32Array(16);
  out[0] = f / aspect;
  out[5] = f;
  out[10] = (far + near) / (near - far);
  out[11] = -1;
  out[14] = (2 * far * near) / (near - far);
  return out;
}

export function lookAt(eye, target, up) {
  const sub = (a, b) => a.map((v, i) => v - b[i]);
  const normalize = (v) => {
    const length = Math.hypot(...v);
    return v.map((x) => x / length);
  };
  const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const f = normalize(sub(target, eye));
  const s = normalize(cross(f, up));
  const u = cross(s, f);
  return new Float32Array([
    s[0], u[0], -f[0], 0,
    s[1], u[1], -f[1], 0,
    s[2], u[2], -f[2], 0,
    -dot(s, eye), -dot(u, eye), dot(f, eye), 1,
  ]);
}

/** The same, as one object, for `mat4.multiply(...)` at the call site. */
export const mat4 = { identity, multiply, translation, rotationY, rotation, perspective, lookAt };
