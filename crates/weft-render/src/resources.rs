//! GPU resources a draw binds: the environment, material textures, uniform
//! buffers and mesh buffers (`bindings.rs` ties them to a shader's
//! reflected bindings).

use crate::environment::EnvironmentMaps;
use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::math::{self, Mat4};
use crate::meta_wgpu::texture_view_dimension;
use crate::pipelines::vertex_format;
use crate::scene::Mesh;
use crate::values::TextureValue;
use std::borrow::Cow;
use std::collections::BTreeMap;
use weft_meta::{Binding, BindingKind, TextureDefault, VariantShader, VertexInput};
use wgpu::util::DeviceExt;

/// Group 0's environment: the prefiltered cube, its mip count and the SH
/// irradiance written into `weft_frame`.
#[derive(Clone)]
pub(crate) struct GpuEnvironment {
    pub view: wgpu::TextureView,
    pub mip_count: u32,
    pub sh: [[f32; 3]; 9],
}

pub(crate) fn upload_environment(gpu: &Gpu, env: &EnvironmentMaps) -> GpuEnvironment {
    let size = env.mips[0].size;
    let mip_count = env.mip_count();
    // Layer-major: face 0 mips 0..n, face 1 mips 0..n, ...
    let mut data: Vec<u8> = Vec::new();
    for face in 0..6u32 {
        for level in &env.mips {
            let n = (level.size * level.size) as usize;
            let start = face as usize * n;
            for t in &level.data[start..start + n] {
                for c in [t[0], t[1], t[2], 1.0] {
                    data.extend_from_slice(&half::f16::from_f32(c).to_le_bytes());
                }
            }
        }
    }
    let texture = cube_f16_texture(gpu, "weft_environment", size, mip_count, &data);
    GpuEnvironment {
        view: cube_view(&texture),
        mip_count,
        sh: env.sh,
    }
}

/// A 1x1 black cube: the environment of an engine without one.
pub(crate) fn black_environment(gpu: &Gpu) -> GpuEnvironment {
    let texel: Vec<u8> = [0.0f32, 0.0, 0.0, 1.0]
        .iter()
        .flat_map(|c| half::f16::from_f32(*c).to_le_bytes())
        .collect();
    let data = texel.repeat(6);
    let texture = cube_f16_texture(gpu, "weft_environment (black)", 1, 1, &data);
    GpuEnvironment {
        view: cube_view(&texture),
        mip_count: 1,
        sh: [[0.0; 3]; 9],
    }
}

fn cube_f16_texture(gpu: &Gpu, label: &str, size: u32, mips: u32, data: &[u8]) -> wgpu::Texture {
    gpu.device.create_texture_with_data(
        &gpu.queue,
        &wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width: size,
                height: size,
                depth_or_array_layers: 6,
            },
            mip_level_count: mips,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba16Float,
            // COPY_SRC: tests read back what was uploaded.
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        data,
    )
}

fn cube_view(texture: &wgpu::Texture) -> wgpu::TextureView {
    texture.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::Cube),
        ..Default::default()
    })
}

/// What a material texture binding samples, whichever path supplied it.
/// The binding's `texture.format` says how RGBA8 texels are read (an
/// `rgba8unorm_srgb` view for colour data).
pub(crate) enum TextureSource<'a> {
    /// A 2D texture parameter.
    Texture2d(Cow<'a, TextureValue>),
    /// A cube parameter.
    Cube(Cow<'a, TextureValue>),
    /// A gradient ramp: RGBA8 texels, `width` = len / 4, 1 row.
    Ramp(&'a [u8]),
}

/// Whether RGBA8 texels bound to `b` are sRGB-encoded, from the binding's
/// `texture.format`.
fn rgba8_is_srgb(b: &Binding) -> Result<bool> {
    let format = b.texture.as_ref().map(|t| t.format.as_str());
    match format {
        Some("rgba8unorm_srgb") => Ok(true),
        Some("rgba8unorm") => Ok(false),
        Some(other) => Err(Error::Metadata(format!(
            "texture binding `{}` has format `{other}`; weft-render binds material textures \
             as rgba8unorm or rgba8unorm_srgb",
            b.name
        ))),
        None => Err(Error::Metadata(format!(
            "texture binding `{}` (group {}, binding {}) has no `texture` entry",
            b.name, b.group, b.binding
        ))),
    }
}

/// Creates the views of a shader's group-1 textures, by binding number;
/// `source` says what each texture binding carries.
pub(crate) fn material_texture_views<'a>(
    gpu: &Gpu,
    shader: &VariantShader,
    mut source: impl FnMut(&Binding) -> Result<TextureSource<'a>>,
) -> Result<BTreeMap<u32, wgpu::TextureView>> {
    let mut views = BTreeMap::new();
    for b in &shader.bindings {
        if b.group != weft_meta::engine::MATERIAL_GROUP
            || b.resource.is_some()
            || !is_texture_binding(b)
        {
            continue;
        }
        let label = b.parameter.as_deref().unwrap_or(&b.name);
        let dim = texture_view_dimension(b)?;
        let srgb = rgba8_is_srgb(b)?;
        let texture = match (dim, source(b)?) {
            (wgpu::TextureViewDimension::D2, TextureSource::Texture2d(value)) => {
                texture_2d(gpu, label, &value, srgb)?
            }
            (wgpu::TextureViewDimension::D2, TextureSource::Ramp(rgba8)) => {
                if rgba8.is_empty() || !rgba8.len().is_multiple_of(4) {
                    return Err(Error::InvalidValue {
                        name: label.into(),
                        message: format!("a ramp of {} bytes is not RGBA8 texels", rgba8.len()),
                    });
                }
                rgba8_texture(gpu, label, (rgba8.len() / 4) as u32, 1, 1, rgba8, srgb)
            }
            (wgpu::TextureViewDimension::Cube, TextureSource::Cube(value)) => {
                cube_texture(gpu, label, &value, srgb)?
            }
            (dim, _) => {
                return Err(Error::Metadata(format!(
                    "binding `{}` ({dim:?}) cannot carry the texture given for `{label}`",
                    b.name
                )));
            }
        };
        views.insert(
            b.binding,
            texture.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(dim),
                ..Default::default()
            }),
        );
    }
    Ok(views)
}

/// A texture binding: described by a `texture` entry (or, in metadata
/// without one, by its kind; [`rgba8_is_srgb`] then reports it).
pub(crate) fn is_texture_binding(b: &Binding) -> bool {
    b.texture.is_some()
        || matches!(
            b.kind,
            BindingKind::Texture2d
                | BindingKind::TextureCube
                | BindingKind::Texture2dArray
                | BindingKind::Texture3d
                | BindingKind::DepthTexture2d
        )
}

fn rgba8_texture(
    gpu: &Gpu,
    label: &str,
    width: u32,
    height: u32,
    layers: u32,
    data: &[u8],
    srgb: bool,
) -> wgpu::Texture {
    rgba8_texture_levels(gpu, label, width, height, layers, 1, data, srgb)
}

/// A 2D texture parameter's RGBA8 image with its full mip chain, built as
/// the metadata's `mip_chain` says (`weft_meta::bake::rgba8_mip_chain`: box
/// 2×2, in linear light for sRGB): what docs/engine-interface.md asks of
/// an engine for a texture file.
fn rgba8_texture_mipped(
    gpu: &Gpu,
    label: &str,
    width: u32,
    height: u32,
    level0: &[u8],
    srgb: bool,
) -> wgpu::Texture {
    let chain = weft_meta::bake::rgba8_mip_chain(width, height, level0, srgb);
    let levels = chain.len() as u32;
    rgba8_texture_levels(gpu, label, width, height, 1, levels, &chain.concat(), srgb)
}

/// `data`: every level of layer 0 (level 0 first), then of layer 1, …
#[allow(clippy::too_many_arguments)]
fn rgba8_texture_levels(
    gpu: &Gpu,
    label: &str,
    width: u32,
    height: u32,
    layers: u32,
    levels: u32,
    data: &[u8],
    srgb: bool,
) -> wgpu::Texture {
    gpu.device.create_texture_with_data(
        &gpu.queue,
        &wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: layers,
            },
            mip_level_count: levels,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: if srgb {
                wgpu::TextureFormat::Rgba8UnormSrgb
            } else {
                wgpu::TextureFormat::Rgba8Unorm
            },
            // COPY_SRC: tests read back what was uploaded.
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        data,
    )
}

/// A built-in texture's texel: `weft_meta`'s bytes, the ones the metadata
/// states (`conventions.builtin_textures`).
fn texel_bytes(t: TextureDefault) -> [u8; 4] {
    t.rgba8()
}

fn texture_2d(gpu: &Gpu, label: &str, t: &TextureValue, srgb: bool) -> Result<wgpu::Texture> {
    Ok(match t {
        TextureValue::Builtin(d) => rgba8_texture(gpu, label, 1, 1, 1, &texel_bytes(*d), srgb),
        TextureValue::Rgba8 {
            width,
            height,
            data,
        } => {
            let expected = *width as usize * *height as usize * 4;
            if data.len() != expected || expected == 0 {
                return Err(Error::InvalidValue {
                    name: label.into(),
                    message: format!("{} bytes are not {width}x{height} RGBA8 texels", data.len()),
                });
            }
            rgba8_texture_mipped(gpu, label, *width, *height, data, srgb)
        }
        TextureValue::CubeRgbaF32 { .. } => {
            return Err(Error::InvalidValue {
                name: label.into(),
                message: "a cube cannot be bound to a 2D texture".into(),
            });
        }
    })
}

fn cube_texture(gpu: &Gpu, label: &str, t: &TextureValue, srgb: bool) -> Result<wgpu::Texture> {
    Ok(match t {
        TextureValue::Builtin(d) => {
            let face = texel_bytes(*d);
            let data: Vec<u8> = (0..6).flat_map(|_| face).collect();
            rgba8_texture(gpu, label, 1, 1, 6, &data, srgb)
        }
        TextureValue::CubeRgbaF32 { size, data } => {
            let bytes: Vec<u8> = data
                .iter()
                .flatten()
                .flat_map(|c| half::f16::from_f32(*c).to_le_bytes())
                .collect();
            cube_f16_texture(gpu, label, *size, 1, &bytes)
        }
        TextureValue::Rgba8 { .. } => {
            return Err(Error::InvalidValue {
                name: label.into(),
                message: "a 2D texture cannot be bound to a cube".into(),
            });
        }
    })
}

/// The `weft_object` members of engine interface 1 in declaration order:
/// model, then the normal matrix (inverse-transpose of the model's upper
/// 3x3), column-major. (Draws write each member at the offset the
/// binding's layout gives: `engine_uniforms.rs`.)
pub fn object_uniform(model: &Mat4) -> Vec<f32> {
    let mut o: Vec<f32> = Vec::with_capacity(32);
    o.extend(model.iter().flatten());
    o.extend(math::normal_matrix(model).iter().flatten());
    o
}

pub(crate) fn uniform_buffer(gpu: &Gpu, label: &str, size: u64) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        // STORAGE: `RenderOptions::uniforms_as_storage` binds it so.
        usage: wgpu::BufferUsages::UNIFORM
            | wgpu::BufferUsages::STORAGE
            | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// A mesh's vertex streams (one buffer per vertex input of the shader, in
/// its order) and indices.
pub(crate) struct GpuMesh {
    pub vertex_buffers: Vec<wgpu::Buffer>,
    pub index_buffer: wgpu::Buffer,
    pub index_count: u32,
}

impl GpuMesh {
    pub fn upload(gpu: &Gpu, mesh: &Mesh, inputs: &[VertexInput]) -> Result<GpuMesh> {
        let vertex_count = mesh.vertex_count();
        if let Some(bad) = mesh.indices.iter().find(|&&i| i as usize >= vertex_count) {
            return Err(Error::InvalidValue {
                name: "mesh".into(),
                message: format!("index {bad} is out of range ({vertex_count} vertices)"),
            });
        }
        let device = &gpu.device;
        let vertex_buffers = inputs
            .iter()
            .map(|vi| {
                let mut bytes = vertex_stream(mesh, vi)?;
                if bytes.is_empty() {
                    bytes = vec![0; 16];
                }
                Ok(
                    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                        label: Some(&vi.name),
                        contents: &bytes,
                        usage: wgpu::BufferUsages::VERTEX,
                    }),
                )
            })
            .collect::<Result<Vec<_>>>()?;
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("indices"),
            contents: if mesh.indices.is_empty() {
                &[0; 4]
            } else {
                bytemuck::cast_slice(&mesh.indices)
            },
            usage: wgpu::BufferUsages::INDEX,
        });
        Ok(GpuMesh {
            vertex_buffers,
            index_buffer,
            index_count: mesh.indices.len() as u32,
        })
    }
}

/// The mesh stream of a vertex input, as tightly packed f32s of its format.
pub(crate) fn vertex_stream(mesh: &Mesh, vi: &VertexInput) -> Result<Vec<u8>> {
    let n = vertex_format(&vi.format)?.size() as usize / 4;
    let count = mesh.vertex_count();
    let get = |i: usize| -> [f32; 4] {
        match vi.name.as_str() {
            "position" => {
                let p = mesh.positions[i];
                [p[0], p[1], p[2], 1.0]
            }
            "normal" => {
                let p = mesh.normals.get(i).copied().unwrap_or([0.0, 0.0, 1.0]);
                [p[0], p[1], p[2], 0.0]
            }
            "tangent" => mesh
                .tangents
                .get(i)
                .copied()
                .unwrap_or([1.0, 0.0, 0.0, 1.0]),
            "uv0" => {
                let p = mesh.uv0.get(i).copied().unwrap_or([0.0, 0.0]);
                [p[0], p[1], 0.0, 1.0]
            }
            "uv1" => {
                let p = mesh
                    .uv1
                    .get(i)
                    .or_else(|| mesh.uv0.get(i))
                    .copied()
                    .unwrap_or([0.0, 0.0]);
                [p[0], p[1], 0.0, 1.0]
            }
            "color" => mesh.colors.get(i).copied().unwrap_or([1.0; 4]),
            _ => [0.0; 4],
        }
    };
    if !matches!(
        vi.name.as_str(),
        "position" | "normal" | "tangent" | "uv0" | "uv1" | "color"
    ) {
        return Err(Error::Metadata(format!(
            "vertex input `{}` is not part of the engine interface",
            vi.name
        )));
    }
    let mut out = Vec::with_capacity(count * n * 4);
    for i in 0..count {
        let v = get(i);
        for c in &v[..n] {
            out.extend_from_slice(&c.to_le_bytes());
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The built-in textures weft uploads hold exactly the bytes the
    /// metadata states (`conventions.builtin_textures`): read back from the
    /// GPU, 2D and every cube face, in both formats.
    #[test]
    fn builtin_textures_upload_the_stated_texels() {
        let gpu = Gpu::new().expect("a Vulkan adapter (lavapipe: mesa-vulkan-drivers)");
        let stated = weft_meta::Conventions::current().builtin_textures;
        for d in TextureDefault::ALL {
            for srgb in [false, true] {
                let want = stated[d.name()];
                let t = texture_2d(&gpu, d.name(), &TextureValue::Builtin(d), srgb).unwrap();
                let got = gpu.read_texture_rgba8(&t, 0, 0).unwrap();
                assert_eq!(got, want, "{} (srgb {srgb})", d.name());
                let c = cube_texture(&gpu, d.name(), &TextureValue::Builtin(d), srgb).unwrap();
                for face in 0..6 {
                    let got = gpu.read_texture_rgba8(&c, 0, face).unwrap();
                    assert_eq!(got, want, "{} cube face {face} (srgb {srgb})", d.name());
                }
            }
        }
    }

    /// A texture parameter's image is bound with the mip chain its
    /// metadata states (`mip_chain`): every level read back from the GPU is
    /// `weft_meta::bake::rgba8_mip_chain`'s, for a shipped file (hair's
    /// 64×256 flow map, eye's sRGB matcap) and an odd-sized image.
    #[test]
    fn texture_files_upload_the_stated_mip_chain() {
        let gpu = Gpu::new().expect("a Vulkan adapter (lavapipe: mesa-vulkan-drivers)");
        let generated = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../generated");
        let mut images = Vec::new();
        for (material, param) in [("hair", "flow_map"), ("eye", "matcap_map")] {
            let meta_path = generated.join(format!("{material}/{material}.meta.json"));
            let meta = weft_meta::MaterialMetadata::from_json(
                &std::fs::read_to_string(&meta_path).unwrap(),
            )
            .unwrap();
            let p = meta.parameters.iter().find(|p| p.name == param).unwrap();
            let t = p.texture.as_ref().unwrap();
            let file = t.file.as_ref().expect("a shipped image");
            let chain = file
                .mip_chain
                .as_ref()
                .expect("texture files state their mip chain");
            assert_eq!(
                chain,
                &weft_meta::MipChain::for_texture(file.width, file.height, t.srgb)
            );
            let roots = crate::texture_files::material_roots(meta_path.parent().unwrap());
            let value = crate::texture_files::read(&roots, file).unwrap();
            images.push((format!("{material}.{param}"), value, t.srgb, chain.levels));
        }
        let odd: Vec<u8> = (0..5 * 3 * 4).map(|i| (i * 37 % 256) as u8).collect();
        for srgb in [false, true] {
            let value = TextureValue::Rgba8 {
                width: 5,
                height: 3,
                data: odd.clone(),
            };
            images.push((format!("5x3 (srgb {srgb})"), value, srgb, 3));
        }
        for (label, value, srgb, levels) in images {
            let TextureValue::Rgba8 {
                width,
                height,
                data,
            } = &value
            else {
                unreachable!()
            };
            let want = weft_meta::bake::rgba8_mip_chain(*width, *height, data, srgb);
            assert_eq!(want.len() as u32, levels, "{label}");
            let texture = texture_2d(&gpu, &label, &value, srgb).unwrap();
            assert_eq!(texture.mip_level_count(), levels, "{label}");
            for (m, level) in want.iter().enumerate() {
                let got = gpu.read_texture_rgba8(&texture, m as u32, 0).unwrap();
                assert_eq!(&got, level, "{label}: level {m}");
            }
        }
    }
}
