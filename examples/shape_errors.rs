//! Rect and disk lights, measured (docs/design.md §1.11, §1.12): each LTC method's error
//! against the exact integral (`measure::shape_error`), by the light's solid angle and the
//! elevation of its centre, as the Markdown tables of the design notes.
//!
//! `cargo run --release --example shape_errors [CASES] [SEED]` (defaults 300 a cell and 7):
//! random square-to-oblong rects facing the point (tilted up to 45°) and, at the same place
//! and tilt, disks of the same solid angle; radiance 1, F0 0.04. The exact rules' own error is
//! measured too, on the same measure: 64 nodes a triangle (a piece) against 128.

use ltc_lab::ltc::lut::Lut;
use ltc_lab::measure::shape_error::{DISK_METHODS, RECT_METHODS, ShapeError, shape_errors};

/// One shape's tables, a lobe each: `pick` gives a cell's figures, one per method.
fn print(shape: &str, names: &[&str], rows: &[ShapeError], pick: fn(&ShapeError) -> Vec<[f64; 2]>) {
    for (lobe, k) in [("specular", 0), ("diffuse", 1)] {
        let cases = rows.first().map_or(0, |r| r.cases);
        println!("\n{shape}, {lobe}: Σ|method − exact| / Σ exact, {cases} cases a cell\n");
        println!(
            "| solid angle | centre's elevation | {} |",
            names.join(" | ")
        );
        println!("|---:|---|{}", "---:|".repeat(names.len()));
        for r in rows {
            let cells: Vec<String> = pick(r)
                .iter()
                .map(|e| format!("{:.1}%", 100.0 * e[k]))
                .collect();
            println!(
                "| {} sr | {}–{}° | {} |",
                r.solid_angle,
                r.band[0],
                r.band[1],
                cells.join(" | ")
            );
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let cases: usize = args.next().map_or(Ok(300), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(7), |a| a.parse())?;
    let rows = shape_errors(Lut::embedded(), cases, seed, 64, true);
    let rect_names: Vec<&str> = RECT_METHODS.iter().map(|m| m.name()).collect();
    let disk_names: Vec<&str> = DISK_METHODS.iter().map(|m| m.name()).collect();
    print("rects", &rect_names, &rows, |r| r.rects.to_vec());
    print("disks", &disk_names, &rows, |r| r.disks.to_vec());
    let worst = |k: usize| {
        rows.iter()
            .filter_map(|r| r.rule)
            .map(|w| w[k])
            .fold(0.0, f64::max)
    };
    println!(
        "\nThe exact rules, 64 nodes against 128, Σ|64 − 128| / Σ 128 over both lobes: at most {:.1e} a cell (rects), {:.1e} (disks); seed {seed}",
        worst(0),
        worst(1)
    );
    Ok(())
}
