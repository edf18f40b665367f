//! The engine data the page binds, computed by `weft-render` exactly as
//! `weft preview` computes it, so the page reimplements no lighting: the
//! procedural sky's GGX-prefiltered cube and its SH irradiance (group 0),
//! the main light, and the built-in meshes with their cameras and model
//! matrices. The LUTs come from the build itself (`luts/…`).

use serde_json::{Value, json};
use std::sync::Arc;
use weft_runtime::{EnvironmentMaps, Scene, SceneKind, SkyParams};

/// `environment.json` (layout and SH) and `environment.bin` (texels).
pub struct Environment {
    pub json: Arc<Vec<u8>>,
    pub bin: Arc<Vec<u8>>,
}

/// The sky `weft preview` renders under by default (sun where the default
/// light is): mip-major, then face (+X, −X, +Y, −Y, +Z, −Z), rows top
/// first, RGBA half floats (alpha 1) — ready for `writeTexture` per mip
/// and face of an `rgba16float` cube.
pub fn environment() -> Environment {
    environment_for(None)
}

/// The sky `weft preview --light x,y,z` renders under: the direct light
/// and the sky's sun both along `light` (None: the default light), computed
/// by the same `weft_runtime::lit` and `EnvironmentMaps::sky` as the preview.
pub fn environment_for(light: Option<[f32; 3]>) -> Environment {
    let (scene, sky) =
        weft_runtime::lit(Scene::new(SceneKind::Sphere), light, SkyParams::default());
    let env = EnvironmentMaps::sky(&sky);
    let light = scene.light;
    let mut bin = Vec::new();
    let mut mips = Vec::new();
    for level in &env.mips {
        let offset = bin.len();
        for t in &level.data {
            for c in [t[0], t[1], t[2], 1.0] {
                bin.extend_from_slice(&half::f16::from_f32(c).to_le_bytes());
            }
        }
        mips.push(json!({
            "size": level.size,
            "offset": offset,
            "face_bytes": level.size as usize * level.size as usize * 8,
        }));
    }
    let json = json!({
        "format": "rgba16float",
        "layout": "mip-major, then face (+x, -x, +y, -y, +z, -z), rows top first, RGBA f16 little-endian",
        "size": env.mips[0].size,
        "mip_count": env.mip_count(),
        "mips": mips,
        "mip_roughness": env.mip_roughness,
        "sh": env.sh,
        "light": { "direction": light.direction, "radiance": light.radiance },
        "exposure": 1.0,
        "sky": {
            "sun_direction": sky.sun_direction,
            "sun_radiance": sky.sun_radiance,
            "sun_radius_degrees": sky.sun_radius_degrees,
            "zenith": sky.zenith,
            "horizon": sky.horizon,
            "ground": sky.ground,
            "samples": sky.samples,
        },
    });
    Environment {
        json: Arc::new(serde_json::to_vec(&json).unwrap_or_default()),
        bin: Arc::new(bin),
    }
}

/// A built-in mesh: `(json, bin)`. The binary holds every engine-interface
/// stream as tightly packed little-endian f32 (position 3, normal 3,
/// tangent 4, uv0 2, uv1 2, color 4 — uv1 defaults to uv0, colour to
/// white, as weft-render's streams do), then u32 indices; the JSON gives
/// offsets, the model matrix and the camera `weft preview` uses.
pub fn mesh(kind: SceneKind) -> (Vec<u8>, Vec<u8>) {
    let scene = Scene::new(kind);
    let m = &scene.mesh;
    let n = m.vertex_count();
    let mut bin: Vec<u8> = Vec::new();
    let mut streams = serde_json::Map::new();
    let mut push = |name: &str, components: usize, values: &mut dyn Iterator<Item = f32>| {
        let offset = bin.len();
        for v in values {
            bin.extend_from_slice(&v.to_le_bytes());
        }
        streams.insert(
            name.into(),
            json!({ "offset": offset, "components": components, "format": format!("float32x{components}") }),
        );
    };
    push("position", 3, &mut m.positions.iter().flatten().copied());
    push(
        "normal",
        3,
        &mut (0..n).flat_map(|i| m.normals.get(i).copied().unwrap_or([0.0, 0.0, 1.0])),
    );
    push(
        "tangent",
        4,
        &mut (0..n).flat_map(|i| m.tangents.get(i).copied().unwrap_or([1.0, 0.0, 0.0, 1.0])),
    );
    push(
        "uv0",
        2,
        &mut (0..n).flat_map(|i| m.uv0.get(i).copied().unwrap_or([0.0, 0.0])),
    );
    push(
        "uv1",
        2,
        &mut (0..n).flat_map(|i| {
            m.uv1
                .get(i)
                .or_else(|| m.uv0.get(i))
                .copied()
                .unwrap_or([0.0, 0.0])
        }),
    );
    push(
        "color",
        4,
        &mut (0..n).flat_map(|i| m.colors.get(i).copied().unwrap_or([1.0; 4])),
    );
    let index_offset = bin.len();
    for i in &m.indices {
        bin.extend_from_slice(&i.to_le_bytes());
    }
    let c = &scene.camera;
    let json: Value = json!({
        "name": kind.name(),
        "vertex_count": n,
        "streams": streams,
        "indices": { "offset": index_offset, "count": m.indices.len(), "format": "uint32" },
        "model": scene.model,
        "camera": {
            "eye": c.eye, "target": c.target, "up": c.up,
            "fov_y_degrees": c.fov_y_degrees, "near": c.near, "far": c.far,
        },
    });
    (serde_json::to_vec(&json).unwrap_or_default(), bin)
}
