//! The material-level half of the inspector metadata (parameters, keywords,
//! tiers, presets, passes). The per-variant half comes from `reflect.rs`.

use crate::compile::prelude::{self, Prelude};
use serde_json::{Value, json};
use std::collections::BTreeMap;
use weft_front::model::{Instances, Material, ParamValue, PresetValue};
use weft_front::samples;
use weft_meta::*;

fn text(en: &str, zh: &Option<String>) -> Text {
    Text {
        en: en.to_string(),
        zh: zh.clone(),
    }
}

fn opt_text(en: &Option<String>, zh: &Option<String>) -> Option<Text> {
    match (en, zh) {
        (None, None) => None,
        _ => Some(Text {
            en: en.clone().unwrap_or_default(),
            zh: zh.clone(),
        }),
    }
}

/// A parameter value as JSON (numbers stay numbers, textures become names).
pub fn value_json(v: &ParamValue) -> Value {
    match v {
        ParamValue::Float(x) => json!(x),
        ParamValue::Int(i) => json!(i),
        ParamValue::Bool(b) => json!(b),
        ParamValue::Vector(xs) => json!(xs),
        ParamValue::Texture(t) => json!(t.name()),
        ParamValue::Curve(keys) => serde_json::to_value(keys).unwrap_or(Value::Null),
        ParamValue::Gradient(stops) => serde_json::to_value(stops).unwrap_or(Value::Null),
    }
}

pub fn parameters(m: &Material, prelude: &Prelude) -> Vec<Parameter> {
    let members = prelude::uniform_members(m);
    m.params
        .iter()
        .map(|p| {
            let binding = prelude
                .texture_bindings
                .iter()
                .find(|(n, _)| *n == p.name)
                .map(|(_, b)| *b);
            let uniform_member = members
                .iter()
                .find(|mem| mem.name == p.name)
                .map(|mem| mem.name.clone());
            let color = (p.kind == ParamKind::Color).then(|| {
                let d = match &p.default {
                    ParamValue::Vector(v) => v.clone(),
                    _ => vec![1.0; 4],
                };
                ColorInfo {
                    hdr: p.hdr,
                    linear_default: weft_meta::uniform::color_as_uploaded(&d, p.hdr),
                }
            });
            let texture = match (&p.kind, &p.default) {
                (ParamKind::Texture2d | ParamKind::Cube, ParamValue::Texture(t)) => {
                    Some(TextureInfo {
                        default: *t,
                        default_when: p
                            .default_when
                            .iter()
                            .map(|(condition, default)| ConditionalTextureDefault {
                                condition: condition.clone(),
                                default: *default,
                            })
                            .collect(),
                        srgb: p.srgb,
                        file: crate::compile::texture_files::resource_file(m, p),
                        tiling_member: p.tiling.then(|| format!("{}_st", p.name)),
                        tiling_default: p.tiling.then_some([1.0, 1.0, 0.0, 0.0]),
                    })
                }
                _ => None,
            };
            let curve = match &p.default {
                ParamValue::Curve(keys) => Some(CurveInfo {
                    keyframes: keys.clone(),
                    samples: p.samples,
                    baked_default: samples::sample_curve(keys, p.samples),
                    time_range: samples::curve_time_range(keys),
                    encoding: CurveEncoding::F32x4PackedV1,
                }),
                _ => None,
            };
            let gradient = match &p.default {
                ParamValue::Gradient(stops) => Some(GradientInfo {
                    stops: stops.clone(),
                    width: p.samples,
                    encoding: GradientEncoding::Rgba8SrgbRampV1,
                    baked_default: samples::bake_gradient(stops, p.samples),
                }),
                _ => None,
            };
            Parameter {
                name: p.name.clone(),
                kind: p.kind,
                label: text(&p.label, &p.label_zh),
                tooltip: opt_text(&p.tooltip, &p.tooltip_zh),
                group: p.group.clone(),
                order: p.order,
                default: value_json(&p.default),
                range: p.range,
                soft_range: p.soft_range,
                step: p.step,
                power: p.power,
                show_if: p.show_if.clone(),
                color,
                texture,
                curve,
                gradient,
                uniform_member,
                binding,
            }
        })
        .collect()
}

pub fn keywords(m: &Material) -> Vec<Keyword> {
    m.keywords
        .iter()
        .map(|k| Keyword {
            name: k.name.clone(),
            kind: k.kind,
            mode: k.mode,
            values: k.values.clone(),
            default: k.values[k.default].clone(),
            label: text(&k.label, &k.label_zh),
            tooltip: opt_text(&k.tooltip, &k.tooltip_zh),
            group: k.group.clone(),
            show_if: k.show_if.clone(),
        })
        .collect()
}

pub fn tiers(m: &Material) -> Tiers {
    Tiers {
        values: m.tiers.values.clone(),
        default: m.tiers.values[m.tiers.default].clone(),
        reference: m.tiers.values[m.tiers.reference].clone(),
        approximates: m
            .tiers
            .approximates
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.map(|j| (m.tiers.values[i].clone(), m.tiers.values[j].clone())))
            .collect(),
        looks: m
            .tiers
            .values
            .iter()
            .zip(&m.tiers.looks)
            .filter(|(_, look)| **look)
            .map(|(t, _)| t.clone())
            .collect(),
        descriptions: m
            .tiers
            .descriptions
            .iter()
            .map(|(t, en, zh)| {
                (
                    t.clone(),
                    Text {
                        en: en.clone(),
                        zh: zh.clone(),
                    },
                )
            })
            .collect(),
        stylised: m.stylised,
    }
}

pub fn presets(m: &Material) -> Vec<Preset> {
    m.presets
        .iter()
        .map(|p| Preset {
            name: p.name.clone(),
            label: text(&p.label, &p.label_zh),
            values: p
                .values
                .iter()
                .map(|(k, v)| {
                    let j = match v {
                        // Presets read numbers as floats; int parameters show as ints.
                        PresetValue::Param(ParamValue::Float(x))
                            if m.param(k).is_some_and(|p| p.kind == ParamKind::Int) =>
                        {
                            json!(*x as i64)
                        }
                        PresetValue::Param(pv) => value_json(pv),
                        PresetValue::Keyword(s) => json!(s),
                    };
                    (k.clone(), j)
                })
                .collect::<BTreeMap<_, _>>(),
        })
        .collect()
}

pub fn passes(m: &Material) -> Vec<Pass> {
    m.passes.iter().map(pass).collect()
}

/// One pass of a material as the metadata states it.
pub fn pass(p: &weft_front::model::Pass) -> Pass {
    {
        Pass {
            name: p.name.clone(),
            vertex_entry: p.vertex.clone(),
            fragment_entry: p.fragment.clone(),
            render_state: RenderState {
                blend: p.blend,
                cull: p.cull,
                depth_write: p.depth_write,
                depth_test: p.depth_test,
                queue: p.queue,
                stencil: p.stencil,
            },
            instances: match &p.instances {
                Instances::Fixed(n) => InstanceCount::Fixed(*n),
                Instances::Param(s) => InstanceCount::Parameter(s.clone()),
            },
            when: p.when.clone(),
            primitive: PrimitiveState {
                topology: PrimitiveTopology::TriangleList,
                front_face: FrontFace::Ccw,
                cull_mode: p.cull,
            },
            color_targets: vec![ColorTarget {
                location: 0,
                format: COLOR_TARGET_FORMAT.into(),
                output: match p.blend {
                    BlendMode::Premultiplied => ColorOutput::PremultipliedLinearRadiance,
                    _ => ColorOutput::LinearRadiance,
                },
                exposure_applied: false,
                tone_mapped: false,
                blend: blend_state(p.blend),
                write_mask: vec![
                    ColorChannel::Red,
                    ColorChannel::Green,
                    ColorChannel::Blue,
                    ColorChannel::Alpha,
                ],
            }],
            depth_stencil: depth_stencil_state(p),
        }
    }
}

/// The attachment state of a pass: its depth test and write, and its
/// `stencil` (the same for both faces), or a stencil that always passes and
/// writes nothing.
fn depth_stencil_state(p: &weft_front::model::Pass) -> DepthStencilState {
    let face = |s: Option<&StencilRenderState>| StencilFaceState {
        compare: s.map_or(DepthTest::Always, |s| s.compare),
        fail_op: s.map_or(StencilOperation::Keep, |s| s.fail_op),
        depth_fail_op: s.map_or(StencilOperation::Keep, |s| s.depth_fail_op),
        pass_op: s.map_or(StencilOperation::Keep, |s| s.pass_op),
    };
    let s = p.stencil.as_ref();
    DepthStencilState {
        format: DEPTH_STENCIL_FORMAT.into(),
        depth_write_enabled: p.depth_write,
        depth_compare: p.depth_test,
        depth_clear_value: 1.0,
        stencil_front: face(s),
        stencil_back: face(s),
        stencil_read_mask: s.map_or(0xff, |s| s.read_mask),
        stencil_write_mask: s.map_or(0, |s| s.write_mask),
        stencil_reference: s.map_or(0, |s| s.reference),
        stencil_clear_value: 0,
    }
}

/// The colour target format of the goldens and `weft-render`.
pub const COLOR_TARGET_FORMAT: &str = "rgba16float";

/// Each blend mode's colour and alpha equations. Alpha accumulates coverage
/// the same way in `alpha` and `premultiplied` ("over"), and `additive` and
/// `multiply` leave the target's alpha as it was.
pub fn blend_state(mode: BlendMode) -> Option<BlendState> {
    use BlendFactor::*;
    let c = |src_factor, dst_factor| BlendComponent {
        src_factor,
        dst_factor,
        operation: BlendOperation::Add,
    };
    let over_alpha = c(One, OneMinusSrcAlpha);
    let keep_alpha = c(Zero, One);
    match mode {
        BlendMode::Opaque => None,
        BlendMode::Alpha => Some(BlendState {
            color: c(SrcAlpha, OneMinusSrcAlpha),
            alpha: over_alpha,
        }),
        BlendMode::Premultiplied => Some(BlendState {
            color: c(One, OneMinusSrcAlpha),
            alpha: over_alpha,
        }),
        BlendMode::Additive => Some(BlendState {
            color: c(SrcAlpha, One),
            alpha: keep_alpha,
        }),
        BlendMode::Multiply => Some(BlendState {
            color: c(Dst, Zero),
            alpha: keep_alpha,
        }),
    }
}

pub fn groups(m: &Material) -> Vec<Group> {
    m.groups
        .iter()
        .map(|g| Group {
            name: g.name.clone(),
            label: text(&g.label, &g.label_zh),
        })
        .collect()
}

pub fn vertex_inputs(m: &Material) -> Vec<VertexInput> {
    m.requires
        .iter()
        .map(|a| VertexInput {
            name: a.name().into(),
            location: a.location(),
            format: a.format().into(),
        })
        .collect()
}
