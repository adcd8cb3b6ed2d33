//! Work made from the lab's parts and done off the UI thread: caches keyed on what they read,
//! jobs of steps on a worker (or queued in the browser), the pacer that sizes a frame's chunk
//! of GPU work, and the wall-clock completion of that work.

pub mod background;
pub mod cache;
pub mod completion;
pub mod pacer;
