//! The CPU reference renderer: the plane seen by the camera, shaded in f64 with the exact
//! BRDF (eq. 28) or the LTC approximation (eq. 30 with docs/design.md §1's corrections), rows in
//! parallel with rayon. It is the ground truth every GPU test compares against. Its `cases`
//! map each pixel's clipping and sphere cases.

pub mod cases;

use std::ops::Range;

use glam::DVec3;
use rayon::prelude::*;

use crate::brdf::{
    Lobes, brdf_cos_aniso, irradiance_scale, point_light_exact_aniso, window_falloff,
};
use crate::light::sphere::{SphereMethod, SphereShading, sphere_light_with};
use crate::light::{EmitterShading, ExactRule, Shape};
use crate::ltc::LtcPair;
use crate::ltc::lut::Lut;
use crate::ltc::nl_fit::{self, NlTerms};
use crate::ltc::remedy::HorizonRule;
use crate::metrics::relative_difference;
use crate::render::{
    Frame, FrameKind, Gloss, LtcRules, LutFilter, RenderSettings, ShadingFrame, SurfacePoint,
    Tables, View,
};
use crate::render::{ShapeMethod, ShapeMethods};
use crate::scene::{Light, Scene};

/// The per-pixel state of LTC shading: the frame, the two looked-up lobes and the horizon
/// rule with its correction read at the same place of the table.
#[derive(Clone, Copy, Debug)]
pub struct LtcPixel {
    pub frame: ShadingFrame,
    pub pair: LtcPair,
    pub horizon: HorizonRule,
    /// `nl-fit`'s coefficients (zero under the other rules).
    pub nl: NlTerms,
}

impl LtcPixel {
    /// The pixel's lobes for a material of roughness `gloss` seen from `view` (world, unit):
    /// an isotropic material in the view's frame from the 2D table, an anisotropic one in
    /// its tangent's frame (`anisotropic`).
    pub fn new(lut: &Lut, gloss: &Gloss, view: DVec3, rules: &LtcRules) -> Self {
        if gloss.alpha.is_isotropic() {
            Self::isotropic(lut, gloss.alpha.x, view, rules)
        } else {
            Self::anisotropic(lut, gloss, view, rules)
        }
    }

    /// An anisotropic material (docs/design.md §1.13): both lobes in the tangent frame
    /// (`Lut::aniso_pair`). The 4D table is read bilinearly whatever the
    /// rules' filter, and the horizon rules apply without `nl-fit`'s correction, which was
    /// fitted to the 2D table's lobes.
    pub fn anisotropic(lut: &Lut, gloss: &Gloss, view: DVec3, rules: &LtcRules) -> Self {
        let frame = ShadingFrame::of(gloss, view);
        let v = frame.tangent_from_world(view);
        Self {
            frame,
            pair: lut.aniso_pair(gloss.alpha, v),
            horizon: rules.horizon,
            nl: [0.0; 4],
        }
    }

    /// An isotropic material of roughness `alpha`.
    pub fn isotropic(lut: &Lut, alpha: f64, view: DVec3, rules: &LtcRules) -> Self {
        let frame = ShadingFrame::new(view);
        let cos_theta_o = frame.tangent_from_world(view).z;
        type NlSampler = fn(&Lut, f64, f64) -> NlTerms;
        let (sample, nl): (_, NlSampler) = match rules.filter {
            LutFilter::Bilinear => (lut.sample(alpha, cos_theta_o), nl_fit::nl_sample_uv),
            LutFilter::Nearest => (
                lut.sample_nearest(alpha, cos_theta_o),
                nl_fit::nl_sample_nearest,
            ),
        };
        let nl = match rules.horizon {
            HorizonRule::NlFit => {
                let (u, v) = lut.uv(alpha, cos_theta_o);
                nl(lut, u, v)
            }
            _ => [0.0; 4],
        };
        Self {
            frame,
            pair: sample.ltc_pair(),
            horizon: rules.horizon,
            nl,
        }
    }
}

impl LtcPixel {
    /// Both lobes of a unit-irradiance light toward unit `l` (shading frame), base colour 1:
    /// eq. 30 with `rules`, then the pixel's horizon rule (`exact` gives the BRDF's lobes,
    /// asked for only inside `exact-band`'s band).
    pub fn lobes(
        &self,
        l: DVec3,
        f0: f64,
        rules: &LtcRules,
        exact: impl FnOnce() -> Lobes<f64>,
    ) -> Lobes<f64> {
        let ltc = self
            .pair
            .ltc_lobes(l, f0, rules.clipping, rules.normalization);
        self.horizon.apply(l.z, ltc, &self.nl, exact)
    }
}

/// The exact radiance toward the camera at `p` (eq. 28), summed over `lights` as points.
pub fn shade_exact(scene: &Scene, p: &SurfacePoint, lights: &[Light]) -> DVec3 {
    if p.view.z <= 0.0 {
        return DVec3::ZERO;
    }
    let frame = ShadingFrame::of(&scene.material.gloss(), p.view);
    lights.iter().fold(DVec3::ZERO, |sum, light| {
        sum + exact_term(scene, &frame, p, light)
    })
}

/// One light's exact radiance toward the camera (eq. 28's summand).
pub fn exact_term(scene: &Scene, frame: &ShadingFrame, p: &SurfacePoint, light: &Light) -> DVec3 {
    let m = &scene.material;
    let u = frame.tangent_from_world(DVec3::from(light.position) - p.position);
    let lobes = point_light_exact_aniso(
        frame.tangent_from_world(p.view).to_array(),
        u.to_array(),
        1.0,
        light.range_or_infinity(),
        m.roughness(),
        m.f0,
    );
    light.radiant_intensity() * combine(lobes, m.base_color)
}

/// The LTC radiance toward the camera at `p` (eq. 30, corrected or paper-literal), summed over
/// `lights` as points.
pub fn shade_ltc(
    scene: &Scene,
    lut: &Lut,
    p: &SurfacePoint,
    lights: &[Light],
    rules: &LtcRules,
) -> DVec3 {
    if p.view.z <= 0.0 {
        return DVec3::ZERO;
    }
    let px = LtcPixel::new(lut, &scene.material.gloss(), p.view, rules);
    lights.iter().fold(DVec3::ZERO, |sum, light| {
        sum + ltc_term(scene, &px, p, light, rules)
    })
}

/// One light's LTC radiance toward the camera (eq. 30's summand), under the pixel's horizon
/// rule.
pub fn ltc_term(
    scene: &Scene,
    px: &LtcPixel,
    p: &SurfacePoint,
    light: &Light,
    rules: &LtcRules,
) -> DVec3 {
    let m = &scene.material;
    let u = px
        .frame
        .tangent_from_world(DVec3::from(light.position) - p.position);
    let d = u.length();
    let e = irradiance_scale(1.0, d, light.range_or_infinity());
    if e <= 0.0 {
        return DVec3::ZERO;
    }
    let l = u / d;
    let lobes = px.lobes(l, m.f0, rules, || {
        let v = px.frame.tangent_from_world(p.view);
        brdf_cos_aniso(v.to_array(), l.to_array(), m.roughness(), m.f0)
    });
    light.radiant_intensity() * (e * combine(lobes, m.base_color))
}

/// One sphere light's radiance toward the camera by `method` (docs/design.md §1.10), with
/// the pixel's LTC lobes for the LTC methods (eq. 30's clipping and normalization; the
/// horizon rules are the point formula's) and the renderers' rule for the exact one.
pub fn sphere_term(
    scene: &Scene,
    px: &LtcPixel,
    p: &SurfacePoint,
    (light, radius): (&Light, f64),
    rules: &LtcRules,
    (method, rule): (SphereMethod, ExactRule),
) -> DVec3 {
    let m = &scene.material;
    let shading = SphereShading {
        v: px.frame.tangent_from_world(p.view),
        u: px
            .frame
            .tangent_from_world(DVec3::from(light.position) - p.position),
        intensity: 1.0,
        range: light.range_or_infinity(),
        radius,
        alpha: m.roughness(),
        f0: m.f0,
        ltc: &px.pair,
        clip: rules.clipping,
        normalization: rules.normalization,
    };
    let lobes = sphere_light_with(method, &shading, rule);
    light.radiant_intensity() * combine(lobes, m.base_color)
}

/// One emitter's radiance toward the camera by `method`, a method of its shape (a rect,
/// §1.11; a disk, §1.12…: `ShapeMethod::emitter_lobes`): its radiance `I/A`
/// times the unit-radiance lobes, windowed at the centre's distance as a sphere is, with the
/// renderers' rule for the exact method. `None` for a point, a sphere or another shape's
/// method.
pub fn emitter_term(
    scene: &Scene,
    px: &LtcPixel,
    p: &SurfacePoint,
    light: &Light,
    rules: &LtcRules,
    (method, rule): (ShapeMethod, ExactRule),
) -> Option<DVec3> {
    let m = &scene.material;
    let centre = DVec3::from(light.position) - p.position;
    let shading = EmitterShading {
        v: px.frame.tangent_from_world(p.view),
        alpha: m.roughness(),
        f0: m.f0,
        ltc: &px.pair,
        clip: rules.clipping,
        normalization: rules.normalization,
    };
    let to_frame = |w: DVec3| px.frame.tangent_from_world(w);
    let (lobes, area) = method.emitter_lobes((light.shape, centre), &to_frame, &shading, rule)?;
    Some(emitter_radiance(scene, light, (centre, area), lobes))
}

/// An emitter's radiance toward the camera from its unit-radiance `lobes`: times its
/// radiance `I/A` (`area` A) and the window at its centre's distance (`centre`), every
/// emitter's one tail (light_shape.wgsl's `add_emitter_lobes`).
fn emitter_radiance(
    scene: &Scene,
    light: &Light,
    (centre, area): (DVec3, f64),
    lobes: Lobes<f64>,
) -> DVec3 {
    let scale = window_falloff(centre.length(), light.range_or_infinity()) / area;
    light.radiant_intensity() * scale * combine(lobes, scene.material.base_color)
}

/// One side of a render: its method for each light shape, the table its LTC methods read,
/// and the rule its exact methods integrate by (the renders' own, but for a reference made
/// by another: `measure::exact_rule`).
#[derive(Clone, Copy, Debug)]
pub struct Side<'a> {
    pub methods: ShapeMethods,
    pub lut: &'a Lut,
    pub rule: ExactRule,
}

impl<'a> Side<'a> {
    /// Method A's side of `s`.
    pub fn a(s: &RenderSettings, tables: Tables<'a>) -> Self {
        Self {
            methods: s.a,
            lut: tables.a,
            rule: ExactRule::Render,
        }
    }

    /// Method B's side of `s`.
    pub fn b(s: &RenderSettings, tables: Tables<'a>) -> Self {
        Self {
            methods: s.b,
            lut: tables.for_b(s),
            rule: ExactRule::Render,
        }
    }
}

/// One light's radiance toward the camera by one side: by the side's method for the light's
/// shape (`shape_term`).
pub fn light_term(
    scene: &Scene,
    px: &LtcPixel,
    p: &SurfacePoint,
    light: &Light,
    rules: &LtcRules,
    side: &Side<'_>,
) -> DVec3 {
    let method = side.methods.of(light.shape.kind());
    shape_term(scene, px, p, light, rules, (method, side.rule))
}

/// One light's radiance toward the camera by `method`, a method of its shape (for a point,
/// the CPU's literal form of it): a point's, a sphere's, or an emitter's (`emitter_term`).
pub fn shape_term(
    scene: &Scene,
    px: &LtcPixel,
    p: &SurfacePoint,
    light: &Light,
    rules: &LtcRules,
    (method, rule): (ShapeMethod, ExactRule),
) -> DVec3 {
    match (light.shape, method) {
        (Shape::Point, ShapeMethod::Point(m)) if m.is_ltc() => {
            Some(ltc_term(scene, px, p, light, rules))
        }
        (Shape::Point, ShapeMethod::Point(_)) => Some(exact_term(scene, &px.frame, p, light)),
        (Shape::Sphere { radius }, ShapeMethod::Sphere(m)) => {
            Some(sphere_term(scene, px, p, (light, radius), rules, (m, rule)))
        }
        (Shape::Point | Shape::Sphere { .. }, _) => None,
        _ => emitter_term(scene, px, p, light, rules, (method, rule)),
    }
    .unwrap_or_else(|| {
        // Another shape's method, which `ShapeMethods::of` never gives: the shape's exact
        // integral.
        let exact = ShapeMethod::reference(light.shape.kind());
        shape_term(scene, px, p, light, rules, (exact, rule))
    })
}

/// `specular + c · diffuse`, per channel.
fn combine(lobes: Lobes<f64>, base_color: [f64; 3]) -> DVec3 {
    DVec3::splat(lobes.specular) + lobes.diffuse * DVec3::from(base_color)
}

/// Renders the scene as `s.view` shows it: one method's radiance, both split at the divider,
/// or their relative difference. `tables`: one table, or A's and B's (B's where `s.b_reads_table_b`).
pub fn render<'a>(scene: &Scene, tables: impl Into<Tables<'a>>, s: &RenderSettings) -> Frame {
    let tables = tables.into();
    let mut bands = Bands::new(s);
    // A pass a step, each band the whole image (its rows in parallel).
    loop {
        if let Some(frame) = bands.step(scene, tables, s.height) {
            return frame;
        }
    }
}

/// The radiance images a render of `s` is made of: two (A's and B's) for a difference view,
/// else one.
fn passes(s: &RenderSettings) -> usize {
    if s.view == View::Diff { 2 } else { 1 }
}

/// Rows `rows` of pass `pass`'s radiance: a band of the image.
fn render_rows<'a>(
    scene: &Scene,
    tables: impl Into<Tables<'a>>,
    s: &RenderSettings,
    pass: usize,
    rows: Range<usize>,
) -> Frame {
    let tables = tables.into();
    let (a, b) = (Side::a(s, tables), Side::b(s, tables));
    let divider = s.divider_column();
    let shade = |pick: &Pick<'_>| render_radiance(scene, s, pick, rows.clone());
    match (s.view, pass) {
        (View::A, _) | (View::Diff, 0) => shade(&|_| a),
        (View::B | View::Diff, _) => shade(&|_| b),
        (View::Split, _) => shade(&|x| if x < divider { a } else { b }),
    }
}

/// The image of `s` from its passes, each whole.
fn assemble(s: &RenderSettings, passes: Vec<Frame>) -> Frame {
    let mut passes = passes.into_iter();
    let first = passes.next().expect("a render has a pass");
    match s.view {
        View::Diff => relative_difference(&first, &passes.next().expect("B's pass")),
        View::Split => Frame {
            divider: Some(s.divider_column()),
            ..first
        },
        View::A | View::B => first,
    }
}

/// A render made band by band (`render_rows`), for a caller that renders in steps (the
/// browser, which has no threads to wait on); `render` is one step a pass.
pub struct Bands {
    s: RenderSettings,
    done: Vec<Vec<Frame>>,
    pass: usize,
    row: usize,
}

impl Bands {
    pub fn new(s: &RenderSettings) -> Self {
        Self {
            s: *s,
            done: vec![Vec::new(); passes(s)],
            pass: 0,
            row: 0,
        }
    }

    /// Renders the next `rows` rows (at least one); the image once the last is done.
    pub fn step<'a>(
        &mut self,
        scene: &Scene,
        tables: impl Into<Tables<'a>>,
        rows: usize,
    ) -> Option<Frame> {
        let end = (self.row + rows.max(1)).min(self.s.height);
        let band = render_rows(scene, tables, &self.s, self.pass, self.row..end);
        self.done[self.pass].push(band);
        self.row = end;
        if self.row < self.s.height {
            return None;
        }
        (self.pass, self.row) = (self.pass + 1, 0);
        if self.pass < self.done.len() {
            return None;
        }
        let passes = self.done.drain(..).map(stack).collect();
        Some(assemble(&self.s, passes))
    }
}

/// Bands of rows of one image, stacked in order into the whole.
fn stack(bands: Vec<Frame>) -> Frame {
    let mut bands = bands.into_iter();
    let mut whole = bands.next().expect("at least one band");
    for band in bands {
        whole.height += band.height;
        whole.pixels.extend(band.pixels);
        whole.on_plane.extend(band.on_plane);
    }
    whole
}

/// The side that shades a pixel column.
type Pick<'a> = dyn Fn(usize) -> Side<'a> + Sync + 'a;

/// The radiance at one surface point by one side, its lights summed in order.
pub fn shade(scene: &Scene, p: &SurfacePoint, rules: &LtcRules, side: &Side<'_>) -> DVec3 {
    if p.view.z <= 0.0 {
        return DVec3::ZERO;
    }
    let px = LtcPixel::new(side.lut, &scene.material.gloss(), p.view, rules);
    scene.lights.iter().fold(DVec3::ZERO, |sum, light| {
        sum + light_term(scene, &px, p, light, rules, side)
    })
}

/// The radiance image of `s`'s size with every pixel by one `side` (a reference made by
/// another rule than the renders': `measure::exact_rule`).
pub fn render_side(scene: &Scene, s: &RenderSettings, side: Side<'_>) -> Frame {
    render_radiance(scene, s, &|_| side, 0..s.height)
}

/// Radiance over rows `rows` with the method (and table) `pick` gives for each pixel column.
fn render_radiance(
    scene: &Scene,
    s: &RenderSettings,
    pick: &Pick<'_>,
    rows: Range<usize>,
) -> Frame {
    let height = rows.len();
    let rows: Vec<(Vec<DVec3>, Vec<bool>)> = rows
        .into_par_iter()
        .map(|y| {
            (0..s.width)
                .map(|x| match scene.surface_point(x, y, s.width, s.height) {
                    None => (DVec3::ZERO, false),
                    Some(p) => (shade(scene, &p, &s.rules, &pick(x)), true),
                })
                .unzip()
        })
        .collect();
    let (pixels, on_plane) = rows
        .into_iter()
        .fold((Vec::new(), Vec::new()), |mut acc, (p, m)| {
            acc.0.extend(p);
            acc.1.extend(m);
            acc
        });
    Frame {
        width: s.width,
        height,
        kind: FrameKind::Radiance,
        pixels,
        on_plane,
        divider: None,
    }
}
