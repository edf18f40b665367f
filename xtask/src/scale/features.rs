//! The pool of keywords a synthetic material gets: each feature's
//! keyword, parameters and shading code, in [`FEATURES`].

use super::Rng;

/// A float literal valid in both TOML and WGSL (always with a decimal point).
pub(super) fn lit(x: f64) -> String {
    let s = format!("{x}");
    if s.contains('.') || s.contains('e') {
        s
    } else {
        format!("{s}.0")
    }
}

fn colour(rng: &mut Rng, lo: f64, hi: f64) -> String {
    format!(
        "[{}, {}, {}, 1.0]",
        lit(rng.range(lo, hi)),
        lit(rng.range(lo, hi)),
        lit(rng.range(lo, hi))
    )
}

/// One synthetic keyword: its declaration, parameters and shading code.
pub struct Feature {
    /// Enum values; empty for a toggle.
    pub values: &'static [&'static str],
    /// `[params.*]` and `[keywords.*]` tables (TOML), given the material's rng.
    pub(super) toml: fn(&mut Rng) -> String,
    /// Statements for the wrapper entry point, given the material's rng. In
    /// scope: `c` (var vec4, the shipped entry point's result), `vin`
    /// (WeftVaryings), `n`, `v`, `n_dot_v`, `l`.
    pub(super) wgsl: fn(&mut Rng) -> String,
}

impl Feature {
    pub fn value_count(&self) -> usize {
        if self.values.is_empty() {
            2
        } else {
            self.values.len()
        }
    }
}

/// A `[params.<name>]` table; `labels` is the English and Chinese label.
fn param(
    name: &str,
    kind: &str,
    default: &str,
    extra: &str,
    (label, zh): (&str, &str),
    order: u32,
    show_if: &str,
) -> String {
    format!(
        "[params.{name}]\ntype = \"{kind}\"\ndefault = {default}\n{extra}label = \"{label}\"\nlabel_zh = \"{zh}\"\ngroup = \"synthetic\"\norder = {order}\nshow_if = \"{show_if}\"\n\n"
    )
}

fn toggle(name: &str, label: &str, zh: &str, tooltip: &str) -> String {
    format!(
        "[keywords.{name}]\ntype = \"toggle\"\ndefault = false\nlabel = \"{label}\"\nlabel_zh = \"{zh}\"\ntooltip = \"{tooltip}\"\ngroup = \"synthetic\"\n\n"
    )
}

fn enumeration(name: &str, values: &[&str], label: &str, zh: &str, tooltip: &str) -> String {
    let list = values
        .iter()
        .map(|v| format!("\"{v}\""))
        .collect::<Vec<_>>()
        .join(", ");
    format!(
        "[keywords.{name}]\ntype = \"enum\"\nvalues = [{list}]\ndefault = \"{}\"\nlabel = \"{label}\"\nlabel_zh = \"{zh}\"\ntooltip = \"{tooltip}\"\ngroup = \"synthetic\"\n\n",
        values[0]
    )
}

/// The pool of synthetic keywords: toggles first, then three-value enums.
pub const FEATURES: &[Feature] = &[
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_RIM",
                "Rim light",
                "边缘光",
                "Adds a Fresnel-like rim lit by the main light.",
            ) + &param(
                "syn_rim_color",
                "color",
                &colour(r, 0.5, 1.0),
                "",
                ("Rim colour", "边缘光颜色"),
                100,
                "SYN_RIM",
            ) + &param(
                "syn_rim_power",
                "float",
                &lit(r.range(1.5, 6.0)),
                "range = [0.5, 8.0]\nstep = 0.01\n",
                ("Rim power", "边缘光指数"),
                101,
                "SYN_RIM",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_RIM {{
        let rim = pow(1.0 - n_dot_v, max(material.syn_rim_power, 0.5)) * {};
        let lit_side = saturate(dot(n, l) * 0.5 + 0.5);
        c = vec4<f32>(c.rgb + rim * lit_side * material.syn_rim_color.rgb * weft_main_light_radiance() * c.a, c.a);
    }}
",
                lit(r.range(0.6, 1.0))
            )
        },
    },
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_FOG",
                "Distance fog",
                "距离雾",
                "Blends towards the fog colour with distance from the camera.",
            ) + &param(
                "syn_fog_color",
                "color",
                &colour(r, 0.4, 0.9),
                "",
                ("Fog colour", "雾颜色"),
                110,
                "SYN_FOG",
            ) + &param(
                "syn_fog_density",
                "float",
                &lit(r.range(0.01, 0.2)),
                "range = [0.0, 1.0]\nstep = 0.001\n",
                ("Fog density", "雾密度"),
                111,
                "SYN_FOG",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_FOG {{
        let d = length(weft_frame.camera_position.xyz - vin.world_position);
        let f = saturate(1.0 - exp(-max(material.syn_fog_density, 0.0) * d * {}));
        c = vec4<f32>(mix(c.rgb, material.syn_fog_color.rgb * c.a, f), c.a);
    }}
",
                lit(r.range(0.8, 1.2))
            )
        },
    },
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_DETAIL",
                "Detail map",
                "细节贴图",
                "Modulates the colour with a tiled grey detail texture (0.5 is neutral).",
            ) + &param(
                "syn_detail_map",
                "texture2d",
                "\"gray\"",
                "tiling = true\n",
                ("Detail map", "细节贴图"),
                120,
                "SYN_DETAIL",
            ) + &param(
                "syn_detail_strength",
                "float",
                &lit(r.range(0.2, 0.8)),
                "range = [0.0, 1.0]\nstep = 0.01\n",
                ("Detail strength", "细节强度"),
                121,
                "SYN_DETAIL",
            )
        },
        wgsl: |_| {
            "    if SYN_DETAIL {
        let duv = weft_transform_uv(vin.uv0, material.syn_detail_map_st);
        let detail = textureSample(syn_detail_map, material_sampler, duv).rgb;
        let k = mix(vec3<f32>(1.0), 2.0 * detail, saturate(material.syn_detail_strength));
        c = vec4<f32>(c.rgb * k, c.a);
    }
"
            .into()
        },
    },
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_GLINT",
                "Glints",
                "闪点",
                "Sparse sparkles: a hashed cell grid over uv0, lit along the mirror direction.",
            ) + &param(
                "syn_glint_density",
                "float",
                &lit(r.range(64.0, 512.0)),
                "range = [1.0, 2048.0]\nstep = 1.0\n",
                ("Glint density", "闪点密度"),
                130,
                "SYN_GLINT",
            ) + &param(
                "syn_glint_amount",
                "float",
                &lit(r.range(0.02, 0.2)),
                "range = [0.0, 1.0]\nstep = 0.001\n",
                ("Glint amount", "闪点比例"),
                131,
                "SYN_GLINT",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_GLINT {{
        let cell = floor(vin.uv0 * max(material.syn_glint_density, 1.0));
        let h = fract(sin(dot(cell, vec2<f32>({}, {}))) * 43758.5453);
        let lobe = pow(saturate(dot(reflect(-l, n), v)), {});
        let glint = select(0.0, 1.0, h > 1.0 - saturate(material.syn_glint_amount)) * lobe;
        c = vec4<f32>(c.rgb + glint * weft_main_light_radiance() * c.a, c.a);
    }}
",
                lit(r.range(10.0, 15.0)),
                lit(r.range(70.0, 90.0)),
                lit(r.range(32.0, 128.0).round())
            )
        },
    },
    Feature {
        values: &["neutral", "warm", "cool"],
        toml: |r| {
            enumeration(
                "SYN_GRADE",
                &["neutral", "warm", "cool"],
                "Colour grade",
                "调色",
                "Tints the result warm or cool.",
            ) + &param(
                "syn_grade_strength",
                "float",
                &lit(r.range(0.3, 1.0)),
                "range = [0.0, 1.0]\nstep = 0.01\n",
                ("Grade strength", "调色强度"),
                140,
                "SYN_GRADE != neutral",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_GRADE == SYN_GRADE_WARM {{
        c = vec4<f32>(c.rgb * mix(vec3<f32>(1.0), vec3<f32>({}, 1.0, {}), saturate(material.syn_grade_strength)), c.a);
    }}
    if SYN_GRADE == SYN_GRADE_COOL {{
        c = vec4<f32>(c.rgb * mix(vec3<f32>(1.0), vec3<f32>({}, {}, {}), saturate(material.syn_grade_strength)), c.a);
    }}
",
                lit(r.range(1.04, 1.12)),
                lit(r.range(0.85, 0.95)),
                lit(r.range(0.88, 0.95)),
                lit(r.range(0.97, 1.0)),
                lit(r.range(1.04, 1.12))
            )
        },
    },
    Feature {
        values: &["off", "soft", "deep"],
        toml: |r| {
            enumeration(
                "SYN_WRAP",
                &["off", "soft", "deep"],
                "Wrap lighting",
                "包裹光照",
                "Adds light that wraps past the terminator (soft) or scatters through (deep).",
            ) + &param(
                "syn_wrap_color",
                "color",
                &colour(r, 0.3, 0.9),
                "",
                ("Wrap colour", "包裹光颜色"),
                150,
                "SYN_WRAP != off",
            ) + &param(
                "syn_wrap_amount",
                "float",
                &lit(r.range(0.2, 0.7)),
                "range = [0.0, 1.0]\nstep = 0.01\n",
                ("Wrap amount", "包裹量"),
                151,
                "SYN_WRAP != off",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_WRAP == SYN_WRAP_SOFT {{
        let w = saturate(material.syn_wrap_amount);
        let wrap = saturate((dot(n, l) + w) / ((1.0 + w) * (1.0 + w))) - saturate(dot(n, l));
        c = vec4<f32>(c.rgb + max(wrap, 0.0) * WEFT_INV_PI * material.syn_wrap_color.rgb * weft_main_light_radiance() * c.a, c.a);
    }}
    if SYN_WRAP == SYN_WRAP_DEEP {{
        let back = pow(saturate(dot(v, -l)), {}) * saturate(material.syn_wrap_amount);
        let sh = weft_sh_irradiance(-n);
        c = vec4<f32>(c.rgb + (back * weft_main_light_radiance() + {} * sh) * material.syn_wrap_color.rgb * c.a, c.a);
    }}
",
                lit(r.range(2.0, 8.0).round()),
                lit(r.range(0.05, 0.2))
            )
        },
    },
    Feature {
        values: &["linear", "shoulder", "clip"],
        toml: |r| {
            enumeration(
                "SYN_TONE",
                &["linear", "shoulder", "clip"],
                "Highlight roll-off",
                "高光压缩",
                "Compresses highlights with a smooth shoulder, or clips them.",
            ) + &param(
                "syn_tone_white",
                "float",
                &lit(r.range(2.0, 16.0)),
                "range = [0.5, 64.0]\nstep = 0.1\n",
                ("White point", "白点"),
                160,
                "SYN_TONE != linear",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_TONE == SYN_TONE_SHOULDER {{
        let w = max(material.syn_tone_white, 0.5);
        let x = c.rgb;
        c = vec4<f32>(x * (vec3<f32>(1.0) + x / (w * w)) / (vec3<f32>(1.0) + x * {}), c.a);
    }}
    if SYN_TONE == SYN_TONE_CLIP {{
        c = vec4<f32>(min(c.rgb, vec3<f32>(max(material.syn_tone_white, 0.5) * c.a)), c.a);
    }}
",
                lit(r.range(0.9, 1.1))
            )
        },
    },
];
