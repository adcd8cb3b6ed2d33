//! The clipping panel's rect view (docs/design.md §1.11): a rect's spherical polygon P with
//! the surface's horizon (clip case 1) beside its image M^-1 P with the cosine's horizon (clip
//! case 2), each seen from the side along the plane of incidence (the horizon a line, the
//! mirror side on the left), and what the lab's rules make of it: ∫ D over P by ltc-polygon,
//! the signed integral unclipped, the proxy, and what turning case 1 off adds (ltc_code's
//! leak); and the lobe's radiance from P by the exact integral and by each rect method, with
//! each one's error. The rect is the pinned pixel's where one is pinned (the lobe view's polygon), else
//! one leaning across the horizon on the mirror side.

use egui::{Color32, Pos2, Stroke, Vec2};
use glam::DVec3;

use crate::app::lab::{Lab, LobeView, TableId};
use crate::brdf::{brdf_cos_aniso, view_from_theta};
use crate::light::rect::{
    Rect, RectMethod, clip_horizon, ltc_polygon, ltc_proxy, ltc_proxy_fast, polygon_integral_about,
};
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
    let pair = lab.ltc_pair(&lab.tables().get(which).lut);
    match view.lobe {
        Lobe::Specular => pair.spec,
        Lobe::Diffuse => pair.diff,
    }
}

/// The material's roughness as a label: α, or α_x, α_y and φo while anisotropic (its cell
/// of the 4D table).
fn roughness_label(lab: &Lab) -> String {
    let a = lab.material().roughness();
    match a.is_isotropic() {
        true => format!("α = {:.4}", a.x),
        false => format!(
            "α_x = {:.4}, α_y = {:.4}, φo = {:.1}°",
            a.x,
            a.y,
            lab.lobe_view().phi_o_deg
        ),
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
        "the rect of the plane's pinned pixel (click another rect's row in the plane's pixel table)"
    } else {
        "a rect leaning across the horizon on the mirror side (to see one of the plane's: pin a pixel, then click a rect's row in its table)"
    });
    ui.small("bright: what the rules keep · faint: the whole polygon · seen from the side, the mirror direction to the left");
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
        "∫ D over P ({lobe} lobe, θo = {:.1}°, {}): {rules:.4} by the lab's rules (ltc-polygon)",
        view.theta_o_deg,
        roughness_label(lab)
    ));
    ui.label(format!(
        "unclipped (signed): {unclipped:.4} · proxy (ltc-proxy): {proxy:.4} · case 1 off adds {leak:.4} (the leak)"
    ));
    let [exact, methods @ ..] = radiances(lab, which, &corners);
    let errors: Vec<String> = [
        RectMethod::LtcPolygon,
        RectMethod::LtcProxy,
        RectMethod::LtcProxyFast,
    ]
    .iter()
    .zip(methods)
    .map(|(m, x)| format!("{} {x:.4} ({:+.1}%)", m.name(), 100.0 * (x / exact - 1.0)))
    .collect();
    ui.label(format!(
        "radiance at unit radiance ({lobe}): exact {exact:.4} · {}",
        errors.join(" · ")
    ));
}

/// The shown lobe's radiance from P at unit radiance (the lab's F0, its rules): the exact
/// integral of the BRDF over P above the surface (the rect rule, 32 nodes a triangle, over
/// the cone of the corners' directions), then ltc-polygon's, ltc-proxy's and ltc-proxy-fast's
/// (each lobe's integral times its magnitude).
pub fn radiances(lab: &Lab, which: TableId, corners: &[DVec3]) -> [f64; 4] {
    let view = lab.lobe_view();
    let v = DVec3::from(view_from_theta(view.theta_o_deg.to_radians()));
    let (alpha, f0) = (lab.material().roughness(), lab.material().f0);
    let pair = lab.ltc_pair(&lab.tables().get(which).lut);
    let turn = lab.tangent_from_view();
    let (ltc, weight, k) = match view.lobe {
        Lobe::Specular => (&pair.spec, pair.spec_magnitude(f0), 0),
        Lobe::Diffuse => (&pair.diff, pair.diff.magnitude(), 1),
    };
    let mirror = DVec3::new(-v.x, -v.y, v.z);
    // The corners are directions: the rule wants a planar polygon with the same cone, their
    // points on the plane at unit distance along their mean direction.
    let mean = corners.iter().sum::<DVec3>().normalize_or_zero();
    let planar: Vec<DVec3> = corners.iter().map(|&c| c / c.dot(mean)).collect();
    let exact = polygon_integral_about(&clip_horizon(&planar), 32, Some(mirror), |l| {
        let (v, l) = ((turn * v).to_array(), (turn * l).to_array());
        let f = brdf_cos_aniso(v, l, alpha, f0);
        [f.specular, f.diffuse]
    })[k];
    let (clip, n) = (lab.rules().clipping, Normalization::Corrected);
    [
        exact,
        weight * ltc_polygon(ltc, corners, clip, n),
        weight * ltc_proxy(ltc, corners, clip, n),
        weight * ltc_proxy_fast(ltc, corners, clip, n),
    ]
}

/// One side view, zoomed to the polygon and the shading point: the unit circle, the horizon
/// and the normal (labelled), `whole` faint and `kept` bright (each edge along its great
/// circle), and a caption saying whether the rule cuts.
fn side_view(
    ui: &mut egui::Ui,
    side: f32,
    (title, whole, kept): (&str, &[DVec3], &[DVec3]),
    rule_on: bool,
) {
    let arcs = |poly: &[DVec3]| -> Vec<DVec3> {
        let n = poly.len();
        (0..n)
            .flat_map(|k| {
                let (a, b) = (poly[k], poly[(k + 1) % n]);
                (0..16).map(move |i| a.lerp(b, i as f64 / 16.0).normalize_or_zero())
            })
            .chain(poly.first().copied())
            .collect()
    };
    let (whole, kept) = (arcs(whole), arcs(kept));
    ui.vertical(|ui| {
        let (response, painter) = ui.allocate_painter(Vec2::splat(side), egui::Sense::hover());
        let r = response.rect;
        // Seen along −y: x to the right, z up. The view spans the polygon and the shading point
        // (the origin), with a margin; a small polygon is magnified, up to 8× the unit sphere.
        let flat = |w: DVec3| Vec2::new(w.x as f32, -w.z as f32);
        let points = whole.iter().chain(&kept).map(|&w| flat(w));
        let (lo, hi) = points.fold((Vec2::ZERO, Vec2::ZERO), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        });
        let span = (hi - lo).max_elem().max(0.125);
        let scale = 0.8 * side / span;
        let mid = r.center() - (lo + hi) * 0.5 * scale;
        let project = |w: DVec3| mid + flat(w) * scale;
        painter.rect_filled(r, 2.0, Color32::from_gray(18));
        painter.circle_stroke(mid, scale, Stroke::new(1.0, Color32::from_gray(90)));
        let grey = Color32::from_gray(200);
        painter.line_segment(
            [Pos2::new(r.left(), mid.y), Pos2::new(r.right(), mid.y)],
            Stroke::new(1.5, grey),
        );
        let font = egui::FontId::proportional(11.0);
        let labelled = |at: Pos2, text: &str, anchor: egui::Align2| {
            painter.text(at, anchor, text, font.clone(), grey);
        };
        labelled(
            Pos2::new(r.right() - 4.0, mid.y - 2.0),
            "horizon",
            egui::Align2::RIGHT_BOTTOM,
        );
        let tip = project(DVec3::Z * (0.25 * span as f64));
        painter.arrow(mid, tip - mid, Stroke::new(1.5, grey));
        labelled(tip + Vec2::new(4.0, 0.0), "n", egui::Align2::LEFT_CENTER);
        let line = |poly: Vec<DVec3>, stroke| {
            if poly.len() > 3 {
                painter.add(egui::Shape::line(
                    poly.into_iter().map(project).collect(),
                    stroke,
                ));
            }
        };
        line(whole, Stroke::new(1.0, Color32::from_rgb(120, 70, 110)));
        line(kept, Stroke::new(2.5, Color32::from_rgb(255, 90, 220)));
        let rule = if rule_on {
            "the rule cuts at the horizon"
        } else {
            "rule off: nothing cut"
        };
        ui.small(format!("{title}: {rule}"));
    });
}
