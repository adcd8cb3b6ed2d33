//! What the panels draw alike: plot axes, images and their colour bars, and widgets more
//! than one panel shows.

pub mod axes;
pub mod display;
pub mod widgets;
