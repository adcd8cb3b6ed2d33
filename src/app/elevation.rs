//! The clipping panel's view of one light over its elevation (docs/design.md §4.7): at the
//! lab's (θo, α), the specular lobe of one light in the plane of incidence, on the mirror
//! side, from below the horizon to the zenith — exact and through the table with the lab's
//! rules — and the error of each elevation band over every azimuth. With an angular radius σ,
//! the light is a sphere (docs/design.md §1.10, §4.9): its exact integral against the point
//! formula at its centre, the LTC disk and the representative point, per band.

use egui::{Color32, Vec2};

use crate::app::axes::symlog_y;
use crate::app::cache::{Cached, Own};
use crate::app::lab::{Lab, TableId};
use crate::horizon::{self, BandError};
use crate::ltc::lut::Lut;
use crate::sphere_error::{
    APPROXIMATIONS, MEASURE_NODES, SphereError, one_sphere, sphere_errors_at,
};
use crate::sphere_light::SphereMethod;

/// Cases per band at one view and roughness: 20 000 keep each band's error within a few
/// percent of itself (docs/design.md §4.7 measured 3% at 10⁵ over every view, where the cases
/// vary far more) and take about 20 ms on two cores, once per change.
pub const CASES: usize = 20_000;

/// Cases per band of a sphere's measure at one view: each costs an exact cap integral
/// (`MEASURE_NODES`), so 500 (a quarter second on two cores) keep each band's figure within
/// about a tenth of itself — the methods differ by more than that from 5° on (§4.9).
pub const SPHERE_CASES: usize = 500;

/// The largest angular radius the view offers: the design's table's (§4.9).
pub const MAX_SIGMA_DEG: f64 = 30.0;

/// The band errors as last measured, and the light's angular radius (0: a point).
pub struct ElevationView {
    bands: Cached<Vec<BandError>>,
    spheres: Cached<Vec<SphereError>>,
    sigma_deg: f64,
}

impl Default for ElevationView {
    fn default() -> Self {
        Self {
            bands: Cached::new("clipping.elevation"),
            spheres: Cached::new("clipping.elevation_spheres"),
            sigma_deg: 0.0,
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
        ui.add(egui::Slider::new(&mut self.sigma_deg, 0.0..=MAX_SIGMA_DEG).text("sphere σ (°)"))
            .on_hover_text("The light's angular radius: 0 is the paper's point light; above it a sphere, its exact integral over the cap against the point formula, the LTC disk and the representative point (docs/design.md §4.9)");
        if self.sigma_deg > 0.0 {
            self.show_sphere(ui, lab, which);
            return;
        }
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

    /// The sphere's band errors per method and its lobe over the centre's elevation.
    fn show_sphere(&mut self, ui: &mut egui::Ui, lab: &Lab, which: TableId) {
        let sigma = self.sigma_deg;
        let inputs = (
            lab.material(),
            lab.lobe_view(),
            lab.tables(),
            Own((which, sigma.to_bits())),
        );
        let errors = self
            .spheres
            .get(inputs, |(material, view, tables, Own((which, _)))| {
                let at = (view.theta_o_deg, material.alpha);
                let lut = &tables.get(which).lut;
                sphere_errors_at(lut, at, sigma, (SPHERE_CASES, horizon::SEED, MEASURE_NODES))
            });
        let (theta_o, alpha) = (lab.lobe_view().theta_o_deg, lab.alpha());
        ui.small(format!(
            "a sphere of σ = {sigma:.1}° over its centre's elevation at θo = {theta_o:.1}°, α = {alpha:.4}, specular lobe, table {which:?} (eq. 30's rules); error Σ|method − exact| / Σ exact per band:"
        ));
        for e in errors {
            let cells: Vec<String> = APPROXIMATIONS
                .iter()
                .zip(e.specular)
                .map(|(m, x)| format!("{} {:.0}%", m.name(), 100.0 * x))
                .collect();
            ui.small(format!(
                "{:.0}–{:.0}°: {}",
                e.band[0],
                e.band[1],
                cells.join(", ")
            ))
            .on_hover_text("Over spheres whose centres are uniform in this band at every azimuth");
        }
        let lut = &lab.tables().get(which).lut;
        sphere_plot(ui, lut, (theta_o, alpha), sigma);
    }

    pub fn counts(&self) -> [(&'static str, u64); 2] {
        [self.bands.count(), self.spheres.count()]
    }
}

/// A sphere of angular radius `sigma` on the mirror side of the plane of incidence, its centre
/// from σ + 10° below the horizon to the zenith: the exact specular lobe and each method's.
fn sphere_plot(ui: &mut egui::Ui, lut: &Lut, at: (f64, f64), sigma: f64) {
    let low = -sigma - 10.0;
    let samples: Vec<(f64, [f64; 4])> = (0..=100)
        .map(|k| {
            let e = low + (90.0 - low) * f64::from(k) / 100.0;
            let r = e.to_radians();
            let l = glam::DVec3::new(-r.cos(), 0.0, r.sin());
            let (exact, got) = one_sphere(lut, at, l, sigma, MEASURE_NODES);
            (
                e,
                [
                    exact.specular,
                    got[0].specular,
                    got[1].specular,
                    got[2].specular,
                ],
            )
        })
        .collect();
    let peak = samples
        .iter()
        .flat_map(|s| s.1)
        .fold(1e-30f64, |m, x| m.max(x.abs()));
    let c = peak * 1e-4;
    let curve = |k: usize| -> Vec<[f64; 2]> {
        samples
            .iter()
            .map(|s| [s.0, crate::colormap::symlog(s.1[k], c)])
            .collect()
    };
    let plot = egui_plot::Plot::new("sphere elevation profile")
        .legend(egui_plot::Legend::default())
        .x_axis_label("the sphere's centre above the surface (degrees)")
        .y_axis_label("f·cos over the cap (symlog)")
        .x_grid_spacer(egui_plot::uniform_grid_spacer(|_| [5.0, 15.0, 30.0]))
        .min_size(Vec2::new(80.0, 120.0))
        .height(ui.available_height().max(120.0))
        .allow_scroll(false);
    let colours = [
        Color32::from_rgb(240, 150, 60),
        Color32::from_rgb(90, 210, 120),
        Color32::from_rgb(90, 150, 240),
        Color32::from_rgb(220, 90, 200),
    ];
    let names = ["exact"]
        .into_iter()
        .chain(APPROXIMATIONS.map(SphereMethod::name));
    symlog_y(plot, c).show(ui, |p| {
        for (k, (name, colour)) in names.zip(colours).enumerate() {
            p.line(egui_plot::Line::new(name, curve(k)).color(colour));
        }
    });
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
