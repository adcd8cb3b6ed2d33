//! The lobe panel's sphere: the exact lobe and its LTC as radial surfaces over directions
//! packed about the lobe's peak, orbited and projected orthographically, sorted far to near,
//! with the normal, the view, the LTC's frame and a pinned pixel's light as labelled arrows.

use egui::{Color32, Pos2, Vec2};
use glam::DVec3;

use crate::app::ui::display::rgb;
use crate::brdf::Alpha;
use crate::colormap::ColourScale;
use crate::ltc::lobe::Lobe;
use crate::ltc::{Clipping, Ltc, Normalization};

/// Sphere tessellation: rings in θ and segments in φ (enough for a smooth α = 0.05 lobe at
/// panel size; 64 × 128 directions).
const RINGS: usize = 64;
const SEGMENTS: usize = 128;

/// `f cos` of the lobe (F = 1, c = 1) and `n D` of the LTC toward `l`.
pub fn values(lobe: Lobe, v: DVec3, alpha: Alpha<f64>, ltc: &Ltc, l: DVec3) -> (f64, f64) {
    let exact = lobe.value_aniso(v, l, alpha);
    let approx = ltc.magnitude() * ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected);
    (exact, approx)
}

/// What the sphere and the slice show: the lobe seen from `v` at `alpha`, its (morphed) LTC,
/// table B's, and a pinned pixel's light.
pub struct Drawn {
    pub lobe: Lobe,
    pub v: DVec3,
    pub alpha: Alpha<f64>,
    pub ltc: Ltc,
    pub other: Option<Ltc>,
    pub light: Option<DVec3>,
    /// That light's corners where it is a rect (unit directions).
    pub polygon: Option<[DVec3; 4]>,
}

/// The sphere's surfaces as shapes, their projection, and the difference's colour scale.
pub struct Sphere {
    shapes: Vec<egui::Shape>,
    view: Projection,
    pub difference: Option<ColourScale>,
}

impl Sphere {
    /// The surfaces of `d` seen from the orbit `(yaw, pitch)` in `rect`, or (`difference`)
    /// the difference coloured on the unit sphere.
    pub fn new(d: &Drawn, (yaw, pitch): (f32, f32), difference: bool, rect: egui::Rect) -> Self {
        let surface = Surface::new(d);
        // Auto-scale: the lobes' extent, not the unit sphere's, fills the view (the
        // difference is painted on the unit sphere itself).
        // The frame's arrows and the horizon ring too (at least 0.6 long): a sharp lobe at a
        // grazing view framed alone pushed the view vector and the ring off the view.
        let frame = [
            DVec3::Z,
            d.v,
            DVec3::X,
            DVec3::NEG_X,
            DVec3::Y,
            DVec3::NEG_Y,
        ]
        .map(|p| p * 0.6);
        let shown: Vec<DVec3> = if difference {
            UNIT_SPHERE.to_vec()
        } else {
            surface
                .exact
                .iter()
                .chain(&surface.ltc)
                .chain(&frame)
                .copied()
                .collect()
        };
        let view = Projection::fitted(Orbit::new(yaw, pitch), rect, &shown);
        let project = |p: DVec3| view.project(p);
        let difference = difference.then(|| surface.difference_scale());
        let shapes = match &difference {
            Some(scale) => {
                let colours: Vec<Color32> = surface
                    .vals
                    .iter()
                    .map(|&(e, a)| rgb(scale.colour(a - e)))
                    .collect();
                vec![mesh_surface(&project, &surface.dirs, &|n| colours[n])]
            }
            None => {
                // The exact lobe filled, the LTC (and table B) as meshes of lines over it:
                // two filled surfaces that nearly coincide z-fight.
                let fill = Color32::from_rgba_unmultiplied(240, 150, 60, 170);
                let mut shapes = vec![mesh_surface(&project, &surface.exact, &|_| fill)];
                let blue = Color32::from_rgb(90, 160, 255);
                shapes.extend(wireframe(&surface.ltc, &project, blue));
                if let Some(o) = &d.other {
                    let green = Color32::from_rgb(80, 220, 120);
                    shapes.extend(wireframe(&surface.of(d, o), &project, green));
                }
                shapes
            }
        };
        Self {
            shapes,
            view,
            difference,
        }
    }

    /// The surfaces on a dark ground, then the frame's arrows over them.
    pub fn paint(&self, painter: &egui::Painter, rect: egui::Rect, d: &Drawn) {
        painter.rect_filled(rect, 4.0, Color32::from_gray(18));
        painter.extend(self.shapes.iter().cloned());
        let view = &self.view;
        // With the difference coloured on the unit sphere, the horizon circle is its equator.
        let reach = if self.difference.is_some() {
            1.0
        } else {
            0.5 * view.span.min(1.2)
        };
        paint_frame(painter, rect, &|p| view.project(p), reach, d);
    }
}

/// The lobe and its LTC as radial surfaces over directions about the lobe's peak.
struct Surface {
    dirs: Vec<DVec3>,
    /// (exact f·cos, LTC n·D) per direction.
    vals: Vec<(f64, f64)>,
    /// The exact lobe's peak, which the radii are scaled to.
    peak: f64,
    exact: Vec<DVec3>,
    ltc: Vec<DVec3>,
}

impl Surface {
    fn new(d: &Drawn) -> Self {
        let exact_at = |l: DVec3| d.lobe.value_aniso(d.v, l, d.alpha);
        // The tessellation's pole is the exact lobe's peak, its rings packed toward it, so that
        // a sharp lobe (α ≈ 0.02, a degree wide) is made of many triangles, not one sliver.
        let dirs = pole_grid(peak_direction(d.lobe, d.v, exact_at));
        let vals: Vec<(f64, f64)> = dirs
            .iter()
            .map(|&l| values(d.lobe, d.v, d.alpha, &d.ltc, l))
            .collect();
        // Scaled to the exact lobe's peak: the LTC can spike where M^-1 ω is short, and a
        // spike must not flatten everything else (the difference read uniform grey).
        let peak = vals.iter().fold(1e-12f64, |m, &(e, _)| m.max(e));
        let mut s = Self {
            exact: Vec::new(),
            ltc: Vec::new(),
            dirs,
            vals,
            peak,
        };
        s.exact = s
            .dirs
            .iter()
            .zip(&s.vals)
            .map(|(l, v)| *l * s.radius(v.0))
            .collect();
        s.ltc = s
            .dirs
            .iter()
            .zip(&s.vals)
            .map(|(l, v)| *l * s.radius(v.1).max(0.0))
            .collect();
        s
    }

    /// A value as a radius: relative to the peak, within ±1.5.
    fn radius(&self, x: f64) -> f64 {
        (x / self.peak).clamp(-1.5, 1.5)
    }

    /// Another LTC's surface over the same directions.
    fn of(&self, d: &Drawn, ltc: &Ltc) -> Vec<DVec3> {
        self.dirs
            .iter()
            .map(|&l| l * self.radius(values(d.lobe, d.v, d.alpha, ltc, l).1).max(0.0))
            .collect()
    }

    /// The difference's colour scale: its largest magnitude, at most the peak.
    fn difference_scale(&self) -> ColourScale {
        let max = self
            .vals
            .iter()
            .map(|&(e, a)| (a - e).abs())
            .fold(0.0f64, f64::max)
            .min(self.peak)
            .max(1e-12);
        ColourScale::signed(max, "n·D − f·cos (1/sr)")
    }
}

/// The six points where the unit sphere meets the axes: its extent in any orbit.
const UNIT_SPHERE: [DVec3; 6] = [
    DVec3::X,
    DVec3::NEG_X,
    DVec3::Y,
    DVec3::NEG_Y,
    DVec3::Z,
    DVec3::NEG_Z,
];

/// The orbit of the lobe view: yaw about z, then pitch about the screen's x axis;
/// orthographic, z up.
#[derive(Clone, Copy)]
struct Orbit {
    cos_yaw: f64,
    sin_yaw: f64,
    cos_pitch: f64,
    sin_pitch: f64,
}

impl Orbit {
    fn new(yaw: f32, pitch: f32) -> Self {
        let (yaw, pitch) = (f64::from(yaw), f64::from(pitch));
        Self {
            cos_yaw: yaw.cos(),
            sin_yaw: yaw.sin(),
            cos_pitch: pitch.cos(),
            sin_pitch: pitch.sin(),
        }
    }

    /// A point seen from the orbit: across, up, and depth.
    fn view_of(&self, p: DVec3) -> (f64, f64, f64) {
        let x = self.cos_yaw * p.x - self.sin_yaw * p.y;
        let y = self.sin_yaw * p.x + self.cos_yaw * p.y;
        (
            x,
            self.cos_pitch * p.z - self.sin_pitch * y,
            self.sin_pitch * p.z + self.cos_pitch * y,
        )
    }
}

/// The orbit scaled and centred so that the points it was fitted to fill 80% of the view.
struct Projection {
    orbit: Orbit,
    scale: f64,
    centre: Pos2,
    /// The larger side of the fitted points' extent, in scene units.
    span: f64,
}

impl Projection {
    fn fitted(orbit: Orbit, rect: egui::Rect, points: &[DVec3]) -> Self {
        let extent = points
            .iter()
            .map(|p| {
                let (x, up, _) = orbit.view_of(*p);
                (x, up)
            })
            .fold([0.0f64, 0.0, 0.0, 0.0], |b, (x, y)| {
                [b[0].min(x), b[1].max(x), b[2].min(y), b[3].max(y)]
            });
        let (span_x, span_y) = (
            (extent[1] - extent[0]).max(0.2),
            (extent[3] - extent[2]).max(0.2),
        );
        let scale = (f64::from(rect.width()) / span_x).min(f64::from(rect.height()) / span_y) * 0.8;
        let mid = egui::vec2(
            ((extent[0] + extent[1]) * 0.5 * scale) as f32,
            (-(extent[2] + extent[3]) * 0.5 * scale) as f32,
        );
        Self {
            orbit,
            scale,
            centre: rect.center() - mid,
            span: span_x.max(span_y),
        }
    }

    /// Where `p` lands in the view, and its depth.
    fn project(&self, p: DVec3) -> (Pos2, f64) {
        let (x, up, depth) = self.orbit.view_of(p);
        let offset = Vec2::new((x * self.scale) as f32, (-up * self.scale) as f32);
        (self.centre + offset, depth)
    }
}

/// A filled, lit surface through `positions` (the pole grid), far triangles first.
fn mesh_surface(
    project: &dyn Fn(DVec3) -> (Pos2, f64),
    positions: &[DVec3],
    colours: &dyn Fn(usize) -> Color32,
) -> egui::Shape {
    let mut triangles: Vec<(f64, [Pos2; 3], [Color32; 3])> = Vec::new();
    for (quad, p) in quads(positions) {
        let normal = (p[1] - p[0])
            .cross(p[3] - p[0])
            .try_normalize()
            .unwrap_or(DVec3::Z);
        let light = 0.6 + 0.4 * normal.z.abs();
        for tri in [[0, 1, 2], [0, 2, 3]] {
            let proj: Vec<(Pos2, f64)> = tri.iter().map(|&t| project(p[t])).collect();
            let depth = proj.iter().map(|x| x.1).sum::<f64>();
            let cols = tri.map(|t| shade(colours(quad[t]), light as f32));
            triangles.push((depth, [proj[0].0, proj[1].0, proj[2].0], cols));
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
    egui::Shape::mesh(mesh)
}

/// The horizon circle of radius `reach`, the normal, the view vector, the LTC's frame and a
/// pinned pixel's light, as labelled arrows.
fn paint_frame(
    painter: &egui::Painter,
    rect: egui::Rect,
    project: &dyn Fn(DVec3) -> (Pos2, f64),
    reach: f64,
    d: &Drawn,
) {
    let (v, ltc) = (d.v, &d.ltc);
    let ring: Vec<Pos2> = (0..=64)
        .map(|k| {
            let p = std::f64::consts::TAU * k as f64 / 64.0;
            project(DVec3::new(p.cos(), p.sin(), 0.0) * reach).0
        })
        .collect();
    painter.add(egui::Shape::line(
        ring,
        egui::Stroke::new(1.0, Color32::from_gray(90)),
    ));
    let origin = project(DVec3::ZERO).0;
    let font = egui::FontId::proportional(12.0);
    // Arrows shortened to stay in the view (a margin for their labels), labels placed
    // after all arrows, each moved down past the ones it would cover.
    let inside = rect.shrink2(egui::vec2(48.0, 16.0));
    let mut labels: Vec<(Pos2, Color32, &str)> = Vec::new();
    let mut arrow = |d: DVec3, c: Color32, name: &'static str| {
        let tip = shorten_into(origin, project(d * reach).0, inside);
        painter.arrow(origin, tip - origin, egui::Stroke::new(2.0, c));
        labels.push((tip, c, name));
    };
    arrow(DVec3::Z, Color32::WHITE, "n");
    arrow(v, Color32::YELLOW, "v");
    let frame = ltc.brdf_from_cos;
    for (k, (c, name)) in [
        (Color32::RED, "M x"),
        (Color32::GREEN, "M y"),
        (Color32::from_rgb(80, 120, 255), "M z"),
    ]
    .into_iter()
    .enumerate()
    {
        arrow(frame.col(k).normalize_or_zero() * 0.6, c, name);
    }
    // A light of the plane's pinned pixel, and its image under the (morphed) M^-1.
    if let Some(w) = d.light {
        arrow(w, Color32::from_rgb(255, 90, 220), "ω (light)");
        let image = (ltc.cos_from_brdf * w).normalize_or_zero();
        arrow(image, Color32::from_rgb(80, 230, 230), "ω' = M^-1 ω");
    }
    // A rect's spherical polygon P over the lobe, and M^-1 P, where the clamped cosine
    // integrates what D does over P (the paper's Figure 1).
    if let Some(corners) = d.polygon {
        let mapped = corners.map(|c| (ltc.cos_from_brdf * c).normalize_or_zero());
        for (poly, c, name) in [
            (corners, Color32::from_rgb(255, 90, 220), "P (rect)"),
            (mapped, Color32::from_rgb(80, 230, 230), "M^-1 P"),
        ] {
            painter.add(egui::Shape::line(
                spherical_polygon(&poly, reach, project),
                egui::Stroke::new(2.0, c),
            ));
            let centre: DVec3 = poly.iter().sum::<DVec3>().normalize_or_zero();
            labels.push((project(centre * reach).0, c, name));
        }
    }
    let mut placed: Vec<egui::Rect> = Vec::new();
    for (tip, c, name) in labels {
        let galley = painter.layout_no_wrap(name.to_string(), font.clone(), c);
        let mut at =
            egui::Rect::from_min_size(tip - egui::vec2(0.0, galley.size().y), galley.size());
        while let Some(hit) = placed.iter().find(|r| r.intersects(at)) {
            at = at.translate(egui::vec2(0.0, hit.max.y - at.min.y + 1.0));
        }
        // On a dark plate: a label over the lobe's mesh ("M z") was lost in its lines.
        painter.rect_filled(at.expand(1.0), 2.0, Color32::from_black_alpha(170));
        painter.galley(at.min, galley, c);
        placed.push(at);
    }
}

/// A spherical polygon's outline at radius `reach`: each edge along its great circle (16
/// steps of normalized linear interpolation), closed.
fn spherical_polygon(
    corners: &[DVec3],
    reach: f64,
    project: &dyn Fn(DVec3) -> (Pos2, f64),
) -> Vec<Pos2> {
    let n = corners.len();
    (0..n)
        .flat_map(|k| {
            let (a, b) = (corners[k], corners[(k + 1) % n]);
            (0..16).map(move |i| a.lerp(b, i as f64 / 16.0).normalize_or_zero())
        })
        .chain(corners.first().copied())
        .map(|w| project(w * reach).0)
        .collect()
}

/// The point on the segment from `origin` to `tip` nearest `tip` that lies in `area` (the
/// whole segment where `tip` does; `origin` is inside).
fn shorten_into(origin: Pos2, tip: Pos2, area: egui::Rect) -> Pos2 {
    let d = tip - origin;
    let mut t = 1.0f32;
    for (o, dd, lo, hi) in [
        (origin.x, d.x, area.min.x, area.max.x),
        (origin.y, d.y, area.min.y, area.max.y),
    ] {
        if o + t * dd > hi && dd > 0.0 {
            t = (hi - o) / dd;
        }
        if o + t * dd < lo && dd < 0.0 {
            t = (lo - o) / dd;
        }
    }
    origin + d * t.max(0.0)
}

/// Where the exact lobe peaks: the best of a coarse grid of the upper hemisphere.
fn peak_direction(lobe: Lobe, v: DVec3, exact_at: impl Fn(DVec3) -> f64) -> DVec3 {
    // The specular lobe's peak is near the mirror direction; search around it and the normal.
    let mirror = DVec3::new(-v.x, -v.y, v.z);
    let start = if lobe == Lobe::Specular {
        mirror
    } else {
        DVec3::Z
    };
    (0..=40)
        .flat_map(|i| (0..72).map(move |k| (i, k)))
        .map(|(i, k)| {
            let t = std::f64::consts::FRAC_PI_2 * f64::from(i) / 40.0;
            let p = std::f64::consts::TAU * f64::from(k) / 72.0;
            DVec3::new(t.sin() * p.cos(), t.sin() * p.sin(), t.cos())
        })
        .chain([start])
        .map(|d| (exact_at(d), d))
        .fold(
            (f64::NEG_INFINITY, start),
            |b, x| if x.0 > b.0 { x } else { b },
        )
        .1
}

/// Directions on the sphere in rings about `pole`, packed toward it (θ ∝ (i/RINGS)²).
fn pole_grid(pole: DVec3) -> Vec<DVec3> {
    let z = pole.normalize_or(DVec3::Z);
    let (x, y) = z.any_orthonormal_pair();
    (0..=RINGS)
        .flat_map(|i| {
            let f = i as f64 / RINGS as f64;
            let t = std::f64::consts::PI * f * f;
            (0..SEGMENTS).map(move |k| {
                let p = std::f64::consts::TAU * k as f64 / SEGMENTS as f64;
                x * (t.sin() * p.cos()) + y * (t.sin() * p.sin()) + z * t.cos()
            })
        })
        .collect()
}

/// The quads of a `pole_grid` surface (vertex indices and positions), skipping empty ones.
fn quads(positions: &[DVec3]) -> Vec<([usize; 4], [DVec3; 4])> {
    let index = |i: usize, k: usize| i * SEGMENTS + k % SEGMENTS;
    (0..RINGS)
        .flat_map(|i| (0..SEGMENTS).map(move |k| (i, k)))
        .map(|(i, k)| {
            let q = [
                index(i, k),
                index(i, k + 1),
                index(i + 1, k + 1),
                index(i + 1, k),
            ];
            (q, q.map(|n| positions[n]))
        })
        .filter(|(_, p)| p.iter().any(|x| x.length_squared() >= 1e-8))
        .collect()
}

/// A surface as lines along every 4th ring and every 8th segment.
fn wireframe(
    positions: &[DVec3],
    project: &dyn Fn(DVec3) -> (Pos2, f64),
    colour: Color32,
) -> Vec<egui::Shape> {
    let stroke = egui::Stroke::new(1.0, colour.gamma_multiply(0.85));
    let at = |i: usize, k: usize| project(positions[i * SEGMENTS + k % SEGMENTS]).0;
    let rings = (0..=RINGS)
        .step_by(4)
        .map(|i| (0..=SEGMENTS).map(|k| at(i, k)).collect::<Vec<Pos2>>());
    let meridians = (0..SEGMENTS)
        .step_by(8)
        .map(|k| (0..=RINGS).map(|i| at(i, k)).collect::<Vec<Pos2>>());
    rings
        .chain(meridians)
        .map(|line| egui::Shape::line(line, stroke))
        .collect()
}

fn shade(c: Color32, k: f32) -> Color32 {
    Color32::from_rgba_unmultiplied(
        (f32::from(c.r()) * k) as u8,
        (f32::from(c.g()) * k) as u8,
        (f32::from(c.b()) * k) as u8,
        c.a(),
    )
}
