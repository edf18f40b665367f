//! The metadata's WebGPU-named pipeline state mapped onto Vulkan, one
//! function per enum. Unknown names are errors naming the value, never guesses.

use crate::error::{Error, Result};
use ash::vk;
use weft_meta::pipeline::{BlendFactor, BlendOperation, ColorChannel, FrontFace, StencilFaceState};
use weft_meta::{BindingKind, CullMode, DepthTest, Stage, StencilOperation};

/// The Vulkan format of a WebGPU vertex format name, with its size in bytes.
pub fn vertex_format(name: &str) -> Result<(vk::Format, u32)> {
    Ok(match name {
        "float32" => (vk::Format::R32_SFLOAT, 4),
        "float32x2" => (vk::Format::R32G32_SFLOAT, 8),
        "float32x3" => (vk::Format::R32G32B32_SFLOAT, 12),
        "float32x4" => (vk::Format::R32G32B32A32_SFLOAT, 16),
        "uint32" => (vk::Format::R32_UINT, 4),
        "uint32x2" => (vk::Format::R32G32_UINT, 8),
        "uint32x3" => (vk::Format::R32G32B32_UINT, 12),
        "uint32x4" => (vk::Format::R32G32B32A32_UINT, 16),
        "sint32" => (vk::Format::R32_SINT, 4),
        "unorm8x4" => (vk::Format::R8G8B8A8_UNORM, 4),
        "float16x2" => (vk::Format::R16G16_SFLOAT, 4),
        "float16x4" => (vk::Format::R16G16B16A16_SFLOAT, 8),
        other => return Err(unknown("vertex format", other)),
    })
}

/// The Vulkan format of a WebGPU colour target format name (snake_case, as the metadata writes it).
pub fn color_format(name: &str) -> Result<vk::Format> {
    Ok(match name {
        "rgba16float" => vk::Format::R16G16B16A16_SFLOAT,
        "rgba32float" => vk::Format::R32G32B32A32_SFLOAT,
        "rgba8unorm" => vk::Format::R8G8B8A8_UNORM,
        "rgba8unorm_srgb" => vk::Format::R8G8B8A8_SRGB,
        "bgra8unorm" => vk::Format::B8G8R8A8_UNORM,
        "bgra8unorm_srgb" => vk::Format::B8G8R8A8_SRGB,
        "rg16float" => vk::Format::R16G16_SFLOAT,
        "r16float" => vk::Format::R16_SFLOAT,
        "r32float" => vk::Format::R32_SFLOAT,
        "r8unorm" => vk::Format::R8_UNORM,
        "rgb10a2unorm" => vk::Format::A2B10G10R10_UNORM_PACK32,
        "rg11b10ufloat" => vk::Format::B10G11R11_UFLOAT_PACK32,
        other => return Err(unknown("colour target format", other)),
    })
}

/// The Vulkan format of the depth-stencil attachment. WebGPU's `depth24plus_stencil8` lets
/// the implementation pick the depth precision ("24 bits or more"); AMD has no
/// `D24_UNORM_S8_UINT`, so RADV (like Dawn and wgpu on AMD) uses `D32_SFLOAT_S8_UINT`.
pub fn depth_stencil_format(name: &str) -> Result<vk::Format> {
    Ok(match name {
        "depth24plus_stencil8" | "depth32float_stencil8" => vk::Format::D32_SFLOAT_S8_UINT,
        "depth24plus" | "depth32float" => vk::Format::D32_SFLOAT,
        "depth16unorm" => vk::Format::D16_UNORM,
        other => return Err(unknown("depth-stencil format", other)),
    })
}

/// Whether the depth-stencil format has a stencil aspect.
pub fn has_stencil(format: vk::Format) -> bool {
    format == vk::Format::D32_SFLOAT_S8_UINT
}

pub fn blend_factor(f: BlendFactor) -> vk::BlendFactor {
    match f {
        BlendFactor::Zero => vk::BlendFactor::ZERO,
        BlendFactor::One => vk::BlendFactor::ONE,
        // WebGPU `src`/`dst` apply per equation: the colour in rgb, the alpha in alpha,
        // which is what Vulkan's *_COLOR factors do in each equation.
        BlendFactor::Src => vk::BlendFactor::SRC_COLOR,
        BlendFactor::OneMinusSrc => vk::BlendFactor::ONE_MINUS_SRC_COLOR,
        BlendFactor::SrcAlpha => vk::BlendFactor::SRC_ALPHA,
        BlendFactor::OneMinusSrcAlpha => vk::BlendFactor::ONE_MINUS_SRC_ALPHA,
        BlendFactor::Dst => vk::BlendFactor::DST_COLOR,
        BlendFactor::OneMinusDst => vk::BlendFactor::ONE_MINUS_DST_COLOR,
        BlendFactor::DstAlpha => vk::BlendFactor::DST_ALPHA,
        BlendFactor::OneMinusDstAlpha => vk::BlendFactor::ONE_MINUS_DST_ALPHA,
    }
}

pub fn blend_op(op: BlendOperation) -> vk::BlendOp {
    match op {
        BlendOperation::Add => vk::BlendOp::ADD,
        BlendOperation::Subtract => vk::BlendOp::SUBTRACT,
        BlendOperation::ReverseSubtract => vk::BlendOp::REVERSE_SUBTRACT,
        BlendOperation::Min => vk::BlendOp::MIN,
        BlendOperation::Max => vk::BlendOp::MAX,
    }
}

pub fn write_mask(channels: &[ColorChannel]) -> vk::ColorComponentFlags {
    channels
        .iter()
        .fold(vk::ColorComponentFlags::empty(), |m, c| {
            m | match c {
                ColorChannel::Red => vk::ColorComponentFlags::R,
                ColorChannel::Green => vk::ColorComponentFlags::G,
                ColorChannel::Blue => vk::ColorComponentFlags::B,
                ColorChannel::Alpha => vk::ColorComponentFlags::A,
            }
        })
}

pub fn compare_op(t: DepthTest) -> vk::CompareOp {
    match t {
        DepthTest::Always => vk::CompareOp::ALWAYS,
        DepthTest::Never => vk::CompareOp::NEVER,
        DepthTest::Less => vk::CompareOp::LESS,
        DepthTest::LessEqual => vk::CompareOp::LESS_OR_EQUAL,
        DepthTest::Equal => vk::CompareOp::EQUAL,
        DepthTest::Greater => vk::CompareOp::GREATER,
        DepthTest::GreaterEqual => vk::CompareOp::GREATER_OR_EQUAL,
        DepthTest::NotEqual => vk::CompareOp::NOT_EQUAL,
    }
}

fn stencil_op(op: StencilOperation) -> vk::StencilOp {
    match op {
        StencilOperation::Keep => vk::StencilOp::KEEP,
        StencilOperation::Zero => vk::StencilOp::ZERO,
        StencilOperation::Replace => vk::StencilOp::REPLACE,
        StencilOperation::Invert => vk::StencilOp::INVERT,
        StencilOperation::IncrementClamp => vk::StencilOp::INCREMENT_AND_CLAMP,
        StencilOperation::DecrementClamp => vk::StencilOp::DECREMENT_AND_CLAMP,
        StencilOperation::IncrementWrap => vk::StencilOp::INCREMENT_AND_WRAP,
        StencilOperation::DecrementWrap => vk::StencilOp::DECREMENT_AND_WRAP,
    }
}

/// One face's stencil state; the reference is dynamic (set while drawing, as in WebGPU).
pub fn stencil_face(s: &StencilFaceState, read: u32, write: u32) -> vk::StencilOpState {
    vk::StencilOpState {
        fail_op: stencil_op(s.fail_op),
        pass_op: stencil_op(s.pass_op),
        depth_fail_op: stencil_op(s.depth_fail_op),
        compare_op: compare_op(s.compare),
        compare_mask: read,
        write_mask: write,
        reference: 0,
    }
}

pub fn cull_mode(c: CullMode) -> vk::CullModeFlags {
    match c {
        CullMode::None => vk::CullModeFlags::NONE,
        CullMode::Front => vk::CullModeFlags::FRONT,
        CullMode::Back => vk::CullModeFlags::BACK,
    }
}

/// WGSL's front face is Vulkan's as is: WebGPU implementations flip y with a negative
/// viewport height, which keeps the winding.
pub fn front_face(f: FrontFace) -> vk::FrontFace {
    match f {
        FrontFace::Ccw => vk::FrontFace::COUNTER_CLOCKWISE,
        FrontFace::Cw => vk::FrontFace::CLOCKWISE,
    }
}

pub fn stage_flags(stages: &[Stage]) -> vk::ShaderStageFlags {
    stages.iter().fold(vk::ShaderStageFlags::empty(), |m, s| {
        m | match s {
            Stage::Vertex => vk::ShaderStageFlags::VERTEX,
            Stage::Fragment => vk::ShaderStageFlags::FRAGMENT,
            Stage::Compute => vk::ShaderStageFlags::COMPUTE,
        }
    })
}

/// The descriptor type of a binding (dynamic buffers when the layout entry says so).
pub fn descriptor_type(kind: BindingKind, dynamic: bool) -> vk::DescriptorType {
    match (kind, dynamic) {
        (BindingKind::UniformBuffer, false) => vk::DescriptorType::UNIFORM_BUFFER,
        (BindingKind::UniformBuffer, true) => vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
        (BindingKind::StorageBuffer, false) => vk::DescriptorType::STORAGE_BUFFER,
        (BindingKind::StorageBuffer, true) => vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
        (BindingKind::Sampler | BindingKind::ComparisonSampler, _) => vk::DescriptorType::SAMPLER,
        (
            BindingKind::Texture2d
            | BindingKind::TextureCube
            | BindingKind::Texture2dArray
            | BindingKind::Texture3d
            | BindingKind::DepthTexture2d,
            _,
        ) => vk::DescriptorType::SAMPLED_IMAGE,
    }
}

fn unknown(what: &str, name: &str) -> Error {
    Error::Input(format!(
        "unknown {what} `{name}` in the metadata (weft-gpu-stats maps the names weft emits; \
         add this one to crates/weft-gpu-stats/src/state.rs)"
    ))
}
