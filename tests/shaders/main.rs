//! The WGSL, without an adapter: naga parses and validates every file (in the order they are
//! composed), the Rust Pod types have the WGSL structs' layout, the functions mirrored
//! between Rust and WGSL carry the same names, and the constants and bindings Rust writes
//! for the shaders are the WGSL's.

use ltc_lab::gpu::scene::{GpuLight, Params};
use ltc_lab::gpu::{
    bin_module_source, brdf, brdf_aniso, ltc, ltc_aniso, plane_module_source, sphere_light,
};

mod aniso;

/// brdf.wgsl and brdf_aniso.wgsl, which every later file builds on (the exact lobes of either
/// material: `exact_lobes`).
fn brdf_sources() -> String {
    [brdf::SOURCE, brdf_aniso::SOURCE].join("\n")
}

fn validate(name: &str, src: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(src)
        .unwrap_or_else(|e| panic!("{name} does not parse:\n{}", e.emit_to_string(src)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{name} does not validate:\n{}", e.emit_to_string(src)));
    module
}

#[test]
fn every_wgsl_file_validates() {
    validate("brdf.wgsl", brdf::SOURCE);
    validate("brdf.wgsl + brdf_aniso.wgsl", &brdf_sources());
    validate(
        "brdf.wgsl + brdf_aniso.wgsl + ltc.wgsl",
        &[&brdf_sources(), ltc::SOURCE].join("\n"),
    );
    for f16 in [false, true] {
        let module = validate(
            &format!("brdf.wgsl + ltc.wgsl + scene.wgsl + plane.wgsl (f16: {f16})"),
            &plane_module_source(f16),
        );
        for entry in ["shade", "reduce", "floor_of_means", "resolve"] {
            assert!(
                module.entry_points.iter().any(|e| e.name == entry),
                "{entry}"
            );
        }
    }
    validate(
        "brdf.wgsl + brdf_aniso.wgsl + ltc.wgsl + sphere_light.wgsl",
        &[&brdf_sources(), ltc::SOURCE, sphere_light::SOURCE].join("\n"),
    );
    let module = validate("scene.wgsl + bin.wgsl", &bin_module_source());
    for entry in ["bin_count", "bin_scan", "bin_write"] {
        assert!(
            module.entry_points.iter().any(|e| e.name == entry),
            "{entry}"
        );
    }
}

/// `(member name, byte offset)` of a WGSL struct, and its size, as naga lays it out.
fn wgsl_layout(module: &naga::Module, name: &str) -> (Vec<(String, u32)>, u32) {
    let ty = module
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no struct {name}"))
        .1;
    match &ty.inner {
        naga::TypeInner::Struct { members, span } => (
            members
                .iter()
                .map(|m| (m.name.clone().unwrap(), m.offset))
                .collect(),
            *span,
        ),
        other => panic!("{name} is {other:?}"),
    }
}

macro_rules! rust_layout {
    ($t:ty, $($field:ident),*) => {
        (vec![$((stringify!($field).to_string(), std::mem::offset_of!($t, $field) as u32)),*],
         std::mem::size_of::<$t>() as u32)
    };
}

#[test]
fn pod_types_match_the_wgsl_structs() {
    let module = validate("plane", &plane_module_source(false));
    assert_eq!(
        rust_layout!(
            Params,
            eye,
            forward,
            right,
            up,
            base_color,
            alpha,
            f0,
            tan_half_fov,
            aspect,
            half_size,
            divider,
            probe_x,
            probe_y,
            width,
            height,
            light_count,
            lut_size,
            clip,
            normalization,
            tiles_x,
            tiles_y,
            light_start,
            light_end,
            cull,
            tile_capacity,
            lut_size_b,
            lut_base_b,
            lut_base,
            bin_row,
            alpha_y,
            tangent_x,
            tangent_y,
            aniso_pad,
            aniso_a,
            aniso_dims_a,
            aniso_b,
            aniso_dims_b
        ),
        wgsl_layout(&module, "Params")
    );
    assert_eq!(
        rust_layout!(GpuLight, position_range, intensity),
        wgsl_layout(&module, "GpuLight")
    );
}

/// The names of a module's functions.
fn function_names(module: &naga::Module) -> Vec<&str> {
    module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.as_deref())
        .collect()
}

#[test]
fn mirrored_functions_have_the_same_names() {
    let module = validate("plane", &plane_module_source(false));
    let wgsl = function_names(&module);
    // Each exists in Rust under this name (src/brdf/mod.rs, src/ltc/mod.rs, src/ltc/lut/); the
    // `use` below fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::brdf::{
        d_ggx, diffuse_cos, f_schlick, fd_burley, g2_correlated, irradiance_scale, lambda_ggx,
        specular_cos, v_smith_ggx_correlated, window_falloff_d2,
    };
    #[allow(unused_imports)]
    use ltc_lab::ltc::cos_from_brdf_from_entries;
    // The horizon rules and the sampler's taps.
    #[allow(unused_imports)]
    use ltc_lab::ltc::{
        lut::bilinear_taps,
        nl_fit::{nl_sample_nearest, nl_sample_uv, nl_weight},
        remedy::in_exact_band,
    };
    for f in [
        "d_ggx",
        "lambda_ggx",
        "g2_correlated",
        "f_schlick",
        "fd_burley",
        "specular_cos",
        "diffuse_cos",
        "irradiance_scale",
        "window_falloff_d2",
        "v_smith_ggx_correlated",
        "ltc_eval",
        "cos_from_brdf_from_entries",
        "lut_sample_uv",
        "lut_uv",
        "spec_magnitude",
        "surface_point",
        "camera_ray",
        "luminance",
        "bilinear_taps",
        "nl_sample_uv",
        "nl_sample_nearest",
        "nl_weight",
        "in_exact_band",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}

/// The sphere lights' functions carry their Rust names (a method `Cap::f` as `cap_f`).
#[test]
fn sphere_light_functions_have_the_rust_names() {
    let source = [&brdf_sources(), ltc::SOURCE, sphere_light::SOURCE].join("\n");
    let module = validate("sphere_light", &source);
    let wgsl = function_names(&module);
    // Each exists in Rust under this name; the `use` fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::light::sphere::quadrature::visible_half_azimuth;
    #[allow(unused_imports)]
    use ltc_lab::light::sphere::{
        cap::Cap,
        disk::{ltc_disk, negative_eigenvalue, transformed_cone},
    };
    #[allow(unused_imports)]
    use ltc_lab::light::sphere::{
        fd_toward, mirror, sphere_exact, sphere_ltc_disk, sphere_point, sphere_radiance,
        sphere_representative_point,
    };
    #[allow(unused_imports)]
    use ltc_lab::ltc::sphere::illuminance_sphere;
    let _ = (
        Cap::of_sphere,
        Cap::encloses,
        Cap::below_horizon,
        Cap::illuminance,
    );
    for f in [
        "cap_of_sphere",
        "cap_encloses",
        "cap_below_horizon",
        "cap_illuminance",
        "illuminance_sphere",
        "negative_eigenvalue",
        "transformed_cone",
        "ltc_disk",
        "sphere_radiance",
        "sphere_ltc_disk",
        "sphere_representative_point",
        "fd_toward",
        "sphere_exact",
        "sphere_point",
        "visible_half_azimuth",
        "mirror",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}

/// The disk lights' functions carry their Rust names (a method `Disk::f` as `disk_f`,
/// `Segment::f` as `segment_f`).
#[test]
fn disk_light_functions_have_the_rust_names() {
    use ltc_lab::gpu::{disk_light, rect_light};
    let source = [
        &brdf_sources(),
        ltc::SOURCE,
        sphere_light::SOURCE,
        rect_light::SOURCE,
        disk_light::SOURCE,
        // The method codes plane.wgsl defines.
        "const RECT_EXACT: u32 = 0u; const RECT_LTC_POLYGON: u32 = 1u; const RECT_LTC_PROXY: u32 = 2u; const RECT_LTC_PROXY_FAST: u32 = 3u; const DISK_EXACT: u32 = 0u; const DISK_LTC_DISK: u32 = 1u;",
    ]
    .join("\n");
    let module = validate("disk_light", &source);
    let wgsl = function_names(&module);
    // Each exists in Rust under this name; the `use` fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::light::disk::quadrature::Segment;
    #[allow(unused_imports)]
    use ltc_lab::light::disk::{
        Disk, disk_exact, disk_light, disk_ltc, disk_point, ltc_disk_light,
    };
    #[allow(unused_imports)]
    use ltc_lab::light::sphere::disk::{cone_image, cone_integral, hemisphere};
    let _ = (
        Disk::area,
        Disk::faces_origin,
        Disk::angular_size,
        Disk::below_horizon,
        Disk::point_irradiance,
        Disk::half_axes,
        Segment::above,
        Segment::point,
        Segment::hit_inside,
        Segment::pieces,
        Segment::reach,
    );
    for f in [
        "disk_area",
        "disk_faces_origin",
        "disk_angular_size",
        "disk_below_horizon",
        "disk_point_irradiance",
        "disk_half_axes",
        "segment_above",
        "segment_point",
        "segment_hit_inside",
        "segment_pieces",
        "segment_reach",
        "disk_point",
        "disk_exact",
        "disk_ltc",
        "ltc_disk_light",
        "disk_light",
        "cone_image",
        "cone_integral",
        "hemisphere",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}

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
const SHADER_ONLY: [(&str, &str); 6] = [
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
    // plane.wgsl's largest finite f32, the floor of an empty min.
    ("F32_MAX", "a bound inside plane.wgsl"),
];

/// Every constant the WGSL and Rust share, as Rust has it: `(name in the WGSL, value)`.
fn shared_constants() -> Vec<(&'static str, Vec<f64>)> {
    use ltc_lab::gpu::light_shape::{disk_constant, rect_constant, sphere_constant};
    use ltc_lab::gpu::limits::LOAD;
    use ltc_lab::gpu::ltc::{
        CLIP_HORIZON, CLIP_TRANSFORMED, LUT_VEC4S_PER_CELL, horizon_constant,
        normalization_constant,
    };
    use ltc_lab::gpu::plane::{ViewConstant, method_constant};
    use ltc_lab::gpu::scene::TILE_SIDE;
    use ltc_lab::light::Shape;
    use ltc_lab::light::sphere::SphereMethod;
    use ltc_lab::ltc::Normalization;
    use ltc_lab::ltc::remedy::HorizonRule;
    use ltc_lab::render::Method;
    // A WGSL f32 literal holds the Rust f64 rounded to f32: compare in that rounding.
    let f32s = |v: &[f64]| v.iter().map(|&x| f64::from(x as f32)).collect::<Vec<_>>();
    let codes = Method::ALL
        .map(method_constant)
        .into_iter()
        .chain(SphereMethod::ALL.map(sphere_constant))
        .chain(ltc_lab::light::rect::RectMethod::ALL.map(rect_constant))
        .chain(ltc_lab::light::disk::DiskMethod::ALL.map(disk_constant))
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
        .chain(
            [
                Shape::Point,
                Shape::Sphere { radius: 1.0 },
                Shape::Rect {
                    half_u: glam::DVec3::X,
                    half_v: glam::DVec3::Y,
                },
                Shape::Disk {
                    normal: glam::DVec3::Z,
                    radius: 1.0,
                },
            ]
            .map(ltc_lab::gpu::scene::shape_constant),
        )
        .chain([
            (CLIP_HORIZON, "CLIP_HORIZON"),
            (CLIP_TRANSFORMED, "CLIP_TRANSFORMED"),
        ])
        .chain(ltc_lab::ltc::aniso::AnisoAxes::ALL.map(ltc_aniso::axes_constant))
        .chain(ltc_lab::ltc::aniso::Stored::ALL.map(ltc_aniso::stored_constant))
        .map(|(value, name)| (name, vec![f64::from(value)]));
    // The positive half of the 8-point rule in increasing order, as sphere_light.wgsl's
    // `gl8` unfolds it.
    let mut gl8 = ltc_lab::light::sphere::quadrature::gauss_legendre(8);
    gl8.retain(|&(x, _)| x > 0.0);
    gl8.sort_by(|a, b| a.0.total_cmp(&b.0));
    let half = |pick: fn(&(f64, f64)) -> f64| f32s(&gl8.iter().map(pick).collect::<Vec<_>>());
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
            ("GL8_NODES", half(|&(x, _)| x)),
            ("GL8_WEIGHTS", half(|&(_, w)| w)),
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

/// What a WGSL global bound in group 0 is, in `binding::Kind`'s terms.
fn kind_of(module: &naga::Module, var: &naga::GlobalVariable) -> ltc_lab::gpu::binding::Kind {
    use ltc_lab::gpu::binding::Kind;
    match (var.space, &module.types[var.ty].inner) {
        (naga::AddressSpace::Uniform, _) => Kind::Uniform,
        (naga::AddressSpace::Storage { access }, _)
            if access.contains(naga::StorageAccess::STORE) =>
        {
            Kind::ReadWrite
        }
        (naga::AddressSpace::Storage { .. }, _) => Kind::Read,
        (_, naga::TypeInner::Image { class, .. }) => match class {
            naga::ImageClass::Storage { format, .. } => Kind::WrittenTexture(match format {
                naga::StorageFormat::Rgba32Float => wgpu::TextureFormat::Rgba32Float,
                naga::StorageFormat::Rgba8Unorm => wgpu::TextureFormat::Rgba8Unorm,
                other => panic!("a storage texture of {other:?}"),
            }),
            _ => Kind::Texture,
        },
        other => panic!("{:?} is bound as {other:?}", var.name),
    }
}

/// Each shader module's bindings as Rust lists them (and makes its layout and bind groups
/// from) are exactly the WGSL's: the same numbers, variables and kinds, none missing.
#[test]
fn the_bindings_rust_lists_are_the_wgsl_ones() {
    use ltc_lab::gpu::binding::Binding;
    use ltc_lab::gpu::{bin, display, plane};
    let modules: [(&str, String, &[Binding]); 4] = [
        ("plane", plane_module_source(false), &plane::BINDINGS),
        (
            "plane with f16",
            plane_module_source(true),
            &plane::BINDINGS,
        ),
        ("bin", bin_module_source(), &bin::BINDINGS),
        ("display", display::SOURCE.to_string(), &display::BINDINGS),
    ];
    for (name, src, listed) in modules {
        let module = validate(name, &src);
        let mut wgsl: Vec<Binding> = module
            .global_variables
            .iter()
            .filter_map(|(_, v)| {
                let b = v.binding.as_ref()?;
                assert_eq!(b.group, 0, "{name}: {:?} is not in group 0", v.name);
                let var = v.name.clone().unwrap_or_default();
                let listed_name = listed
                    .iter()
                    .find(|l| l.name == var)
                    .unwrap_or_else(|| panic!("{name}: Rust does not list {var}"))
                    .name;
                Some(Binding {
                    number: b.binding,
                    name: listed_name,
                    kind: kind_of(&module, v),
                })
            })
            .collect();
        wgsl.sort_by_key(|b| b.number);
        let mut rust = listed.to_vec();
        rust.sort_by_key(|b| b.number);
        assert_eq!(rust, wgsl, "{name}");
    }
}

/// Every repository path that a shader's, a source file's or a document's text names
/// (`src/…rs`, `shaders/…wgsl`, `tests/…rs`, `docs/…md`) exists: a file moved without its
/// mentions fails here instead of leaving a reader at a dead end.
#[test]
fn every_path_the_comments_name_exists() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut texts = vec![root.join("README.md")];
    let mut dirs = vec![
        root.join("src"),
        root.join("shaders"),
        root.join("docs"),
        root.join("tests"),
    ];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path
                .extension()
                .is_some_and(|e| e == "rs" || e == "wgsl" || e == "md")
            {
                texts.push(path);
            }
        }
    }
    let mut missing = Vec::new();
    for file in &texts {
        let text = std::fs::read_to_string(file).unwrap();
        for (at, _) in text.match_indices(['s', 't', 'd']) {
            let rest = &text[at..];
            let Some(prefix) = ["src/", "shaders/", "tests/", "docs/"]
                .into_iter()
                .find(|p| rest.starts_with(p))
            else {
                continue;
            };
            // Only a path that starts a word (not `gpu_tests/…`, not inside another path).
            if at > 0 {
                let before = text[..at].chars().next_back().unwrap();
                if before.is_alphanumeric() || "_/.-".contains(before) {
                    continue;
                }
            }
            let len = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || "_/.-".contains(c)))
                .unwrap_or(rest.len());
            let path = rest[..len].trim_end_matches('.');
            let named_file = [".rs", ".wgsl", ".md"].iter().any(|e| path.ends_with(e));
            if path.len() > prefix.len() && named_file && !root.join(path).exists() {
                missing.push(format!(
                    "{}: {path}",
                    file.strip_prefix(root).unwrap().display()
                ));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "paths that do not exist:\n{}",
        missing.join("\n")
    );
}
