//! The GPU against the CPU reference, on one device for the whole binary (lavapipe and GL in
//! CI; skipped loudly without an adapter unless `LTC_LAB_REQUIRE_GPU` is set): the LUT's
//! in-shader sampler, the plane renders' parity, renders of every method and view, the
//! browser's self-check, the spheres' methods and every emitter's (rects, disks, tubes).

#[path = "../gpu_common/mod.rs"]
mod gpu_common;

mod aniso;
mod emitters;
mod exact_rule;
mod failures;
mod lut;
mod method_file;
mod parity;
mod render;
mod selfcheck;
mod sphere_light;
