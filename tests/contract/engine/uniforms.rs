//! Uniform bytes at a layout's offsets: the material block from parameter
//! defaults (by `parameter` + `encoding`) or from a scene instance's values
//! (by member name), and the engine's frame and object blocks (by member
//! name, as the members' descriptions say).

use super::data::{Environment, FrameInputs, Mat4};
use std::collections::BTreeMap;
use weft_meta::{MaterialMetadata, MemberEncoding, UniformLayout, UniformMember};

fn put(bytes: &mut [u8], m: &UniformMember, data: &[u8]) -> Result<(), String> {
    if data.len() > m.size as usize {
        return Err(format!(
            "member `{}` ({}) holds {} bytes, {} given",
            m.name,
            m.ty,
            m.size,
            data.len()
        ));
    }
    let at = m.offset as usize;
    let end = at + data.len();
    if end > bytes.len() {
        return Err(format!("member `{}` ends past the block", m.name));
    }
    bytes[at..end].copy_from_slice(data);
    Ok(())
}

fn f32s(v: &[f32]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

fn expect_ty(m: &UniformMember, want: &[&str]) -> Result<(), String> {
    // The type as the JSON spells it: this engine reads the docs, not weft's encoder.
    if want.contains(&m.ty.to_string().as_str()) {
        Ok(())
    } else {
        Err(format!(
            "member `{}` is `{}`, its encoding wants one of {want:?}",
            m.name, m.ty
        ))
    }
}

fn numbers(v: &serde_json::Value, what: &str) -> Result<Vec<f64>, String> {
    match v {
        serde_json::Value::Number(n) => Ok(vec![n.as_f64().unwrap()]),
        serde_json::Value::Bool(b) => Ok(vec![f64::from(u8::from(*b))]),
        serde_json::Value::Array(a) => a
            .iter()
            .map(|x| {
                x.as_f64()
                    .ok_or_else(|| format!("{what}: `{x}` is not a number"))
            })
            .collect(),
        other => Err(format!("{what}: `{other}` is not a number or an array")),
    }
}

/// The material block with every parameter at its declared default.
pub fn material_defaults(
    meta: &MaterialMetadata,
    layout: &UniformLayout,
) -> Result<Vec<u8>, String> {
    let mut bytes = vec![0u8; layout.size as usize];
    for m in &layout.members {
        let (Some(pname), Some(enc)) = (&m.parameter, m.encoding) else {
            return Err(format!(
                "material member `{}` names no parameter and encoding",
                m.name
            ));
        };
        let p = meta
            .parameters
            .iter()
            .find(|p| &p.name == pname)
            .ok_or_else(|| format!("member `{}`: no parameter `{pname}`", m.name))?;
        let what = format!("parameter `{pname}`");
        let data: Vec<u8> = match enc {
            MemberEncoding::F32 => {
                expect_ty(m, &["f32"])?;
                let v = p
                    .default
                    .as_f64()
                    .ok_or(format!("{what}: default not a number"))?;
                f32s(&[v as f32])
            }
            MemberEncoding::I32 => {
                expect_ty(m, &["i32"])?;
                let v = p
                    .default
                    .as_f64()
                    .ok_or(format!("{what}: default not a number"))?;
                (v.round() as i32).to_le_bytes().to_vec()
            }
            MemberEncoding::BoolU32 => {
                expect_ty(m, &["u32"])?;
                let v = match &p.default {
                    serde_json::Value::Bool(b) => u32::from(*b),
                    other => return Err(format!("{what}: default `{other}` is not a bool")),
                };
                v.to_le_bytes().to_vec()
            }
            MemberEncoding::Vector => {
                expect_ty(m, &["vec2<f32>", "vec3<f32>", "vec4<f32>"])?;
                let v = numbers(&p.default, &what)?;
                f32s(&v.iter().map(|x| *x as f32).collect::<Vec<_>>())
            }
            MemberEncoding::Color => {
                expect_ty(m, &["vec4<f32>"])?;
                let c = p
                    .color
                    .as_ref()
                    .ok_or(format!("{what}: colour without `color.linear_default`"))?;
                f32s(&c.linear_default.map(|x| x as f32))
            }
            MemberEncoding::Curve => {
                let c = p
                    .curve
                    .as_ref()
                    .ok_or(format!("{what}: curve without `curve`"))?;
                if c.baked_default.len() != c.samples as usize {
                    return Err(format!(
                        "{what}: {} baked samples, `samples` says {}",
                        c.baked_default.len(),
                        c.samples
                    ));
                }
                let elements = (c.samples as usize).div_ceil(4);
                expect_ty(m, &[format!("array<vec4<f32>, {elements}>").as_str()])?;
                // Sample i in element i / 4, component i % 4: with a 16-byte
                // array stride that is sample i at byte 4 i. Tail stays zero.
                f32s(
                    &c.baked_default
                        .iter()
                        .map(|x| *x as f32)
                        .collect::<Vec<_>>(),
                )
            }
            MemberEncoding::TilingOffset => {
                expect_ty(m, &["vec4<f32>"])?;
                let st = p
                    .texture
                    .as_ref()
                    .and_then(|t| t.tiling_default)
                    .unwrap_or([1.0, 1.0, 0.0, 0.0]);
                f32s(&st.map(|x| x as f32))
            }
        };
        put(&mut bytes, m, &data)?;
    }
    Ok(bytes)
}

/// A block filled from values by member name (a scene instance's
/// `uniform_values`), each written as the member's WGSL type says.
pub fn by_member_values(
    values: &BTreeMap<String, serde_json::Value>,
    layout: &UniformLayout,
) -> Result<Vec<u8>, String> {
    let mut bytes = vec![0u8; layout.size as usize];
    for m in &layout.members {
        let v = values
            .get(&m.name)
            .ok_or_else(|| format!("no value for uniform member `{}`", m.name))?;
        let what = format!("member `{}`", m.name);
        let n = numbers(v, &what)?;
        let data: Vec<u8> = match m.ty.to_string().as_str() {
            "i32" => (n[0].round() as i32).to_le_bytes().to_vec(),
            "u32" => (n[0].round() as u32).to_le_bytes().to_vec(),
            ty if ty == "f32" || ty.starts_with("vec") || ty.starts_with("array<vec4<f32>") => {
                f32s(&n.iter().map(|x| *x as f32).collect::<Vec<_>>())
            }
            other => return Err(format!("{what}: cannot write type `{other}`")),
        };
        put(&mut bytes, m, &data)?;
    }
    Ok(bytes)
}

fn mat(m: &Mat4) -> Vec<f32> {
    m.iter().flatten().copied().collect()
}

fn normalize(v: [f32; 3]) -> [f32; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l > 0.0 { v.map(|x| x / l) } else { v }
}

/// `weft_frame` by member name.
pub fn frame(
    layout: &UniformLayout,
    f: &FrameInputs,
    env: &Environment,
) -> Result<Vec<u8>, String> {
    let mut bytes = vec![0u8; layout.size as usize];
    for m in &layout.members {
        let v: Vec<f32> = match m.name.as_str() {
            "view_proj" => mat(&f.view_proj),
            "view" => mat(&f.view),
            "camera_position" => {
                let p = f.camera_position;
                vec![p[0], p[1], p[2], 1.0]
            }
            "light_direction" => {
                let d = normalize(f.light_direction);
                vec![d[0], d[1], d[2], 0.0]
            }
            "light_color" => {
                let c = f.light_color;
                vec![c[0], c[1], c[2], 1.0]
            }
            "sh" => env
                .sh
                .iter()
                .flat_map(|c| [c[0], c[1], c[2], 0.0])
                .collect(),
            "params" => vec![env.mips.len() as f32, f.exposure, f.time, 0.0],
            "viewport" => {
                let [w, h] = f.viewport;
                vec![w, h, 1.0 / w, 1.0 / h]
            }
            other => return Err(format!("unknown weft_frame member `{other}`")),
        };
        put(&mut bytes, m, &f32s(&v))?;
    }
    Ok(bytes)
}

/// Inverse transpose of the upper 3×3 of `m`, in a mat4 (rest identity).
pub fn normal_matrix(m: &Mat4) -> Mat4 {
    // a[r][c] = m[c][r] (row-major copy of the upper 3×3).
    let a = |r: usize, c: usize| f64::from(m[c][r]);
    let cof = |r: usize, c: usize| {
        let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
        let (c1, c2) = ((c + 1) % 3, (c + 2) % 3);
        a(r1, c1) * a(r2, c2) - a(r1, c2) * a(r2, c1)
    };
    let det = a(0, 0) * cof(0, 0) + a(0, 1) * cof(0, 1) + a(0, 2) * cof(0, 2);
    // inverse = adjugate / det = cofactorᵀ / det; its transpose = cofactor / det.
    let mut out = [[0.0f32; 4]; 4];
    for (c, col) in out.iter_mut().enumerate() {
        for (r, v) in col.iter_mut().enumerate() {
            *v = if r < 3 && c < 3 {
                (cof(r, c) / det) as f32
            } else if r == c {
                1.0
            } else {
                0.0
            };
        }
    }
    out
}

/// `weft_object` by member name.
pub fn object(layout: &UniformLayout, model: &Mat4) -> Result<Vec<u8>, String> {
    let mut bytes = vec![0u8; layout.size as usize];
    for m in &layout.members {
        let v = match m.name.as_str() {
            "model" => mat(model),
            "normal_matrix" => mat(&normal_matrix(model)),
            other => return Err(format!("unknown weft_object member `{other}`")),
        };
        put(&mut bytes, m, &f32s(&v))?;
    }
    Ok(bytes)
}
