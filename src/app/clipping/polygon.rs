//! The clipping panel's rect view (docs/design.md §1.11): a rect's spherical polygon P with
//! the surface's horizon (clip case 1) beside its image M^-1 P with the cosine's horizon (clip
//! case 2), each seen from the side along the plane of incidence (the horizon a line, the
//! mirror side on the left), and what the lab's rules make of it: ∫ D over P by ltc-polygon,
//! the signed integral unclipped, the proxy, and what turning case 1 off adds (ltc_code's
//! leak). The rect is the pinned pixel's where one is pinned (the lobe view's polygon), else
//! one leaning across the horizon on the mirror side.

use egui::{Color32, Pos2, Stroke, Vec2};
use glam::DVec3;

use crate::app::lab::{Lab, LobeView, TableId};
use crate::brdf::view_from_theta;
use crate::light::rect::{Rect, clip_horizon, ltc_polygon, ltc_proxy};
use crate::ltc::lobe::Lobe;
use crate::ltc::{Clipping, Ltc, Normalization};

/// The rect shown without a pinned one: centred 3° above the horizon on the mirror side of
/// θo, 0.7 wide and 0.5 high at unit distance (some 40° × 30°), facing the point, so that
/// both horizons cut it at every θo and α.
fn leaning_rect(theta_o_deg: f64) -> [DVec3; 4] {
    let side = if theta_o_deg > 0.0 { -1.0 } else { 1.0 };
    let up = 3f64.to_radians();
    let centre = DVec3::new(side * up.cos(), 0.0, up.sin());
    let across = DVec3::Y * 0.35;
    let rise = DVec3::Y.cross(centre);
    let rise = if rise.z < 0.0 { -rise } else { rise } * 0.25;
    // u × v must point back at the point: the order of the two half-edges says which side.
    let (u, v) = if across.cross(rise).dot(centre) < 0.0 {
        (across, rise)
    } else {
        (rise, across)
    };
    Rect { centre, u, v }.corners().map(DVec3::normalize)
}

/// What the lab's rules make of P: `(by the rules, unclipped, the proxy, case 1 off minus on)`.
pub fn readings(ltc: &Ltc, corners: &[DVec3], clip: Clipping) -> [f64; 4] {
    let n = Normalization::Corrected;
    let with = |case1| Clipping { case1, ..clip };
    [
        ltc_polygon(ltc, corners, clip, n),
        ltc_polygon(ltc, corners, Clipping::NONE, n),
        ltc_proxy(ltc, corners, clip, n),
        ltc_polygon(ltc, corners, with(false), n) - ltc_polygon(ltc, corners, with(true), n),
    ]
}

/// The polygon shown (its corners' directions in the shading frame) and whether it is the
/// pinned pixel's rect.
pub fn shown_polygon(view: &LobeView) -> ([DVec3; 4], bool) {
    match view.polygon {
        Some(c) => (c.map(DVec3::from), true),
        None => (leaning_rect(view.theta_o_deg), false),
    }
}

/// The lobe the view shows: the lobe panel's, at the lab's θo and α, from table `which`.
pub fn shown_lobe(lab: &Lab, which: TableId) -> Ltc {
    let view = lab.lobe_view();
    let v = DVec3::from(view_from_theta(view.theta_o_deg.to_radians()));
    let pair = lab.tables().get(which).lut.ltc_pair(lab.alpha(), v);
    match view.lobe {
        Lobe::Specular => pair.spec,
        Lobe::Diffuse => pair.diff,
    }
}

/// The view, for table `which`, at the lab's θo and α and the lobe panel's lobe.
pub fn show(ui: &mut egui::Ui, lab: &Lab, which: TableId) {
    let view = lab.lobe_view();
    let (corners, pinned) = shown_polygon(view);
    let ltc = &shown_lobe(lab, which);
    let clip = lab.rules().clipping;
    ui.strong("rect clipping: P at the surface's horizon, then M^-1 P at the cosine's");
    ui.small(if pinned {
        "the pinned pixel's rect (pin another in the plane's table)"
    } else {
        "a rect leaning across the horizon on the mirror side (pin a pixel lit by a rect to see its own)"
    });
    // Case 1 on: P is cut at the surface's horizon before M^-1; case 2 on: M^-1 P at the
    // cosine's. Each picture draws the whole polygon faint and what is kept bright.
    let above = if clip.case1 {
        clip_horizon(&corners)
    } else {
        corners.to_vec()
    };
    let mapped: Vec<DVec3> = above
        .iter()
        .map(|&c| (ltc.cos_from_brdf * c).normalize_or_zero())
        .collect();
    let kept = if clip.case2 {
        clip_horizon(&mapped)
    } else {
        mapped.clone()
    };
    let whole_mapped: Vec<DVec3> = corners
        .iter()
        .map(|&c| (ltc.cos_from_brdf * c).normalize_or_zero())
        .collect();
    let side = (ui.available_width() / 2.0 - 12.0).clamp(120.0, 260.0);
    ui.horizontal(|ui| {
        side_view(
            ui,
            side,
            ("P (rect), the surface's horizon", &corners, &above),
            clip.case1,
        );
        side_view(
            ui,
            side,
            ("M^-1 P, the cosine's horizon", &whole_mapped, &kept),
            clip.case2,
        );
    });
    let [rules, unclipped, proxy, leak] = readings(ltc, &corners, clip);
    let lobe = match view.lobe {
        Lobe::Specular => "specular",
        Lobe::Diffuse => "diffuse",
    };
    ui.label(format!(
        "∫ D over P ({lobe} lobe, θo = {:.1}°, α = {:.4}): {rules:.4} by the lab's rules (ltc-polygon)",
        view.theta_o_deg,
        lab.alpha()
    ));
    ui.label(format!(
        "unclipped (signed): {unclipped:.4} · proxy (ltc-proxy): {proxy:.4} · case 1 off adds {leak:.4} (the leak)"
    ));
}

/// One side view: the unit circle, the horizon, `whole` faint and `kept` bright (each edge
/// along its great circle), and a caption saying whether the rule cuts.
fn side_view(
    ui: &mut egui::Ui,
    side: f32,
    (title, whole, kept): (&str, &[DVec3], &[DVec3]),
    rule_on: bool,
) {
    ui.vertical(|ui| {
        let (response, painter) = ui.allocate_painter(Vec2::splat(side), egui::Sense::hover());
        let r = response.rect;
        let centre = r.center();
        let radius = 0.45 * side;
        // Seen along −y: x to the right, z up.
        let project = |w: DVec3| centre + Vec2::new(w.x as f32, -w.z as f32) * radius;
        painter.rect_filled(r, 2.0, Color32::from_gray(18));
        painter.circle_stroke(centre, radius, Stroke::new(1.0, Color32::from_gray(90)));
        painter.line_segment(
            [
                centre - Vec2::new(radius * 1.05, 0.0),
                centre + Vec2::new(radius * 1.05, 0.0),
            ],
            Stroke::new(1.5, Color32::from_gray(200)),
        );
        let outline = |poly: &[DVec3]| -> Vec<Pos2> {
            let n = poly.len();
            (0..n)
                .flat_map(|k| {
                    let (a, b) = (poly[k], poly[(k + 1) % n]);
                    (0..16).map(move |i| a.lerp(b, i as f64 / 16.0).normalize_or_zero())
                })
                .chain(poly.first().copied())
                .map(project)
                .collect()
        };
        if whole.len() >= 3 {
            painter.add(egui::Shape::line(
                outline(whole),
                Stroke::new(1.0, Color32::from_rgb(120, 70, 110)),
            ));
        }
        if kept.len() >= 3 {
            painter.add(egui::Shape::line(
                outline(kept),
                Stroke::new(2.5, Color32::from_rgb(255, 90, 220)),
            ));
        }
        let rule = if rule_on {
            "cut here"
        } else {
            "rule off: not cut"
        };
        ui.small(format!("{title}: {rule}"));
    });
}
