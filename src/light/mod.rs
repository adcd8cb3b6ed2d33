//! Lights with a size, beside the paper's point light: a sphere's methods (`sphere`) and the
//! Gauss–Legendre rule over its cap that the exact method integrates by (`quadrature`),
//! docs/design.md §1.10.

pub mod quadrature;
pub mod sphere;
