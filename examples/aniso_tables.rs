//! The anisotropic tables measured side by side (docs/design.md §2.9, §4.11), in one run:
//! 1. each 4D table's lobe error against the exact anisotropic lobe (`measure::aniso_table`)
//!    at the nodes and at the cell centres of each table's grid — the lab's shipped table
//!    and I3D 2022's two, read as an engine reads them — with each table's worst blend;
//! 2. the first accuracy table of anisotropic LTC on area lights: each shape's LTC method
//!    against the exact integral, by anisotropy and elevation (`measure::aniso_shapes`), the
//!    lab's table beside I3D 2022's (α_x, α_y) one.
//!
//! `cargo run --release --example aniso_tables [shapes] [CASES [NODES]]` (CASES per shape
//! cell, default 1000; NODES of the exact rules, default 64; `shapes`: the second part alone;
//! about 4 minutes on 2 cores).

use std::time::Instant;

use ltc_lab::ltc::aniso::source::AnisoSource;
use ltc_lab::ltc::aniso::{AnisoAxes, AnisoLut, worst_blend};
use ltc_lab::ltc::lut::Lut;
use ltc_lab::measure::aniso_shapes::{AnisoShapeError, RATIOS, aniso_shape_errors};
use ltc_lab::measure::aniso_table::{domain_points, errors_at};
use ltc_lab::measure::shape_error::BANDS;

/// Mean, median, 90th percentile and largest of column `k`.
fn summary(name: &str, errors: &[Vec<f64>], k: usize) -> String {
    let mut xs: Vec<f64> = errors.iter().map(|e| e[k]).collect();
    xs.sort_by(f64::total_cmp);
    let mean = xs.iter().sum::<f64>() / xs.len() as f64;
    format!(
        "  {name:<18} mean {:6.2}%  median {:6.2}%  p90 {:6.2}%  max {:7.2}%",
        100.0 * mean,
        100.0 * xs[xs.len() / 2],
        100.0 * xs[xs.len() * 9 / 10],
        100.0 * xs[xs.len() - 1]
    )
}

fn lobe_errors(tables: &[&AnisoLut], names: &[&str]) {
    // What each file holds a node: the lab's nine stored numbers, two magnitudes and the
    // error; I3D 2022's nine entries of M (their magnitudes are an engine's own table).
    let per_node = [12, 9, 9];
    for ((name, t), floats) in names.iter().zip(tables).zip(per_node) {
        let bytes = t.cells.len() * floats * 4;
        println!(
            "{name}: {:?} nodes, {bytes} bytes of f32 ({floats} a node), worst blend {:?}",
            t.dims,
            worst_blend(t, 4)
        );
    }
    for (axes, table) in [
        (AnisoAxes::I3dAlphaXY, tables[1]),
        (AnisoAxes::I3dAlphaLambda, tables[2]),
        (AnisoAxes::Lab, tables[0]),
    ] {
        for midpoints in [false, true] {
            let points = domain_points(axes, table.dims, midpoints);
            let t = Instant::now();
            let errors = errors_at(tables, &points);
            println!(
                "\nat the {} of the {} grid ({} points, {:.1} s):",
                if midpoints { "cell centres" } else { "nodes" },
                axes.name(),
                points.len(),
                t.elapsed().as_secs_f64()
            );
            for (k, name) in names.iter().enumerate() {
                println!("{}", summary(name, &errors, k));
            }
        }
    }
}

fn shape_table(errors: &[AnisoShapeError], names: &[&str]) {
    let bands: Vec<String> = BANDS
        .iter()
        .map(|b| format!("{}..{}°", b[0], b[1]))
        .collect();
    println!(
        "\n| shape | α_y/α_x | table | {} |\n|---|---|---|{}",
        bands.join(" | "),
        "---|".repeat(BANDS.len())
    );
    for chunk in errors.chunks(BANDS.len()) {
        for (k, name) in names.iter().enumerate() {
            let cells: Vec<String> = chunk
                .iter()
                .map(|e| format!("{:.1}%", 100.0 * e.errors[k]))
                .collect();
            println!(
                "| {} | {} | {name} | {} |",
                chunk[0].shape.name(),
                chunk[0].ratio,
                cells.join(" | ")
            );
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let shapes_only = args.first().is_some_and(|a| a == "shapes");
    let numbers: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let cases = numbers.first().copied().unwrap_or(1000);
    // Nodes of the exact rules: 64 keep them within 0.1% of 128's on these cases (the
    // example's `shapes 1000 128` run).
    let nodes = numbers.get(1).copied().unwrap_or(64);
    let load = |s: AnisoSource| s.load().expect("the embedded tables load");
    let lab = load(AnisoSource::Lab);
    let xy = load(AnisoSource::I3d(AnisoAxes::I3dAlphaXY));
    let lambda = load(AnisoSource::I3d(AnisoAxes::I3dAlphaLambda));
    let names = ["lab", "i3d-alphax-alphay", "i3d-alpha-lambda"];
    if !shapes_only {
        lobe_errors(&[&lab, &xy, &lambda], &names);
    }
    let start = Instant::now();
    let luts = [&lab, &xy].map(|t| Lut::embedded().clone().with_aniso(t.clone()));
    let errors = aniso_shape_errors(&[&luts[0], &luts[1]], cases, 20261128, nodes);
    println!(
        "\nspecular Σ|LTC − exact| / Σ exact, {cases} cases a cell, exact rules of {nodes} nodes, α_x in [0.1, 0.8], θo to 80°, every φo; ratios {RATIOS:?} ({:.1} s):",
        start.elapsed().as_secs_f64()
    );
    shape_table(&errors, &names[..2]);
}
