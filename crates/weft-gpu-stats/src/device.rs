//! RADV's null device: a Vulkan instance and logical device that compile
//! pipelines for the GPU family named by `RADV_FORCE_FAMILY`, without a GPU.
//!
//! The loader reads `VK_ICD_FILENAMES` and RADV reads `RADV_FORCE_FAMILY`
//! from the process environment, so a process holds one family: the
//! [`crate::worker`] sets both on a child process per family.

use crate::error::{Error, Result, vk_err};
use ash::vk;
use std::ffi::CStr;

/// An instance, the null physical device and a logical device with
/// `VK_KHR_pipeline_executable_properties` and the 16-bit features that `.f16.spv` files need.
pub struct NullDevice {
    _entry: ash::Entry,
    instance: ash::Instance,
    pub(crate) device: ash::Device,
    pub(crate) executables: ash::khr::pipeline_executable_properties::Device,
    /// The driver's device name, e.g. `AMD RADV NAVI21` (for the null device: `Null hardware
    /// (RADV NAVI21)` on some Mesa versions).
    pub device_name: String,
    /// The driver's version string, e.g. `Mesa 22.3.6`.
    pub driver_info: String,
}

impl NullDevice {
    /// Opens the first physical device whose driver is RADV. The caller has set
    /// `VK_ICD_FILENAMES` to RADV's manifest and `RADV_FORCE_FAMILY` to a family.
    pub fn open() -> Result<Self> {
        // SAFETY: loading the system's Vulkan loader runs its initialisers; nothing else
        // in this process holds Vulkan state that they could disturb.
        let entry =
            unsafe { ash::Entry::load() }.map_err(|e| Error::LoaderMissing(e.to_string()))?;
        let app = vk::ApplicationInfo::default()
            .application_name(c"weft-gpu-stats")
            .api_version(vk::API_VERSION_1_3);
        let info = vk::InstanceCreateInfo::default().application_info(&app);
        // SAFETY: `info` and what it points to live across the call.
        let instance = unsafe { entry.create_instance(&info, None) }
            .map_err(vk_err("creating a Vulkan instance on RADV"))?;
        match Self::open_device(&entry, &instance) {
            Ok((device, device_name, driver_info)) => {
                let executables =
                    ash::khr::pipeline_executable_properties::Device::new(&instance, &device);
                Ok(Self {
                    _entry: entry,
                    instance,
                    device,
                    executables,
                    device_name,
                    driver_info,
                })
            }
            Err(e) => {
                // SAFETY: nothing was created from the instance that is still alive.
                unsafe { instance.destroy_instance(None) };
                Err(e)
            }
        }
    }

    fn open_device(
        entry: &ash::Entry,
        instance: &ash::Instance,
    ) -> Result<(ash::Device, String, String)> {
        let _ = entry;
        // SAFETY: `instance` is a live instance.
        let physicals = unsafe { instance.enumerate_physical_devices() }
            .map_err(vk_err("listing Vulkan devices on RADV's null device"))?;
        let mut found = None;
        for pd in physicals {
            let mut driver = vk::PhysicalDeviceDriverProperties::default();
            let mut props = vk::PhysicalDeviceProperties2::default().push_next(&mut driver);
            // SAFETY: `pd` comes from `instance`; `props` chains a valid struct.
            unsafe { instance.get_physical_device_properties2(pd, &mut props) };
            let name = cstr(&props.properties.device_name);
            if driver.driver_id == vk::DriverId::MESA_RADV {
                found = Some((pd, name, cstr(&driver.driver_info)));
                break;
            }
        }
        let (pd, name, driver_info) = found.ok_or_else(|| {
            Error::Unsupported(
                "the Vulkan loader found no RADV device: is VK_ICD_FILENAMES set to RADV's \
                 manifest and RADV_FORCE_FAMILY to a family this Mesa knows (navi21; gfx1100 or navi31)?"
                    .into(),
            )
        })?;
        check_features(instance, pd)?;
        let mut f11 = vk::PhysicalDeviceVulkan11Features::default()
            .storage_buffer16_bit_access(true)
            .uniform_and_storage_buffer16_bit_access(true);
        let mut f12 = vk::PhysicalDeviceVulkan12Features::default().shader_float16(true);
        let mut f13 = vk::PhysicalDeviceVulkan13Features::default().dynamic_rendering(true);
        let mut exec = vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR::default()
            .pipeline_executable_info(true);
        let priorities = [1.0f32];
        // The queue is never used (the null device submits nothing); Vulkan requires one.
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(0)
            .queue_priorities(&priorities)];
        let extensions = [ash::khr::pipeline_executable_properties::NAME.as_ptr()];
        let info = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_extension_names(&extensions)
            .push_next(&mut f11)
            .push_next(&mut f12)
            .push_next(&mut f13)
            .push_next(&mut exec);
        // SAFETY: `pd` belongs to `instance`; `info` and its chain live across the call.
        let device = unsafe { instance.create_device(pd, &info, None) }
            .map_err(vk_err(format!("creating a logical device on {name}")))?;
        Ok((device, name, driver_info))
    }
}

/// Checks that the device offers what the pipelines need, naming what is missing.
fn check_features(instance: &ash::Instance, pd: vk::PhysicalDevice) -> Result<()> {
    let mut f11 = vk::PhysicalDeviceVulkan11Features::default();
    let mut f12 = vk::PhysicalDeviceVulkan12Features::default();
    let mut f13 = vk::PhysicalDeviceVulkan13Features::default();
    let mut exec = vk::PhysicalDevicePipelineExecutablePropertiesFeaturesKHR::default();
    let mut all = vk::PhysicalDeviceFeatures2::default()
        .push_next(&mut f11)
        .push_next(&mut f12)
        .push_next(&mut f13)
        .push_next(&mut exec);
    // SAFETY: `pd` belongs to `instance`; the chain holds valid structs.
    unsafe { instance.get_physical_device_features2(pd, &mut all) };
    let needed = [
        ("pipelineExecutableInfo", exec.pipeline_executable_info),
        ("dynamicRendering", f13.dynamic_rendering),
        ("shaderFloat16", f12.shader_float16),
        ("storageBuffer16BitAccess", f11.storage_buffer16_bit_access),
        (
            "uniformAndStorageBuffer16BitAccess",
            f11.uniform_and_storage_buffer16_bit_access,
        ),
    ];
    let missing: Vec<&str> = needed
        .iter()
        .filter(|(_, on)| *on == vk::FALSE)
        .map(|(n, _)| *n)
        .collect();
    if missing.is_empty() {
        Ok(())
    } else {
        Err(Error::Unsupported(format!(
            "RADV's null device lacks {} (Mesa too old? 22.3 has them)",
            missing.join(", ")
        )))
    }
}

impl Drop for NullDevice {
    fn drop(&mut self) {
        // SAFETY: every object created from the device was destroyed by its owner
        // (pipelines, layouts and modules are scoped to one compile); the device
        // goes before the instance.
        unsafe {
            self.device.destroy_device(None);
            self.instance.destroy_instance(None);
        }
    }
}

/// A driver-filled, NUL-terminated fixed-size string.
pub(crate) fn cstr(chars: &[std::ffi::c_char]) -> String {
    // SAFETY: c_char and u8 have the same size and alignment; the slice stays borrowed.
    let bytes: &[u8] = unsafe { std::slice::from_raw_parts(chars.as_ptr().cast(), chars.len()) };
    CStr::from_bytes_until_nul(bytes)
        .map(|c| c.to_string_lossy().into_owned())
        .unwrap_or_else(|_| String::from_utf8_lossy(bytes).into_owned())
}
