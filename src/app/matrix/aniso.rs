//! The matrix panel's 4D tables (docs/design.md §2.9): a slice over (α_x, θo) at the α_y/α_x
//! and φo of two sliders, coloured by the lobe error of table A's and table B's 4D tables
//! against the exact anisotropic lobe, and both tables' M⁻¹ at the material's point.

use egui::{Color32, Vec2};
use glam::DVec3;
use rayon::prelude::*;

use crate::app::lab::{Lab, TableId, Tables};
use crate::app::matrix::entries::matrix;
use crate::app::ui::display::{colour_bar, rgb};
use crate::app::work::cache::{Cached, Own};
use crate::brdf::Alpha;
use crate::colormap::{ColourScale, short_number};
use crate::ltc::aniso::AnisoLut;
use crate::ltc::lobe::{Stratum, strata};
use crate::ltc::lut::{ALPHA_MIN, THETA_MAX};
use crate::measure::aniso_table::{LobePoint, lobe_errors};

/// Points per side of the slice: the lab table's 8 nodes and three points between each pair,
/// so that the nodes and the space between them are both seen.
const SLICE: usize = 29;

/// Quadrature strata per side at each point (576 nodes): the slice is a picture, drawn
/// while sliders move; the published numbers take `MEASURE_STRATA` (256 per side), and at
/// 24 per side a lobe's error reads within a few tenths of a percent of it (§4.11).
const STRATA: usize = 24;

/// The slice's two other axes, and its maps.
pub struct AnisoSlice {
    /// α_y / α_x along the slice (1: isotropic).
    ratio: f64,
    /// The view's azimuth from the tangent, degrees.
    phi_deg: f64,
    maps: Cached<SliceMaps>,
}

impl Default for AnisoSlice {
    fn default() -> Self {
        Self {
            ratio: 0.25,
            phi_deg: 0.0,
            maps: Cached::new("matrix.aniso_slice"),
        }
    }
}

/// Each table's error over the slice, and the textures that show them on one scale.
struct SliceMaps {
    errors: [Vec<f64>; 2],
    scale: ColourScale,
    textures: [egui::TextureHandle; 2],
}

/// The material at the slice's point `(i, j)`: α_x on the lab table's axis (`α_min + (1 −
/// α_min) r²`), θo on its view axis (`1 − cos θ = s² (1 − cos θ_max)`), both from 0 at the
/// top left.
fn slice_point(i: usize, j: usize, ratio: f64, phi: f64) -> LobePoint {
    let last = (SLICE - 1) as f64;
    let (r, s) = (i as f64 / last, j as f64 / last);
    let x = ALPHA_MIN + (1.0 - ALPHA_MIN) * r * r;
    let alpha = Alpha {
        x,
        y: (ratio * x).max(ALPHA_MIN),
    };
    let cos_theta = 1.0 - s * s * (1.0 - THETA_MAX.cos());
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let view = DVec3::new(sin_theta * phi.cos(), sin_theta * phi.sin(), cos_theta);
    LobePoint { alpha, view }
}

impl SliceMaps {
    fn new(tables: [&AnisoLut; 2], (ratio, phi): (f64, f64), ctx: &egui::Context) -> Self {
        let quadrature = strata(STRATA);
        let errors: Vec<Vec<f64>> = (0..SLICE * SLICE)
            .into_par_iter()
            .map(|k| {
                let point = slice_point(k % SLICE, k / SLICE, ratio, phi.to_radians());
                lobe_errors(&tables, &point, &quadrature)
            })
            .collect();
        let of = |t: usize| errors.iter().map(|e| e[t]).collect::<Vec<f64>>();
        let errors = [of(0), of(1)];
        let hi = errors.iter().flatten().fold(0.0f64, |m, &x| m.max(x));
        // 1%: below it a lobe reads as its LTC (the 2D maps' floor is the fit's 0.1% noise;
        // these come from a 24² quadrature, whose noise is near 1%).
        let scale = ColourScale::log(1e-2, hi.max(2e-2), "lobe error (log)").in_percent();
        let textures = [0, 1].map(|t| {
            let pixels = errors[t].iter().map(|&e| rgb(scale.colour(e))).collect();
            let image = egui::ColorImage::new([SLICE, SLICE], pixels);
            ctx.load_texture(
                format!("aniso slice {t}"),
                image,
                egui::TextureOptions::NEAREST,
            )
        });
        Self {
            errors,
            scale,
            textures,
        }
    }
}

impl AnisoSlice {
    /// The sliders, both maps with the material's point crossed, and the readings.
    pub fn show(&mut self, ui: &mut egui::Ui, lab: &Lab) {
        ui.strong("4D tables (anisotropic GGX): a slice over α_x and θo");
        ui.add(egui::Slider::new(&mut self.ratio, 0.0..=1.0).text("α_y / α_x"))
            .on_hover_text("The slice's third axis: α_y = max(ratio · α_x, α_min) at every point");
        ui.add(egui::Slider::new(&mut self.phi_deg, 0.0..=90.0).text("slice φo (°)"))
            .on_hover_text("The slice's fourth axis: the view's azimuth from the tangent (the tables fold every \
                other azimuth onto 0°…90° by the lobe's mirror symmetries)");
        let ctx = ui.ctx().clone();
        let inputs = (lab.tables(), Own((self.ratio, self.phi_deg)));
        let maps = self.maps.get(inputs, |(t, Own(axes))| {
            SliceMaps::new(aniso_of(t), axes, &ctx)
        });
        ui.small(format!(
            "each map: x: √(α_x − α_min) from α_min to 1, y (down): θo from 0° to {:.0}° (by \
             √(1 − cos θo)); the lab table's nodes every {} points",
            THETA_MAX.to_degrees(),
            (SLICE - 1) / 7
        ));
        colour_bar(ui, &maps.scale, 260.0);
        let side = ((ui.available_width() - 16.0) / 2.0).clamp(80.0, 260.0);
        let marker = material_marker(lab);
        let names = [TableId::A, TableId::B].map(|id| lab.tables().aniso(id).short_name());
        let mut hovered = None;
        ui.horizontal(|ui| {
            for t in 0..2 {
                ui.vertical(|ui| {
                    let mean = maps.errors[t].iter().sum::<f64>() / maps.errors[t].len() as f64;
                    ui.small(format!(
                        "{} ({}): mean {:.1}%",
                        ["A", "B"][t],
                        names[t],
                        100.0 * mean
                    ));
                    let at = slice_map(ui, &maps.textures[t], side, marker, &names[t]);
                    hovered = at.or(hovered);
                });
            }
        });
        let text = match hovered {
            Some((i, j)) => {
                let p = slice_point(i, j, self.ratio, self.phi_deg.to_radians());
                let k = j * SLICE + i;
                format!(
                    "α_x = {}, α_y = {}, θo = {:.1}°: A {:.1}%, B {:.1}%",
                    short_number(p.alpha.x),
                    short_number(p.alpha.y),
                    p.view.z.acos().to_degrees(),
                    100.0 * maps.errors[0][k],
                    100.0 * maps.errors[1][k]
                )
            }
            None => "hover a map to read both tables' lobe error there".into(),
        };
        ui.add(egui::Label::new(egui::RichText::new(text).small()).truncate());
        material_matrices(ui, lab);
    }
}

/// Tables A's and B's 4D tables.
fn aniso_of(tables: &crate::app::lab::Part<Tables>) -> [&AnisoLut; 2] {
    [tables.a().lut.aniso(), tables.b().lut.aniso()]
}

/// Where the material's (α_x, θo) falls on the slice, as fractions of its sides.
fn material_marker(lab: &Lab) -> (f32, f32) {
    let alpha = lab.material().roughness();
    let r = ((alpha.x.max(alpha.y) - ALPHA_MIN) / (1.0 - ALPHA_MIN))
        .max(0.0)
        .sqrt();
    let s = ((1.0 - lab.theta_o().cos()) / (1.0 - THETA_MAX.cos())).sqrt();
    (r as f32, s.min(1.0) as f32)
}

/// One table's map, `side` points wide, the material's point crossed; the point under the
/// pointer.
fn slice_map(
    ui: &mut egui::Ui,
    texture: &egui::TextureHandle,
    side: f32,
    (u, v): (f32, f32),
    name: &str,
) -> Option<(usize, usize)> {
    let (rect, response) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::hover());
    let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
    ui.painter().image(texture.id(), rect, uv, Color32::WHITE);
    // Texel centres sit at (k + ½)/SLICE.
    let to_screen = |t: f32| (t * (SLICE - 1) as f32 + 0.5) / SLICE as f32 * side;
    let p = rect.min + Vec2::new(to_screen(u), to_screen(v));
    let stroke = egui::Stroke::new(1.0, Color32::WHITE);
    ui.painter().hline(rect.x_range(), p.y, stroke);
    ui.painter().vline(p.x, rect.y_range(), stroke);
    let label = format!("{name} 4D error map");
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &label));
    let pos = response.hover_pos()?;
    let k = ((pos - rect.min) / side * SLICE as f32).floor();
    let clamp = |x: f32| (x.max(0.0) as usize).min(SLICE - 1);
    Some((clamp(k.x), clamp(k.y)))
}

/// Both tables' M⁻¹ (cos_from_brdf, in the tangent frame) at the material and the lobe
/// panel's view, with their lobe errors there (64² strata).
fn material_matrices(ui: &mut egui::Ui, lab: &Lab) {
    let theta = lab.theta_o();
    let phi = lab.lobe_view().phi_o_deg.to_radians();
    let view = DVec3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    );
    let point = LobePoint {
        alpha: lab.material().roughness(),
        view,
    };
    let tables = aniso_of(lab.tables());
    let quadrature: Vec<Stratum> = strata(64);
    let errors = lobe_errors(&tables, &point, &quadrature);
    ui.small(format!(
        "at the material (α_x = {}, α_y = {}) seen from θo = {:.1}°, φo = {:.1}°:",
        short_number(point.alpha.x),
        short_number(point.alpha.y),
        theta.to_degrees(),
        lab.lobe_view().phi_o_deg
    ));
    ui.horizontal(|ui| {
        for (t, table) in tables.iter().enumerate() {
            let m = table.ltc(point.alpha, view).cos_from_brdf;
            let title = format!("M^-1, {} 4D table, error {:.1}%", ["A", "B"][t], 100.0 * errors[t]);
            matrix(ui, &title, m, "cos_from_brdf in the tangent frame: maps a lobe direction to the clamped-cosine domain; \
                a full 3×3 matrix, read from the 4D table's 16 nodes about this point");
            ui.add_space(12.0);
        }
    });
}
