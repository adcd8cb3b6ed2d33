//! The window's device: eframe's (or a test harness's) wgpu device, which the plane shades on
//! and the chart measures on, and what eframe is asked for when it opens one.

use std::sync::Arc;

use crate::gpu::GpuContext;

/// The window's wgpu set-up: the default one (`WGPU_BACKEND` honoured) asking the device for
/// what the plane's renderer uses — timestamp queries for its budget, f16 shaders, the
/// adapter's own limits for the largest light buffer (`gpu::device_descriptor`).
pub fn wgpu_setup() -> egui_wgpu::WgpuSetup {
    let mut setup = egui_wgpu::WgpuSetupCreateNew::without_display_handle();
    setup.device_descriptor = Arc::new(crate::gpu::device_descriptor);
    setup.into()
}

/// The device of the window's render state, or why the plane cannot be shaded on it: the
/// window draws without wgpu, or its device has no compute shaders (WebGL2 draws the window
/// but has neither compute shaders nor storage buffers). The plane is then shaded on the CPU.
pub fn of_window(render_state: Option<&egui_wgpu::RenderState>) -> Result<GpuContext, String> {
    let rs = render_state.ok_or("the window draws without wgpu")?;
    let downlevel = rs.adapter.get_downlevel_capabilities();
    if !downlevel
        .flags
        .contains(wgpu::DownlevelFlags::COMPUTE_SHADERS)
    {
        return Err(format!(
            "{} has no compute shaders (WebGL2?)",
            rs.adapter.get_info().name
        ));
    }
    Ok(GpuContext::from_parts(
        rs.device.clone(),
        rs.queue.clone(),
        rs.adapter.get_info(),
        downlevel.flags,
    ))
}
