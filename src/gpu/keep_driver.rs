//! The window's GPU driver stays loaded until the process ends. When eframe drops the
//! window's wgpu instance, the last EGL display ends and Mesa unloads its GL driver
//! (`swrast_dri.so`, llvmpipe, Mesa 22.3), yet an exit handler registered for it stays in
//! libc's list: now and then (3 of some 180 lab windows under load here, and once in CI)
//! the process then crashed with SIGSEGV in `exit`, after its screenshot and frame log were
//! written. Keeping one device keeps its instance, whose display keeps the driver mapped
//! until the operating system takes the whole process back (docs/design.md §5.10).

/// Keeps `device` (the first one given) for the rest of the process.
#[cfg(not(target_arch = "wasm32"))]
pub fn keep_driver_loaded(device: &wgpu::Device) {
    static KEPT: std::sync::OnceLock<wgpu::Device> = std::sync::OnceLock::new();
    KEPT.get_or_init(|| device.clone());
}
