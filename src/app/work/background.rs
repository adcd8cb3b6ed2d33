//! Work off the UI thread. On the desktop a job runs on a thread of its own. The browser
//! build has no threads: there a job is a sequence of steps, and the lab runs the
//! queued jobs' steps at the start of each frame within a budget (`run_for`), so that a frame
//! never waits for a whole job and the window stays live while it runs.

#[cfg(target_arch = "wasm32")]
use std::cell::RefCell;

/// A job: each call does one step of it and says whether it is done.
pub type Steps = Box<dyn FnMut() -> bool + Send>;

#[cfg(target_arch = "wasm32")]
thread_local! {
    /// The browser's queued jobs, oldest first.
    static QUEUE: RefCell<Vec<Steps>> = const { RefCell::new(Vec::new()) };
}

/// Runs `work` in one go: on a thread named `name` (the desktop), or as a single step of
/// the browser's queue.
pub fn spawn(name: &str, work: impl FnOnce() + Send + 'static) {
    let mut work = Some(work);
    spawn_steps(
        name,
        Box::new(move || {
            if let Some(w) = work.take() {
                w();
            }
            true
        }),
    );
}

/// Runs `steps` until it says it is done: on a thread named `name` (the desktop), or step by
/// step over the browser's frames (`run_for`).
pub fn spawn_steps(name: &str, steps: Steps) {
    #[cfg(not(target_arch = "wasm32"))]
    std::thread::Builder::new()
        .name(format!("ltc-lab {name}"))
        .spawn(move || {
            let mut steps = steps;
            while !steps() {}
        })
        .expect("the system starts a thread");
    #[cfg(target_arch = "wasm32")]
    {
        let _ = name;
        QUEUE.with(|q| q.borrow_mut().push(steps));
    }
}

/// Runs queued steps, the oldest job first, until `budget_ms` has passed; whether any job
/// is left (the frame then asks for the next). At least one step runs, so that a step longer
/// than the budget still advances. On the desktop there is no queue: nothing to do.
pub fn run_for(budget_ms: f64) -> bool {
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = budget_ms;
        false
    }
    #[cfg(target_arch = "wasm32")]
    {
        let started = web_time::Instant::now();
        loop {
            // Taken out while it runs: a step may queue a job of its own.
            let Some(mut job) = QUEUE.with(|q| {
                let mut q = q.borrow_mut();
                (!q.is_empty()).then(|| q.remove(0))
            }) else {
                return false;
            };
            let done = job();
            if !done {
                QUEUE.with(|q| q.borrow_mut().insert(0, job));
            }
            if started.elapsed().as_secs_f64() * 1e3 >= budget_ms {
                return QUEUE.with(|q| !q.borrow().is_empty());
            }
        }
    }
}
