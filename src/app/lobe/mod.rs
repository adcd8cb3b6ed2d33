//! The lobe panel: the exact cosine-weighted BRDF lobe and its LTC as radial surfaces on the
//! sphere (orbit by dragging), the normal, the view vector and the LTC's frame; a slider that
//! morphs M from the identity (the clamped cosine) to the fitted matrix; the pointwise
//! difference coloured on the sphere; and a slice through the plane of incidence.

pub mod sphere;

use egui::{Color32, Vec2};
use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use crate::app::lab::part::Notes;
use crate::app::lab::{Checked, Lab, LastRefit, LobeView, Part, TableId, Tables};
use crate::app::lobe::sphere::{Drawn, Sphere, values};
use crate::app::panel::Panel;
use crate::app::ui::display::colour_bar;
use crate::app::work::cache::{Cached, Inputs, Own};
use crate::ltc::Ltc;
use crate::ltc::lut::THETA_MAX;
use crate::scene::Material;

/// The lobe panel's own settings, kept between runs (θo and the lobe are the lab's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct LobeState {
    /// 0: the clamped cosine (M = I); 1: the fitted LTC.
    pub morph: f64,
    pub orbit_yaw: f32,
    pub orbit_pitch: f32,
    /// The pointwise difference coloured on the unit sphere instead of the lobes.
    pub colour_difference: bool,
    /// Table B's LTC overlaid.
    pub overlay_table_b: bool,
}

/// How far the orbit's pitch leans: just short of the poles (±86°), where the orbit's frame
/// would flip.
const PITCH_LIMIT: f32 = 1.5;

impl Default for LobeState {
    fn default() -> Self {
        Self {
            morph: 1.0,
            orbit_yaw: 0.6,
            orbit_pitch: 0.35,
            colour_difference: false,
            overlay_table_b: true,
        }
    }
}

impl Checked for LobeState {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        let mut n = Notes(Vec::new());
        n.number(
            "the lobe's morph",
            &mut self.morph,
            previous.morph,
            [0.0, 1.0],
        );
        // Any yaw is a turn; beyond a few turns it only loses precision.
        let turns = [-100.0, 100.0];
        n.number_f32(
            "the lobe's orbit",
            &mut self.orbit_yaw,
            previous.orbit_yaw,
            turns,
        );
        let pitch = [-PITCH_LIMIT, PITCH_LIMIT];
        n.number_f32(
            "the lobe's pitch",
            &mut self.orbit_pitch,
            previous.orbit_pitch,
            pitch,
        );
        n.0
    }
}

pub struct LobePanel {
    state: LobeState,
    /// The sphere's surfaces (thousands of sorted triangles), made again only when what they
    /// show changes.
    sphere: Cached<Sphere>,
}

/// The LTC shown: M morphed from I to the fitted M, with the lobe's magnitude.
pub fn morphed_ltc(ltc: &Ltc, t: f64) -> Ltc {
    let m = DMat3::IDENTITY * (1.0 - t) + ltc.brdf_from_cos * t;
    Ltc::from_brdf_from_cos(m, ltc.norm, ltc.fresnel).with_scale(ltc.scale)
}

impl Panel for LobePanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        self.header(ui, lab);
        let parts = (lab.material(), lab.lobe_view(), lab.tables(), lab.refit());
        let shown = drawn(parts, &self.state);
        let plot_h = (ui.available_height() * 0.3).clamp(60.0, 160.0);
        let size = Vec2::new(
            ui.available_width(),
            (ui.available_height() - plot_h - 30.0).max(80.0),
        );
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::drag());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "lobe view"));
        let response = response.on_hover_text("Drag to orbit. Orange: the exact lobe f·cos; blue: the LTC n·D. White: the normal, \
            yellow: the view, red/green/blue: the LTC's frame (columns of M); magenta and cyan: the \
            pinned pixel's light ω (or rect P) and its image under M^-1");
        if response.dragged() {
            let d = response.drag_delta();
            self.state.orbit_yaw += d.x * 0.01;
            self.state.orbit_pitch =
                (self.state.orbit_pitch + d.y * 0.01).clamp(-PITCH_LIMIT, PITCH_LIMIT);
        }
        let (m, v, t, r) = parts;
        let inputs = (m, v, t, r, Own(self.state.clone()), Place(rect));
        let sphere = self
            .sphere
            .get(inputs, |(m, v, t, r, Own(st), Place(rect))| {
                let orbit = (st.orbit_yaw, st.orbit_pitch);
                Sphere::new(&drawn((m, v, t, r), &st), orbit, st.colour_difference, rect)
            });
        sphere.paint(&ui.painter_at(rect), rect, &shown);
        match &sphere.difference {
            Some(scale) => colour_bar(ui, scale, 200.0),
            None => {
                ui.label("orange: exact f·cos (filled); blue lines: LTC n·D; green lines: table B; n normal, v view, M x/y/z the columns of M");
            }
        }
        slice_plot(ui, &shown, plot_h);
    }

    fn caches(&self) -> Vec<(&'static str, u64)> {
        vec![self.sphere.count()]
    }
}

impl LobePanel {
    pub fn new(state: LobeState) -> Self {
        Self {
            state,
            sphere: Cached::new("lobe.sphere"),
        }
    }

    pub fn state(&self) -> &LobeState {
        &self.state
    }

    /// Its settings from a view (a lesson's step), checked by the caller.
    pub fn set_state(&mut self, state: LobeState) {
        self.state = state;
    }

    /// The parameters on the panel's face, so that a picture of it (a slide made with the
    /// controls folded) carries what it shows; then the lobe, overlay and morph controls.
    fn header(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        let st = &mut self.state;
        // File names without their directories: a path pushed the row past the panel.
        // An anisotropic lobe comes from the 4D tables: B's is the one overlaid.
        let b_name = match lab.material().is_anisotropic() {
            true => lab.tables().aniso(TableId::B).short_name(),
            false => lab.tables().b().short_name().to_string(),
        };
        let b = if st.overlay_table_b {
            format!(", B: {b_name}")
        } else {
            String::new()
        };
        let refitted = lab
            .refit_ltc()
            .is_some_and(|(l, _)| l == lab.lobe_view().lobe);
        let m = lab.material();
        let (view, tables) = (lab.lobe_view(), lab.tables());
        match m.is_anisotropic() {
            true => ui.strong(format!(
                "θo = {:.1}°   φo = {:.1}°   α_x = {:.4}   α_y = {:.4}   4D table A: {}{}",
                view.theta_o_deg,
                view.phi_o_deg,
                m.roughness().x,
                m.roughness().y,
                tables.aniso(TableId::A).short_name(),
                if st.overlay_table_b {
                    format!(", B: {}", tables.aniso(TableId::B).short_name())
                } else {
                    String::new()
                }
            )),
            false => ui.strong(format!(
                "θo = {:.1}°   α = {:.4}   table A: {}{}{b}",
                view.theta_o_deg,
                lab.alpha(),
                tables.a().short_name(),
                if refitted { " (refitted)" } else { "" }
            )),
        };
        ui.horizontal(|ui| {
            lab.edit(|v: &mut LobeView| {
                use crate::ltc::lobe::Lobe;
                ui.selectable_value(&mut v.lobe, Lobe::Specular, "specular")
                    .on_hover_text("GGX f_s·cos with F = 1 against n_s·D_s");
                ui.selectable_value(&mut v.lobe, Lobe::Diffuse, "diffuse")
                    .on_hover_text("Burley fd·cos with c = 1 against n_d·D_d");
            });
            ui.checkbox(&mut st.overlay_table_b, format!("table B ({b_name})"))
                .on_hover_text("Overlay table B's LTC (green): by default the other shipped table (the point-light fit \
                    over the classic one, or the reverse); \"as B\" in the side panel loads another");
            ui.checkbox(&mut st.colour_difference, "difference")
                .on_hover_text("Colour the unit sphere by n·D − f·cos in 1/sr, the slice plot's units (orange: LTC too bright, blue: too dark)");
        });
        ui.add(egui::Slider::new(&mut st.morph, 0.0..=1.0).text("M: I -> fitted"))
            .on_hover_text("D is the clamped cosine pushed through M_t = (1−t)·I + t·M: at 0 the cosine, at 1 the fitted LTC (the transformed lobe)");
    }
}

/// The sphere's place on the screen, as its key: the same while within a point of the place
/// the sphere was made for. The side panel is as wide as its widest row, the selected light's
/// numbers among them, so a dragged light moved every panel by a fraction of a point; a
/// sphere a fraction of a point away looks the same, and is made again once the place has
/// moved a point.
struct Place(egui::Rect);

/// A place, equal to another within a point.
#[derive(Clone, Copy)]
struct Near(egui::Rect);

impl PartialEq for Near {
    fn eq(&self, other: &Self) -> bool {
        let (a, b) = (self.0, other.0);
        (a.min - b.min).abs().max_elem() < 1.0 && (a.max - b.max).abs().max_elem() < 1.0
    }
}

impl Inputs for Place {
    type Key = Near;

    fn key(&self) -> Near {
        Near(self.0)
    }
}

/// The parts the lobe is drawn from.
type DrawnFrom<'a> = (
    &'a Part<Material>,
    &'a Part<LobeView>,
    &'a Part<Tables>,
    &'a Part<LastRefit>,
);

/// The lobe at the lab's (θo, α): table A's LTC (or the refit of its cell, while it is the
/// cell chosen), morphed, and table B's where overlaid; a pinned pixel's light. An
/// anisotropic material is seen from (θo, φo) in its tangent frame, its lobes from each
/// table's 4D table (`Lut::aniso_pair`).
fn drawn((material, view, tables, refit): DrawnFrom<'_>, st: &LobeState) -> Drawn {
    let theta = view.theta_o_deg.to_radians().min(THETA_MAX);
    let alpha = material.roughness();
    let v = match material.is_anisotropic() {
        true => {
            let phi = view.phi_o_deg.to_radians();
            DVec3::new(
                theta.sin() * phi.cos(),
                theta.sin() * phi.sin(),
                theta.cos(),
            )
        }
        false => DVec3::new(theta.sin(), 0.0, theta.cos()),
    };
    let pair = |lut: &crate::ltc::lut::Lut| match material.is_anisotropic() {
        true => lut.aniso_pair(alpha, v),
        false => lut.sample(alpha.x, theta.cos()).ltc_pair(),
    };
    let a = &tables.a().lut;
    let refitted = refit.0.as_ref().filter(|r| {
        !material.is_anisotropic()
            && r.lobe == view.lobe
            && r.cell == a.nearest_cell(alpha.x, theta.cos())
    });
    let fitted = match refitted {
        Some(r) => r.ltc(),
        None => *pair(a).lobe(view.lobe),
    };
    Drawn {
        lobe: view.lobe,
        v,
        alpha,
        ltc: morphed_ltc(&fitted, st.morph),
        other: st
            .overlay_table_b
            .then(|| morphed_ltc(pair(&tables.b().lut).lobe(view.lobe), st.morph)),
        light: view.light.map(DVec3::from),
        polygon: view.polygon.map(|c| c.map(DVec3::from)),
    }
}

/// Both lobes along the plane of incidence, θ from −90° (away from the view) to 90°.
fn slice_plot(ui: &mut egui::Ui, d: &Drawn, height: f32) {
    let (lobe, v, alpha, ltc, other) = (d.lobe, d.v, d.alpha, &d.ltc, d.other.as_ref());
    let samples = 361;
    // The plane through the normal and the view (an anisotropic view has an azimuth).
    let (sin_phi, cos_phi) = v.y.atan2(v.x).sin_cos();
    let points = |which: &Ltc, exact: bool| -> Vec<[f64; 2]> {
        (0..samples)
            .map(|k| {
                let deg = -90.0 + 180.0 * k as f64 / (samples - 1) as f64;
                let t = deg.to_radians();
                let l = DVec3::new(t.sin() * cos_phi, t.sin() * sin_phi, t.cos());
                let (e, a) = values(lobe, v, alpha, which, l);
                [deg, if exact { e } else { a }]
            })
            .collect()
    };
    egui_plot::Plot::new("lobe slice")
        .height(height)
        .legend(egui_plot::Legend::default())
        .x_axis_label("θ in the plane of incidence (°)")
        .y_axis_label("1/sr")
        // Ticks every 10°, 30° and 90° (the default's 10s and 100s label only 0 here).
        .x_grid_spacer(egui_plot::uniform_grid_spacer(|_| [10.0, 30.0, 90.0]))
        .include_x(-90.0)
        .include_x(90.0)
        .allow_scroll(false)
        .show(ui, |p| {
            p.line(
                egui_plot::Line::new("exact f·cos", points(ltc, true))
                    .color(Color32::from_rgb(240, 150, 60)),
            );
            p.line(
                egui_plot::Line::new("LTC n·D", points(ltc, false))
                    .color(Color32::from_rgb(70, 140, 255)),
            );
            if let Some(o) = other {
                p.line(
                    egui_plot::Line::new("table B", points(o, false))
                        .color(Color32::from_rgb(80, 220, 120)),
                );
            }
        });
}
