//! `shaders/tube_band.wgsl`: a tube's exact rule on the GPU — the band of its silhouette about
//! the segment's plane, its cuts and stretched nodes — mirroring `crate::light::tube::band` by
//! name (docs/design.md §1.15). Composed after `tube_light`, whose `Tube` it reads and whose
//! exact method calls it.

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/tube_band.wgsl");
