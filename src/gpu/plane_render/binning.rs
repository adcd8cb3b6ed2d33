//! How far a render's tile lists are made, and their making band by band over frames
//! (docs/design.md §4).

use super::PlaneRender;
use crate::gpu::GpuContext;
use crate::gpu::bin::BinPass;

/// Where the making of the tile lists is: the next band of tile rows to count, or to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum BinStage {
    Count(u32),
    Write(u32),
}

impl PlaneRender {
    /// How far the tile lists are made, 0 to 1; `None` when they are (or there are none).
    pub fn binning_progress(&self) -> Option<f32> {
        let rows = self.kept.target.tiles.1 as f32;
        self.bin_stage.map(|stage| match stage {
            BinStage::Count(r) => r as f32 / (2.0 * rows),
            BinStage::Write(r) => (rows + r as f32) / (2.0 * rows),
        })
    }

    /// Makes the next `rows` tile rows of the tile lists (counting them, then writing them):
    /// binning spread over frames. One submission, timed in `Slot::Bin`. Does nothing when
    /// the lists are made.
    pub fn bin_step(&mut self, ctx: &GpuContext, rows: usize) {
        let Some(stage) = self.bin_stage else {
            return;
        };
        let (tiles_x, tiles_y) = self.tiles();
        let (first, pass) = match stage {
            BinStage::Count(r) => (r, BinPass::Count),
            BinStage::Write(0) => (0, BinPass::ScanThenWrite),
            BinStage::Write(r) => (r, BinPass::Write),
        };
        let end = (first + rows.max(1) as u32).min(tiles_y);
        self.params.bin_row = first;
        self.write_params(ctx);
        let mut encoder = ctx
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("bin band"),
            });
        let mut timer = self.kept.timer.take();
        let mut timing = timer.as_mut().filter(|t| t.can_resolve());
        if let Some(t) = &mut timing {
            t.clear();
        }
        let band = (tiles_x, end - first, pass);
        self.binning
            .encode_band(&mut encoder, &self.bin_group, band, timing.as_deref_mut());
        let timed = timing.is_some();
        if let Some(t) = timing {
            t.resolve(&mut encoder);
        }
        ctx.queue.submit([encoder.finish()]);
        if timed && let Some(t) = &mut timer {
            t.request();
        }
        self.kept.timer = timer;
        self.bin_stage = match (pass, end == tiles_y) {
            (BinPass::Count, true) => Some(BinStage::Write(0)),
            (BinPass::Count, false) => Some(BinStage::Count(end)),
            (_, true) => None,
            (_, false) => Some(BinStage::Write(end)),
        };
    }

    /// The entries of its tile lists, read back (blocks): how much culling kept of
    /// `tiles × lights`. `None` where it is not culled or not yet binned (or the device
    /// could not read them back).
    pub fn tile_entries(&self, ctx: &GpuContext) -> Option<(u64, u64)> {
        let t = &self.kept.target;
        if self.params.cull == 0 || self.bin_stage.is_some() {
            return None;
        }
        let all = (t.tiles.0 * t.tiles.1 * self.light_count) as u64;
        Some((t.tile_entries(ctx)?, all))
    }
}
