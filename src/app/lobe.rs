//! The lobe panel: the exact cosine-weighted BRDF lobe and its LTC as radial surfaces on the
//! sphere (orbit by dragging), the normal, the view vector and the LTC's frame; a slider that
//! morphs M from the identity (the clamped cosine) to the fitted matrix; the pointwise
//! difference coloured on the sphere; and a slice through the plane of incidence.

use egui::{Color32, Pos2, Vec2};
use glam::{DMat3, DVec3};

use crate::app::other::OtherTable;
use crate::app::state::LabState;
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, Ltc, Normalization};

#[derive(Default)]
pub struct LobePanel;

/// Sphere tessellation: rings in θ and segments in φ (enough for a smooth α = 0.05 lobe at
/// panel size; 64 × 128 directions).
const RINGS: usize = 64;
const SEGMENTS: usize = 128;

/// The LTC shown: M morphed from I to the fitted M, with the lobe's magnitude.
pub fn morphed_ltc(ltc: &Ltc, t: f64) -> Ltc {
    let m = DMat3::IDENTITY * (1.0 - t) + ltc.brdf_from_cos * t;
    Ltc::from_brdf_from_cos(m, ltc.norm, ltc.fresnel).with_scale(ltc.scale)
}

/// `f cos` of the lobe (F = 1, c = 1) and `n D` of the LTC toward `l`.
fn values(lobe: Lobe, v: DVec3, alpha: f64, ltc: &Ltc, l: DVec3) -> (f64, f64) {
    let exact = lobe.eval(v, l, alpha).value;
    let approx = ltc.magnitude() * ltc.ltc_eval(l, Clipping::TRANSFORMED, Normalization::Corrected);
    (exact, approx)
}

impl LobePanel {
    pub fn show(
        &mut self,
        ui: &mut egui::Ui,
        s: &mut LabState,
        lut: &Lut,
        refit: Option<(Lobe, Ltc)>,
        other: &OtherTable,
    ) {
        ui.horizontal(|ui| {
            ui.selectable_value(&mut s.lobe, Lobe::Specular, "specular")
                .on_hover_text("GGX f_s·cos with F = 1 against n_s·D_s");
            ui.selectable_value(&mut s.lobe, Lobe::Diffuse, "diffuse")
                .on_hover_text("Burley fd·cos with c = 1 against n_d·D_d");
            ui.checkbox(&mut s.overlay_other_fit, format!("table B ({})", other.name))
                .on_hover_text("Overlay table B's LTC (green): by default the other shipped table (the point-light fit over the classic one, or the reverse); \"as B\" in the side panel loads another");
            ui.checkbox(&mut s.colour_difference, "difference")
                .on_hover_text("Colour the unit sphere by n·D − f·cos (red: LTC too bright, blue: too dark), relative to the lobe's peak");
        });
        ui.add(egui::Slider::new(&mut s.morph, 0.0..=1.0).text("M: I -> fitted"))
            .on_hover_text("D is the clamped cosine pushed through M_t = (1−t)·I + t·M: at 0 the cosine, at 1 the fitted LTC (the transformed lobe)");
        let theta = s.theta_o_deg.to_radians().min(crate::ltc::lut::THETA_MAX);
        let v = DVec3::new(theta.sin(), 0.0, theta.cos());
        let alpha = s.alpha();
        let pair = s.ltc_pair(lut);
        let fitted = match (refit, s.lobe) {
            (Some((lobe, ltc)), l) if lobe == l => ltc,
            (_, Lobe::Specular) => pair.spec,
            (_, Lobe::Diffuse) => pair.diff,
        };
        let ltc = morphed_ltc(&fitted, s.morph);
        let other_pair = s.ltc_pair(&other.lut);
        let other_ltc = s.overlay_other_fit.then(|| {
            morphed_ltc(
                if s.lobe == Lobe::Specular {
                    &other_pair.spec
                } else {
                    &other_pair.diff
                },
                s.morph,
            )
        });
        let plot_h = (ui.available_height() * 0.3).clamp(60.0, 160.0);
        let size = Vec2::new(
            ui.available_width(),
            (ui.available_height() - plot_h - 8.0).max(80.0),
        );
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::drag());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "lobe view"));
        let response = response.on_hover_text("Drag to orbit. Orange: the exact lobe f·cos; blue: the LTC n·D. White: the normal, yellow: the view, red/green/blue: the LTC's frame (columns of M)");
        if response.dragged() {
            let d = response.drag_delta();
            s.orbit_yaw += d.x * 0.01;
            s.orbit_pitch = (s.orbit_pitch + d.y * 0.01).clamp(-1.5, 1.5);
        }
        self.paint_sphere(ui, rect, s, v, alpha, &ltc, other_ltc.as_ref());
        slice_plot(ui, s.lobe, v, alpha, &ltc, other_ltc.as_ref(), plot_h);
    }

    fn paint_sphere(
        &self,
        ui: &egui::Ui,
        rect: egui::Rect,
        s: &LabState,
        v: DVec3,
        alpha: f64,
        ltc: &Ltc,
        other: Option<&Ltc>,
    ) {
        let painter = ui.painter_at(rect);
        painter.rect_filled(rect, 4.0, Color32::from_gray(18));
        let (cy, sy) = (f64::from(s.orbit_yaw).cos(), f64::from(s.orbit_yaw).sin());
        let (cp, sp) = (
            f64::from(s.orbit_pitch).cos(),
            f64::from(s.orbit_pitch).sin(),
        );
        let scale = f64::from(rect.width().min(rect.height())) * 0.42;
        let centre = rect.center() + Vec2::new(0.0, rect.height() * 0.15);
        // Orbit: yaw about z, then pitch about the screen's x axis; orthographic, z up.
        let project = |p: DVec3| -> (Pos2, f64) {
            let x = cy * p.x - sy * p.y;
            let y = sy * p.x + cy * p.y;
            let (up, depth) = (cp * p.z - sp * y, sp * p.z + cp * y);
            (
                centre + Vec2::new((x * scale) as f32, (-up * scale) as f32),
                depth,
            )
        };
        let dirs: Vec<DVec3> = (0..=RINGS)
            .flat_map(|i| {
                let t = std::f64::consts::PI * i as f64 / RINGS as f64;
                (0..SEGMENTS).map(move |k| {
                    let p = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
                    DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
                })
            })
            .collect();
        let vals: Vec<(f64, f64)> = dirs
            .iter()
            .map(|&l| values(s.lobe, v, alpha, ltc, l))
            .collect();
        let peak = vals.iter().fold(1e-12f64, |m, &(a, b)| m.max(a).max(b));
        let mut triangles: Vec<(f64, [Pos2; 3], [Color32; 3])> = Vec::new();
        let index = |i: usize, k: usize| i * SEGMENTS + k % SEGMENTS;
        // Each surface: a position and a colour per direction.
        let surfaces: Vec<(Vec<DVec3>, Vec<Color32>)> = if s.colour_difference {
            let colours = vals
                .iter()
                .map(|&(e, a)| diverging(((a - e) / peak).clamp(-1.0, 1.0)))
                .collect();
            vec![(dirs.clone(), colours)]
        } else {
            let radial = |pick: fn(&(f64, f64)) -> f64| -> Vec<DVec3> {
                dirs.iter()
                    .zip(&vals)
                    .map(|(d, v)| *d * (pick(v) / peak))
                    .collect()
            };
            let n = dirs.len();
            let mut surfaces = vec![
                (
                    radial(|v| v.0),
                    vec![Color32::from_rgba_unmultiplied(240, 150, 60, 150); n],
                ),
                (
                    radial(|v| v.1),
                    vec![Color32::from_rgba_unmultiplied(70, 140, 255, 120); n],
                ),
            ];
            if let Some(o) = other {
                let positions = dirs
                    .iter()
                    .map(|&l| l * (values(s.lobe, v, alpha, o, l).1 / peak))
                    .collect();
                surfaces.push((
                    positions,
                    vec![Color32::from_rgba_unmultiplied(80, 220, 120, 90); n],
                ));
            }
            surfaces
        };
        for (position, colour) in &surfaces {
            let position = |n: usize| position[n];
            let colour = |n: usize| colour[n];
            for i in 0..RINGS {
                for k in 0..SEGMENTS {
                    let quad = [
                        index(i, k),
                        index(i, k + 1),
                        index(i + 1, k + 1),
                        index(i + 1, k),
                    ];
                    let p: Vec<DVec3> = quad.iter().map(|&n| position(n)).collect();
                    if p.iter().all(|x| x.length_squared() < 1e-8) {
                        continue;
                    }
                    // Lambert shading from the viewer's side, for depth cues.
                    let normal = (p[1] - p[0])
                        .cross(p[3] - p[0])
                        .try_normalize()
                        .unwrap_or(DVec3::Z);
                    let light = 0.55 + 0.45 * normal.z.abs();
                    for tri in [[0, 1, 2], [0, 2, 3]] {
                        let proj: Vec<(Pos2, f64)> = tri.iter().map(|&t| project(p[t])).collect();
                        let depth = proj.iter().map(|x| x.1).sum::<f64>();
                        let cols = tri.map(|t| shade(colour(quad[t]), light as f32));
                        triangles.push((depth, [proj[0].0, proj[1].0, proj[2].0], cols));
                    }
                }
            }
        }
        // Painter's algorithm: far triangles first.
        triangles.sort_by(|a, b| b.0.total_cmp(&a.0));
        let mut mesh = egui::Mesh::default();
        for (_, p, c) in &triangles {
            let base = mesh.vertices.len() as u32;
            for k in 0..3 {
                mesh.colored_vertex(p[k], c[k]);
            }
            mesh.add_triangle(base, base + 1, base + 2);
        }
        painter.add(egui::Shape::mesh(mesh));
        // The horizon circle, the normal, the view vector and the LTC's frame.
        let ring: Vec<Pos2> = (0..=64)
            .map(|k| {
                let p = std::f64::consts::TAU * k as f64 / 64.0;
                project(DVec3::new(p.cos(), p.sin(), 0.0)).0
            })
            .collect();
        painter.add(egui::Shape::line(
            ring,
            egui::Stroke::new(1.0, Color32::from_gray(90)),
        ));
        let origin = project(DVec3::ZERO).0;
        let arrow = |d: DVec3, c: Color32| {
            painter.arrow(origin, project(d).0 - origin, egui::Stroke::new(2.0, c));
        };
        arrow(DVec3::Z, Color32::WHITE);
        arrow(v, Color32::YELLOW);
        let frame = ltc.brdf_from_cos;
        for (k, c) in [
            Color32::RED,
            Color32::GREEN,
            Color32::from_rgb(80, 120, 255),
        ]
        .into_iter()
        .enumerate()
        {
            arrow(frame.col(k).normalize_or_zero() * 0.6, c);
        }
    }
}

/// Blue (LTC too dark) – grey – red (too bright).
fn diverging(d: f64) -> Color32 {
    let t = d.abs() as f32;
    let base = 70.0;
    let (r, g, b) = if d >= 0.0 {
        (
            base + (255.0 - base) * t,
            base * (1.0 - t),
            base * (1.0 - t),
        )
    } else {
        (
            base * (1.0 - t),
            base * (1.0 - t) + 60.0 * t,
            base + (255.0 - base) * t,
        )
    };
    Color32::from_rgb(r as u8, g as u8, b as u8)
}

fn shade(c: Color32, k: f32) -> Color32 {
    Color32::from_rgba_unmultiplied(
        (f32::from(c.r()) * k) as u8,
        (f32::from(c.g()) * k) as u8,
        (f32::from(c.b()) * k) as u8,
        c.a(),
    )
}

/// Both lobes along the plane of incidence, θ from −90° (away from the view) to 90°.
fn slice_plot(
    ui: &mut egui::Ui,
    lobe: Lobe,
    v: DVec3,
    alpha: f64,
    ltc: &Ltc,
    other: Option<&Ltc>,
    height: f32,
) {
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
