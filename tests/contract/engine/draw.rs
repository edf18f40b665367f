//! Resources, bind groups and draws: group 0 by `resource.id` (frame,
//! environment, baked LUT files), group 1 from the material inputs, group 2
//! the object; samplers as `bindings[].sampler` states them; passes drawn
//! in the order given into one colour target, read back as linear RGBA.

use super::data::{Environment, FrameInputs, Image, Mat4, Mesh};
use super::device::Engine;
use super::formats;
use super::library::{
    MaterialInputs, ShaderRef, TextureData, canonical_variants, library_inputs, queue_order,
    variant_passes,
};
use super::pipeline::{self, Language, Orientation, Pipelines};
use super::uniforms;
use std::collections::HashMap;
use std::path::Path;
use weft_meta::{Binding, MaterialMetadata, TextureViewDimension};
use wgpu::util::DeviceExt;

/// The engine's world: environment and frame constants, and textures it
/// has uploaded (the environment per format, LUT files per path). The
/// environment cube is uploaded on first use: change `env` before drawing,
/// or make a new world.
pub struct World {
    pub env: Environment,
    pub frame: FrameInputs,
    textures: HashMap<String, wgpu::TextureView>,
}

impl World {
    pub fn new(env: Environment, frame: FrameInputs) -> World {
        World {
            env,
            frame,
            textures: HashMap::new(),
        }
    }
}

/// One shader bound for one object: pipelines, bind groups, mesh buffers,
/// instance counts per pass.
pub struct Prepared {
    pub label: String,
    pub pipelines: Pipelines,
    bind_groups: Vec<wgpu::BindGroup>,
    vertex_buffers: Vec<wgpu::Buffer>,
    index_buffer: wgpu::Buffer,
    index_count: u32,
    pub instances: Vec<u32>,
}

/// One pass of one prepared object, in draw order.
#[derive(Clone, Copy)]
pub struct DrawItem<'a> {
    pub prepared: &'a Prepared,
    pub pass: usize,
}

/// Texel bytes of linear RGBA values in a float format.
fn float_texels(format: wgpu::TextureFormat, texels: &[[f32; 4]]) -> Result<Vec<u8>, String> {
    Ok(match format {
        wgpu::TextureFormat::Rgba16Float => texels
            .iter()
            .flatten()
            .flat_map(|c| half::f16::from_f32(*c).to_le_bytes())
            .collect(),
        wgpu::TextureFormat::Rgba32Float => texels
            .iter()
            .flatten()
            .flat_map(|c| c.to_le_bytes())
            .collect(),
        other => return Err(format!("cannot write float texels as {other:?}")),
    })
}

/// The mip chain docs/engine-interface.md describes ("Texture files: mip
/// chains"), written from the page: level n + 1 halves each side (never
/// below 1); each texel is the mean of the 2×2 texels above it, clamped to
/// the level's edge; RGB in linear light when `linear_light` (sRGB decoded,
/// averaged, encoded, rounded), otherwise (and alpha) bytes averaged and
/// rounded half up.
fn box_mip_chain(
    width: u32,
    height: u32,
    level0: Vec<u8>,
    levels: u32,
    linear_light: bool,
) -> Vec<Vec<u8>> {
    let decode = |b: u8| {
        let c = f64::from(b) / 255.0;
        if c <= 0.04045 {
            c / 12.92
        } else {
            ((c + 0.055) / 1.055).powf(2.4)
        }
    };
    let encode = |l: f64| {
        let c = if l <= 0.0031308 {
            l * 12.92
        } else {
            1.055 * l.powf(1.0 / 2.4) - 0.055
        };
        (c * 255.0).round().clamp(0.0, 255.0) as u8
    };
    let mut out = vec![level0];
    let (mut w, mut h) = (width as usize, height as usize);
    while (out.len() as u32) < levels {
        let above = out.last().unwrap();
        let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
        let mut level = vec![0u8; nw * nh * 4];
        for y in 0..nh {
            for x in 0..nw {
                let mut texels = Vec::with_capacity(4);
                for (i, j) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    let (sx, sy) = ((2 * x + i).min(w - 1), (2 * y + j).min(h - 1));
                    texels.push(&above[(sy * w + sx) * 4..][..4]);
                }
                for c in 0..4 {
                    level[(y * nw + x) * 4 + c] = if linear_light && c < 3 {
                        encode(texels.iter().map(|t| decode(t[c])).sum::<f64>() / 4.0)
                    } else {
                        ((texels.iter().map(|t| u32::from(t[c])).sum::<u32>() + 2) / 4) as u8
                    };
                }
            }
        }
        out.push(level);
        (w, h) = (nw, nh);
    }
    out
}

impl Engine {
    /// A texture with `layers` layers and `mips.len()` levels, each level's
    /// bytes layer-major then row-major.
    fn texture(
        &self,
        label: &str,
        format: wgpu::TextureFormat,
        (width, height, layers): (u32, u32, u32),
        mips: &[Vec<u8>],
    ) -> Result<wgpu::Texture, String> {
        let texel = formats::texel_size(format)?;
        let texture = self.device.create_texture(&wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: layers,
            },
            mip_level_count: mips.len() as u32,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format,
            usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
            view_formats: &[],
        });
        for (m, data) in mips.iter().enumerate() {
            let (w, h) = ((width >> m).max(1), (height >> m).max(1));
            let want = (w * h * layers * texel) as usize;
            if data.len() != want {
                return Err(format!(
                    "{label}: mip {m} has {} bytes, {w}×{h}×{layers} {format:?} needs {want}",
                    data.len()
                ));
            }
            self.queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &texture,
                    mip_level: m as u32,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                data,
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(w * texel),
                    rows_per_image: Some(h),
                },
                wgpu::Extent3d {
                    width: w,
                    height: h,
                    depth_or_array_layers: layers,
                },
            );
        }
        Ok(texture)
    }

    fn view(texture: &wgpu::Texture, dim: TextureViewDimension) -> wgpu::TextureView {
        texture.create_view(&wgpu::TextureViewDescriptor {
            dimension: Some(formats::view_dimension(dim)),
            ..Default::default()
        })
    }

    /// The view an engine-data texture binding (`resource`) gets.
    fn engine_texture(
        &self,
        world: &mut World,
        s: &ShaderRef,
        b: &Binding,
    ) -> Result<wgpu::TextureView, String> {
        let t = b.texture.as_ref().expect("texture binding");
        let r = b
            .resource
            .as_ref()
            .ok_or_else(|| format!("engine texture `{}` has no `resource`", b.name))?;
        let format = formats::texture_format(&t.format)?;
        let key = format!("{}|{}|{format:?}", r.id, s.root.display());
        if let Some(v) = world.textures.get(&key) {
            return Ok(v.clone());
        }
        let view = if let Some(file) = &r.file {
            // docs/engine-interface.md: LUT paths are relative to the
            // library root (the folder holding `luts/`).
            let path = s.root.join(&file.path);
            let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
            let file_format = formats::texture_format(&file.format)?;
            if file_format != format {
                return Err(format!(
                    "`{}`: the file is {}, the binding wants {}",
                    b.name, file.format, t.format
                ));
            }
            let texture = self.texture(
                &r.id,
                format,
                (file.width, file.height, 1),
                std::slice::from_ref(&bytes),
            )?;
            Self::view(&texture, t.view_dimension)
        } else if r.id == "environment" {
            if t.view_dimension != TextureViewDimension::Cube {
                return Err(format!("`{}` is not a cube", b.name));
            }
            let env = &world.env;
            let mips = env
                .mips
                .iter()
                .map(|m| float_texels(format, m))
                .collect::<Result<Vec<_>, _>>()?;
            let texture = self.texture(&r.id, format, (env.size, env.size, 6), &mips)?;
            Self::view(&texture, t.view_dimension)
        } else {
            return Err(format!(
                "texture `{}`: unknown engine resource `{}` without a file",
                b.name, r.id
            ));
        };
        world.textures.insert(key, view.clone());
        Ok(view)
    }

    /// A material texture: a built-in 1×1 (cube: six 1×1 faces), a ramp,
    /// or an image file under the library `root`.
    fn material_texture(
        &self,
        b: &Binding,
        data: &TextureData,
        root: &Path,
    ) -> Result<wgpu::TextureView, String> {
        let t = b.texture.as_ref().expect("texture binding");
        let format = formats::texture_format(&t.format)?;
        let layers = match t.view_dimension {
            TextureViewDimension::D2 => 1,
            TextureViewDimension::Cube => 6,
            other => return Err(format!("`{}`: cannot make a {other:?} default", b.name)),
        };
        let rgba8 = matches!(
            format,
            wgpu::TextureFormat::Rgba8Unorm | wgpu::TextureFormat::Rgba8UnormSrgb
        );
        if let TextureData::File(f) = data {
            // The file's own format: the binding's says the same (a
            // mismatch would be a metadata error worth seeing).
            if f.format != t.format || layers != 1 {
                return Err(format!(
                    "`{}`: image `{}` is {} but the binding is {} {:?}",
                    b.name, f.path, f.format, t.format, t.view_dimension
                ));
            }
            let bytes = std::fs::read(root.join(&f.path))
                .map_err(|e| format!("`{}`: {}: {e}", b.name, f.path))?;
            // The file is level 0; the metadata says which chain to build.
            let chain = f
                .mip_chain
                .as_ref()
                .ok_or_else(|| format!("`{}`: image `{}` states no `mip_chain`", b.name, f.path))?;
            if chain.filter != "box_2x2" {
                return Err(format!(
                    "`{}`: unknown mip filter `{}`",
                    b.name, chain.filter
                ));
            }
            let mips = box_mip_chain(f.width, f.height, bytes, chain.levels, chain.linear_light);
            let texture = self.texture(&b.name, format, (f.width, f.height, 1), &mips)?;
            return Ok(Self::view(&texture, t.view_dimension));
        }
        let (width, bytes) = match data {
            TextureData::Builtin(d) if rgba8 => (1, d.repeat(layers as usize)),
            TextureData::Builtin(d) => {
                let texel = d.map(|b| f32::from(b) / 255.0);
                (1, float_texels(format, &vec![texel; layers as usize])?)
            }
            TextureData::Ramp(r) if rgba8 && layers == 1 && r.len() % 4 == 0 => {
                ((r.len() / 4) as u32, r.clone())
            }
            TextureData::File(_) => unreachable!("bound above"),
            TextureData::Ramp(r) => {
                return Err(format!(
                    "`{}`: a ramp of {} bytes cannot be {} {:?}",
                    b.name,
                    r.len(),
                    t.format,
                    t.view_dimension
                ));
            }
        };
        let texture = self.texture(&b.name, format, (width, 1, layers), &[bytes])?;
        Ok(Self::view(&texture, t.view_dimension))
    }

    fn buffer(&self, label: &str, bytes: &[u8], min: u64) -> wgpu::Buffer {
        let mut contents = bytes.to_vec();
        if (contents.len() as u64) < min {
            contents.resize(min as usize, 0);
        }
        self.device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: &contents,
                usage: wgpu::BufferUsages::UNIFORM,
            })
    }

    /// Builds `s`'s pipelines for `language` and binds it for one object.
    #[allow(clippy::too_many_arguments)]
    pub fn prepare(
        &self,
        world: &mut World,
        s: &ShaderRef,
        language: Language,
        inputs: &MaterialInputs,
        mesh: &Mesh,
        model: &Mat4,
    ) -> Result<Prepared, String> {
        let pipelines = pipeline::build(self, s, language)?;
        if inputs.instances.len() != pipelines.passes.len() {
            return Err(format!(
                "{}: {} instance counts for {} passes",
                s.label,
                inputs.instances.len(),
                pipelines.passes.len()
            ));
        }
        let mut bind_groups = Vec::new();
        for (g, layout) in pipelines.layouts.iter().enumerate() {
            // Resources first (they must outlive the entries that borrow them).
            enum Res {
                Buffer(wgpu::Buffer),
                View(wgpu::TextureView),
                Sampler(wgpu::Sampler),
            }
            let mut res: Vec<(u32, Res)> = Vec::new();
            for b in s.shader.bindings.iter().filter(|b| b.group == g as u32) {
                let id = b.resource.as_ref().map(|r| r.id.as_str());
                let r = if let Some(sampler) = &b.sampler {
                    Res::Sampler(
                        self.device
                            .create_sampler(&formats::sampler_descriptor(&b.name, sampler)),
                    )
                } else if let Some(buf) = &b.buffer {
                    let bytes = match (b.group, id) {
                        (_, Some("frame")) => {
                            uniforms::frame(&buf.layout, &world.frame, &world.env)?
                        }
                        (_, Some("object")) => uniforms::object(&buf.layout, model)?,
                        (1, None) => inputs
                            .uniform
                            .clone()
                            .ok_or_else(|| format!("`{}`: no material uniform given", b.name))?,
                        (_, other) => {
                            return Err(format!(
                                "buffer `{}` (group {g}): unknown resource {other:?}",
                                b.name
                            ));
                        }
                    };
                    if bytes.len() as u64 != buf.layout.size as u64 {
                        return Err(format!(
                            "`{}`: {} bytes for a {}-byte block",
                            b.name,
                            bytes.len(),
                            buf.layout.size
                        ));
                    }
                    Res::Buffer(self.buffer(&b.name, &bytes, buf.min_binding_size))
                } else if b.texture.is_some() {
                    match (b.group, id) {
                        (1, None) => {
                            let data = inputs.textures.get(&b.binding).ok_or_else(|| {
                                format!("`{}`: no material texture given", b.name)
                            })?;
                            Res::View(self.checked(&format!("texture `{}`", b.name), || {
                                self.material_texture(b, data, &s.root)
                            })??)
                        }
                        _ => Res::View(self.engine_texture(world, s, b)?),
                    }
                } else {
                    return Err(format!("binding `{}` has no layout entry", b.name));
                };
                res.push((b.binding, r));
            }
            for &(_, n) in pipelines
                .placeholders
                .iter()
                .filter(|(pg, _)| *pg == g as u32)
            {
                res.push((
                    n,
                    Res::Sampler(self.device.create_sampler(&Default::default())),
                ));
            }
            let entries: Vec<wgpu::BindGroupEntry> = res
                .iter()
                .map(|(binding, r)| wgpu::BindGroupEntry {
                    binding: *binding,
                    resource: match r {
                        Res::Buffer(b) => b.as_entire_binding(),
                        Res::View(v) => wgpu::BindingResource::TextureView(v),
                        Res::Sampler(s) => wgpu::BindingResource::Sampler(s),
                    },
                })
                .collect();
            bind_groups.push(self.checked(&format!("group {g} of {}", s.label), || {
                self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some(&format!("{} group {g}", s.label)),
                    layout,
                    entries: &entries,
                })
            })?);
        }

        // Vertex streams: one buffer per input, in `vertex_inputs` order.
        let n = mesh.positions.len();
        if let Some(bad) = mesh.indices.iter().find(|&&i| i as usize >= n) {
            return Err(format!("mesh index {bad} out of range ({n} vertices)"));
        }
        let mut vertex_buffers = Vec::new();
        for vi in &s.shader.vertex_inputs {
            let components = (formats::vertex_format(&vi.format)?.size() / 4) as usize;
            let bytes: Vec<u8> = mesh
                .stream(&vi.name)?
                .iter()
                .flat_map(|v| v[..components].to_vec())
                .flat_map(f32::to_le_bytes)
                .collect();
            vertex_buffers.push(self.device.create_buffer_init(
                &wgpu::util::BufferInitDescriptor {
                    label: Some(&vi.name),
                    contents: &bytes,
                    usage: wgpu::BufferUsages::VERTEX,
                },
            ));
        }
        let index_buffer = self
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("indices"),
                contents: bytemuck::cast_slice(&mesh.indices),
                usage: wgpu::BufferUsages::INDEX,
            });
        self.take_uncaptured(&s.label)?;
        Ok(Prepared {
            label: s.label.clone(),
            pipelines,
            bind_groups,
            vertex_buffers,
            index_buffer,
            index_count: mesh.indices.len() as u32,
            instances: inputs.instances.clone(),
        })
    }

    /// Draws `draws` in order over `clear` into a `width`×`height` target
    /// and reads it back (rows reordered when the language's row 0 is the
    /// bottom).
    pub fn render(
        &self,
        draws: &[DrawItem],
        width: u32,
        height: u32,
        clear: [f64; 4],
    ) -> Result<Image, String> {
        let first = draws.first().ok_or("nothing to draw")?;
        let orientation: Orientation = first.prepared.pipelines.orientation;
        // One colour target (location 0) shared by every pass.
        let mut color_format = None;
        let mut depth_format = None;
        for d in draws {
            let pass = &d.prepared.pipelines.passes[d.pass].pass;
            let f = d.prepared.pipelines.color_format;
            if *color_format.get_or_insert(f) != f {
                return Err("passes draw into different colour formats".into());
            }
            // Every pass draws into the one depth-stencil attachment.
            let ds = &pass.depth_stencil;
            let f = formats::texture_format(&ds.format)?;
            let want = (f, ds.depth_clear_value, ds.stencil_clear_value);
            if *depth_format.get_or_insert(want) != want {
                return Err("passes use different depth-stencil formats or clear values".into());
            }
            if d.prepared.pipelines.orientation != orientation {
                return Err("draws of different orientations in one picture".into());
            }
        }
        let color_format = color_format.expect("a draw");
        let device = &self.device;
        let size = wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        };
        let target = |format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some("target"),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let color = target(
            color_format,
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let color_view = color.create_view(&Default::default());
        let (depth_format, depth_clear, stencil_clear) = depth_format.expect("a draw");
        let depth = target(depth_format, wgpu::TextureUsages::RENDER_ATTACHMENT)
            .create_view(&Default::default());
        let has_stencil = depth_format.has_stencil_aspect();
        let texel = formats::texel_size(color_format)?;
        let row = (width * texel).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
            * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size: u64::from(row) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let commands = self.checked("recording the draws", || {
            let mut enc = device.create_command_encoder(&Default::default());
            let attachments = |color_load, (depth_load, stencil_load)| {
                (
                    [Some(wgpu::RenderPassColorAttachment {
                        view: &color_view,
                        depth_slice: None,
                        resolve_target: None,
                        ops: wgpu::Operations {
                            load: color_load,
                            store: wgpu::StoreOp::Store,
                        },
                    })],
                    Some(wgpu::RenderPassDepthStencilAttachment {
                        view: &depth,
                        depth_ops: Some(wgpu::Operations {
                            load: depth_load,
                            store: wgpu::StoreOp::Store,
                        }),
                        stencil_ops: has_stencil.then_some(wgpu::Operations {
                            load: stencil_load,
                            store: wgpu::StoreOp::Store,
                        }),
                    }),
                )
            };
            // Clear colour, depth and stencil.
            {
                let (c, d) = attachments(
                    wgpu::LoadOp::Clear(wgpu::Color {
                        r: clear[0],
                        g: clear[1],
                        b: clear[2],
                        a: clear[3],
                    }),
                    (
                        wgpu::LoadOp::Clear(depth_clear),
                        wgpu::LoadOp::Clear(stencil_clear),
                    ),
                );
                enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("clear"),
                    color_attachments: &c,
                    depth_stencil_attachment: d,
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
            }
            for d in draws {
                let p = d.prepared;
                let pp = &p.pipelines.passes[d.pass];
                let instances = p.instances[d.pass];
                if instances == 0 || p.index_count == 0 {
                    continue;
                }
                let (c, ds) =
                    attachments(wgpu::LoadOp::Load, (wgpu::LoadOp::Load, wgpu::LoadOp::Load));
                let mut rp = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some(&pp.pass.name),
                    color_attachments: &c,
                    depth_stencil_attachment: ds,
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                });
                rp.set_pipeline(&pp.pipeline);
                rp.set_stencil_reference(pp.pass.depth_stencil.stencil_reference);
                for (g, bg) in p.bind_groups.iter().enumerate() {
                    rp.set_bind_group(g as u32, bg, &[]);
                }
                for (i, vb) in p.vertex_buffers.iter().enumerate() {
                    rp.set_vertex_buffer(i as u32, vb.slice(..));
                }
                rp.set_index_buffer(p.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                rp.draw_indexed(0..p.index_count, 0, 0..instances);
            }
            enc.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture: &color,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                wgpu::TexelCopyBufferInfo {
                    buffer: &staging,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(row),
                        rows_per_image: Some(height),
                    },
                },
                size,
            );
            enc.finish()
        })?;
        self.queue.submit([commands]);
        let (tx, rx) = std::sync::mpsc::channel();
        staging.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        self.wait()?;
        rx.recv()
            .map_err(|_| "readback never completed".to_string())?
            .map_err(|e| format!("readback: {e}"))?;
        let bytes = staging
            .get_mapped_range(..)
            .map_err(|e| format!("readback: {e}"))?
            .to_vec();
        staging.unmap();
        self.take_uncaptured("drawing")?;
        let mut pixels = Vec::with_capacity((width * height) as usize);
        for y in 0..height {
            let line = &bytes[(y * row) as usize..(y * row + width * texel) as usize];
            match color_format {
                wgpu::TextureFormat::Rgba16Float => pixels.extend(line.chunks_exact(8).map(|p| {
                    [0, 2, 4, 6].map(|i| half::f16::from_le_bytes([p[i], p[i + 1]]).to_f32())
                })),
                wgpu::TextureFormat::Rgba32Float => pixels.extend(line.chunks_exact(16).map(|p| {
                    [0, 4, 8, 12].map(|i| f32::from_le_bytes([p[i], p[i + 1], p[i + 2], p[i + 3]]))
                })),
                other => return Err(format!("cannot read back {other:?}")),
            }
        }
        let image = Image {
            width,
            height,
            pixels,
        };
        Ok(if orientation.bottom_row_first {
            image.flipped_rows()
        } else {
            image
        })
    }
}

/// The identity model matrix.
pub const IDENTITY: Mat4 = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

impl Engine {
    /// A library variant (`variant`: a canonical id) with every parameter
    /// at its default, on `mesh` at the origin: every pass in queue order.
    #[allow(clippy::too_many_arguments)]
    pub fn draw_variant(
        &self,
        world: &mut World,
        root: &Path,
        meta_path: &Path,
        meta: &MaterialMetadata,
        variant: &str,
        language: Language,
        mesh: &Mesh,
        (width, height): (u32, u32),
        clear: [f64; 4],
    ) -> Result<Image, String> {
        let (v, shader) = canonical_variants(meta)?
            .into_iter()
            .find(|(v, _)| v.id == variant)
            .ok_or_else(|| format!("{}: no canonical variant `{variant}`", meta.name))?;
        let passes = variant_passes(meta, v);
        let s = ShaderRef {
            label: format!("{}/{variant}", meta.name),
            dir: meta_path
                .parent()
                .ok_or("metadata path without a folder")?
                .to_path_buf(),
            root: root.to_path_buf(),
            shader,
            passes: &passes,
            languages: Some(&meta.languages),
        };
        let inputs = library_inputs(meta, &passes, shader)?;
        let prepared = self.prepare(world, &s, language, &inputs, mesh, &IDENTITY)?;
        let draws: Vec<DrawItem> = queue_order(&passes)
            .into_iter()
            .map(|pass| DrawItem {
                prepared: &prepared,
                pass,
            })
            .collect();
        self.render(&draws, width, height, clear)
    }
}
