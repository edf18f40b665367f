//! The engine's wgpu device: Vulkan only (lavapipe on machines without a
//! GPU). No adapter is a failure with what to install, never a skip.

use std::sync::{Arc, Mutex};

pub struct Engine {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub adapter_info: wgpu::AdapterInfo,
    /// Whether SPIR-V can be handed to the driver as is.
    pub passthrough: bool,
    uncaptured: Arc<Mutex<Vec<String>>>,
}

impl Engine {
    /// A Vulkan device; with `passthrough`, one with
    /// `Features::PASSTHROUGH_SHADERS` (SPIR-V modules given to the driver
    /// untouched).
    pub fn new(passthrough: bool) -> Engine {
        pollster::block_on(Engine::new_async(passthrough))
    }

    async fn new_async(passthrough: bool) -> Engine {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::VULKAN;
        let instance = wgpu::Instance::new(desc);
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::None,
                force_fallback_adapter: false,
                compatible_surface: None,
                apply_limit_buckets: false,
            })
            .await
            .unwrap_or_else(|e| {
                panic!(
                    "no Vulkan adapter ({e}): install Mesa's software Vulkan driver \
                     (`apt-get install -y mesa-vulkan-drivers libvulkan1`, see .ci/run)"
                )
            });
        let adapter_info = adapter.get_info();
        let mut required_features = wgpu::Features::empty();
        if passthrough {
            assert!(
                adapter
                    .features()
                    .contains(wgpu::Features::PASSTHROUGH_SHADERS),
                "{}: no PASSTHROUGH_SHADERS",
                adapter_info.name
            );
            required_features |= wgpu::Features::PASSTHROUGH_SHADERS;
        }
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("independent engine"),
                required_features,
                required_limits: wgpu::Limits::default().using_resolution(adapter.limits()),
                experimental_features: wgpu::ExperimentalFeatures::disabled(),
                memory_hints: wgpu::MemoryHints::Performance,
                trace: wgpu::Trace::Off,
            })
            .await
            .unwrap_or_else(|e| panic!("no device on {}: {e}", adapter_info.name));
        let uncaptured = Arc::new(Mutex::new(Vec::new()));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| {
            sink.lock().unwrap().push(e.to_string());
        }));
        Engine {
            device,
            queue,
            adapter_info,
            passthrough,
            uncaptured,
        }
    }

    pub fn describe(&self) -> String {
        let i = &self.adapter_info;
        format!("{} ({}; {:?})", i.name, i.driver_info, i.backend)
    }

    /// Runs `f` in a validation error scope; a validation error (or an
    /// uncaptured one reported meanwhile) becomes `Err`.
    pub fn checked<T>(&self, what: &str, f: impl FnOnce() -> T) -> Result<T, String> {
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let out = f();
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(format!("{what}: {e}"));
        }
        self.take_uncaptured(what)?;
        Ok(out)
    }

    pub fn take_uncaptured(&self, what: &str) -> Result<(), String> {
        let mut v = self.uncaptured.lock().unwrap();
        if v.is_empty() {
            return Ok(());
        }
        let msg = v.join("; ");
        v.clear();
        Err(format!("{what}: {msg}"))
    }

    pub fn wait(&self) -> Result<(), String> {
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map(|_| ())
            .map_err(|e| format!("poll: {e}"))
    }
}
