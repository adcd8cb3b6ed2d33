//! Work off the UI thread: a thread of its own on the desktop. The browser build has no
//! threads (issue 21), so there the work runs at once on the UI thread and its result is
//! waiting when the panel next looks: correct, but the frame that starts it waits for it.

/// Runs `work` on a thread named `name` (on the desktop), or now (in the browser).
pub fn spawn(name: &str, work: impl FnOnce() + Send + 'static) {
    #[cfg(not(target_arch = "wasm32"))]
    std::thread::Builder::new()
        .name(format!("ltc-lab {name}"))
        .spawn(work)
        .expect("the system starts a thread");
    #[cfg(target_arch = "wasm32")]
    {
        let _ = name;
        work();
    }
}
