//! The clipping panel's view of one light over its elevation (docs/design.md §4.7): at the
//! lab's (θo, α), the specular lobe of one light in the plane of incidence, on the mirror
//! side, from below the horizon to the zenith — exact and through the table with the lab's
//! rules — and the error of each elevation band over every azimuth. With an angular radius σ,
//! the light is a sphere (docs/design.md §1.10, §4.9): its exact integral against the point
//! formula at its centre, the LTC disk and the representative point, per band.

use egui::{Color32, Vec2};

use crate::app::lab::{Lab, TableId};
use crate::app::ui::axes::symlog_y;
use crate::app::work::cache::{Cached, Own};
use crate::light::sphere::SphereMethod;
use crate::ltc::lut::Lut;
use crate::measure::horizon::{self, BandError};
use crate::measure::sphere_error::{
    APPROXIMATIONS, MEASURE_NODES, SphereError, one_sphere, sphere_errors_at,
};

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
    /// The sphere's band errors and its lobe over its centre's elevation (each an exact cap
    /// integral: made when its inputs change, not every frame).
    spheres: Cached<(Vec<SphereError>, Vec<SphereSample>)>,
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
            .on_hover_text("The light's angular radius: 0 is the paper's point light; above it a sphere, its exact \
                integral over the cap against the point formula, the LTC disk and the representative \
                point (docs/design.md §4.9)");
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
        let (errors, samples) =
            self.spheres
                .get(inputs, |(material, view, tables, Own((which, _)))| {
                    let at = (view.theta_o_deg, material.alpha);
                    let lut = &tables.get(which).lut;
                    let cases = (SPHERE_CASES, horizon::SEED, MEASURE_NODES);
                    (
                        sphere_errors_at(lut, at, sigma, cases),
                        sphere_samples(lut, at, sigma),
                    )
                });
        let (theta_o, alpha) = (lab.lobe_view().theta_o_deg, lab.alpha());
        ui.small(format!(
            "a sphere of σ = {sigma:.1}° over its centre's elevation at θo = {theta_o:.1}°, α = \
                {alpha:.4}, specular lobe, table {which:?} (eq. 30's rules); error Σ|method − exact| / Σ \
                exact per band:"
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
        let names = ["exact"]
            .into_iter()
            .chain(APPROXIMATIONS.map(SphereMethod::name));
        let curves: Vec<(&str, Color32, Vec<[f64; 2]>)> = names
            .zip(COLOURS)
            .enumerate()
            .map(|(k, (name, colour))| {
                (
                    name,
                    colour,
                    samples.iter().map(|s| [s.0, s.1[k]]).collect(),
                )
            })
            .collect();
        let labels = (
            "the sphere's centre above the surface (degrees)",
            "f·cos over the cap (symlog)",
        );
        profile_plot(ui, "sphere elevation profile", labels, &curves);
    }

    pub fn counts(&self) -> [(&'static str, u64); 2] {
        [self.bands.count(), self.spheres.count()]
    }
}

/// The curves' colours: the exact lobe's orange, then one per approximation.
const COLOURS: [Color32; 4] = [
    Color32::from_rgb(240, 150, 60),
    Color32::from_rgb(90, 210, 120),
    Color32::from_rgb(90, 150, 240),
    Color32::from_rgb(220, 90, 200),
];

/// The centre's elevation (degrees), and there the exact specular lobe and each of
/// `APPROXIMATIONS`'.
type SphereSample = (f64, [f64; 4]);

/// A sphere of angular radius `sigma` on the mirror side of the plane of incidence, its centre
/// from σ + 10° below the horizon to the zenith.
fn sphere_samples(lut: &Lut, at: (f64, f64), sigma: f64) -> Vec<SphereSample> {
    let low = -sigma - 10.0;
    (0..=100)
        .map(|k| {
            let e = low + (90.0 - low) * f64::from(k) / 100.0;
            let r = e.to_radians();
            let l = glam::DVec3::new(-r.cos(), 0.0, r.sin());
            let (exact, got) = one_sphere(lut, at, l, sigma, MEASURE_NODES);
            let [a, b, c] = got.map(|g| g.specular);
            (e, [exact.specular, a, b, c])
        })
        .collect()
}

/// The exact lobe and the LTC (the lab's rules) of one light on the mirror side of the plane of
/// incidence, over its elevation from −10° to 90°, on a symmetric log axis.
fn plot(ui: &mut egui::Ui, lut: &Lut, rules: &crate::render::LtcRules, at: (f64, f64)) {
    let (mut exact, mut ltc) = (Vec::new(), Vec::new());
    for k in 0..=200 {
        let e = -10.0 + 100.0 * f64::from(k) / 200.0;
        let r = e.to_radians();
        let l = glam::DVec3::new(-r.cos(), 0.0, r.sin());
        let (want, got) = horizon::lobes(lut, rules, at, l);
        exact.push([e, want.specular]);
        ltc.push([e, got.specular]);
    }
    let curves = [
        ("BRDF", COLOURS[0], exact),
        ("LTC, the lab's rules", COLOURS[1], ltc),
    ];
    let labels = (
        "light elevation above the surface (degrees)",
        "f·cos (symlog)",
    );
    profile_plot(ui, "elevation profile", labels, &curves);
}

/// Curves over an elevation on a symmetric log axis four decades under their peak (the
/// horizon's error is a fraction of the peak's), grid lines every 5°, 15° and 30° (the bands'
/// edges fall on them).
fn profile_plot(
    ui: &mut egui::Ui,
    id: &str,
    (x_label, y_label): (&str, &str),
    curves: &[(&str, Color32, Vec<[f64; 2]>)],
) {
    let peak = curves
        .iter()
        .flat_map(|c| &c.2)
        .fold(1e-30f64, |m, p| m.max(p[1].abs()));
    let c = peak * 1e-4;
    let plot = egui_plot::Plot::new(id)
        .legend(egui_plot::Legend::default())
        .x_axis_label(x_label)
        .y_axis_label(y_label)
        .x_grid_spacer(egui_plot::uniform_grid_spacer(|_| [5.0, 15.0, 30.0]))
        .min_size(Vec2::new(80.0, 120.0))
        .height(ui.available_height().max(120.0))
        .allow_scroll(false);
    symlog_y(plot, c).show(ui, |p| {
        for (name, colour, points) in curves {
            let symlog = points
                .iter()
                .map(|&[x, y]| [x, crate::colormap::symlog(y, c)])
                .collect::<Vec<_>>();
            p.line(egui_plot::Line::new(*name, symlog).color(*colour));
        }
    });
}
