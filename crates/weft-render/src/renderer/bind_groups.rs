//! Binding a variant's shader to the renderer's resources: the engine's
//! group 0 and 2 (frame and object uniforms, environment, LUTs) and the
//! material's group 1 (its uniform block, textures, samplers), from the
//! metadata's bindings alone (`bindings.rs` has the pieces).

use super::Renderer;
use crate::bindings::{BoundShader, ObjectResources, engine_resource, lut_file, lut_texture};
use crate::engine_uniforms::{UniformBlock, frame_member_type, object_bytes, object_member_type};
use crate::error::{Error, Result};
use crate::meta_wgpu::{sampler_descriptor, sampler_key, texture_format};
use crate::pipelines::{ShaderInput, VariantPipelines};
use crate::targets::ColorFormat;
use weft_meta::engine;
use weft_meta::{Binding, Pass, VariantShader};
use wgpu::util::DeviceExt;

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
        let shader = input.shader;
        self.prepare_engine_bindings(shader)?;
        let uniform = match &resources.uniform_bytes {
            Some(bytes) => Some(self.material_uniform_buffer(shader, bytes)?),
            None => None,
        };
        let mut frame = None;
        let mut object = None;
        for b in shader.bindings.iter() {
            match engine_resource(b).map(|r| r.id.as_str()) {
                Some(engine::FRAME) => frame = Some(self.frame_block(b)?),
                Some(engine::OBJECT) => {
                    let block = UniformBlock::new(&self.gpu, b, object_member_type)?;
                    let bytes = object_bytes(&block, &resources.model)?;
                    self.gpu.queue.write_buffer(&block.buffer, 0, &bytes);
                    object = Some(block);
                }
                _ => {}
            }
        }
        let bind_groups = self.gpu.checked("binding material resources", || {
            self.bind_groups(
                shader,
                &pipelines,
                uniform.as_ref(),
                frame.as_ref(),
                object.as_ref(),
                &resources,
            )
        })??;
        Ok(BoundShader {
            pipelines,
            bind_groups,
            uniform,
            frame,
            object,
        })
    }

    /// The group-1 uniform buffer: the packed bytes, at least the
    /// binding's `min_binding_size` long.
    fn material_uniform_buffer(
        &self,
        shader: &VariantShader,
        bytes: &[u8],
    ) -> Result<wgpu::Buffer> {
        let min = shader
            .bindings
            .iter()
            .find(|b| b.group == engine::MATERIAL_GROUP && b.resource.is_none())
            .and_then(|b| b.buffer.as_ref())
            .map_or(0, |buf| buf.min_binding_size);
        let mut contents = bytes.to_vec();
        let len = (contents.len() as u64)
            .max(min)
            .next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT);
        contents.resize(len as usize, 0);
        Ok(self
            .gpu
            .device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("material"),
                contents: &contents,
                // STORAGE: `RenderOptions::uniforms_as_storage` binds it so.
                usage: wgpu::BufferUsages::UNIFORM
                    | wgpu::BufferUsages::STORAGE
                    | wgpu::BufferUsages::COPY_DST
                    | wgpu::BufferUsages::COPY_SRC,
            }))
    }

    /// The `weft_frame` buffer for a frame binding's layout (one per
    /// distinct layout; every one is written each frame).
    fn frame_block(&mut self, b: &Binding) -> Result<UniformBlock> {
        let layout = b
            .buffer
            .as_ref()
            .map(|buf| (&buf.layout, buf.min_binding_size));
        if let Some((layout, min)) = layout
            && let Some(block) = self
                .frame_blocks
                .iter()
                .find(|f| &f.layout == layout && f.size >= min)
        {
            return Ok(block.clone());
        }
        let block = UniformBlock::new(&self.gpu, b, frame_member_type)?;
        self.frame_blocks.push(block.clone());
        Ok(block)
    }

    /// Creates the samplers and LUT textures `shader`'s bindings describe
    /// that this renderer does not have yet.
    fn prepare_engine_bindings(&mut self, shader: &VariantShader) -> Result<()> {
        for b in &shader.bindings {
            if let Some(s) = &b.sampler {
                let key = sampler_key(s);
                if !self.samplers.contains_key(&key) {
                    let sampler = self.gpu.checked(&format!("sampler `{}`", b.name), || {
                        self.gpu
                            .device
                            .create_sampler(&sampler_descriptor(&b.name, s))
                    })?;
                    self.samplers.insert(key, sampler);
                }
            }
            let Some(r) = engine_resource(b) else {
                continue;
            };
            // The engine interface's LUTs and a material's baked tables
            // (`[tables]`): any resource that ships its texels in a file.
            if r.file.is_none() {
                continue;
            }
            let file = lut_file(b, r)?;
            if self.lut_views.contains_key(&file.path) {
                continue;
            }
            let format = texture_format(&file.format).ok_or_else(|| {
                Error::Metadata(format!(
                    "LUT `{}` has format `{}`, which weft-render cannot create",
                    file.path, file.format
                ))
            })?;
            let texels = self.luts.texels(&r.id, file)?;
            let view = self.gpu.checked(&format!("LUT `{}`", file.path), || {
                lut_texture(&self.gpu, &b.name, file, format, &texels)
            })?;
            self.lut_views.insert(file.path.clone(), view);
        }
        Ok(())
    }

    fn bind_groups(
        &self,
        shader: &VariantShader,
        pipelines: &VariantPipelines,
        uniform: Option<&wgpu::Buffer>,
        frame: Option<&UniformBlock>,
        object: Option<&UniformBlock>,
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
                let resource = self.binding_resource(b, uniform, frame, object, res)?;
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

    /// What one binding binds, chosen from its metadata: a sampler by its
    /// description, engine data by `resource.id`, else the material.
    fn binding_resource<'a>(
        &'a self,
        b: &Binding,
        uniform: Option<&'a wgpu::Buffer>,
        frame: Option<&'a UniformBlock>,
        object: Option<&'a UniformBlock>,
        res: &'a ObjectResources,
    ) -> Result<wgpu::BindingResource<'a>> {
        let not_interface = |why: &str| {
            Error::Metadata(format!(
                "binding `{}` (group {}, binding {}, {:?}) {why}: it is not part of engine \
                 interface {}",
                b.name,
                b.group,
                b.binding,
                b.kind,
                weft_meta::ENGINE_INTERFACE_VERSION
            ))
        };
        if let Some(s) = &b.sampler {
            let sampler = self
                .samplers
                .get(&sampler_key(s))
                .ok_or_else(|| Error::Gpu(format!("sampler `{}` was not created", b.name)))?;
            return Ok(wgpu::BindingResource::Sampler(sampler));
        }
        if let Some(r) = engine_resource(b) {
            let block = |block: Option<&'a UniformBlock>| {
                block
                    .map(|f| f.buffer.as_entire_binding())
                    .ok_or_else(|| not_interface("has no buffer layout"))
            };
            return match r.id.as_str() {
                engine::FRAME => block(frame),
                engine::OBJECT => block(object),
                engine::ENVIRONMENT => Ok(wgpu::BindingResource::TextureView(&res.env.view)),
                _ if r.file.is_some() => {
                    let file = lut_file(b, r)?;
                    let view = self.lut_views.get(&file.path).ok_or_else(|| {
                        Error::Gpu(format!("LUT `{}` was not created", file.path))
                    })?;
                    Ok(wgpu::BindingResource::TextureView(view))
                }
                other => Err(not_interface(&format!(
                    "carries engine resource `{other}`, which weft-render does not provide"
                ))),
            };
        }
        if b.group != engine::MATERIAL_GROUP {
            return Err(not_interface("names no `resource`"));
        }
        if b.buffer.is_some() {
            return Ok(uniform
                .ok_or_else(|| {
                    Error::Metadata(format!(
                        "the variant binds `{}` but has no material_uniform layout",
                        b.name
                    ))
                })?
                .as_entire_binding());
        }
        if b.texture.is_some() {
            return Ok(wgpu::BindingResource::TextureView(
                res.textures
                    .get(&b.binding)
                    .ok_or_else(|| not_interface("has no texture to bind"))?,
            ));
        }
        Err(not_interface(
            "is neither a buffer, a texture nor a sampler",
        ))
    }
}
