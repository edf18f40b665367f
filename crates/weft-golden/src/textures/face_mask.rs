//! The face's shadow mask (seed 004 §4's `_SkinShadowMap`, its
//! c_Charolic_FaceShadowMap): R is 1 over the face and fades to 0 under the
//! jaw towards the neck and up into the hairline; the seed multiplies it
//! into the SDF result, so the neck-facing underside of the chin and the
//! skin under the fringe stay in shadow whatever the light. G is 1 and B 0,
//! as the seed's texture has them (its B, a cheek and nose-tip highlight,
//! the seed leaves unused).

use super::head;
use super::math::cos;
use super::{Channels, Texture, quantise, smoothstep};
use weft_render::HAIR_END;

pub const SIZE: usize = 128;

/// R at head uv (u, v) ∈ [0, 1]².
pub fn mask(u: f64, v: f64) -> f64 {
    let (theta, phi) = head::angles(u, v);
    // Under the jaw: the normal turns down towards the neck.
    let n = head::normal(theta, phi);
    let jaw = smoothstep(-0.9, -0.55, n[1]);
    // The hairline: where the bust's hair cards end (the fringe in front,
    // lower towards the ears), with a short fade into the skin below.
    let hair = f64::from(HAIR_END[0]) + f64::from(HAIR_END[1]) * (0.5 - 0.5 * cos(phi));
    let hairline = smoothstep(hair - 0.04, hair + 0.03, v);
    jaw * hairline
}

pub fn texture() -> Texture {
    let mut data = Vec::with_capacity(SIZE * SIZE * 3);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let (u, v) = (
                (i as f64 + 0.5) / SIZE as f64,
                (j as f64 + 0.5) / SIZE as f64,
            );
            data.extend([quantise(mask(u, v)), 255, 0]);
        }
    }
    Texture {
        path: "materials/face/textures/face_shadow_mask.png",
        width: SIZE as u32,
        height: SIZE as u32,
        channels: Channels::Rgb,
        srgb: false,
        data,
    }
}
