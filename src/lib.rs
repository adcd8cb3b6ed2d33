//! LTC Lab: shading many point lights with a physically based BRDF (GGX specular + Burley
//! diffuse) approximated by Linearly Transformed Cosines. The math (`brdf`, `ltc`) knows
//! nothing of GPUs or windows; `render` says what a render is for every renderer; `cpu` is
//! the reference renderer, `gpu` the wgpu one, `app` the lab. The command line is the
//! binary's (`src/main.rs`, `src/cli/`).

pub mod app;
pub mod brdf;
pub mod colormap;
pub mod cpu;
pub mod error;
pub mod files;
pub mod gpu;
pub mod light;
pub mod ltc;
pub mod measure;
pub mod metrics;
pub(crate) mod named;
pub mod output;
pub mod pixel;
pub mod plot;
pub mod render;
pub mod scene;
pub mod tables;
