//! How a rect is written, shown and sampled outside its methods (docs/design.md §5.12): its
//! vectors in a scene file, its presets, its sizes and outline in the lab, its `eval`
//! columns and its `bench` lights.

use glam::DVec3;

use crate::light::rect::Rect;
use crate::light::{MIN_RADIUS, Shape, ShapeSize, VectorField};

/// A rect's vectors in a scene file (`ShapeKind::vector_fields`): its half-edges; it emits
/// toward `half_u × half_v`.
pub const VECTORS: [VectorField; 2] = [
    VectorField {
        name: "half_u",
        direction: false,
    },
    VectorField {
        name: "half_v",
        direction: false,
    },
];

/// The failure cases of rect lights (docs/design.md §1.11): rects across the horizon, edge-on
/// and facing away; touching the surface, behind it and tiny; and one filling the sky.
pub const PRESETS: [(&str, &str); 3] = [
    (
        "rect-horizon",
        include_str!("../../../assets/scenes/rect-horizon.toml"),
    ),
    (
        "rect-limits",
        include_str!("../../../assets/scenes/rect-limits.toml"),
    ),
    (
        "rect-ceiling",
        include_str!("../../../assets/scenes/rect-ceiling.toml"),
    ),
];

/// The rect `bench` times (`ShapeKind::bench_shape`): a square of half-edge `h` facing
/// down onto the plane.
pub fn bench_shape(h: f64) -> Shape {
    // half_u × half_v = (h, 0, 0) × (0, −h, 0) = (0, 0, −h²): toward the plane.
    Shape::Rect {
        half_u: DVec3::new(h, 0.0, 0.0),
        half_v: DVec3::new(0.0, -h, 0.0),
    }
}

/// `bench_shape`'s lights in words.
pub fn bench_title(h: f64) -> String {
    format!("every light a square rect of half-edge {h}, facing the plane")
}

/// A rect's sizes in the lab (`Shape::sizes`): its width and height (its edges' full
/// lengths), each along its own direction, so that the orientation stays. From 2·MIN_RADIUS,
/// so that a square keeps the scene's least area, to 4 (the default plane's side).
pub const SIZES: [ShapeSize; 2] = [
    ShapeSize {
        label: "w",
        hover: "Width: the length of the rect's first edge (2 |half_u|)",
        range: [2.0 * MIN_RADIUS, 4.0],
        speed: 0.005,
        get: |s| 2.0 * s.half_edges().map_or(0.0, |(u, _)| u.length()),
        set: |s, full| match s {
            Shape::Rect { half_u, half_v } => Shape::Rect {
                half_u: resized(half_u, full),
                half_v,
            },
            s => s,
        },
    },
    ShapeSize {
        label: "h",
        hover: "Height: the length of its second edge (2 |half_v|)",
        range: [2.0 * MIN_RADIUS, 4.0],
        speed: 0.005,
        get: |s| 2.0 * s.half_edges().map_or(0.0, |(_, v)| v.length()),
        set: |s, full| match s {
            Shape::Rect { half_u, half_v } => Shape::Rect {
                half_u,
                half_v: resized(half_v, full),
            },
            s => s,
        },
    },
];

impl Rect {
    /// Its outline as the lab draws it (`Shape::outline`): its four edges, and a tick from
    /// the centre along its normal, toward the side it lights, half its shorter half-edge long.
    pub fn outline(&self) -> Vec<Vec<DVec3>> {
        let mut edges = self.corners().to_vec();
        edges.push(edges[0]);
        let reach = 0.5 * self.u.length().min(self.v.length());
        let tip = self.centre + self.normal().normalize() * reach;
        vec![edges, vec![self.centre, tip]]
    }
}

/// A half-edge of full length `full` along its own direction (one of no length stays).
fn resized(edge: DVec3, full: f64) -> DVec3 {
    let length = edge.length();
    match length > 0.0 {
        true => edge * (0.5 * full / length),
        false => edge,
    }
}

/// A rect's columns in an `eval` file, after θo, α and F0 (docs/design.md §6): its centre
/// and two half-edge vectors in the shading frame (radiance 1, emitting toward `u × v`).
pub const EVAL_COLUMNS: &str = "cx,cy,cz,ux,uy,uz,vx,vy,vz";

/// An `eval` row's rect (`get` reads a column of `EVAL_COLUMNS`): the shape and its centre in
/// the row's frame, or why the row is refused.
pub fn eval_row(get: &dyn Fn(&str) -> f64) -> Result<(Shape, DVec3), String> {
    let vector = |x, y, z| DVec3::new(get(x), get(y), get(z));
    let rect = Rect {
        centre: vector("cx", "cy", "cz"),
        u: vector("ux", "uy", "uz"),
        v: vector("vx", "vy", "vz"),
    };
    // Sizes from 1e-9 (a rect that small is its point light to far below f64's rounding of
    // the BRDF) to 1e6 (the scene's coordinates' bound), in scene units.
    let sizes = [rect.centre.length(), rect.u.length(), rect.v.length()];
    if sizes.iter().any(|&s| !(1e-9..=1e6).contains(&s)) {
        return Err(
            "the centre's distance and each half-edge's length must be in [1e-9, 1e6]".into(),
        );
    }
    if rect.normal().length() <= 1e-12 * sizes[1] * sizes[2] {
        return Err("u and v are parallel: not a rect".into());
    }
    let shape = Shape::Rect {
        half_u: rect.u,
        half_v: rect.v,
    };
    Ok((shape, rect.centre))
}

/// A rect of about `omega` sr seen from the origin, centred at the unit direction `centre`
/// (distance 1), as the error tables draw it (`measure::shape_error::lights`, whose rects
/// these are; `uniform` draws in a range): facing the origin, tilted by up to 45°, of aspect 1
/// to 3, of area `A` with `A cos θe = omega`.
pub fn error_sample(
    uniform: &mut dyn FnMut([f64; 2]) -> f64,
    omega: f64,
    centre: DVec3,
) -> (Shape, DVec3) {
    let (t1, t2, cos_e) = tilted_frame(uniform, centre);
    let aspect = uniform([1.0, 3.0]);
    // Area A = 4 hu hv with hu = aspect · hv.
    let hv = (omega / cos_e / (4.0 * aspect)).sqrt();
    let shape = Shape::Rect {
        half_u: t1 * (aspect * hv),
        half_v: t2 * hv,
    };
    (shape, centre)
}

/// The error tables' frame at `centre` (unit, distance 1): two unit vectors across the line of
/// sight and the direction back to the origin, `w = −centre`.
pub fn sight_frame(centre: DVec3) -> (DVec3, DVec3, DVec3) {
    let w = -centre;
    let up = if w.z.abs() < 0.9 { DVec3::Z } else { DVec3::X };
    let t1 = up.cross(w).normalize();
    (t1, w.cross(t1), w)
}

/// The error tables' emitter plane at `centre` (unit, distance 1): two unit vectors across it,
/// facing the origin tilted by up to 45° about the first, and the cosine between its normal
/// and the line of sight.
pub fn tilted_frame(
    uniform: &mut dyn FnMut([f64; 2]) -> f64,
    centre: DVec3,
) -> (DVec3, DVec3, f64) {
    let (t1, t2, w) = sight_frame(centre);
    let tilt = uniform([-45.0, 45.0]).to_radians();
    let t2 = t2 * tilt.cos() + w * tilt.sin();
    let cos_e = t1.cross(t2).dot(w).abs();
    (t1, t2, cos_e)
}
