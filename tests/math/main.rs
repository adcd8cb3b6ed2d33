//! The math and the CPU reference, tested without a GPU (docs/design.md §1–§3): the exact
//! BRDF, LTC evaluation and its clipping rules, the horizon remedies, the clipping case map,
//! a pixel opened into its lights, the shipped presets, and stability over the whole domain.

#[path = "../common/mod.rs"]
mod common;

mod brdf;
mod case_map;
mod horizon;
mod ltc;
mod pixel;
mod presets;
mod stability;
