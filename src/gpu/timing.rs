//! GPU time of compute passes from timestamp queries: each pass a slot (its beginning and end),
//! read back after the submission, blocking (the command line) or when ready (the lab).

use std::sync::Arc;
use std::sync::atomic::{AtomicU8, Ordering};

/// The passes one render times.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slot {
    /// Binning the lights into tiles (culled renders only).
    Bin = 0,
    /// Summing the lights.
    Shade = 1,
}

const SLOTS: u32 = 2;
const WAITING: u8 = 0;
const MAPPED: u8 = 1;
const FAILED: u8 = 2;
const QUERIES: u32 = 2 * SLOTS;
const RESOLVE_BYTES: u64 = QUERIES as u64 * 8;

/// GPU milliseconds per slot; `None` for a slot not written since the last `clear`.
pub type SlotTimes = [Option<f64>; SLOTS as usize];

/// The GPU milliseconds of one frame's passes.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameTimes {
    /// Binning (culled renders), timestamps; `None` when there was none.
    pub bin_ms: Option<f64>,
    /// Shading (timestamps), or submit-to-done wall clock of the whole frame without them.
    pub shade_ms: f64,
}

impl FrameTimes {
    pub fn total_ms(&self) -> f64 {
        self.shade_ms + self.bin_ms.unwrap_or(0.0)
    }

    /// The slots' times, or the wall clock where the shading pass was not timed.
    pub fn from_slots(slots: SlotTimes, wall_ms: f64) -> Self {
        match slots[Slot::Shade as usize] {
            Some(shade_ms) => Self {
                bin_ms: slots[Slot::Bin as usize],
                shade_ms,
            },
            None => Self {
                bin_ms: None,
                shade_ms: wall_ms,
            },
        }
    }
}

/// Times the passes of one submission.
pub struct PassTimer {
    query_set: wgpu::QuerySet,
    resolve: wgpu::Buffer,
    readback: wgpu::Buffer,
    /// Nanoseconds per timestamp tick.
    period_ns: f64,
    written: [bool; SLOTS as usize],
    /// A read-back in flight (`request`): `WAITING`, `MAPPED` or `FAILED`.
    pending: Option<Arc<AtomicU8>>,
    pending_written: [bool; SLOTS as usize],
}

impl PassTimer {
    /// `None` where the device lacks `TIMESTAMP_QUERY`.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Option<Self> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        let query_set = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("pass timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count: QUERIES,
        });
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("timestamp resolve"),
            size: RESOLVE_BYTES,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("timestamp readback"),
            size: RESOLVE_BYTES,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        Some(Self {
            query_set,
            resolve,
            readback,
            period_ns: f64::from(queue.get_timestamp_period()),
            written: [false; SLOTS as usize],
            pending: None,
            pending_written: [false; SLOTS as usize],
        })
    }

    /// Forgets which slots were written (at the start of a submission).
    pub fn clear(&mut self) {
        self.written = [false; SLOTS as usize];
    }

    /// The timestamp writes of a pass in `slot`.
    pub fn writes(&mut self, slot: Slot) -> wgpu::ComputePassTimestampWrites<'_> {
        self.written[slot as usize] = true;
        let k = 2 * slot as u32;
        wgpu::ComputePassTimestampWrites {
            query_set: &self.query_set,
            beginning_of_pass_write_index: Some(k),
            end_of_pass_write_index: Some(k + 1),
        }
    }

    /// Whether a read-back is in flight (`try_read` will have it, or say it failed).
    pub fn pending(&self) -> bool {
        self.pending.is_some()
    }

    /// Whether the read-back buffer is free for `resolve` (no read-back in flight).
    pub fn can_resolve(&self) -> bool {
        self.pending.is_none()
    }

    /// Records the copy of the timestamps after the passes (only if `can_resolve`).
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        encoder.resolve_query_set(&self.query_set, 0..QUERIES, &self.resolve, 0);
        encoder.copy_buffer_to_buffer(&self.resolve, 0, &self.readback, 0, RESOLVE_BYTES);
    }

    /// The milliseconds of each written slot, once the submission is done (blocks).
    pub fn read_ms(&mut self, device: &wgpu::Device) -> SlotTimes {
        self.request();
        let _ = device.poll(wgpu::PollType::wait_indefinitely());
        self.try_read().unwrap_or([None; SLOTS as usize])
    }

    /// Starts the read-back of the last resolved timestamps (after the submission).
    pub fn request(&mut self) {
        if self.pending.is_some() {
            return;
        }
        let done = Arc::new(AtomicU8::new(WAITING));
        let flag = done.clone();
        self.readback
            .slice(..)
            .map_async(wgpu::MapMode::Read, move |r| {
                flag.store(if r.is_ok() { MAPPED } else { FAILED }, Ordering::Release);
            });
        self.pending = Some(done);
        self.pending_written = self.written;
    }

    /// The read-back's milliseconds if it has arrived (the device polled since), else `None`
    /// and still pending.
    pub fn try_read(&mut self) -> Option<SlotTimes> {
        match self.pending.as_ref()?.load(Ordering::Acquire) {
            WAITING => return None,
            FAILED => {
                self.pending = None;
                return None;
            }
            _ => {}
        }
        // The callback said it is mapped; a device lost since has no times either.
        self.pending = None;
        let ticks: [u64; QUERIES as usize] = {
            let view = self.readback.slice(..).get_mapped_range().ok()?;
            bytemuck::pod_read_unaligned(&view[..RESOLVE_BYTES as usize])
        };
        self.readback.unmap();
        Some(std::array::from_fn(|s| {
            self.pending_written[s].then(|| {
                ticks[2 * s + 1].saturating_sub(ticks[2 * s]) as f64 * self.period_ns * 1e-6
            })
        }))
    }
}
