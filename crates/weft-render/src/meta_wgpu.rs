//! The metadata's pipeline and binding descriptions (`weft_meta::pipeline`:
//! per pass `primitive`, `color_targets`, `depth`; per binding `buffer`,
//! `texture`, `sampler`) as wgpu types. Everything an outside engine would
//! read from the metadata is read from it here; nothing is looked up by
//! blend mode name or binding kind.

use crate::error::{Error, Result};
use crate::targets::{ColorFormat, DEPTH_FORMAT};
use std::num::NonZeroU64;
use weft_meta::{
    AddressMode, Binding, BlendComponent, BlendFactor, BlendOperation, BlendState,
    BufferBindingType, ColorChannel, CullMode, DepthTest, FilterMode, FrontFace, Pass,
    PrimitiveTopology, SamplerBinding, SamplerBindingType, Stage, StencilFaceState,
    StencilOperation, TextureSampleType, TextureViewDimension,
};

/// The depth-stencil format's name in the metadata (`depth_stencil.format`).
pub(crate) const DEPTH_FORMAT_NAME: &str = weft_meta::DEPTH_STENCIL_FORMAT;

pub(crate) fn compare(d: DepthTest) -> wgpu::CompareFunction {
    match d {
        DepthTest::Always => wgpu::CompareFunction::Always,
        DepthTest::Never => wgpu::CompareFunction::Never,
        DepthTest::Less => wgpu::CompareFunction::Less,
        DepthTest::LessEqual => wgpu::CompareFunction::LessEqual,
        DepthTest::Equal => wgpu::CompareFunction::Equal,
        DepthTest::Greater => wgpu::CompareFunction::Greater,
        DepthTest::GreaterEqual => wgpu::CompareFunction::GreaterEqual,
        DepthTest::NotEqual => wgpu::CompareFunction::NotEqual,
    }
}

fn stencil_operation(o: StencilOperation) -> wgpu::StencilOperation {
    match o {
        StencilOperation::Keep => wgpu::StencilOperation::Keep,
        StencilOperation::Zero => wgpu::StencilOperation::Zero,
        StencilOperation::Replace => wgpu::StencilOperation::Replace,
        StencilOperation::Invert => wgpu::StencilOperation::Invert,
        StencilOperation::IncrementClamp => wgpu::StencilOperation::IncrementClamp,
        StencilOperation::DecrementClamp => wgpu::StencilOperation::DecrementClamp,
        StencilOperation::IncrementWrap => wgpu::StencilOperation::IncrementWrap,
        StencilOperation::DecrementWrap => wgpu::StencilOperation::DecrementWrap,
    }
}

fn stencil_face(f: &StencilFaceState) -> wgpu::StencilFaceState {
    wgpu::StencilFaceState {
        compare: compare(f.compare),
        fail_op: stencil_operation(f.fail_op),
        depth_fail_op: stencil_operation(f.depth_fail_op),
        pass_op: stencil_operation(f.pass_op),
    }
}

/// `pass.primitive`.
pub(crate) fn primitive_state(pass: &Pass) -> wgpu::PrimitiveState {
    let p = &pass.primitive;
    wgpu::PrimitiveState {
        topology: match p.topology {
            PrimitiveTopology::TriangleList => wgpu::PrimitiveTopology::TriangleList,
        },
        front_face: match p.front_face {
            FrontFace::Ccw => wgpu::FrontFace::Ccw,
            FrontFace::Cw => wgpu::FrontFace::Cw,
        },
        cull_mode: match p.cull_mode {
            CullMode::None => None,
            CullMode::Front => Some(wgpu::Face::Front),
            CullMode::Back => Some(wgpu::Face::Back),
        },
        ..Default::default()
    }
}

/// `pass.depth_stencil`, for the renderer's depth-stencil attachment (the
/// stencil reference is set per draw, `DrawCall::stencil_reference`).
pub(crate) fn depth_stencil_state(pass: &Pass) -> Result<wgpu::DepthStencilState> {
    let d = &pass.depth_stencil;
    if d.format != DEPTH_FORMAT_NAME {
        return Err(Error::Metadata(format!(
            "pass `{}` asks for a `{}` depth attachment; weft-render draws into \
             `{DEPTH_FORMAT_NAME}`",
            pass.name, d.format
        )));
    }
    Ok(wgpu::DepthStencilState {
        format: DEPTH_FORMAT,
        depth_write_enabled: Some(d.depth_write_enabled),
        depth_compare: Some(compare(d.depth_compare)),
        stencil: wgpu::StencilState {
            front: stencil_face(&d.stencil_front),
            back: stencil_face(&d.stencil_back),
            read_mask: d.stencil_read_mask,
            write_mask: d.stencil_write_mask,
        },
        bias: Default::default(),
    })
}

fn blend_factor(f: BlendFactor) -> wgpu::BlendFactor {
    match f {
        BlendFactor::Zero => wgpu::BlendFactor::Zero,
        BlendFactor::One => wgpu::BlendFactor::One,
        BlendFactor::Src => wgpu::BlendFactor::Src,
        BlendFactor::OneMinusSrc => wgpu::BlendFactor::OneMinusSrc,
        BlendFactor::SrcAlpha => wgpu::BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha => wgpu::BlendFactor::OneMinusSrcAlpha,
        BlendFactor::Dst => wgpu::BlendFactor::Dst,
        BlendFactor::OneMinusDst => wgpu::BlendFactor::OneMinusDst,
        BlendFactor::DstAlpha => wgpu::BlendFactor::DstAlpha,
        BlendFactor::OneMinusDstAlpha => wgpu::BlendFactor::OneMinusDstAlpha,
    }
}

fn blend_component(c: &BlendComponent) -> wgpu::BlendComponent {
    wgpu::BlendComponent {
        src_factor: blend_factor(c.src_factor),
        dst_factor: blend_factor(c.dst_factor),
        operation: match c.operation {
            BlendOperation::Add => wgpu::BlendOperation::Add,
            BlendOperation::Subtract => wgpu::BlendOperation::Subtract,
            BlendOperation::ReverseSubtract => wgpu::BlendOperation::ReverseSubtract,
            BlendOperation::Min => wgpu::BlendOperation::Min,
            BlendOperation::Max => wgpu::BlendOperation::Max,
        },
    }
}

fn blend_state(b: &BlendState) -> wgpu::BlendState {
    wgpu::BlendState {
        color: blend_component(&b.color),
        alpha: blend_component(&b.alpha),
    }
}

/// Whether a WebGPU texture format name (`rgba16float`, `rg11b10ufloat`)
/// stores floating-point values.
fn is_float_format(name: &str) -> bool {
    name.ends_with("float")
}

/// `pass.color_targets`: weft-render draws one colour target, in `format`
/// (a float format, like the `rgba16float` of the metadata, or the
/// `rgba32float` of the stability sweep).
pub(crate) fn color_target_state(
    pass: &Pass,
    format: ColorFormat,
) -> Result<wgpu::ColorTargetState> {
    let [target] = pass.color_targets.as_slice() else {
        return Err(Error::Metadata(format!(
            "pass `{}` has {} colour targets; weft-render draws exactly one",
            pass.name,
            pass.color_targets.len()
        )));
    };
    if target.location != 0 {
        return Err(Error::Metadata(format!(
            "pass `{}` writes its colour target at location {}; weft-render binds location 0",
            pass.name, target.location
        )));
    }
    if !is_float_format(&target.format) {
        return Err(Error::Metadata(format!(
            "pass `{}` outputs to a `{}` colour target; weft-render renders into float \
             targets only ({:?} asked for), which a non-float format does not match",
            pass.name, target.format, format
        )));
    }
    let mut write_mask = wgpu::ColorWrites::empty();
    for c in &target.write_mask {
        write_mask |= match c {
            ColorChannel::Red => wgpu::ColorWrites::RED,
            ColorChannel::Green => wgpu::ColorWrites::GREEN,
            ColorChannel::Blue => wgpu::ColorWrites::BLUE,
            ColorChannel::Alpha => wgpu::ColorWrites::ALPHA,
        };
    }
    Ok(wgpu::ColorTargetState {
        format: format.wgpu(),
        blend: target.blend.as_ref().map(blend_state),
        write_mask,
    })
}

pub(crate) fn stages(s: &[Stage]) -> wgpu::ShaderStages {
    let mut out = wgpu::ShaderStages::NONE;
    for st in s {
        out |= match st {
            Stage::Vertex => wgpu::ShaderStages::VERTEX,
            Stage::Fragment => wgpu::ShaderStages::FRAGMENT,
            Stage::Compute => wgpu::ShaderStages::COMPUTE,
        };
    }
    out
}

fn view_dimension(d: TextureViewDimension) -> wgpu::TextureViewDimension {
    match d {
        TextureViewDimension::D1 => wgpu::TextureViewDimension::D1,
        TextureViewDimension::D2 => wgpu::TextureViewDimension::D2,
        TextureViewDimension::D2Array => wgpu::TextureViewDimension::D2Array,
        TextureViewDimension::Cube => wgpu::TextureViewDimension::Cube,
        TextureViewDimension::CubeArray => wgpu::TextureViewDimension::CubeArray,
        TextureViewDimension::D3 => wgpu::TextureViewDimension::D3,
    }
}

/// The view dimension a texture binding's metadata asks for.
pub(crate) fn texture_view_dimension(b: &Binding) -> Result<wgpu::TextureViewDimension> {
    let t = b.texture.as_ref().ok_or_else(|| missing(b, "texture"))?;
    Ok(view_dimension(t.view_dimension))
}

fn missing(b: &Binding, field: &str) -> Error {
    Error::Metadata(format!(
        "binding `{}` (group {}, binding {}, {:?}) has no `{field}` entry (metadata schema {} \
         states every binding's layout entry)",
        b.name,
        b.group,
        b.binding,
        b.kind,
        weft_meta::SCHEMA_VERSION
    ))
}

/// A bind group layout entry from the binding's `buffer`, `texture` or
/// `sampler` description (exactly one of them).
pub(crate) fn binding_layout_entry(b: &Binding) -> Result<wgpu::BindGroupLayoutEntry> {
    let ty = match (&b.buffer, &b.texture, &b.sampler) {
        (Some(buf), None, None) => wgpu::BindingType::Buffer {
            ty: match buf.ty {
                BufferBindingType::Uniform => wgpu::BufferBindingType::Uniform,
                BufferBindingType::ReadOnlyStorage => {
                    wgpu::BufferBindingType::Storage { read_only: true }
                }
                BufferBindingType::Storage => wgpu::BufferBindingType::Storage { read_only: false },
            },
            has_dynamic_offset: buf.has_dynamic_offset,
            min_binding_size: NonZeroU64::new(buf.min_binding_size),
        },
        (None, Some(tex), None) => wgpu::BindingType::Texture {
            sample_type: match tex.sample_type {
                TextureSampleType::Float => wgpu::TextureSampleType::Float { filterable: true },
                TextureSampleType::UnfilterableFloat => {
                    wgpu::TextureSampleType::Float { filterable: false }
                }
                TextureSampleType::Depth => wgpu::TextureSampleType::Depth,
                TextureSampleType::Sint => wgpu::TextureSampleType::Sint,
                TextureSampleType::Uint => wgpu::TextureSampleType::Uint,
            },
            view_dimension: view_dimension(tex.view_dimension),
            multisampled: tex.multisampled,
        },
        (None, None, Some(s)) => wgpu::BindingType::Sampler(match s.binding_type {
            SamplerBindingType::Filtering => wgpu::SamplerBindingType::Filtering,
            SamplerBindingType::NonFiltering => wgpu::SamplerBindingType::NonFiltering,
            SamplerBindingType::Comparison => wgpu::SamplerBindingType::Comparison,
        }),
        (None, None, None) => return Err(missing(b, "buffer`, `texture` or `sampler")),
        _ => {
            return Err(Error::Metadata(format!(
                "binding `{}` (group {}, binding {}) describes more than one of `buffer`, \
                 `texture` and `sampler`",
                b.name, b.group, b.binding
            )));
        }
    };
    Ok(wgpu::BindGroupLayoutEntry {
        binding: b.binding,
        visibility: stages(&b.stages),
        ty,
        count: None,
    })
}

fn address_mode(a: AddressMode) -> wgpu::AddressMode {
    match a {
        AddressMode::ClampToEdge => wgpu::AddressMode::ClampToEdge,
        AddressMode::Repeat => wgpu::AddressMode::Repeat,
        AddressMode::MirrorRepeat => wgpu::AddressMode::MirrorRepeat,
    }
}

fn filter(f: FilterMode) -> wgpu::FilterMode {
    match f {
        FilterMode::Nearest => wgpu::FilterMode::Nearest,
        FilterMode::Linear => wgpu::FilterMode::Linear,
    }
}

/// The sampler a binding's `sampler` entry describes.
pub(crate) fn sampler_descriptor<'a>(
    label: &'a str,
    s: &SamplerBinding,
) -> wgpu::SamplerDescriptor<'a> {
    wgpu::SamplerDescriptor {
        label: Some(label),
        address_mode_u: address_mode(s.address_mode_u),
        address_mode_v: address_mode(s.address_mode_v),
        address_mode_w: address_mode(s.address_mode_w),
        mag_filter: filter(s.mag_filter),
        min_filter: filter(s.min_filter),
        mipmap_filter: match s.mipmap_filter {
            FilterMode::Nearest => wgpu::MipmapFilterMode::Nearest,
            FilterMode::Linear => wgpu::MipmapFilterMode::Linear,
        },
        lod_min_clamp: s.lod_min_clamp,
        lod_max_clamp: s.lod_max_clamp,
        compare: s.compare.map(compare),
        anisotropy_clamp: s.anisotropy_clamp.max(1),
        border_color: None,
    }
}

/// A cache key for a sampler description (its f32 fields by bits).
pub(crate) fn sampler_key(s: &SamplerBinding) -> String {
    format!(
        "{:?}|{:?}|{:?}|{:?}|{:?}|{:?}|{:?}|{:x}|{:x}|{}|{:?}",
        s.binding_type,
        s.mag_filter,
        s.min_filter,
        s.mipmap_filter,
        s.address_mode_u,
        s.address_mode_v,
        s.address_mode_w,
        s.lod_min_clamp.to_bits(),
        s.lod_max_clamp.to_bits(),
        s.anisotropy_clamp,
        s.compare
    )
}

/// Texture formats of the data weft describes: a binding's `texture.format`
/// and a LUT's `file.format`.
pub(crate) fn texture_format(name: &str) -> Option<wgpu::TextureFormat> {
    Some(match name {
        "rgba8unorm" => wgpu::TextureFormat::Rgba8Unorm,
        "rgba8unorm_srgb" => wgpu::TextureFormat::Rgba8UnormSrgb,
        "rgba16float" => wgpu::TextureFormat::Rgba16Float,
        "rgba32float" => wgpu::TextureFormat::Rgba32Float,
        "rg16float" => wgpu::TextureFormat::Rg16Float,
        "r16float" => wgpu::TextureFormat::R16Float,
        "r32float" => wgpu::TextureFormat::R32Float,
        "rg32float" => wgpu::TextureFormat::Rg32Float,
        _ => return None,
    })
}
