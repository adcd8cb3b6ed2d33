//! The constants Rust shares with the shaders are the WGSL's, value for value; the few the
//! shaders keep alone are listed with why.

use ltc_lab::gpu::{bin_module_source, ltc_aniso, plane_module_source};

use crate::validate;

/// A WGSL constant's value, its components flattened (a scalar is one number, a vector or
/// an array its components in order), as naga's constant evaluation left it.
fn constant_value(module: &naga::Module, name: &str) -> Vec<f64> {
    let (_, c) = module
        .constants
        .iter()
        .find(|(_, c)| c.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no constant {name} in the WGSL"));
    expression_value(module, c.init, name)
}

fn expression_value(
    module: &naga::Module,
    e: naga::Handle<naga::Expression>,
    name: &str,
) -> Vec<f64> {
    use naga::{Expression, Literal};
    match &module.global_expressions[e] {
        Expression::Literal(Literal::U32(v)) => vec![f64::from(*v)],
        Expression::Literal(Literal::I32(v)) => vec![f64::from(*v)],
        Expression::Literal(Literal::F32(v)) => vec![f64::from(*v)],
        Expression::Literal(Literal::Bool(v)) => vec![f64::from(u8::from(*v))],
        Expression::Constant(c) => expression_value(module, module.constants[*c].init, name),
        Expression::Compose { components, .. } => components
            .iter()
            .flat_map(|&c| expression_value(module, c, name))
            .collect(),
        other => panic!("{name} is {other:?}: not a value this test reads"),
    }
}

/// The shaders' constants that only the shaders read, each with why Rust has no twin.
const SHADER_ONLY: [(&str, &str); 13] = [
    // add_light's side of the split, which light_shape.wgsl picks each shape's override by.
    ("SIDE_A", "light_shape.wgsl's argument, not a pipeline's"),
    ("SIDE_B", "light_shape.wgsl's argument, not a pipeline's"),
    // tube_band.wgsl's fixed array of cuts, where Rust's band.rs has a Vec.
    ("TUBE_MAX_CUTS", "the size of a WGSL array"),
    // band.rs's PIECE_MIN and line.rs's END_ON are f64 rounding's; these are f32's.
    (
        "TUBE_PIECE_MIN",
        "an f32 angle's rounding (band.rs PIECE_MIN for f64)",
    ),
    (
        "TUBE_END_ON",
        "an f32 cross product's rounding (line.rs END_ON for f64)",
    ),
    // polar.wgsl's stand-in for T = tan(u/2) at u = π, where Rust has f64::INFINITY.
    ("T_INFINITE", "an infinite end f32 cannot hold"),
    // bin.wgsl's workgroup: Rust dispatches its passes by tile, not by it.
    ("WORKGROUP", "bin.wgsl's workgroup size"),
    // Which shapes a method file shades: written by Rust as it composes the file
    // (method_file::MethodFile::composed, checked by tests/inputs/method_file.rs).
    (
        "METHOD_FILE_POINT",
        "written when a method file is composed",
    ),
    (
        "METHOD_FILE_SPHERE",
        "written when a method file is composed",
    ),
    ("METHOD_FILE_RECT", "written when a method file is composed"),
    ("METHOD_FILE_DISK", "written when a method file is composed"),
    ("METHOD_FILE_TUBE", "written when a method file is composed"),
    // plane.wgsl's largest finite f32, the floor of an empty min.
    ("F32_MAX", "a bound inside plane.wgsl"),
];

/// Every constant the WGSL and Rust share, as Rust has it: `(name in the WGSL, value)`.
fn shared_constants() -> Vec<(&'static str, Vec<f64>)> {
    use ltc_lab::gpu::limits::LOAD;
    use ltc_lab::gpu::ltc::{
        CLIP_HORIZON, CLIP_TRANSFORMED, LUT_VEC4S_PER_CELL, horizon_constant,
        normalization_constant,
    };
    use ltc_lab::gpu::plane::{ViewConstant, method_constant};
    use ltc_lab::gpu::scene::TILE_SIDE;
    use ltc_lab::ltc::Normalization;
    use ltc_lab::ltc::remedy::HorizonRule;
    use ltc_lab::render::Method;
    // A WGSL f32 literal holds the Rust f64 rounded to f32: compare in that rounding.
    let f32s = |v: &[f64]| v.iter().map(|&x| f64::from(x as f32)).collect::<Vec<_>>();
    let codes = Method::ALL
        .map(method_constant)
        .into_iter()
        // Every sized shape's methods, each from its own shader (a point's are `Method`'s).
        .chain(
            ltc_lab::light::ShapeKind::ALL
                .into_iter()
                .flat_map(ltc_lab::render::ShapeMethod::all)
                .filter_map(|m| ltc_lab::gpu::light::method_constant(m).ok()),
        )
        .chain(ViewConstant::ALL.map(ViewConstant::constant))
        .chain(
            [
                HorizonRule::Eq30,
                HorizonRule::NlFit,
                HorizonRule::ExactBand,
            ]
            .map(horizon_constant),
        )
        .chain(Normalization::ALL.map(normalization_constant))
        .chain(ltc_lab::light::ShapeKind::ALL.map(ltc_lab::gpu::light::shape_constant))
        .chain([
            (CLIP_HORIZON, "CLIP_HORIZON"),
            (CLIP_TRANSFORMED, "CLIP_TRANSFORMED"),
        ])
        .chain(ltc_lab::ltc::aniso::AnisoAxes::ALL.map(ltc_aniso::axes_constant))
        .chain(ltc_lab::ltc::aniso::Stored::ALL.map(ltc_aniso::stored_constant))
        .map(|(value, name)| (name, vec![f64::from(value)]));
    // The positive half of a rule in increasing order, as polar.wgsl's `rule` unfolds it.
    let half = |n: usize, pick: fn(&(f64, f64)) -> f64| {
        let mut rule = ltc_lab::light::sphere::quadrature::gauss_legendre(n);
        rule.retain(|&(x, _)| x > 0.0);
        rule.sort_by(|a, b| a.0.total_cmp(&b.0));
        f32s(&rule.iter().map(pick).collect::<Vec<_>>())
    };
    use ltc_lab::light::{boundary, polar};
    let background = ltc_lab::output::BACKGROUND.map(|c| f64::from(c) / 255.0);
    codes
        .chain([
            ("LUT_VEC4S_PER_CELL", vec![LUT_VEC4S_PER_CELL as f64]),
            (
                "ANISO_VEC4S_PER_NODE",
                vec![ltc_aniso::ANISO_VEC4S_PER_NODE as f64],
            ),
            ("ANISO_ALPHA_MIN", f32s(&[ltc_lab::ltc::lut::ALPHA_MIN])),
            ("COS_THETA_MAX", f32s(&[ltc_lab::ltc::lut::THETA_MAX.cos()])),
            (
                "I3D_THETA_MAX",
                f32s(&[ltc_lab::ltc::aniso::axes::I3D_THETA_MAX]),
            ),
            (
                "I3D_ALPHA_MIN",
                f32s(&[ltc_lab::ltc::aniso::axes::I3D_ALPHA_MIN]),
            ),
            ("TILE_SIDE", vec![TILE_SIDE as f64]),
            ("LOAD", vec![LOAD as f64]),
            ("PI", f32s(&[std::f64::consts::PI])),
            (
                "MIN_LIGHT_DISTANCE",
                f32s(&[ltc_lab::brdf::MIN_LIGHT_DISTANCE]),
            ),
            ("EXACT_BAND_Z", f32s(&[ltc_lab::ltc::remedy::EXACT_BAND_Z])),
            ("NL_BAND_Z", f32s(&[ltc_lab::ltc::nl_fit::NL_BAND_Z])),
            (
                "POINT_LIMIT_SIN_SIGMA",
                f32s(&[ltc_lab::light::sphere::POINT_LIMIT_SIN_SIGMA]),
            ),
            ("F32_EPSILON", vec![f64::from(f32::EPSILON)]),
            (
                "RECT_POINT_LIMIT",
                f32s(&[ltc_lab::light::rect::RECT_POINT_LIMIT]),
            ),
            (
                "DISK_POINT_LIMIT",
                f32s(&[ltc_lab::light::disk::DISK_POINT_LIMIT]),
            ),
            (
                "TUBE_POINT_LIMIT",
                f32s(&[ltc_lab::light::tube::TUBE_POINT_LIMIT]),
            ),
            ("GL8_NODES", half(8, |&(x, _)| x)),
            ("GL8_WEIGHTS", half(8, |&(_, w)| w)),
            ("GL12_NODES", half(12, |&(x, _)| x)),
            ("GL12_WEIGHTS", half(12, |&(_, w)| w)),
            ("GL24_NODES", half(24, |&(x, _)| x)),
            ("GL24_WEIGHTS", half(24, |&(_, w)| w)),
            ("RULE_NODES", vec![polar::RULE_NODES as f64]),
            ("RULE_NODES_ANISO", vec![polar::RULE_NODES_ANISO as f64]),
            ("DIFFUSE_NODES", vec![polar::DIFFUSE_NODES as f64]),
            ("MAX_PLANES", vec![polar::MAX_PLANES as f64]),
            ("MAX_CUTS", vec![polar::MAX_CUTS as f64]),
            (
                "BRIGHTEST_SAMPLES",
                vec![boundary::BRIGHTEST_SAMPLES as f64],
            ),
            ("BRIGHTEST_STEPS", vec![boundary::BRIGHTEST_STEPS as f64]),
            ("PIECE_MIN_WIDTH", f32s(&[polar::PIECE_MIN_WIDTH])),
            ("SAME_DIRECTION", f32s(&[polar::SAME_DIRECTION])),
            ("CORNER_SNAP", f32s(&[boundary::CORNER_SNAP])),
            (
                "DISK_RENDER_NODES",
                vec![ltc_lab::light::disk::RENDER_NODES as f64],
            ),
            ("BACKGROUND", f32s(&background)),
            (
                "METHOD_FILE_STEPS",
                vec![f64::from(ltc_lab::gpu::method_file::STEPS)],
            ),
        ])
        .collect()
}

/// Every constant the shaders and Rust share has one value on both sides, and every constant
/// of the shaders is either shared (and so checked) or listed as the shaders' own: a value
/// changed or a constant added on one side only fails here. The codes the pipelines pass
/// (methods, sphere methods, views, horizon rules) would otherwise shade every pixel with
/// another method.
#[test]
fn the_constants_rust_shares_are_the_wgsl_ones() {
    let modules = [
        validate("plane", &plane_module_source(true)),
        validate("scene.wgsl + bin.wgsl", &bin_module_source()),
        validate("display.wgsl", ltc_lab::gpu::display::SOURCE),
    ];
    let shared = shared_constants();
    let mut found = Vec::new();
    for module in &modules {
        for (_, c) in module.constants.iter() {
            let name = c.name.as_deref().unwrap_or_default();
            if SHADER_ONLY.iter().any(|&(n, _)| n == name) {
                continue;
            }
            let rust = shared
                .iter()
                .find(|(n, _)| *n == name)
                .unwrap_or_else(|| panic!("the WGSL constant {name} has no Rust twin"));
            assert_eq!(constant_value(module, name), rust.1, "{name}");
            found.push(name);
        }
    }
    for (name, _) in &shared {
        assert!(found.contains(name), "Rust's {name} is in no shader");
    }
}
