//! The lobe panel: the exact cosine-weighted BRDF lobe and its LTC as radial surfaces on the
//! sphere (orbit by dragging), the normal, the view vector and the LTC's frame; a slider that
//! morphs M from the identity (the clamped cosine) to the fitted matrix; the pointwise
//! difference coloured on the sphere; and a slice through the plane of incidence.

use egui::{Color32, Vec2};
use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use crate::app::display::colour_bar;
use crate::app::lab::{Aspect, Lab, Panel, Stamp};
use crate::app::lobe_sphere::{Drawn, Sphere, values};
use crate::colormap::ColourScale;
use crate::ltc::Ltc;
use crate::ltc::lobe::Lobe;

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
    pub overlay_other_fit: bool,
}

impl Default for LobeState {
    fn default() -> Self {
        Self {
            morph: 1.0,
            orbit_yaw: 0.6,
            orbit_pitch: 0.35,
            colour_difference: false,
            overlay_other_fit: true,
        }
    }
}

#[derive(Default)]
pub struct LobePanel {
    pub state: LobeState,
    /// The sphere as last made, and what for.
    sphere: Option<(SphereFor, Sphere)>,
}

/// The LTC shown: M morphed from I to the fitted M, with the lobe's magnitude.
pub fn morphed_ltc(ltc: &Ltc, t: f64) -> Ltc {
    let m = DMat3::IDENTITY * (1.0 - t) + ltc.brdf_from_cos * t;
    Ltc::from_brdf_from_cos(m, ltc.norm, ltc.fresnel).with_scale(ltc.scale)
}

/// What the lab's aspects, the panel's settings and the view's place a sphere was made for.
type SphereFor = (Stamp, LobeState, egui::Rect);

/// What the sphere is drawn from: the material (α), θo and the lobe, the tables and a refit,
/// and the pinned pixel's light.
const DRAWN_FROM: [Aspect; 5] = [
    Aspect::Scene,
    Aspect::LobeView,
    Aspect::Tables,
    Aspect::Refit,
    Aspect::Selection,
];

impl Panel for LobePanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        self.header(ui, lab);
        let drawn = self.drawn(lab);
        let plot_h = (ui.available_height() * 0.3).clamp(60.0, 160.0);
        let size = Vec2::new(
            ui.available_width(),
            (ui.available_height() - plot_h - 30.0).max(80.0),
        );
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::drag());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "lobe view"));
        let response = response.on_hover_text("Drag to orbit. Orange: the exact lobe f·cos; blue: the LTC n·D. White: the normal, yellow: the view, red/green/blue: the LTC's frame (columns of M)");
        if response.dragged() {
            let d = response.drag_delta();
            self.state.orbit_yaw += d.x * 0.01;
            self.state.orbit_pitch = (self.state.orbit_pitch + d.y * 0.01).clamp(-1.5, 1.5);
        }
        let stamp = lab.stamp(&DRAWN_FROM);
        match self.paint_sphere(ui, rect, (&drawn, stamp)) {
            Some(scale) => colour_bar(ui, &scale, 200.0),
            None => {
                ui.label("orange: exact f·cos (filled); blue lines: LTC n·D; green lines: table B; n normal, v view, M x/y/z the columns of M");
            }
        }
        slice_plot(ui, &drawn, plot_h);
    }
}

impl LobePanel {
    pub fn new(state: LobeState) -> Self {
        Self {
            state,
            sphere: None,
        }
    }

    /// The parameters on the panel's face, so that a picture of it (a slide made with the
    /// controls folded) carries what it shows; then the lobe, overlay and morph controls.
    fn header(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        let st = &mut self.state;
        // File names without their directories: a path pushed the row past the panel.
        let b_name = lab.tables().b.short_name().to_string();
        let b = if st.overlay_other_fit {
            format!(", B: {b_name}")
        } else {
            String::new()
        };
        let refitted = if lab.refit_ltc().is_some_and(|(l, _)| l == lab.shared().lobe) {
            " (refitted)"
        } else {
            ""
        };
        ui.strong(format!(
            "θo = {:.1}°   α = {:.4}   table A: {}{refitted}{b}",
            lab.shared().theta_o_deg,
            lab.shared().alpha(),
            lab.tables().a.short_name()
        ));
        ui.horizontal(|ui| {
            lab.edit(Aspect::LobeView, |s| {
                let spec = ui.selectable_value(&mut s.lobe, Lobe::Specular, "specular")
                    .on_hover_text("GGX f_s·cos with F = 1 against n_s·D_s");
                let diff = ui.selectable_value(&mut s.lobe, Lobe::Diffuse, "diffuse")
                    .on_hover_text("Burley fd·cos with c = 1 against n_d·D_d");
                spec.changed() || diff.changed()
            });
            ui.checkbox(&mut st.overlay_other_fit, format!("table B ({b_name})"))
                .on_hover_text("Overlay table B's LTC (green): by default the other shipped table (the point-light fit over the classic one, or the reverse); \"as B\" in the side panel loads another");
            ui.checkbox(&mut st.colour_difference, "difference")
                .on_hover_text("Colour the unit sphere by n·D − f·cos in 1/sr, the slice plot's units (orange: LTC too bright, blue: too dark)");
        });
        ui.add(egui::Slider::new(&mut st.morph, 0.0..=1.0).text("M: I -> fitted"))
            .on_hover_text("D is the clamped cosine pushed through M_t = (1−t)·I + t·M: at 0 the cosine, at 1 the fitted LTC (the transformed lobe)");
    }

    /// The lobe at the lab's (θo, α): table A's LTC (or the refit of its cell), morphed, and
    /// table B's where overlaid.
    fn drawn(&self, lab: &Lab) -> Drawn {
        let s = lab.shared();
        let theta = s.theta_o();
        let pick = |pair: crate::ltc::LtcPair| *pair.lobe(s.lobe);
        let fitted = match lab.refit_ltc() {
            Some((lobe, ltc)) if lobe == s.lobe => ltc,
            _ => pick(s.ltc_pair(&lab.tables().a.lut)),
        };
        let morph = self.state.morph;
        Drawn {
            lobe: s.lobe,
            v: DVec3::new(theta.sin(), 0.0, theta.cos()),
            alpha: s.alpha(),
            ltc: morphed_ltc(&fitted, morph),
            other: self
                .state
                .overlay_other_fit
                .then(|| morphed_ltc(&pick(s.ltc_pair(&lab.tables().b.lut)), morph)),
            light: s.lobe_light.map(DVec3::from),
        }
    }

    /// The exact lobe filled and the LTCs as lines over it (or the difference coloured on the
    /// unit sphere, whose scale it returns), with the frame's arrows. The surfaces (thousands
    /// of triangles, sorted) are made again only when what they show changes.
    fn paint_sphere(
        &mut self,
        ui: &egui::Ui,
        rect: egui::Rect,
        (d, stamp): (&Drawn, Stamp),
    ) -> Option<ColourScale> {
        let made_for = (stamp, self.state.clone(), rect);
        if self.sphere.as_ref().is_none_or(|(f, _)| *f != made_for) {
            let st = &self.state;
            let orbit = (st.orbit_yaw, st.orbit_pitch);
            let sphere = Sphere::new(d, orbit, st.colour_difference, rect);
            self.sphere = Some((made_for, sphere));
        }
        let (_, sphere) = self.sphere.as_ref()?;
        sphere.paint(&ui.painter_at(rect), rect, d);
        sphere.difference.clone()
    }
}

/// Both lobes along the plane of incidence, θ from −90° (away from the view) to 90°.
fn slice_plot(ui: &mut egui::Ui, d: &Drawn, height: f32) {
    let (lobe, v, alpha, ltc, other) = (d.lobe, d.v, d.alpha, &d.ltc, d.other.as_ref());
    let samples = 361;
    let points = |which: &Ltc, exact: bool| -> Vec<[f64; 2]> {
        (0..samples)
            .map(|k| {
                let deg = -90.0 + 180.0 * k as f64 / (samples - 1) as f64;
                let t = deg.to_radians();
                let l = DVec3::new(t.sin(), 0.0, t.cos());
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
