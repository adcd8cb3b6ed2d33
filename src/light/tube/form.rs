//! How a tube is written, shown and sampled outside its methods (docs/design.md §5.12,
//! §1.15): its vector in a scene file, its presets, its sizes and outline in the lab, its
//! `eval` columns, its `bench` lights and the error table's tubes.

use glam::DVec3;

use crate::light::{RADIUS_RANGE, Shape, ShapeSize, VectorField};

/// A tube's vector in a scene file (`ShapeKind::vector_fields`): its half axis, so that the
/// segment runs from `position − half_axis` to `position + half_axis`.
pub const VECTORS: [VectorField; 1] = [VectorField {
    name: "half_axis",
    direction: false,
}];

/// The tube's failure presets (docs/design.md §1.15): across the horizon, standing on the
/// plane (end-on), long and thin, tiny and far.
pub const PRESETS: [(&str, &str); 1] = [(
    "tube-limits",
    include_str!("../../../assets/scenes/tube-limits.toml"),
)];

/// A benchmark tube's length in radii: a fluorescent strip's proportions (a 1.2 m T8 tube is
/// 26 mm across, some 90 radii; 10 keeps it within the scene's light spacing at `bench`'s
/// sizes).
pub const BENCH_LENGTH: f64 = 10.0;

/// The tube `bench` times (`ShapeKind::bench_shape`): of radius `r`, `BENCH_LENGTH` radii
/// long along x.
pub fn bench_shape(r: f64) -> Shape {
    Shape::Tube {
        half_axis: DVec3::X * (0.5 * BENCH_LENGTH * r),
        radius: r,
    }
}

/// `bench_shape`'s lights in words.
pub fn bench_title(r: f64) -> String {
    format!(
        "every light a tube of radius {r} and length {}, along x",
        BENCH_LENGTH * r
    )
}

/// A tube's sizes in the lab (`Shape::sizes`): its length, along the axis it has, and its
/// radius. With them it keeps its intensity, so a larger tube lights a distant point alike.
pub const SIZES: [ShapeSize; 2] = [
    ShapeSize {
        label: "len",
        hover: "Length: the tube's segment, end to end of its axis (0 is a ball); the capsule adds a half ball of radius r at each end",
        // From 0 (a ball) to 4, the default plane's side.
        range: [0.0, 4.0],
        speed: 0.005,
        get: |s| 2.0 * s.half_axis().unwrap_or_default().length(),
        set: |s, full| match s {
            Shape::Tube { half_axis, radius } => Shape::Tube {
                half_axis: half_axis.try_normalize().unwrap_or(DVec3::X) * (0.5 * full),
                radius,
            },
            s => s,
        },
    },
    ShapeSize {
        label: "r",
        hover: "The tube's radius, 0.0001 to 1: with its length it keeps its intensity, so a larger tube lights a distant point alike and is dimmer per area",
        range: RADIUS_RANGE,
        speed: 0.002,
        get: Shape::radius,
        set: |s, radius| match s {
            Shape::Tube { half_axis, .. } => Shape::Tube { half_axis, radius },
            s => s,
        },
    },
];

/// A capsule's outline as the lab draws it (`Shape::outline`; world, about `centre`, seen
/// from `eye`): the segment offset by the radius each side of its axis across the view (its
/// silhouette seen broadside), closed by its ends; and its axis.
pub fn outline(centre: DVec3, (half_axis, radius): (DVec3, f64), eye: DVec3) -> Vec<Vec<DVec3>> {
    let axis = half_axis.try_normalize().unwrap_or(DVec3::X);
    let across = axis
        .cross(centre - eye)
        .try_normalize()
        .unwrap_or_else(|| axis.any_orthonormal_vector())
        * radius;
    let ends = [centre - half_axis, centre + half_axis];
    let sides = vec![
        ends[0] + across,
        ends[1] + across,
        ends[1] - across,
        ends[0] - across,
        ends[0] + across,
    ];
    vec![sides, ends.to_vec()]
}

/// A tube's columns in an `eval` file, after θo, α and F0 (docs/design.md §6): its
/// segment's ends `a` and `b` in the shading frame and the capsule's radius (radiance 1).
pub const EVAL_COLUMNS: &str = "ax,ay,az,bx,by,bz,radius";

/// An `eval` row's tube (`get` reads a column of `EVAL_COLUMNS`): the shape and its centre in
/// the row's frame, or why the row is refused.
pub fn eval_row(get: &dyn Fn(&str) -> f64) -> Result<(Shape, DVec3), String> {
    let vector = |x, y, z| DVec3::new(get(x), get(y), get(z));
    let (a, b, radius) = (
        vector("ax", "ay", "az"),
        vector("bx", "by", "bz"),
        get("radius"),
    );
    // The rect rows' bounds on distances and sizes, for each end and the radius; a segment
    // of no length is a ball.
    if ![a.length(), b.length(), radius]
        .iter()
        .all(|s| (1e-9..=1e6).contains(s))
    {
        return Err("each end's distance and the radius must be in [1e-9, 1e6]".into());
    }
    let shape = Shape::Tube {
        half_axis: 0.5 * (b - a),
        radius,
    };
    Ok((shape, 0.5 * (a + b)))
}

/// A tube of about `omega` sr seen from the origin, centred at the unit direction `centre`
/// (distance 1), as the error table draws it (`measure::emitter_error`; `uniform` draws in a
/// range): its axis across the line of sight, turned about it at random and tilted toward it
/// by up to 45°, its length 0 to 20 radii. Toward the origin it covers about
/// `2 r ℓ sin β + π r²` (its `ltc-point`'s area, β the axis's angle from the line of sight).
pub fn error_sample(
    uniform: &mut dyn FnMut([f64; 2]) -> f64,
    omega: f64,
    centre: DVec3,
) -> (Shape, DVec3) {
    let (t1, t2, w) = crate::light::rect::form::sight_frame(centre);
    let turn = uniform([0.0, std::f64::consts::TAU]);
    let tilt = uniform([-45.0, 45.0]).to_radians();
    let axis = (t1 * turn.cos() + t2 * turn.sin()) * tilt.cos() + w * tilt.sin();
    let radii = uniform([0.0, 20.0]);
    let radius = (omega / (2.0 * radii * tilt.cos() + std::f64::consts::PI)).sqrt();
    let shape = Shape::Tube {
        half_axis: axis * (0.5 * radii * radius),
        radius,
    };
    (shape, centre)
}
