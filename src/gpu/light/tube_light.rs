//! `shaders/tube_light.wgsl`: tube lights on the GPU — the capsule, its LTC line and HDRP's
//! tube, Karis's representative point, the point limit and the band's exact rule — mirroring
//! `crate::light::tube` by name (docs/design.md §1.15), with its method codes (`TUBE_*`, which
//! the pipelines pass as `TUBE_A` and `TUBE_B`). Composed after `sphere_light` (the cap,
//! `fd_toward`, `widening_energy`), `rect_light` (`atan2_precise`) and `polar` (the
//! Gauss–Legendre nodes).

use crate::light::tube::TubeMethod;

/// The shader text, embedded so the binary runs from anywhere.
pub const SOURCE: &str = include_str!("../../../shaders/tube_light.wgsl");

/// `TUBE_*` of tube_light.wgsl: its value and its name there.
pub fn tube_constant(m: TubeMethod) -> (u32, &'static str) {
    match m {
        TubeMethod::Exact => (0, "TUBE_EXACT"),
        TubeMethod::LtcLine => (1, "TUBE_LTC_LINE"),
        TubeMethod::HdrpTube => (2, "TUBE_HDRP_TUBE"),
        TubeMethod::RepresentativePoint => (3, "TUBE_REPRESENTATIVE_POINT"),
        TubeMethod::LtcPoint => (4, "TUBE_LTC_POINT"),
    }
}
