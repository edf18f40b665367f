//! What one render draws into and how: the colour target's format, the
//! depth-stencil format every pass shares, the shader language drawn, the
//! background, and the options of a render (size, exposure, time).

/// Colour target format of a render.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ColorFormat {
    /// What engines use; the standard material clamps its output to the f16 maximum.
    #[default]
    Rgba16Float,
    /// Full f32, e.g. to find NaN/Inf a half-float target would hide.
    Rgba32Float,
}

impl ColorFormat {
    pub fn wgpu(self) -> wgpu::TextureFormat {
        match self {
            ColorFormat::Rgba16Float => wgpu::TextureFormat::Rgba16Float,
            ColorFormat::Rgba32Float => wgpu::TextureFormat::Rgba32Float,
        }
    }

    pub(crate) fn bytes_per_pixel(self) -> u32 {
        match self {
            ColorFormat::Rgba16Float => 8,
            ColorFormat::Rgba32Float => 16,
        }
    }
}

/// Which generated file a variant is drawn from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ShaderLanguage {
    /// `<id>.wgsl`; constant-mode keywords become pipeline constants.
    #[default]
    Wgsl,
    /// `<id><c>.spv` (the file whose baked constants match the current
    /// keyword values), read by naga's SPIR-V front end (wgpu's SPIR-V path)
    /// with the clip-space y flip of weft's Vulkan-native SPIR-V undone.
    SpirV,
}

/// What is behind the object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Background {
    /// The environment cube at this mip level (0 = sharp sky).
    Sky { mip: f32 },
    /// A flat linear colour.
    Color([f32; 4]),
}

/// Size, formats and background of one render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    pub width: u32,
    pub height: u32,
    pub format: ColorFormat,
    pub language: ShaderLanguage,
    pub background: Background,
    /// `weft_frame.params.y` (the runtime does not scale the image by it).
    pub exposure: f32,
    /// `weft_frame.params.z`, seconds.
    pub time: f32,
    /// Draw a half-precision variant's f32 files (`files`) even on a device
    /// with `shader-f16`, where its `f16_files` are drawn by default (the
    /// stability sweep compares the two).
    pub f32_fallback: bool,
    /// Bind the WGSL's `var<uniform>` blocks as read-only storage buffers
    /// (same WGSL layout, same arithmetic). The stability probe sets it:
    /// Mesa 22.3's lavapipe inlines uniform values that decide a branch
    /// into a freshly JIT-compiled shader at every pipeline or bind-group
    /// change and never frees it (about 0.75 MB a draw for `standard`), so
    /// a sweep of a million draws exhausted memory; storage buffers are
    /// never inlined. Ignored for SPIR-V.
    pub uniforms_as_storage: bool,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 256,
            height: 256,
            format: ColorFormat::Rgba16Float,
            language: ShaderLanguage::Wgsl,
            background: Background::Sky { mip: 0.0 },
            exposure: 1.0,
            time: 0.0,
            f32_fallback: false,
            uniforms_as_storage: false,
        }
    }
}

/// The depth-stencil attachment of every pass (`weft_meta::DEPTH_STENCIL_FORMAT`).
pub(crate) const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth24PlusStencil8;
