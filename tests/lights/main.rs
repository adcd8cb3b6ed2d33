//! Lights with a size, each shape in its own module: its methods against f64 references
//! (`sphere_light`, `rect_light`, `disk_light`) and in CPU renders (`sphere_render`,
//! `rect_render`, `disk_render`: failure presets, refusals, the point limit).

#[path = "../common/mod.rs"]
mod common;

mod disk_light;
mod disk_render;
mod light_file;
mod rect_light;
mod rect_render;
mod render_rule;
mod sphere_light;
mod sphere_render;
mod tube_light;
