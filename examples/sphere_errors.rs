//! Lights with a size, measured (docs/design.md §4.9): the error of each way of shading a
//! sphere light against the exact cap integral, by angular radius and by the elevation band
//! of its centre, as the Markdown tables of the design notes and the README.
//!
//! `cargo run --release --example sphere_errors [CASES] [SEED]` (defaults 40 000 and
//! `horizon::SEED`): a minute or two on two cores. Radius 0 is the point light, with
//! §4.7's cases.

use ltc_lab::ltc::lut::Lut;
use ltc_lab::measure::horizon::{BANDS, SEED};
use ltc_lab::measure::sphere_error::{
    APPROXIMATIONS, MEASURE_NODES, RADII_DEG, SphereError, sphere_errors,
};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let cases: usize = args.next().map_or(Ok(40_000), |a| a.parse())?;
    let seed: u64 = args.next().map_or(Ok(SEED), |a| a.parse())?;
    let start = std::time::Instant::now();
    let errors = sphere_errors(Lut::embedded(), &RADII_DEG, cases, seed, MEASURE_NODES);
    for (lobe, pick) in [
        (
            "specular",
            (|e: &SphereError, m: usize| e.specular[m]) as fn(&SphereError, usize) -> f64,
        ),
        ("diffuse", |e, m| e.diffuse[m]),
    ] {
        println!("\n{lobe}: Σ|method − exact| / Σ exact, {cases} cases a cell, seed {seed}\n");
        let bands: Vec<String> = BANDS
            .iter()
            .map(|b| format!("{}–{}°", b[0], b[1]))
            .collect();
        println!("| radius | method | {} |", bands.join(" | "));
        println!("|---|---|{}", "---:|".repeat(BANDS.len()));
        for &radius in &RADII_DEG {
            for (m, method) in APPROXIMATIONS.iter().enumerate() {
                let row: Vec<String> = errors
                    .iter()
                    .filter(|e| e.radius_deg == radius)
                    .map(|e| format!("{:.1}%", 100.0 * pick(e, m)))
                    .collect();
                println!("| {radius}° | {} | {} |", method.name(), row.join(" | "));
            }
        }
    }
    println!("\n{:.0} s", start.elapsed().as_secs_f64());
    Ok(())
}
