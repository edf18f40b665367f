//! The metadata's names (WebGPU enums in snake_case) → wgpu values.

use weft_meta::{
    AddressMode, BlendComponent, BlendFactor, BlendOperation, BlendState, ColorChannel, CullMode,
    DepthStencilState, DepthTest, FilterMode, FrontFace, SamplerBinding, SamplerBindingType, Stage,
    StencilFaceState, StencilOperation, TextureSampleType, TextureViewDimension,
};

/// A texture format name (`rgba8unorm_srgb`, `rg16float`, `depth32float`, …).
pub fn texture_format(name: &str) -> Result<wgpu::TextureFormat, String> {
    use wgpu::TextureFormat as F;
    Ok(match name {
        "r8unorm" => F::R8Unorm,
        "rg8unorm" => F::Rg8Unorm,
        "rgba8unorm" => F::Rgba8Unorm,
        "rgba8unorm_srgb" => F::Rgba8UnormSrgb,
        "bgra8unorm" => F::Bgra8Unorm,
        "bgra8unorm_srgb" => F::Bgra8UnormSrgb,
        "r16float" => F::R16Float,
        "rg16float" => F::Rg16Float,
        "rgba16float" => F::Rgba16Float,
        "r32float" => F::R32Float,
        "rg32float" => F::Rg32Float,
        "rgba32float" => F::Rgba32Float,
        "depth32float" => F::Depth32Float,
        "depth24plus_stencil8" => F::Depth24PlusStencil8,
        "depth24plus" => F::Depth24Plus,
        "depth16unorm" => F::Depth16Unorm,
        other => return Err(format!("unknown texture format `{other}`")),
    })
}

/// A vertex format name (`float32x3`, …).
pub fn vertex_format(name: &str) -> Result<wgpu::VertexFormat, String> {
    use wgpu::VertexFormat as V;
    Ok(match name {
        "float32" => V::Float32,
        "float32x2" => V::Float32x2,
        "float32x3" => V::Float32x3,
        "float32x4" => V::Float32x4,
        other => return Err(format!("unsupported vertex format `{other}`")),
    })
}

pub fn stages(s: &[Stage]) -> wgpu::ShaderStages {
    s.iter().fold(wgpu::ShaderStages::NONE, |acc, st| {
        acc | match st {
            Stage::Vertex => wgpu::ShaderStages::VERTEX,
            Stage::Fragment => wgpu::ShaderStages::FRAGMENT,
            Stage::Compute => wgpu::ShaderStages::COMPUTE,
        }
    })
}

pub fn sample_type(t: TextureSampleType) -> wgpu::TextureSampleType {
    match t {
        TextureSampleType::Float => wgpu::TextureSampleType::Float { filterable: true },
        TextureSampleType::UnfilterableFloat => {
            wgpu::TextureSampleType::Float { filterable: false }
        }
        TextureSampleType::Depth => wgpu::TextureSampleType::Depth,
        TextureSampleType::Sint => wgpu::TextureSampleType::Sint,
        TextureSampleType::Uint => wgpu::TextureSampleType::Uint,
    }
}

pub fn view_dimension(d: TextureViewDimension) -> wgpu::TextureViewDimension {
    match d {
        TextureViewDimension::D1 => wgpu::TextureViewDimension::D1,
        TextureViewDimension::D2 => wgpu::TextureViewDimension::D2,
        TextureViewDimension::D2Array => wgpu::TextureViewDimension::D2Array,
        TextureViewDimension::Cube => wgpu::TextureViewDimension::Cube,
        TextureViewDimension::CubeArray => wgpu::TextureViewDimension::CubeArray,
        TextureViewDimension::D3 => wgpu::TextureViewDimension::D3,
    }
}

pub fn sampler_binding_type(t: SamplerBindingType) -> wgpu::SamplerBindingType {
    match t {
        SamplerBindingType::Filtering => wgpu::SamplerBindingType::Filtering,
        SamplerBindingType::NonFiltering => wgpu::SamplerBindingType::NonFiltering,
        SamplerBindingType::Comparison => wgpu::SamplerBindingType::Comparison,
    }
}

pub fn compare(t: DepthTest) -> wgpu::CompareFunction {
    match t {
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

fn stencil_op(o: StencilOperation) -> wgpu::StencilOperation {
    use wgpu::StencilOperation as W;
    match o {
        StencilOperation::Keep => W::Keep,
        StencilOperation::Zero => W::Zero,
        StencilOperation::Replace => W::Replace,
        StencilOperation::Invert => W::Invert,
        StencilOperation::IncrementClamp => W::IncrementClamp,
        StencilOperation::DecrementClamp => W::DecrementClamp,
        StencilOperation::IncrementWrap => W::IncrementWrap,
        StencilOperation::DecrementWrap => W::DecrementWrap,
    }
}

fn stencil_face(f: &StencilFaceState) -> wgpu::StencilFaceState {
    wgpu::StencilFaceState {
        compare: compare(f.compare),
        fail_op: stencil_op(f.fail_op),
        depth_fail_op: stencil_op(f.depth_fail_op),
        pass_op: stencil_op(f.pass_op),
    }
}

/// `passes[].depth_stencil` (the reference is set while drawing).
pub fn depth_stencil(d: &DepthStencilState) -> Result<wgpu::DepthStencilState, String> {
    Ok(wgpu::DepthStencilState {
        format: texture_format(&d.format)?,
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

fn address(a: AddressMode) -> wgpu::AddressMode {
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

fn mipmap_filter(f: FilterMode) -> wgpu::MipmapFilterMode {
    match f {
        FilterMode::Nearest => wgpu::MipmapFilterMode::Nearest,
        FilterMode::Linear => wgpu::MipmapFilterMode::Linear,
    }
}

/// The sampler a binding's `sampler` entry describes.
pub fn sampler_descriptor<'a>(label: &'a str, s: &SamplerBinding) -> wgpu::SamplerDescriptor<'a> {
    wgpu::SamplerDescriptor {
        label: Some(label),
        address_mode_u: address(s.address_mode_u),
        address_mode_v: address(s.address_mode_v),
        address_mode_w: address(s.address_mode_w),
        mag_filter: filter(s.mag_filter),
        min_filter: filter(s.min_filter),
        mipmap_filter: mipmap_filter(s.mipmap_filter),
        lod_min_clamp: s.lod_min_clamp,
        lod_max_clamp: s.lod_max_clamp,
        compare: s.compare.map(compare),
        anisotropy_clamp: s.anisotropy_clamp,
        border_color: None,
    }
}

pub fn front_face(f: FrontFace) -> wgpu::FrontFace {
    match f {
        FrontFace::Ccw => wgpu::FrontFace::Ccw,
        FrontFace::Cw => wgpu::FrontFace::Cw,
    }
}

pub fn cull(c: CullMode) -> Option<wgpu::Face> {
    match c {
        CullMode::None => None,
        CullMode::Front => Some(wgpu::Face::Front),
        CullMode::Back => Some(wgpu::Face::Back),
    }
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

pub fn blend(b: &BlendState) -> wgpu::BlendState {
    wgpu::BlendState {
        color: blend_component(&b.color),
        alpha: blend_component(&b.alpha),
    }
}

pub fn write_mask(channels: &[ColorChannel]) -> wgpu::ColorWrites {
    channels.iter().fold(wgpu::ColorWrites::empty(), |acc, c| {
        acc | match c {
            ColorChannel::Red => wgpu::ColorWrites::RED,
            ColorChannel::Green => wgpu::ColorWrites::GREEN,
            ColorChannel::Blue => wgpu::ColorWrites::BLUE,
            ColorChannel::Alpha => wgpu::ColorWrites::ALPHA,
        }
    })
}

/// Bytes per texel of the formats this engine uploads or reads back.
pub fn texel_size(f: wgpu::TextureFormat) -> Result<u32, String> {
    f.block_copy_size(None)
        .ok_or_else(|| format!("{f:?} has no single copy size"))
}
