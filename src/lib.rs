//! LTC Lab: shading many point lights with a physically based BRDF (GGX specular + Burley
//! diffuse) approximated by Linearly Transformed Cosines. The math (`brdf`, `ltc`) knows
//! nothing of GPUs or windows; `cpu` is the reference renderer built on it.

pub mod app;
pub mod atlas;
pub mod bench;
pub mod brdf;
pub mod cpu;
pub mod error;
pub mod gpu;
pub mod ltc;
pub mod metrics;
pub mod output;
pub mod plot;
pub mod scene;
pub mod study;
