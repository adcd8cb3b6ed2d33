//! A render's image read back, waiting or not, and refused where a method file was stopped;
//! and the method file's probe of one image point, light by light.

use super::PlaneRender;
use crate::error::{Error, Result};
use crate::gpu::GpuContext;
use crate::gpu::target::PendingRead;
use crate::render::Frame;

impl PlaneRender {
    /// Fills the image with NaN, so that a pixel no pass writes shows.
    pub fn poison(&self, ctx: &GpuContext) {
        self.kept.target.poison(ctx);
    }

    /// The image, read back (blocks); refused where a method file's loops were stopped.
    pub fn read(&self, ctx: &GpuContext) -> Result<Frame> {
        let (frame, stopped) = self.kept.target.read(ctx, &self.settings)?;
        self.check_stopped(stopped)?;
        Ok(frame)
    }

    /// An error naming the method file where `stopped` (the image's mark, `Target::read`).
    fn check_stopped(&self, stopped: bool) -> Result<()> {
        match (&self.file, stopped) {
            (Some(name), true) => Err(Error::input(
                name,
                format!(
                    "stopped: its loops ran past {} steps for one light (docs/design.md §5.13)",
                    crate::gpu::method_file::STEPS
                ),
            )),
            _ => Ok(()),
        }
    }

    /// Starts reading the image back without waiting (the browser cannot wait):
    /// `PendingRead::try_take` gives its texels once the GPU is done, and `frame_of` the
    /// frame that `read` gives.
    pub fn start_read(&self, ctx: &GpuContext) -> PendingRead {
        self.kept.target.start_read(ctx)
    }

    /// The frame of texels that `start_read` fetched.
    pub fn frame_of(&self, texels: &[u8]) -> Frame {
        self.kept.target.frame_of(texels, &self.settings)
    }

    /// Refused where the texels `start_read` fetched carry a method file's stop.
    pub fn check_texels(&self, texels: &[u8]) -> Result<()> {
        self.check_stopped(crate::gpu::target::stopped(texels))
    }

    /// The method file's probe (`probe_file`): each light alone at the image point `at`
    /// (pixels), with the camera's `aspect` in place of this image's; each light's radiance,
    /// `None` where the point is off the plane or seen from below. Blocks.
    pub fn probe(
        &mut self,
        ctx: &GpuContext,
        pipeline: &wgpu::ComputePipeline,
        at: [f32; 2],
        aspect: f32,
    ) -> Result<Option<Vec<glam::DVec3>>> {
        self.params.probe_x = at[0];
        self.params.probe_y = at[1];
        self.params.aspect = aspect;
        self.write_params(ctx);
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("probe"),
            });
        let n = self.light_count as u32;
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("probe"),
                timestamp_writes: None,
            });
            pass.set_bind_group(0, &self.plane_group, &[]);
            pass.set_pipeline(pipeline);
            pass.dispatch_workgroups(n.div_ceil(64).max(1), 1, 1);
        }
        ctx.queue.submit([encoder.finish()]);
        let bytes = u64::from(n.max(1)) * 16;
        let data = crate::gpu::target::read_buffer(ctx, &self.kept.target.sums[0], 0, bytes)
            .ok_or_else(|| Error::machine("GPU", "the probe's read-back failed"))?;
        let values: Vec<[f32; 4]> = data
            .chunks_exact(16)
            .map(bytemuck::pod_read_unaligned)
            .take(n as usize)
            .collect();
        if values.first().is_some_and(|v| v[3] < 0.5) {
            return Ok(None);
        }
        Ok(Some(
            values
                .iter()
                .map(|v| glam::DVec3::new(v[0].into(), v[1].into(), v[2].into()))
                .collect(),
        ))
    }

    /// The output texture (for the lab to show without a read-back).
    pub fn output(&self) -> &wgpu::TextureView {
        &self.kept.target.view
    }
}
