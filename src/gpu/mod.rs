//! The GPU side: headless device set-up, one Rust module per WGSL file (`brdf`, `ltc`,
//! `ltc_f16`, `scene`, `plane`, `bin`, `display`), the plane's renderer and one render of it
//! (`renderer`, `plane_render`), and timing. Shaders are composed from the embedded files at
//! load time.

pub mod bin;
pub mod binding;
pub mod brdf;
pub mod brdf_aniso;
pub mod display;
pub mod driver_output;
pub mod failures;
pub mod keep_driver;
pub mod light;
pub mod limits;
pub mod ltc;
pub mod ltc_aniso;
pub mod ltc_f16;
pub mod method_file;
pub mod plane;
pub mod plane_render;
pub mod renderer;
pub mod scene;
pub mod selfcheck;
pub mod target;
pub mod timing;
pub mod work;

pub use light::*;

use crate::error::Error;

/// The WGSL of the plane shader without a method file (`plane_module_source_with`).
pub fn plane_module_source(f16: bool) -> String {
    plane_module_source_with(f16, None)
}

/// The WGSL of the plane shader: brdf.wgsl, brdf_aniso.wgsl, ltc.wgsl, ltc_aniso.wgsl,
/// the lights' files (`light::sources`), scene.wgsl, light_shape.wgsl, plane.wgsl, method_file.wgsl and
/// ltc_f16.wgsl (behind `enable f16;`) — or, without f16, a stub in place of the last — and
/// then `file` as composed after them (or, without one, the stubs of its functions).
pub fn plane_module_source_with(f16: bool, file: Option<&method_file::MethodFile>) -> String {
    let (enable, last) = if f16 {
        (ltc_f16::ENABLE, ltc_f16::SOURCE)
    } else {
        ("", ltc_f16::STUB)
    };
    let lab = [
        enable,
        brdf::SOURCE,
        brdf_aniso::SOURCE,
        ltc::SOURCE,
        ltc_aniso::SOURCE,
        &light::sources(),
        scene::SOURCE,
        light_shape::SOURCE,
        plane::SOURCE,
        method_file::SOURCE,
        last,
    ]
    .join("\n");
    let after = file.map_or_else(method_file::no_file, |f| f.composed(&lab));
    format!("{lab}\n{after}")
}

/// The WGSL of the binning shader: scene.wgsl and bin.wgsl.
pub fn bin_module_source() -> String {
    [scene::SOURCE, bin::SOURCE].join("\n")
}

/// What this project asks of a device, the command line's and the lab window's alike:
/// timestamp queries and f16 shaders where the adapter has them, and the adapter's own limits
/// (the largest light buffer, 2 GiB bindings on a big GPU rather than WebGPU's defaults).
pub fn device_descriptor(adapter: &wgpu::Adapter) -> wgpu::DeviceDescriptor<'static> {
    wgpu::DeviceDescriptor {
        label: Some("ltc-lab"),
        required_features: adapter.features()
            & (wgpu::Features::TIMESTAMP_QUERY | wgpu::Features::SHADER_F16),
        required_limits: adapter.limits(),
        experimental_features: wgpu::ExperimentalFeatures::disabled(),
        memory_hints: wgpu::MemoryHints::Performance,
        trace: wgpu::Trace::Off,
    }
}

/// A device and what was chosen (cloned: the handles are shared, not the device), and what
/// went wrong on it so far.
#[derive(Clone)]
pub struct GpuContext {
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    pub info: wgpu::AdapterInfo,
    pub limits: wgpu::Limits,
    /// The adapter's downlevel flags (what its shaders take, with the device's features).
    pub downlevel: wgpu::DownlevelFlags,
    /// Its uncaptured errors and its loss, kept instead of wgpu's panic.
    pub failures: failures::Failures,
}

impl GpuContext {
    /// The default adapter without a window (`WGPU_BACKEND` picks the backend), with
    /// timestamp queries where it has them and its own limits (for the largest light buffer).
    /// Not in the browser, which cannot block on it: the lab there uses eframe's device.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new() -> Result<Self, Error> {
        let (opened, drivers_said) = driver_output::held_back(Self::open);
        opened.map_err(|e| Error {
            message: format!("{}{}", e.message, driver_output::as_note(&drivers_said)),
            ..e
        })
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn open() -> Result<Self, Error> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            force_fallback_adapter: false,
            compatible_surface: None,
            // Bucketing hides the adapter's true limits (a fingerprinting defence for the
            // web); a headless lab wants the real ones (the largest light buffer).
            apply_limit_buckets: false,
        }))
        .map_err(|e| {
            Error::machine(
                "GPU",
                format!("no adapter found ({e}); install a Vulkan driver (mesa-vulkan-drivers gives a CPU one) or render on the CPU"),
            )
        })?;
        let info = adapter.get_info();
        let downlevel = adapter.get_downlevel_capabilities().flags;
        let (device, queue) = pollster::block_on(
            adapter.request_device(&device_descriptor(&adapter)),
        )
        .map_err(|e| {
            Error::machine(
                format!("GPU {}", info.name),
                format!("cannot open the device: {e}"),
            )
        })?;
        Ok(Self::from_parts(device, queue, info, downlevel))
    }

    /// A device opened elsewhere (the lab's window's), with `device_descriptor`'s features
    /// where it was asked for them; its failures watched from now on (`Failures::watch`: once
    /// per device, cloned after).
    pub fn from_parts(
        device: wgpu::Device,
        queue: wgpu::Queue,
        info: wgpu::AdapterInfo,
        downlevel: wgpu::DownlevelFlags,
    ) -> Self {
        let limits = device.limits();
        let failures = failures::Failures::watch(&device);
        Self {
            device,
            queue,
            info,
            limits,
            downlevel,
            failures,
        }
    }

    /// The device's name for a message (`GPU lavapipe`).
    pub fn name(&self) -> String {
        format!("GPU {}", self.info.name)
    }

    /// Refuses to go on where the device was lost or reported an error (`Failures::check`).
    pub fn check(&self) -> Result<(), Error> {
        self.failures.check(&self.name())
    }

    /// One line for the log: name, backend, type, timestamps.
    pub fn describe(&self) -> String {
        format!(
            "{} ({:?}, {:?}{})",
            // A browser may keep the adapter's name to itself (a fingerprinting defence).
            if self.info.name.is_empty() {
                "unnamed adapter"
            } else {
                &self.info.name
            },
            self.info.backend,
            self.info.device_type,
            if self.has_timestamps() {
                ", timestamp queries"
            } else {
                ", no timestamp queries: timing by wall clock"
            }
        )
    }

    /// Whether the device runs f16 shaders (the `ltc-f16` method).
    pub fn has_f16(&self) -> bool {
        self.device.features().contains(wgpu::Features::SHADER_F16)
    }

    pub fn has_timestamps(&self) -> bool {
        self.device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY)
    }
}
