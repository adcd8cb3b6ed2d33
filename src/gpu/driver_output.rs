//! What drivers print while an adapter opens (docs/design.md §5.10). Mesa's Vulkan
//! device-select layer connects to a Wayland display to find the default GPU, and where
//! `XDG_RUNTIME_DIR` is not set (a container, an SSH session, `env -i`) libwayland prints
//! "error: XDG_RUNTIME_DIR is invalid or not set in the environment." twice: ahead of the
//! program's own output, or of its real error. wgpu always enables the Wayland surface
//! extension, and the layer can only be turned off through the environment, which this
//! program does not change. So the process's standard error is held back while the adapter
//! opens: dropped when it opens, handed to the error when it does not.

/// Runs `open` with standard error held back; its result, and what was written meanwhile
/// (empty where standard error could not be redirected).
pub fn held_back<T>(open: impl FnOnce() -> T) -> (T, String) {
    hold();
    let out = open();
    (out, give_back())
}

/// Holds standard error back from now on, until `give_back`: for an adapter that opens
/// where a closure cannot wrap it (eframe's window opens its own, then calls back). Nothing
/// where it is already held or cannot be redirected. A panic meanwhile gives it back first,
/// so that the panic, and what the driver said before it, is not lost with the file.
pub fn hold() {
    give_back_on_panic();
    let mut held = lock_held();
    if held.is_none() {
        *held = HeldBack::start();
    }
}

/// Gives standard error back, and what was written to it since `hold` (empty where it was
/// not held). Every way out of a hold ends here: an error, a panic, an interrupt.
pub fn give_back() -> String {
    let held = lock_held().take();
    held.map(HeldBack::release).unwrap_or_default()
}

/// What the driver said, as a note after a message: " (the driver said: …)", or nothing.
pub fn as_note(said: &str) -> String {
    match said {
        "" => String::new(),
        s => format!(" (the driver said: {})", s.replace('\n', "; ")),
    }
}

/// Standard error is the process's: one hold at a time, kept where the panic hook and the
/// interrupt handler can find it.
static HELD: std::sync::Mutex<Option<HeldBack>> = std::sync::Mutex::new(None);

/// The hold, even after a panic elsewhere poisoned the lock (the hold itself stays whole:
/// nothing panics while changing it).
fn lock_held() -> std::sync::MutexGuard<'static, Option<HeldBack>> {
    HELD.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Chains a panic hook, once, that gives standard error back before the usual report.
fn give_back_on_panic() {
    static INSTALLED: std::sync::Once = std::sync::Once::new();
    INSTALLED.call_once(|| {
        let report = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            // `try_lock`: a panic inside `give_back` itself must not wait on its own lock.
            let held = HELD.try_lock().ok().and_then(|mut h| h.take());
            let said = held.map(HeldBack::release).unwrap_or_default();
            if !said.is_empty() {
                eprintln!("{}", as_note(&said).trim_start());
            }
            report(info);
        }));
    });
}

/// Standard error written to an unlinked temporary file until `release`.
#[cfg(unix)]
struct HeldBack {
    saved: std::os::fd::OwnedFd,
    file: std::fs::File,
}

#[cfg(unix)]
impl HeldBack {
    /// Holds standard error back from now on; `None` where it cannot be redirected.
    fn start() -> Option<Self> {
        redirect().map(|(saved, file)| Self { saved, file })
    }

    /// Gives standard error back, and what was written to it meanwhile.
    fn release(mut self) -> String {
        use std::io::{Read, Seek};
        // Restored before anything else is said; a failure to restore leaves it where it is.
        let _ = nix::unistd::dup2_stderr(&self.saved);
        let mut bytes = Vec::new();
        let _ = self
            .file
            .rewind()
            .and_then(|()| self.file.read_to_end(&mut bytes));
        String::from_utf8_lossy(&bytes).trim().to_string()
    }
}

#[cfg(not(unix))]
struct HeldBack;

#[cfg(not(unix))]
impl HeldBack {
    fn start() -> Option<Self> {
        None
    }

    fn release(self) -> String {
        String::new()
    }
}

/// Standard error sent to a new temporary file: the saved descriptor and the file.
#[cfg(unix)]
fn redirect() -> Option<(std::os::fd::OwnedFd, std::fs::File)> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    static SERIAL: AtomicUsize = AtomicUsize::new(0);
    let path = std::env::temp_dir().join(format!(
        ".ltc-lab-driver-output.{}-{}",
        std::process::id(),
        SERIAL.fetch_add(1, Ordering::Relaxed)
    ));
    let file = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&path)
        .ok()?;
    // Unlinked at once: nothing is left behind, whatever happens next.
    std::fs::remove_file(&path).ok()?;
    let saved = nix::unistd::dup(std::io::stderr()).ok()?;
    nix::unistd::dup2_stderr(&file).ok()?;
    Some((saved, file))
}
