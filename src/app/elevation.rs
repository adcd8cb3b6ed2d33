//! The clipping panel's view of one light over its elevation (docs/design.md §4.7): at the
//! lab's (θo, α), the specular lobe of one light in the plane of incidence, on the mirror
//! side, from below the horizon to the zenith — exact and through the table with the lab's
//! rules — and the error of each elevation band over every azimuth.

use egui::{Color32, Vec2};

use crate::app::axes::symlog_y;
use crate::app::cache::{Cached, Own};
use crate::app::lab::{Lab, TableId};
use crate::horizon::{self, BandError};
use crate::ltc::lut::Lut;

/// Cases per band at one view and roughness: 20 000 keep each band's error within a few
/// percent of itself (docs/design.md §4.7 measured 3% at 10⁵ over every view, where the cases
/// vary far more) and take about 20 ms on two cores, once per change.
pub const CASES: usize = 20_000;

/// The band errors as last measured.
pub struct ElevationView {
    bands: Cached<Vec<BandError>>,
}

impl Default for ElevationView {
    fn default() -> Self {
        Self {
            bands: Cached::new("clipping.elevation"),
        }
    }
}

impl ElevationView {
    /// The plot and the band errors for table `which`, at the lab's (θo, α) and rules.
    pub fn show(&mut self, ui: &mut egui::Ui, lab: &Lab, which: TableId) {
        let inputs = (
            lab.material(),
            lab.lobe_view(),
            lab.rules(),
            lab.tables(),
            Own(which),
        );
        let bands = self
            .bands
            .get(inputs, |(material, view, rules, tables, Own(which))| {
                let at = (view.theta_o_deg, material.alpha);
                let lut = &tables.get(which).lut;
                horizon::band_errors_at(lut, rules, at, CASES, horizon::SEED)
            });
        let (theta_o, alpha) = (lab.lobe_view().theta_o_deg, lab.alpha());
        ui.small(format!(
            "one light over its elevation at θo = {theta_o:.1}°, α = {alpha:.4} (the side panel's), specular lobe, table {which:?}:"
        ));
        ui.horizontal_wrapped(|ui| {
            for b in bands {
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
        let lut = &lab.tables().get(which).lut;
        plot(ui, lut, lab.rules(), (theta_o, alpha));
    }

    pub fn count(&self) -> (&'static str, u64) {
        self.bands.count()
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
