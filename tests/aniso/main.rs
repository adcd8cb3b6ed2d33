//! Anisotropic GGX and its 4D table (docs/design.md §1.13, §2.9): the BRDF against f64
//! quadrature (`brdf`), the table's folding, canonical form and interpolation (`table`), the
//! I3D 2022 tables read and measured beside the lab's (`anchor`), and `eval`'s anisotropic
//! rows against an independent reference (`eval`).

#[path = "../common/mod.rs"]
mod common;

mod anchor;
mod brdf;
mod eval;
mod export;
mod table;
