//! The measures: everything that says how wrong or how fast a method is, on the same terms
//! everywhere (docs/design.md §4) — the `eval` cases, the parity of two renders, Table 1's
//! benchmark, the study of speed against accuracy, the error atlas, the horizon's study, and
//! the sphere lights' errors by size and elevation, and the 4D tables' (by lobe and by light shape).

pub mod aniso_shapes;
pub mod aniso_table;
pub mod atlas;
pub mod bench;
pub mod bench_table;
pub mod emitter_error;
pub mod encodings;
pub mod eval;
pub mod exact_rule;
pub mod horizon;
pub mod parity;
pub mod scene_study;
pub mod shape_error;
pub mod sphere_error;
pub mod study;
