//! What the device says went wrong, kept instead of panicking (docs/design.md §5.14): wgpu's
//! default handler of an uncaptured error panics, and a lost device (a watchdog's reset, a
//! driver's) would end the program. `Failures::watch` installs the handler and the loss
//! callback once a device opens; the work that follows asks `check`. Module and pipeline
//! creation and submissions run inside error scopes (`scoped`), whose error names its cause;
//! and every render is split so that a watchdog never sees a submission (`submissions`).

pub mod submissions;

use std::sync::{Arc, Mutex};

use crate::error::{Error, Result};

/// The most uncaptured errors kept: the first says what went wrong, the rest are counted.
const KEPT: usize = 8;

/// A device's failures so far, shared by every handle of the device.
#[derive(Clone, Debug, Default)]
pub struct Failures {
    inner: Arc<Mutex<Seen>>,
}

#[derive(Debug, Default)]
struct Seen {
    /// Why the device was lost, once it is.
    lost: Option<String>,
    /// The first uncaptured errors, and how many there were.
    errors: Vec<String>,
    count: usize,
}

impl Failures {
    /// Failures of `device` from now on: its uncaptured errors and its loss. Installed once per
    /// device (a second call replaces the first's handler: clone the `GpuContext` instead).
    pub fn watch(device: &wgpu::Device) -> Self {
        let failures = Self::default();
        let errors = failures.clone();
        device.on_uncaptured_error(Arc::new(move |e: wgpu::Error| errors.error(&e)));
        let lost = failures.clone();
        device.set_device_lost_callback(move |reason, message| {
            lost.lose(format!("{reason:?}{}", words(&message)));
        });
        failures
    }

    fn seen(&self) -> std::sync::MutexGuard<'_, Seen> {
        // A panic elsewhere while it was held leaves it as it was: still worth reading.
        self.inner
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    fn error(&self, e: &wgpu::Error) {
        let mut seen = self.seen();
        seen.count += 1;
        if seen.errors.len() < KEPT {
            seen.errors.push(e.to_string());
        }
    }

    fn lose(&self, why: String) {
        self.seen().lost.get_or_insert(why);
    }

    /// Why the device was lost, if it was.
    pub fn lost(&self) -> Option<String> {
        self.seen().lost.clone()
    }

    /// The device's failures since the last call, as one error naming `device` (a failure of
    /// the machine: the lab's own work, not the input, met it), and forgets the errors; a loss
    /// stays.
    pub fn check(&self, device: &str) -> Result<()> {
        let mut seen = self.seen();
        if let Some(why) = &seen.lost {
            return Err(Error::machine(
                device,
                format!(
                    "the device was lost ({why}): a driver reset or the operating system's watchdog ended its work"
                ),
            ));
        }
        if seen.errors.is_empty() {
            return Ok(());
        }
        let more = match seen.count - 1 {
            0 => String::new(),
            n => format!(" (and {n} more)"),
        };
        let first = seen.errors[0].clone();
        seen.errors.clear();
        seen.count = 0;
        Err(Error::machine(
            device,
            format!("the device refused the lab's work: {first}{more}"),
        ))
    }
}

/// `message` after a colon, where there is one.
fn words(message: &str) -> String {
    match message.trim() {
        "" => String::new(),
        m => format!(": {m}"),
    }
}

/// `work` run inside error scopes of `device` (validation, out of memory, internal): its result
/// and the first error the device reported of it. In the browser a scope's error arrives later,
/// not now: there it is the uncaptured handler's (`Failures`).
pub fn scoped<T>(device: &wgpu::Device, work: impl FnOnce() -> T) -> (T, Option<wgpu::Error>) {
    let internal = device.push_error_scope(wgpu::ErrorFilter::Internal);
    let memory = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let validation = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let value = work();
    // Popped innermost first.
    let errors = [validation.pop(), memory.pop(), internal.pop()];
    let error = errors.into_iter().find_map(now);
    (value, error)
}

/// A future's value if it is ready at once (wgpu's native scopes are), else `None`.
fn now<T>(future: impl std::future::Future<Output = Option<T>>) -> Option<T> {
    let mut future = std::pin::pin!(future);
    let mut context = std::task::Context::from_waker(std::task::Waker::noop());
    match future.as_mut().poll(&mut context) {
        std::task::Poll::Ready(value) => value,
        std::task::Poll::Pending => None,
    }
}
