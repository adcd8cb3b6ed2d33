//! Every emitter measured alike (docs/design.md §4.9): each method's error against the
//! exact integral (`measure::emitter_error`), by the light's solid angle, the elevation of
//! its centre and α, as Markdown tables, a lobe each.
//!
//! `cargo run --release --example emitter_errors [SHAPE|all] [CASES] [SEED]` (defaults all,
//! 100 a cell and 7): lights of radiance 1 drawn by the shape's module
//! (`ShapeKind::error_sample`), F0 0.04, views θo 0 to 80°.

use ltc_lab::light::ShapeKind;
use ltc_lab::ltc::lut::Lut;
use ltc_lab::measure::emitter_error::{emitter_errors, measured};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let shape = args.next().unwrap_or_else(|| "all".into());
    let emitters = ShapeKind::ALL
        .into_iter()
        .filter(|k| k.error_sample().is_some() && (shape == "all" || k.name() == shape));
    let kinds: Vec<ShapeKind> = emitters.collect();
    if kinds.is_empty() {
        return Err(format!("no emitter `{shape}`").into());
    }
    let cases: usize = args.next().map_or(Ok(100), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(7), |a| a.parse())?;
    for kind in kinds {
        print(kind, cases, seed);
    }
    Ok(())
}

/// `kind`'s tables, a lobe each.
fn print(kind: ShapeKind, cases: usize, seed: u64) {
    let rows = emitter_errors(kind, Lut::embedded(), cases, seed);
    let names: Vec<&str> = measured(kind).iter().map(|m| m.name()).collect();
    for (lobe, k) in [("specular", 0), ("diffuse", 1)] {
        println!(
            "\n{}, {lobe}: Σ|method − exact| / Σ exact, {cases} cases a cell, seed {seed}\n",
            kind.lights_title()
        );
        println!(
            "| solid angle | centre's elevation | α | {} |",
            names.join(" | ")
        );
        println!("|---:|---|---|{}", "---:|".repeat(names.len()));
        for r in &rows {
            let cells: Vec<String> = r
                .methods
                .iter()
                .map(|(_, e)| format!("{:.1}%", 100.0 * e[k]))
                .collect();
            println!(
                "| {} sr | {}–{}° | {}–{} | {} |",
                r.solid_angle,
                r.band[0],
                r.band[1],
                r.alpha[0],
                r.alpha[1],
                cells.join(" | ")
            );
        }
    }
}
