//! Baked tables (`[tables.<name>]`): the bytes (`bake/`), the file beside the
//! material's variants, and what the metadata tells engines about it (a
//! group-1 texture binding carrying a `resource` with its `file`, like the
//! engine interface's LUTs).

use crate::bake;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};
use weft_front::model::{BakedTable, Material, TableRecipe};
use weft_meta::{EngineResource, ResourceFile};

/// Texture format of every baked table.
pub const TABLE_FORMAT: &str = "rgba16float";

/// The extension of every baked table's file.
pub const TABLE_EXTENSION: &str = "rgba16f";

/// The table's file name in the material's folder.
pub fn file_name(t: &BakedTable) -> String {
    format!("{}.{TABLE_EXTENSION}", t.name)
}

/// The table's texels (RGBA16Float, row 0 first), computed from the TOML.
/// Baked once per recipe and size in a process: every variant's metadata
/// needs the bytes' hash, and a table is the same for all of them.
pub fn bake(t: &BakedTable) -> Arc<Vec<u8>> {
    static BAKED: OnceLock<Mutex<HashMap<String, Arc<Vec<u8>>>>> = OnceLock::new();
    let key = format!("{:?} {:?}", t.recipe, t.size);
    let cache = BAKED.get_or_init(Default::default);
    if let Some(bytes) = cache.lock().expect("table cache").get(&key) {
        return bytes.clone();
    }
    let bytes = Arc::new(match &t.recipe {
        TableRecipe::PreintegratedSkin { shape, half_ring } => {
            bake::skin::preintegrated_table(t.size, *shape, *half_ring)
        }
        TableRecipe::ThinFilmSensitivity { opd_max_nm } => {
            bake::film::sensitivity_table(t.size, *opd_max_nm)
        }
    });
    cache
        .lock()
        .expect("table cache")
        .entry(key)
        .or_insert(bytes)
        .clone()
}

/// The `resource` of the table's binding: an id unique in a library
/// (`<material>.<table>`) and the file, relative to the library root.
pub fn resource(m: &Material, t: &BakedTable) -> EngineResource {
    let (what, u, v, channels) = match &t.recipe {
        TableRecipe::PreintegratedSkin { shape, half_ring } => (
            format!(
                "Pre-integrated skin diffuse (Penner & Borshukov 2011) over the Burley profile \
                 with shape s = ({}, {}, {}) per RGB channel, integrated over {} of the ring; \
                 baked by weft from the material's [tables.{}]. Bind the file's texels.",
                shape[0],
                shape[1],
                shape[2],
                if *half_ring {
                    "±π/2 (the seed)"
                } else {
                    "±π"
                },
                t.name
            ),
            "N·L · 0.5 + 0.5, 0 at the left edge, 1 at the right; sampled at texel centres",
            "curvature 1/r (0 = flat), 0 at row 0, 1 at the last row; sampled at texel centres",
            "rgb: the diffuse falloff D(θ, r) per channel, a: 1",
        ),
        TableRecipe::ThinFilmSensitivity { opd_max_nm } => (
            format!(
                "The spectral sensitivity of thin-film interference (Belcour & Barla 2017): \
                 S(x) = ∫ CMF(λ) cos(2π x / λ) dλ over 380–780 nm (CIE 1931 2°), in linear \
                 Rec. 709, divided per channel by its value at x = 0, for optical path \
                 differences x from 0 to {opd_max_nm} nm; baked by weft from the material's \
                 [tables.{}]. Bind the file's texels.",
                t.name
            ),
            "x / opd_max (x the optical path difference in nm), 0 at the left edge, 1 at the right; sampled at texel centres",
            "unused: every row holds the same values",
            "rgb: S(x) per channel, signed (1 at x = 0), a: 1",
        ),
    };
    EngineResource {
        id: format!("{}.{}", m.name, t.name),
        description: what,
        file: Some(ResourceFile {
            path: format!("{}/{}", m.name, file_name(t)),
            format: TABLE_FORMAT.into(),
            width: t.size[0],
            height: t.size[1],
            layout: "width × height texels, rows in order (row 0 first), texels in a row left \
                     to right; each texel four little-endian IEEE half floats (r, g, b, a); no \
                     header, no padding"
                .into(),
            u: u.into(),
            v: v.into(),
            channels: channels.into(),
            sha256: Some(crate::compile::digest::sha256_hex(&bake(t))),
            mip_chain: None,
        }),
    }
}
