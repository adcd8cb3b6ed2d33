//! The fitters: ltc_code's classic fit (`classic`), the point fits (`point`) and a cell's
//! refit as the lab runs it (`refit`), each against independent f64 quadrature.

#[path = "../common/mod.rs"]
mod common;

mod classic;
mod point;
mod refit;
