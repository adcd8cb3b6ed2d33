//! `--size-for SHAPE=SIZE`: every light of a run as a light of that shape and size
//! (`ShapeKind::bench_shape`), keyed by the shape (docs/design.md §5.12), and the per-shape
//! flags of before (`--sphere-radius`, `--rect-half-edge`, `--disk-radius`) as its aliases;
//! `bench` times each of the shape's methods, `study` measures them against its exact image.

use ltc_lab::error::{Error, Result};
use ltc_lab::light::ShapeKind;

#[derive(clap::Args, Debug)]
pub struct SizeArgs {
    /// Also every light as a light of SHAPE of this size, by each of its methods
    /// (`size_for_help`).
    #[arg(long, value_name = "SHAPE=SIZE", help = size_for_help())]
    size_for: Vec<String>,
    /// The same as `--size-for sphere=R`.
    #[arg(long)]
    sphere_radius: Option<f64>,
    /// The same as `--size-for rect=H`.
    #[arg(long)]
    rect_half_edge: Option<f64>,
    /// The same as `--size-for disk=R`.
    #[arg(long)]
    disk_radius: Option<f64>,
}

impl SizeArgs {
    /// The shapes and sizes `--size-for` and its aliases name, one size per shape, in
    /// `ShapeKind::ALL`'s order: a shape named twice with two sizes is refused, naming it.
    /// Each size is checked (`check_size`).
    pub fn sizes(&self) -> Result<Vec<(ShapeKind, f64)>> {
        let mut given: Vec<(String, ShapeKind, f64)> = Vec::new();
        for text in &self.size_for {
            let (kind, size) = size_for(text).map_err(|m| Error::input("--size-for", m))?;
            given.push((format!("--size-for {text}"), kind, size));
        }
        let aliases = [
            ("--sphere-radius", ShapeKind::Sphere, self.sphere_radius),
            ("--rect-half-edge", ShapeKind::Rect, self.rect_half_edge),
            ("--disk-radius", ShapeKind::Disk, self.disk_radius),
        ];
        for (flag, kind, size) in aliases {
            if let Some(size) = size {
                given.push((flag.to_string(), kind, size));
            }
        }
        let mut kept: Vec<(ShapeKind, f64)> = Vec::new();
        for (flag, kind, size) in &given {
            super::check_size(flag, *size)?;
            match kept.iter().find(|(k, _)| k == kind) {
                Some((_, s)) if s == size => {}
                Some(_) => {
                    return Err(Error::input(
                        flag,
                        format!("a second size for {}s", kind.name()),
                    ));
                }
                None => kept.push((*kind, *size)),
            }
        }
        kept.sort_by_key(|(k, _)| *k);
        Ok(kept)
    }
}

/// `SHAPE=SIZE` of `--size-for`, SHAPE a shape with a size.
fn size_for(text: &str) -> std::result::Result<(ShapeKind, f64), String> {
    let shapes = || {
        let names: Vec<_> = ShapeKind::sized().map(ShapeKind::name).collect();
        names.join(", ")
    };
    let Some((shape, size)) = text.split_once('=') else {
        return Err(format!("write SHAPE=SIZE (SHAPE one of {})", shapes()));
    };
    let kind = ShapeKind::from_name(shape)
        .filter(|&k| k != ShapeKind::Point)
        .ok_or_else(|| format!("no shape with a size `{shape}`: one of {}", shapes()))?;
    let size = size
        .parse::<f64>()
        .map_err(|_| format!("{shape}'s size `{size}` is not a number"))?;
    Ok((kind, size))
}

/// `--size-for`'s help: each shape with a size and the lights it makes, at 0.05
/// (`ShapeKind::bench_title`).
fn size_for_help() -> String {
    let shapes: Vec<String> = ShapeKind::sized()
        .map(|k| format!("`{}=0.05`: {}", k.name(), k.bench_title(0.05)))
        .collect();
    format!(
        "Also every light as a light of SHAPE of this size (scene units, ≥ 1e-4), in the same \
         run: bench times each of SHAPE's methods; study measures each against SHAPE's exact \
         integral (variants SHAPE-METHOD), with SHAPE's first failure preset as given. One \
         per shape, repeated for several (docs/design.md §5.12). {}",
        shapes.join("; ")
    )
}
