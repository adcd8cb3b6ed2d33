//! When a chunk of GPU work finished, by the wall clock: a thread waits on the device for each
//! submission in turn, so that the UI thread never does. On a CPU driver (lavapipe, llvmpipe)
//! this is the time a pacer must follow — the "GPU" shares the cores with the UI, and its
//! timestamp queries were seen to read ~5 ms whatever the work (lavapipe, Mesa 22.3) — and it
//! wakes the window the moment the work is done. A browser has no threads: there a chunk is
//! done when submitted (`new` says why).

use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use web_time::Instant;

/// The state of the chunk last handed to the waiter.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Chunk {
    /// None submitted yet, or its time already taken.
    Idle,
    InFlight,
    /// Done, `ms` after its submission.
    Done {
        ms: f64,
    },
}

pub struct Completion {
    tx: Option<mpsc::Sender<(wgpu::SubmissionIndex, Instant)>>,
    state: Arc<Mutex<Chunk>>,
}

impl Completion {
    /// No waiter in a browser: no threads, and the queue's callback
    /// (`on_submitted_work_done`) failed on eframe's device in headless Chromium on
    /// SwiftShader ("A valid external Instance reference no longer exists", an error in the
    /// console at every chunk). A chunk is reported done when submitted: the browser runs the
    /// queue's work in order, and the pacer follows the timestamps where they arrive.
    #[cfg(target_arch = "wasm32")]
    pub fn new(_: wgpu::Device, _: wgpu::Queue, _: egui::Context) -> Self {
        Self {
            tx: None,
            state: Arc::new(Mutex::new(Chunk::Idle)),
        }
    }

    /// A waiter on `device`, which asks `window` for a frame when a chunk is done.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new(device: wgpu::Device, _: wgpu::Queue, window: egui::Context) -> Self {
        let (tx, rx) = mpsc::channel::<(wgpu::SubmissionIndex, Instant)>();
        let state = Arc::new(Mutex::new(Chunk::Idle));
        let shared = state.clone();
        let spawned = std::thread::Builder::new()
            .name("ltc-lab chunk waiter".into())
            .spawn(move || {
                // Ends when the sender is dropped with the renderer.
                for (index, submitted) in rx {
                    let _ = device.poll(wgpu::PollType::Wait {
                        submission_index: Some(index),
                        timeout: None,
                    });
                    let ms = submitted.elapsed().as_secs_f64() * 1e3;
                    if let Ok(mut s) = shared.lock() {
                        *s = Chunk::Done { ms };
                    }
                    window.request_repaint();
                }
            });
        Self {
            // Without a thread the UI polls (`take` then reports the chunk done at once).
            tx: spawned.ok().map(|_| tx),
            state,
        }
    }

    /// Hands a submission to the waiter: everything submitted up to `index`.
    pub fn submitted(&self, index: wgpu::SubmissionIndex, at: Instant) {
        let Some(tx) = &self.tx else {
            self.set(Chunk::Done {
                ms: at.elapsed().as_secs_f64() * 1e3,
            });
            return;
        };
        self.set(Chunk::InFlight);
        if tx.send((index, at)).is_err() {
            self.set(Chunk::Done { ms: 0.0 });
        }
    }

    /// The last chunk's state; a `Done` is taken (the next call says `Idle`).
    pub fn take(&self) -> Chunk {
        let Ok(mut s) = self.state.lock() else {
            return Chunk::Idle;
        };
        let now = *s;
        if matches!(now, Chunk::Done { .. }) {
            *s = Chunk::Idle;
        }
        now
    }

    fn set(&self, chunk: Chunk) {
        if let Ok(mut s) = self.state.lock() {
            *s = chunk;
        }
    }
}
