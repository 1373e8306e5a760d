/**
 * The little 3D math the HUNO model needs, without a library: 4×4 rigid transforms stored column-major in a
 * `Float64Array(16)` (the layout of WebGL and of three's `Matrix4.elements`, so the renderer copies them as they
 * are), and 3-vectors as `[x, y, z]` tuples. Pure functions; every result is a new value.
 */

export type Mat4 = Float64Array;
export type Vec3 = readonly [number, number, number];

export function identity(): Mat4 {
  const m = new Float64Array(16);
  m[0] = m[5] = m[10] = m[15] = 1;
  return m;
}

export function translation(x: number, y: number, z: number): Mat4 {
  const m = identity();
  m[12] = x;
  m[13] = y;
  m[14] = z;
  return m;
}

/** A rotation by `angle` radians about the x axis (roll), the y axis (pitch) or the z axis, right-handed. */
export function rotation(axis: "x" | "y" | "z", angle: number): Mat4 {
  const m = identity();
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  if (axis === "x") {
    m[5] = c;
    m[6] = s;
    m[9] = -s;
    m[10] = c;
  } else if (axis === "y") {
    m[0] = c;
    m[2] = -s;
    m[8] = s;
    m[10] = c;
  } else {
    m[0] = c;
    m[1] = s;
    m[4] = -s;
    m[5] = c;
  }
  return m;
}

/** a · b (b applied first). */
export function multiply(a: Mat4, b: Mat4): Mat4 {
  const out = new Float64Array(16);
  for (let col = 0; col < 4; col++) {
    for (let row = 0; row < 4; row++) {
      let sum = 0;
      for (let k = 0; k < 4; k++) sum += a[k * 4 + row]! * b[col * 4 + k]!;
      out[col * 4 + row] = sum;
    }
  }
  return out;
}

/** The point `p` moved by `m`. */
export function transformPoint(m: Mat4, p: Vec3): [number, number, number] {
  const [x, y, z] = p;
  return [
    m[0]! * x + m[4]! * y + m[8]! * z + m[12]!,
    m[1]! * x + m[5]! * y + m[9]! * z + m[13]!,
    m[2]! * x + m[6]! * y + m[10]! * z + m[14]!,
  ];
}

/** The direction `v` turned by `m` (no translation). */
export function transformDirection(m: Mat4, v: Vec3): [number, number, number] {
  const [x, y, z] = v;
  return [
    m[0]! * x + m[4]! * y + m[8]! * z,
    m[1]! * x + m[5]! * y + m[9]! * z,
    m[2]! * x + m[6]! * y + m[10]! * z,
  ];
}

/** The translation part of `m`: where its frame's origin is. */
export function origin(m: Mat4): [number, number, number] {
  return [m[12]!, m[13]!, m[14]!];
}

export function length(v: Vec3): number {
  return Math.hypot(v[0], v[1], v[2]);
}

export function normalize(v: Vec3): [number, number, number] {
  const n = length(v);
  return n === 0 ? [0, 0, 1] : [v[0] / n, v[1] / n, v[2] / n];
}

export function cross(a: Vec3, b: Vec3): [number, number, number] {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

export function dot(a: Vec3, b: Vec3): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/**
 * The smallest rotation that turns the unit vector `from` onto the unit vector `to` (Rodrigues' formula about
 * their common normal). `from` pointing exactly away from `to` turns half a turn about the x axis.
 */
export function rotationBetween(from: Vec3, to: Vec3): Mat4 {
  const c = dot(from, to);
  if (c < -1 + 1e-12) return rotation("x", Math.PI);
  const [x, y, z] = cross(from, to);
  const k = 1 / (1 + c);
  const m = identity();
  // Column-major: m[col * 4 + row].
  m[0] = c + x * x * k;
  m[1] = z + x * y * k;
  m[2] = -y + x * z * k;
  m[4] = -z + x * y * k;
  m[5] = c + y * y * k;
  m[6] = x + y * z * k;
  m[8] = y + x * z * k;
  m[9] = -x + y * z * k;
  m[10] = c + z * z * k;
  return m;
}
