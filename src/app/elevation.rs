//! The clipping panel's view of one light over its elevation (docs/design.md §4.7): at the
//! lab's (θo, α), the specular lobe of one light in the plane of incidence, on the mirror
//! side, from below the horizon to the zenith — exact and through the table with the lab's
//! rules — and the error of each elevation band over every azimuth.

use egui::{Color32, Vec2};

use crate::app::axes::symlog_y;
use crate::app::lab::{Aspect, Lab, Stamp};
use crate::horizon::{self, BandError};
use crate::ltc::lut::Lut;

/// Cases per band at one view and roughness: 20 000 keep each band's error within a few
/// percent of itself (docs/design.md §4.7 measured 3% at 10⁵ over every view, where the cases
/// vary far more) and take about 20 ms on two cores, once per change.
pub const CASES: usize = 20_000;

/// What the view reads: the material (α), θo, the rules and the tables.
const READS: [Aspect; 4] = [
    Aspect::Scene,
    Aspect::LobeView,
    Aspect::Rules,
    Aspect::Tables,
];

/// The band errors as last measured, and for what: the lab's stamp and which table.
#[derive(Default)]
pub struct ElevationView {
    made_for: Option<(Stamp, bool)>,
    bands: Vec<BandError>,
}

impl ElevationView {
    /// The plot and the band errors for `lut` (table B where `table_b`).
    pub fn show(&mut self, ui: &mut egui::Ui, lab: &Lab, (lut, table_b): (&Lut, bool)) {
        let s = lab.shared();
        let (theta_o, alpha) = (s.theta_o_deg, s.alpha());
        let made_for = (lab.stamp(&READS), table_b);
        if self.made_for != Some(made_for) {
            let at = (theta_o, alpha);
            let rules = s.ltc_rules();
            self.bands = horizon::band_errors_at(lut, &rules, at, CASES, horizon::SEED);
            self.made_for = Some(made_for);
        }
        ui.small(format!(
            "one light over its elevation at θo = {theta_o:.1}°, α = {alpha:.4} (the side panel's), specular lobe, table {}:",
            if table_b { "B" } else { "A" }
        ));
        ui.horizontal_wrapped(|ui| {
            for b in &self.bands {
                ui.small(format!(
                    "{:.0}–{:.0}°: {:.0}% (energy ×{:.2})",
                    b.band[0],
                    b.band[1],
                    100.0 * b.specular,
                    b.specular_energy
                ))
                .on_hover_text("Σ|LTC − BRDF| / Σ BRDF over lights uniform in this band at every azimuth, and Σ LTC / Σ BRDF");
            }
        });
        plot(ui, lut, &s.ltc_rules(), (theta_o, alpha));
    }
}

/// The exact lobe and the LTC (the lab's rules) of one light on the mirror side of the plane of
/// incidence, over its elevation from −10° to 90°, on a symmetric log axis.
fn plot(ui: &mut egui::Ui, lut: &Lut, rules: &crate::render::LtcRules, at: (f64, f64)) {
    let samples: Vec<(f64, f64, f64)> = (0..=200)
        .map(|k| {
            let e = -10.0 + 100.0 * f64::from(k) / 200.0;
            let r = e.to_radians();
            let l = glam::DVec3::new(-r.cos(), 0.0, r.sin());
            let (exact, ltc) = horizon::lobes(lut, rules, at, l);
            (e, exact.specular, ltc.specular)
        })
        .collect();
    let peak = samples
        .iter()
        .fold(1e-30f64, |m, s| m.max(s.1.abs()).max(s.2.abs()));
    // Four decades under the peak: the horizon's error is a fraction of the peak's.
    let c = peak * 1e-4;
    let curve = |pick: fn(&(f64, f64, f64)) -> f64| -> Vec<[f64; 2]> {
        samples
            .iter()
            .map(|s| [s.0, crate::colormap::symlog(pick(s), c)])
            .collect()
    };
    let plot = egui_plot::Plot::new("elevation profile")
        .legend(egui_plot::Legend::default())
        .x_axis_label("light elevation above the surface (degrees)")
        .y_axis_label("f·cos (symlog)")
        // Grid lines every 5°, 15° and 30°: the bands' edges fall on them.
        .x_grid_spacer(egui_plot::uniform_grid_spacer(|_| [5.0, 15.0, 30.0]))
        .min_size(Vec2::new(80.0, 120.0))
        .height(ui.available_height().max(120.0))
        .allow_scroll(false);
    symlog_y(plot, c).show(ui, |p| {
        p.line(egui_plot::Line::new("BRDF", curve(|s| s.1)).color(Color32::from_rgb(240, 150, 60)));
        p.line(
            egui_plot::Line::new("LTC, the lab's rules", curve(|s| s.2))
                .color(Color32::from_rgb(90, 210, 120)),
        );
    });
}
