//! How a disk is written, shown and sampled outside its methods (docs/design.md §5.12): its
//! vector in a scene file, its presets, its size and outline in the lab, its `eval` columns
//! and its `bench` lights.

use glam::DVec3;

use crate::light::{RADIUS_RANGE, Shape, ShapeSize, VectorField};

/// A disk's vector in a scene file (`ShapeKind::vector_fields`): its normal, the side it
/// emits toward, of which only the direction is read.
pub const VECTORS: [VectorField; 1] = [VectorField {
    name: "normal",
    direction: true,
}];

/// The failure cases of disk lights (docs/design.md §1.12): across the horizon, behind the
/// surface, edge-on, filling the sky and tiny, in one scene.
pub const PRESETS: [(&str, &str); 1] = [(
    "disk-limits",
    include_str!("../../../assets/scenes/disk-limits.toml"),
)];

/// The disk `bench` times (`ShapeKind::bench_shape`): of radius `r`, facing down onto the
/// plane.
pub fn bench_shape(r: f64) -> Shape {
    Shape::Disk {
        normal: DVec3::NEG_Z,
        radius: r,
    }
}

/// `bench_shape`'s lights in words.
pub fn bench_title(r: f64) -> String {
    format!("every light a disk of radius {r}, facing the plane")
}

/// A disk's one size in the lab (`Shape::sizes`), its radius, never 0: it keeps its normal
/// and its intensity.
pub const SIZES: [ShapeSize; 1] = [ShapeSize {
    label: "r",
    hover: "The disk's radius, 0.0001 to 1 (a value typed beyond is brought into that range): it keeps its normal and its intensity, so a larger disk lights a distant point alike and is dimmer per area",
    range: RADIUS_RANGE,
    speed: 0.004,
    get: Shape::radius,
    set: |s, radius| match s {
        Shape::Disk { normal, .. } => Shape::Disk { normal, radius },
        s => s,
    },
}];

/// A disk's outline as the lab draws it (`Shape::outline`; world, about `centre`): its rim,
/// and a tick from the centre along its normal, half its radius long.
pub fn outline(centre: DVec3, normal: DVec3, radius: f64) -> Vec<Vec<DVec3>> {
    let normal = normal.normalize();
    let (e1, e2) = normal.any_orthonormal_pair();
    // 48 chords: under a pixel from the circle for a disk 200 pixels across.
    let rim = (0..=48)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / 48.0;
            centre + (e1 * t.cos() + e2 * t.sin()) * radius
        })
        .collect();
    vec![rim, vec![centre, centre + normal * (0.5 * radius)]]
}

/// The smallest length of a disk's normal: it is only a direction, but one of no length (or
/// one whose square underflows) has none.
pub const MIN_NORMAL: f64 = 1e-6;

/// A disk's columns in an `eval` file, after θo, α and F0 (docs/design.md §6): its centre and
/// normal (the side it emits toward; any length) in the shading frame and its radius
/// (radiance 1).
pub const EVAL_COLUMNS: &str = "cx,cy,cz,nx,ny,nz,radius";

/// An `eval` row's disk (`get` reads a column of `EVAL_COLUMNS`): the shape and its centre in
/// the row's frame, or why the row is refused.
pub fn eval_row(get: &dyn Fn(&str) -> f64) -> Result<(Shape, DVec3), String> {
    let vector = |x, y, z| DVec3::new(get(x), get(y), get(z));
    let (centre, normal, radius) = (
        vector("cx", "cy", "cz"),
        vector("nx", "ny", "nz"),
        get("radius"),
    );
    // The rect rows' bounds on the centre's distance and the size; a normal as the scene
    // file takes one (at least `MIN_NORMAL` long).
    if ![centre.length(), radius]
        .iter()
        .all(|s| (1e-9..=1e6).contains(s))
    {
        return Err("the centre's distance and the radius must be in [1e-9, 1e6]".into());
    }
    if !(normal.length() >= MIN_NORMAL && normal.length() <= 1e6) {
        return Err(format!(
            "the normal must be {} to 1e6 long",
            crate::error::number(MIN_NORMAL)
        ));
    }
    let shape = Shape::Disk {
        normal: normal.normalize(),
        radius,
    };
    Ok((shape, centre))
}

/// A disk of about `omega` sr seen from the origin, centred at the unit direction `centre`
/// (distance 1), as the error tables draw it (`uniform` draws in a range): facing the origin
/// tilted by up to 45° (the rects' plane, `rect::form::tilted_frame`), of area `π r²` with
/// `π r² cos θe = omega`.
pub fn error_sample(
    uniform: &mut dyn FnMut([f64; 2]) -> f64,
    omega: f64,
    centre: DVec3,
) -> (Shape, DVec3) {
    let (t1, t2, cos_e) = crate::light::rect::form::tilted_frame(uniform, centre);
    let shape = Shape::Disk {
        normal: t1.cross(t2),
        radius: (omega / cos_e / std::f64::consts::PI).sqrt(),
    };
    (shape, centre)
}
