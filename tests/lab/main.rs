//! The lab under egui_kittest with the wgpu renderer (lavapipe in CI), built as eframe builds
//! it (from a creation context whose storage holds the state the test starts from) and driven
//! by role and label as a user drives it: a file per panel, and the parts and caches that
//! the panels share (`parts`).

#[path = "../gpu_common/mod.rs"]
mod gpu_common;

mod aniso;
mod chart;
mod clipping;
mod device_loss;
mod encodings;
mod harness;
mod lesson;
mod lobe;
mod matrix;
mod method_file;
mod parts;
mod plane;
mod rects;
mod spheres;
mod window;
