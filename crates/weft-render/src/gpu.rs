//! The wgpu device: Vulkan only (lavapipe on machines without a GPU).

use crate::error::{Error, Result};
use std::sync::{Arc, Mutex};

/// The variable that picks the adapter [`Gpu::new`] uses: unset or empty,
/// wgpu's default; `hardware`, the first adapter that is not a CPU
/// rasteriser (discrete GPUs first); anything else, the first adapter whose
/// name contains it (case-insensitive, e.g. `llvmpipe`, `nvidia`).
pub const ADAPTER_VARIABLE: &str = "WEFT_ADAPTER";

/// Which adapter to use (see [`ADAPTER_VARIABLE`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum AdapterChoice {
    Default,
    Hardware,
    NameContains(String),
}

impl AdapterChoice {
    /// Reads a value of [`ADAPTER_VARIABLE`].
    pub fn parse(value: &str) -> AdapterChoice {
        match value.trim() {
            "" => AdapterChoice::Default,
            v if v.eq_ignore_ascii_case("hardware") => AdapterChoice::Hardware,
            v => AdapterChoice::NameContains(v.to_lowercase()),
        }
    }

    fn spelling(&self) -> &str {
        match self {
            AdapterChoice::Default => "",
            AdapterChoice::Hardware => "hardware",
            AdapterChoice::NameContains(s) => s,
        }
    }

    /// The index of the chosen adapter in `adapters` (None: no match).
    pub fn pick(&self, adapters: &[wgpu::AdapterInfo]) -> Option<usize> {
        use wgpu::DeviceType as T;
        match self {
            AdapterChoice::Default => (!adapters.is_empty()).then_some(0),
            AdapterChoice::Hardware => [T::DiscreteGpu, T::IntegratedGpu, T::VirtualGpu, T::Other]
                .iter()
                .find_map(|kind| adapters.iter().position(|a| a.device_type == *kind)),
            AdapterChoice::NameContains(part) => adapters
                .iter()
                .position(|a| a.name.to_lowercase().contains(part.as_str())),
        }
    }
}

/// An adapter, device and queue on the Vulkan backend.
pub struct Gpu {
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    uncaptured: Arc<Mutex<Vec<String>>>,
}

impl Gpu {
    /// Whether the device draws half-precision files (`shader-f16`).
    pub fn has_shader_f16(&self) -> bool {
        self.device.features().contains(wgpu::Features::SHADER_F16)
    }

    /// Requests a Vulkan adapter and a device: the one [`ADAPTER_VARIABLE`]
    /// names, else wgpu's default choice. Fails (never skips) with an
    /// [`Error::NoAdapter`] that says to install `mesa-vulkan-drivers` when
    /// there is none.
    pub fn new() -> Result<Gpu> {
        let choice = std::env::var(ADAPTER_VARIABLE).unwrap_or_default();
        pollster::block_on(Gpu::new_async(AdapterChoice::parse(&choice)))
    }

    async fn new_async(choice: AdapterChoice) -> Result<Gpu> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::VULKAN;
        let instance = wgpu::Instance::new(desc);
        let adapter = match &choice {
            AdapterChoice::Default => instance
                .request_adapter(&wgpu::RequestAdapterOptions {
                    power_preference: wgpu::PowerPreference::None,
                    force_fallback_adapter: false,
                    compatible_surface: None,
                    apply_limit_buckets: false,
                })
                .await
                .map_err(|e| Error::NoAdapter(e.to_string()))?,
            _ => {
                let adapters = instance.enumerate_adapters(wgpu::Backends::VULKAN).await;
                let infos: Vec<wgpu::AdapterInfo> = adapters.iter().map(|a| a.get_info()).collect();
                let index = choice.pick(&infos).ok_or_else(|| {
                    let found: Vec<String> = infos
                        .iter()
                        .map(|i| format!("{} ({:?})", i.name, i.device_type))
                        .collect();
                    Error::NoAdapter(format!(
                        "{ADAPTER_VARIABLE}={} matches none of the Vulkan adapters found: {}",
                        choice.spelling(),
                        if found.is_empty() {
                            "none".to_string()
                        } else {
                            found.join(", ")
                        }
                    ))
                })?;
                adapters
                    .into_iter()
                    .nth(index)
                    .expect("pick returns an index into the list")
            }
        };
        let info = adapter.get_info();
        // Blending into an Rgba32Float target needs FLOAT32_BLENDABLE;
        // `Renderer::time_frames` uses TIMESTAMP_QUERY when the adapter has it;
        // half-precision variants' f16 files need SHADER_F16 (without it
        // their f32 files are drawn: pipelines::draws_f16).
        let wanted = wgpu::Features::FLOAT32_BLENDABLE
            | wgpu::Features::TIMESTAMP_QUERY
            | wgpu::Features::SHADER_F16;
        let required_features = adapter.features() & wanted;
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("weft-render"),
                required_features,
                required_limits: wgpu::Limits::default().using_resolution(adapter.limits()),
                experimental_features: wgpu::ExperimentalFeatures::disabled(),
                memory_hints: wgpu::MemoryHints::Performance,
                trace: wgpu::Trace::Off,
            })
            .await
            .map_err(|e| Error::Gpu(format!("cannot create a device on {}: {e}", info.name)))?;
        let uncaptured = Arc::new(Mutex::new(Vec::new()));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            if let Ok(mut v) = sink.lock() {
                v.push(e.to_string());
            }
        }));
        Ok(Gpu {
            adapter,
            device,
            queue,
            info,
            uncaptured,
        })
    }

    pub fn adapter_info(&self) -> &wgpu::AdapterInfo {
        &self.info
    }

    /// One line: name, driver, backend and device type.
    pub fn describe(&self) -> String {
        let i = &self.info;
        format!(
            "{} ({} {}; {:?}, {:?})",
            i.name, i.driver, i.driver_info, i.backend, i.device_type
        )
    }

    /// Runs `f` inside a validation error scope and turns a captured error
    /// (or any uncaptured one reported meanwhile) into [`Error::Gpu`].
    pub(crate) fn checked<T>(&self, what: &str, f: impl FnOnce() -> T) -> Result<T> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let out = f();
        let err = pollster::block_on(scope.pop());
        if let Some(e) = err {
            return Err(Error::Gpu(format!("{what}: {e}")));
        }
        self.take_uncaptured(what)?;
        Ok(out)
    }

    pub(crate) fn take_uncaptured(&self, what: &str) -> Result<()> {
        let mut v = self
            .uncaptured
            .lock()
            .map_err(|_| Error::Gpu("poisoned".into()))?;
        if v.is_empty() {
            Ok(())
        } else {
            let msg = v.join("; ");
            v.clear();
            Err(Error::Gpu(format!("{what}: {msg}")))
        }
    }

    pub(crate) fn wait(&self) -> Result<()> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
            .map_err(|e| Error::Gpu(format!("poll: {e}")))
    }

    /// Runs a one-dispatch compute kernel over storage buffers: binding 0 of
    /// group 0 is `input` (read-only), binding 1 an `output_size`-byte
    /// read-write buffer that is read back. `workgroups` along x. Used by the
    /// numerical tests that evaluate library BSDF functions on the GPU.
    pub fn run_compute(
        &self,
        wgsl: &str,
        entry: &str,
        input: &[u8],
        output_size: u64,
        workgroups: u32,
    ) -> Result<Vec<u8>> {
        use wgpu::util::DeviceExt;
        let device = &self.device;
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(entry),
            source: wgpu::ShaderSource::Wgsl(wgsl.into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: None,
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(Error::Gpu(format!("compute kernel `{entry}`: {e}")));
        }
        let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("compute input"),
            contents: input,
            usage: wgpu::BufferUsages::STORAGE,
        });
        let output = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("compute output"),
            size: output_size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: None,
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: output.as_entire_binding(),
                },
            ],
        });
        let mut enc = device.create_command_encoder(&Default::default());
        {
            let mut pass = enc.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(workgroups, 1, 1);
        }
        self.queue.submit([enc.finish()]);
        self.read_buffer(&output)
    }

    /// Reads a whole buffer (it needs `COPY_SRC`) back to the CPU.
    pub fn read_buffer(&self, buffer: &wgpu::Buffer) -> Result<Vec<u8>> {
        let size = buffer.size();
        let staging = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("weft readback"),
            size,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut enc = self.device.create_command_encoder(&Default::default());
        enc.copy_buffer_to_buffer(buffer, 0, &staging, 0, size);
        self.queue.submit([enc.finish()]);
        self.map_read(&staging)
    }

    /// Reads one mip level of one layer of a 4-byte-per-texel texture (it
    /// needs `COPY_SRC`) back to the CPU, rows tightly packed.
    #[cfg(test)]
    pub(crate) fn read_texture_rgba8(
        &self,
        texture: &wgpu::Texture,
        mip: u32,
        layer: u32,
    ) -> Result<Vec<u8>> {
        let size = texture.size().mip_level_size(mip, texture.dimension());
        let (width, height) = (size.width, size.height);
        let row = (width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let staging = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("weft texture readback"),
            size: u64::from(row * height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        let mut enc = self.device.create_command_encoder(&Default::default());
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: mip,
                origin: wgpu::Origin3d {
                    x: 0,
                    y: 0,
                    z: layer,
                },
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
            wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: 1,
            },
        );
        self.queue.submit([enc.finish()]);
        let padded = self.map_read(&staging)?;
        Ok(padded
            .chunks_exact(row as usize)
            .flat_map(|r| &r[..(width * 4) as usize])
            .copied()
            .collect())
    }

    pub(crate) fn map_read(&self, staging: &wgpu::Buffer) -> Result<Vec<u8>> {
        let (tx, rx) = std::sync::mpsc::channel();
        staging.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        self.wait()?;
        rx.recv()
            .map_err(|_| Error::Gpu("readback never completed".into()))?
            .map_err(|e| Error::Gpu(format!("readback: {e}")))?;
        let bytes = {
            let view = staging
                .get_mapped_range(..)
                .map_err(|e| Error::Gpu(format!("readback: {e}")))?;
            view.to_vec()
        };
        staging.unmap();
        Ok(bytes)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(name: &str, device_type: wgpu::DeviceType) -> wgpu::AdapterInfo {
        wgpu::AdapterInfo {
            name: name.into(),
            ..wgpu::AdapterInfo::new(device_type, wgpu::Backend::Vulkan)
        }
    }

    #[test]
    fn hardware_skips_cpu_rasterisers_and_prefers_discrete_gpus() {
        use wgpu::DeviceType as T;
        let found = [
            info("llvmpipe (LLVM 15.0.6, 256 bits)", T::Cpu),
            info("Intel(R) UHD Graphics 630", T::IntegratedGpu),
            info("NVIDIA H100 80GB HBM3", T::DiscreteGpu),
        ];
        assert_eq!(AdapterChoice::parse("hardware").pick(&found), Some(2));
        assert_eq!(
            AdapterChoice::parse(" HARDWARE ").pick(&found[..2]),
            Some(1)
        );
        assert_eq!(AdapterChoice::parse("hardware").pick(&found[..1]), None);
        assert_eq!(AdapterChoice::parse("LLVMpipe").pick(&found), Some(0));
        assert_eq!(AdapterChoice::parse("nvidia").pick(&found), Some(2));
        assert_eq!(AdapterChoice::parse("radeon").pick(&found), None);
        assert_eq!(AdapterChoice::parse("").pick(&found), Some(0));
        assert_eq!(AdapterChoice::parse(""), AdapterChoice::Default);
    }
}
