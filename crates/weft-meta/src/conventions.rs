//! What an engine must do as weft's renderer does that is neither a binding
//! nor a pipeline state, stated once: the exact texels of the built-in
//! textures and the tangent frame the vertex tangents and the shaders
//! assume. Material metadata (schema 4.2) and scene metadata (3.3) carry it
//! as `conventions`; weft's renderer takes the same values from here, and
//! docs/engine-interface.md explains them.

use crate::TextureDefault;
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The conventions an engine follows to draw what weft draws, beyond the
/// bindings and pipeline states (docs/engine-interface.md).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Conventions {
    /// The RGBA8 texel of each built-in 1×1 texture (a binding's
    /// `texture.default`, a scene texture's `builtin`), by name: exactly the
    /// bytes weft's renderer uploads, in the binding's `format`. 0.5 is
    /// stored as 128 (127.5 rounded half away from zero), so `gray` samples
    /// as 128/255 = 0.50196 in `rgba8unorm` and as 0.21586 (linear) in
    /// `rgba8unorm_srgb`, and `normal` (128, 128, 255) unpacks to
    /// (0.00392, 0.00392, 1) before normalisation.
    pub builtin_textures: BTreeMap<String, [u8; 4]>,
    /// How the shaders build the tangent frame from the vertex `normal` and
    /// `tangent` (location 2), and which uv0 directions the frame follows:
    /// what an engine's tangents must satisfy.
    pub tangent_frame: TangentFrame,
    /// Which textures get mip levels: [`MIP_CHAINS`].
    pub mip_chains: String,
}

/// The mip rule of [`Conventions::mip_chains`].
pub const MIP_CHAINS: &str = "A texture parameter's image (`texture.file`) holds level 0 only: \
     build the chain its `mip_chain` states (box 2x2, in linear light for sRGB formats; \
     weft_meta::bake::rgba8_mip_chain) and bind every level, as weft's renderer does; the \
     material samplers filter linearly between levels. So does a texture the engine binds \
     for a texture2d parameter. Built-in 1x1 textures, gradient ramps, cubes, LUT files and \
     baked tables have one level.";

/// The tangent-frame convention (`weft_tangent_frame` in
/// materials/lib/forward.wgsl, the built-in meshes, `weft_runtime::mesh::compute_tangents`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TangentFrame {
    /// The bitangent the shaders use: `weft_meta::conventions::BITANGENT`,
    /// "w * cross(normal, tangent.xyz), w = -1 if tangent.w < 0 else +1" (the
    /// vertex stage also flips w for a model matrix with a negative
    /// determinant), with the interpolated normal and the tangent made
    /// orthogonal to it: (T, B, N) is right-handed when w = +1.
    pub bitangent: String,
    /// The uv0 direction the tangent `tangent.xyz` points along: `+u`.
    pub tangent_follows: String,
    /// The uv0 direction the bitangent points along: `+v`. A mesh sets
    /// `tangent.w` so that `w · cross(N, T)` has a positive component along
    /// dP/dv.
    pub bitangent_follows: String,
    /// Where v = 0 is in a texture: `top` (row 0 of a texture file, the
    /// image's top row). So +v, and the bitangent, run down the image.
    pub v_origin: String,
    /// What a tangent-space normal map's channels mean under this frame.
    pub normal_map: String,
}

/// The bitangent formula of [`TangentFrame::bitangent`].
pub const BITANGENT: &str = "w * cross(normal, tangent.xyz), w = -1 if tangent.w < 0 else +1";

impl TangentFrame {
    /// weft's convention.
    pub fn current() -> TangentFrame {
        TangentFrame {
            bitangent: BITANGENT.into(),
            tangent_follows: "+u".into(),
            bitangent_follows: "+v".into(),
            v_origin: "top".into(),
            normal_map: "rgb * 2 - 1 = (x, y, z) along (T, B, N): green is +v, down the \
                         image (the \"Y-\" or DirectX convention); a \"Y+\" (OpenGL) map \
                         needs its green channel inverted"
                .into(),
        }
    }
}

impl Conventions {
    /// The conventions this weft writes and draws with.
    pub fn current() -> Conventions {
        Conventions {
            builtin_textures: TextureDefault::ALL
                .iter()
                .map(|d| (d.name().to_string(), d.rgba8()))
                .collect(),
            tangent_frame: TangentFrame::current(),
            mip_chains: MIP_CHAINS.into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_texels_are_stated_for_every_default() {
        let c = Conventions::current();
        assert_eq!(c.builtin_textures.len(), TextureDefault::ALL.len());
        assert_eq!(c.builtin_textures["white"], [255, 255, 255, 255]);
        assert_eq!(c.builtin_textures["black"], [0, 0, 0, 255]);
        // 0.5 is 128, not 127.
        assert_eq!(c.builtin_textures["gray"], [128, 128, 128, 255]);
        assert_eq!(c.builtin_textures["normal"], [128, 128, 255, 255]);
        for d in TextureDefault::ALL {
            let t = d.texel();
            let b = d.rgba8();
            for i in 0..4 {
                assert_eq!(t[i], f32::from(b[i]) / 255.0, "{}", d.name());
            }
        }
    }
}
