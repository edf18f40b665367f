//! GPU resources a draw binds: the environment, material textures, uniform
//! and object buffers, mesh buffers, and the bind groups that tie them to a
//! shader's reflected bindings (engine interface groups 0 and 2, material
//! group 1).

use crate::environment::EnvironmentMaps;
use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::luts::SHEEN_LUT_FILE;
use crate::math::{self, Mat4};
use crate::pipelines::{ShaderInput, VariantPipelines, is_texture, vertex_format};
use crate::renderer::{ColorFormat, Renderer};
use crate::scene::Mesh;
use crate::values::TextureValue;
use std::borrow::Cow;
use std::collections::BTreeMap;
use std::sync::Arc;
use weft_meta::{Binding, BindingKind, Pass, TextureDefault, VariantShader, VertexInput};
use wgpu::util::DeviceExt;

/// Bytes of the `weft_frame` uniform.
pub(crate) const FRAME_SIZE: u64 = 336;
/// Bytes of the `weft_object` uniform.
pub(crate) const OBJECT_SIZE: u64 = 128;

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
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
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
pub(crate) enum TextureSource<'a> {
    /// A 2D texture parameter (sampled through an sRGB view when `srgb`).
    Texture2d {
        value: Cow<'a, TextureValue>,
        srgb: bool,
    },
    /// A cube parameter.
    Cube {
        value: Cow<'a, TextureValue>,
        srgb: bool,
    },
    /// A gradient ramp: RGBA8 texels, `width` = len / 4, 1 row.
    Ramp { rgba8: &'a [u8], srgb: bool },
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
        if b.group != 1 || !is_texture(b.kind) {
            continue;
        }
        let label = b.parameter.as_deref().unwrap_or(&b.name);
        let texture = match (b.kind, source(b)?) {
            (BindingKind::Texture2d, TextureSource::Texture2d { value, srgb }) => {
                texture_2d(gpu, label, &value, srgb)?
            }
            (BindingKind::Texture2d, TextureSource::Ramp { rgba8, srgb }) => {
                if rgba8.is_empty() || !rgba8.len().is_multiple_of(4) {
                    return Err(Error::InvalidValue {
                        name: label.into(),
                        message: format!("a ramp of {} bytes is not RGBA8 texels", rgba8.len()),
                    });
                }
                rgba8_texture(gpu, label, (rgba8.len() / 4) as u32, 1, 1, rgba8, srgb)
            }
            (BindingKind::TextureCube, TextureSource::Cube { value, srgb }) => {
                cube_texture(gpu, label, &value, srgb)?
            }
            (kind, _) => {
                return Err(Error::Metadata(format!(
                    "binding `{}` ({kind:?}) cannot carry the texture given for `{label}`",
                    b.name
                )));
            }
        };
        let dim = match b.kind {
            BindingKind::TextureCube => wgpu::TextureViewDimension::Cube,
            _ => wgpu::TextureViewDimension::D2,
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

fn rgba8_texture(
    gpu: &Gpu,
    label: &str,
    width: u32,
    height: u32,
    layers: u32,
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
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: if srgb {
                wgpu::TextureFormat::Rgba8UnormSrgb
            } else {
                wgpu::TextureFormat::Rgba8Unorm
            },
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        data,
    )
}

fn texel_bytes(t: TextureDefault) -> [u8; 4] {
    t.texel().map(|c| (c * 255.0).round() as u8)
}

fn texture_2d(gpu: &Gpu, label: &str, t: &TextureValue, srgb: bool) -> Result<wgpu::Texture> {
    Ok(match t {
        TextureValue::Builtin(d) => rgba8_texture(gpu, label, 1, 1, 1, &texel_bytes(*d), srgb),
        TextureValue::Rgba8 {
            width,
            height,
            data,
        } => rgba8_texture(gpu, label, *width, *height, 1, data, srgb),
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

/// The `weft_object` contents: model, then the normal matrix
/// (inverse-transpose of the model's upper 3x3), column-major.
pub fn object_uniform(model: &Mat4) -> Vec<f32> {
    let mut o: Vec<f32> = Vec::with_capacity((OBJECT_SIZE / 4) as usize);
    o.extend(model.iter().flatten());
    o.extend(math::normal_matrix(model).iter().flatten());
    o
}

pub(crate) fn uniform_buffer(gpu: &Gpu, label: &str, size: u64) -> wgpu::Buffer {
    gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
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

/// What one shader's draws bind: its pipelines, bind groups and the
/// material uniform buffer behind group 1 (also what the material path's
/// [`crate::PreparedMaterial`] holds).
pub(crate) struct BoundShader {
    pub pipelines: Arc<VariantPipelines>,
    pub bind_groups: Vec<Option<wgpu::BindGroup>>,
    pub uniform: Option<wgpu::Buffer>,
}

/// The per-object inputs of [`Renderer::bind_shader`] (wgpu handles are
/// reference-counted: these are shared, not copied).
pub(crate) struct ObjectResources {
    /// The packed material uniform (`None` when the shader has no layout).
    pub uniform_bytes: Option<Vec<u8>>,
    /// Group-1 texture views by binding number.
    pub textures: BTreeMap<u32, wgpu::TextureView>,
    /// The `weft_object` buffer group 2 binds.
    pub object: wgpu::Buffer,
    /// Group 0's cube.
    pub env: GpuEnvironment,
}

impl Renderer {
    /// Pipelines for `passes` plus bind groups over `resources`: the one
    /// place a draw's resources meet a shader's reflected bindings.
    pub(crate) fn bind_shader(
        &mut self,
        input: &ShaderInput,
        passes: &[Pass],
        format: ColorFormat,
        resources: ObjectResources,
    ) -> Result<BoundShader> {
        let pipelines = self.variant_pipelines(input, passes, format)?;
        let uniform = resources.uniform_bytes.as_ref().map(|bytes| {
            self.gpu
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("material"),
                    contents: bytes,
                    usage: wgpu::BufferUsages::UNIFORM
                        | wgpu::BufferUsages::COPY_DST
                        | wgpu::BufferUsages::COPY_SRC,
                })
        });
        let bind_groups = self.gpu.checked("binding material resources", || {
            self.bind_groups(input.shader, &pipelines, uniform.as_ref(), &resources)
        })??;
        Ok(BoundShader {
            pipelines,
            bind_groups,
            uniform,
        })
    }

    fn bind_groups(
        &self,
        shader: &VariantShader,
        pipelines: &VariantPipelines,
        uniform: Option<&wgpu::Buffer>,
        res: &ObjectResources,
    ) -> Result<Vec<Option<wgpu::BindGroup>>> {
        let mut groups = Vec::new();
        for (g, layout) in pipelines.layouts.iter().enumerate() {
            let g = g as u32;
            let Some(layout) = layout else {
                groups.push(None);
                continue;
            };
            let mut entries = Vec::new();
            for b in shader.bindings.iter().filter(|b| b.group == g) {
                let mismatch = || {
                    Error::Metadata(format!(
                        "binding `{}` (group {g}, binding {}, {:?}) is not part of engine interface {}",
                        b.name,
                        b.binding,
                        b.kind,
                        weft_meta::ENGINE_INTERFACE_VERSION
                    ))
                };
                let resource = match (g, b.binding, b.kind) {
                    (0, 0, BindingKind::UniformBuffer) => self.frame_buffer.as_entire_binding(),
                    (0, 1, BindingKind::TextureCube) => {
                        wgpu::BindingResource::TextureView(&res.env.view)
                    }
                    (0, 2, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.env_sampler)
                    }
                    (0, 3, BindingKind::Texture2d) => {
                        wgpu::BindingResource::TextureView(&self.lut_view)
                    }
                    (0, 4, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.lut_sampler)
                    }
                    (0, 5, BindingKind::Texture2d) => wgpu::BindingResource::TextureView(
                        self.sheen_view.as_ref().ok_or_else(|| {
                            Error::Metadata(format!(
                                "the variant binds `{}` but no sheen LUT was loaded \
                                     (expected `{SHEEN_LUT_FILE}` in the generated folder)",
                                b.name
                            ))
                        })?,
                    ),
                    (1, 0, BindingKind::UniformBuffer) => uniform
                        .ok_or_else(|| {
                            Error::Metadata(
                                "the variant binds `material` but has no material_uniform layout"
                                    .into(),
                            )
                        })?
                        .as_entire_binding(),
                    (1, 1, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.repeat_sampler)
                    }
                    (1, 2, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.clamp_sampler)
                    }
                    (1, _, k) if is_texture(k) => wgpu::BindingResource::TextureView(
                        res.textures.get(&b.binding).ok_or_else(mismatch)?,
                    ),
                    (2, 0, BindingKind::UniformBuffer) => res.object.as_entire_binding(),
                    _ => return Err(mismatch()),
                };
                entries.push(wgpu::BindGroupEntry {
                    binding: b.binding,
                    resource,
                });
            }
            groups.push(Some(self.gpu.device.create_bind_group(
                &wgpu::BindGroupDescriptor {
                    label: Some(&format!("group {g}")),
                    layout,
                    entries: &entries,
                },
            )));
        }
        Ok(groups)
    }
}
