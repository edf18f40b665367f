//! Minimal column-major linear algebra for cameras and transforms (f32, as
//! uploaded). Matrices are `[[f32; 4]; 4]` arrays of columns, the memory
//! layout of WGSL `mat4x4<f32>`.

pub type Vec3 = [f32; 3];
pub type Mat4 = [[f32; 4]; 4];

pub fn add(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: Vec3, s: f32) -> Vec3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

pub fn dot(a: Vec3, b: Vec3) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub fn length(a: Vec3) -> f32 {
    dot(a, a).sqrt()
}

/// `a / |a|`, or `fallback` for a (nearly) zero vector.
pub fn normalize_or(a: Vec3, fallback: Vec3) -> Vec3 {
    let l = length(a);
    if l > 1e-12 {
        scale(a, 1.0 / l)
    } else {
        fallback
    }
}

pub fn normalize(a: Vec3) -> Vec3 {
    normalize_or(a, [0.0, 0.0, 1.0])
}

pub const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

/// `a * b` (apply `b` first).
pub fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [[0.0f32; 4]; 4];
    for (c, col) in out.iter_mut().enumerate() {
        for (r, v) in col.iter_mut().enumerate() {
            *v = (0..4).map(|k| a[k][r] * b[c][k]).sum();
        }
    }
    out
}

pub fn transform_point(m: &Mat4, p: Vec3) -> [f32; 4] {
    let mut out = [0.0f32; 4];
    for (r, v) in out.iter_mut().enumerate() {
        *v = m[0][r] * p[0] + m[1][r] * p[1] + m[2][r] * p[2] + m[3][r];
    }
    out
}

/// Right-handed view matrix (camera looks down -Z in view space).
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Mat4 {
    let f = normalize(sub(target, eye));
    let s = normalize_or(cross(f, up), [1.0, 0.0, 0.0]);
    let u = cross(s, f);
    [
        [s[0], u[0], -f[0], 0.0],
        [s[1], u[1], -f[1], 0.0],
        [s[2], u[2], -f[2], 0.0],
        [-dot(s, eye), -dot(u, eye), dot(f, eye), 1.0],
    ]
}

/// Right-handed perspective projection to WebGPU clip space (depth 0..1).
pub fn perspective(fov_y_radians: f32, aspect: f32, near: f32, far: f32) -> Mat4 {
    let h = 1.0 / (0.5 * fov_y_radians).tan();
    let w = h / aspect;
    let r = far / (near - far);
    [
        [w, 0.0, 0.0, 0.0],
        [0.0, h, 0.0, 0.0],
        [0.0, 0.0, r, -1.0],
        [0.0, 0.0, r * near, 0.0],
    ]
}

/// General 4x4 inverse (cofactors, f64 inside); `None` when singular.
pub fn inverse(m: &Mat4) -> Option<Mat4> {
    // Row-major copy: a[r][c].
    let mut a = [[0.0f64; 4]; 4];
    for (c, col) in m.iter().enumerate() {
        for (r, v) in col.iter().enumerate() {
            a[r][c] = f64::from(*v);
        }
    }
    // Gauss-Jordan with partial pivoting.
    let mut inv = [[0.0f64; 4]; 4];
    for (i, row) in inv.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    for col in 0..4 {
        let pivot = (col..4).max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))?;
        if a[pivot][col].abs() < 1e-300 {
            return None;
        }
        a.swap(col, pivot);
        inv.swap(col, pivot);
        let p = a[col][col];
        for k in 0..4 {
            a[col][k] /= p;
            inv[col][k] /= p;
        }
        for r in 0..4 {
            if r != col {
                let f = a[r][col];
                for k in 0..4 {
                    a[r][k] -= f * a[col][k];
                    inv[r][k] -= f * inv[col][k];
                }
            }
        }
    }
    let mut out = [[0.0f32; 4]; 4];
    for (c, col) in out.iter_mut().enumerate() {
        for (r, v) in col.iter_mut().enumerate() {
            *v = inv[r][c] as f32;
        }
    }
    Some(out)
}

/// Inverse-transpose of the upper 3x3 of `m`, in a mat4 (the engine
/// interface's `normal_matrix`).
pub fn normal_matrix(m: &Mat4) -> Mat4 {
    let mut m3 = *m;
    m3[3] = [0.0, 0.0, 0.0, 1.0];
    for col in m3.iter_mut().take(3) {
        col[3] = 0.0;
    }
    let inv = inverse(&m3).unwrap_or(IDENTITY);
    let mut out = IDENTITY;
    for c in 0..3 {
        for r in 0..3 {
            out[c][r] = inv[r][c];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_round_trips() {
        let v = look_at([1.0, 2.0, 3.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let p = perspective(0.7, 1.5, 0.1, 50.0);
        let vp = mul(&p, &v);
        let i = inverse(&vp).unwrap();
        let id = mul(&vp, &i);
        for (c, col) in id.iter().enumerate() {
            for (r, v) in col.iter().enumerate() {
                let e = if r == c { 1.0 } else { 0.0 };
                assert!((v - e).abs() < 1e-4, "{id:?}");
            }
        }
    }

    #[test]
    fn look_at_puts_target_in_front() {
        let v = look_at([0.0, 0.0, 5.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let p = transform_point(&v, [0.0, 0.0, 0.0]);
        assert!((p[2] + 5.0).abs() < 1e-6);
    }
}
