//! The WGSL, without an adapter: naga parses and validates every file (in the order they are
//! composed), the Rust Pod types have the WGSL structs' layout, the functions mirrored
//! between Rust and WGSL carry the same names, and the constants and bindings Rust writes
//! for the shaders are the WGSL's.

use ltc_lab::gpu::scene::{GpuLight, Params};
use ltc_lab::gpu::{bin_module_source, brdf, ltc, plane_module_source, sphere_light};

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
    validate(
        "brdf.wgsl + ltc.wgsl",
        &[brdf::SOURCE, ltc::SOURCE].join("\n"),
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
        "brdf.wgsl + ltc.wgsl + sphere_light.wgsl",
        &[brdf::SOURCE, ltc::SOURCE, sphere_light::SOURCE].join("\n"),
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
            _pad0,
            _pad1,
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
            bin_row
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
    // Each exists in Rust under this name (src/brdf.rs, src/ltc/mod.rs, src/ltc/lut.rs); the
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
    let source = [brdf::SOURCE, ltc::SOURCE, sphere_light::SOURCE].join("\n");
    let module = validate("sphere_light", &source);
    let wgsl = function_names(&module);
    // Each exists in Rust under this name; the `use` fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::ltc::{
        disk::{ltc_disk, negative_eigenvalue, transformed_cone},
        sphere::{Cap, illuminance_sphere},
    };
    #[allow(unused_imports)]
    use ltc_lab::quadrature::visible_half_azimuth;
    #[allow(unused_imports)]
    use ltc_lab::sphere_light::{
        fd_toward, mirror, sphere_exact, sphere_ltc_disk, sphere_radiance,
        sphere_representative_point,
    };
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
        "visible_half_azimuth",
        "mirror",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}

/// The value of the WGSL constant `name` (a `u32`).
fn constant(module: &naga::Module, name: &str) -> u32 {
    let (_, c) = module
        .constants
        .iter()
        .find(|(_, c)| c.name.as_deref() == Some(name))
        .unwrap_or_else(|| panic!("no constant {name} in the WGSL"));
    match module.global_expressions[c.init] {
        naga::Expression::Literal(naga::Literal::U32(v)) => v,
        ref other => panic!("{name} is {other:?}, not a u32 literal"),
    }
}

/// The pipelines' override constants and uniforms name the methods, sphere methods, views and
/// horizon rules by the values plane.wgsl and ltc.wgsl give them: a constant renumbered on one
/// side only would shade every pixel with another method.
#[test]
fn the_constants_rust_passes_are_the_wgsl_ones() {
    use ltc_lab::gpu::ltc::horizon_constant;
    use ltc_lab::gpu::plane::{ViewConstant, method_constant, sphere_constant};
    use ltc_lab::ltc::remedy::HorizonRule;
    use ltc_lab::render::Method;
    let module = validate("plane", &plane_module_source(true));
    let mut checked = Vec::new();
    let methods = Method::ALL.map(method_constant);
    let spheres = ltc_lab::sphere_light::SphereMethod::ALL.map(sphere_constant);
    let views = ViewConstant::ALL.map(ViewConstant::constant);
    let rules = [
        HorizonRule::Eq30,
        HorizonRule::NlFit,
        HorizonRule::ExactBand,
    ]
    .map(horizon_constant);
    for (value, name) in methods.into_iter().chain(spheres).chain(views).chain(rules) {
        assert_eq!(constant(&module, name), value, "{name}");
        checked.push(name);
    }
    // Every such constant of the WGSL has its Rust twin.
    for (_, c) in module.constants.iter() {
        let name = c.name.as_deref().unwrap_or_default();
        let family = ["METHOD_", "SPHERE_", "VIEW_", "HORIZON_"];
        if family.iter().any(|f| name.starts_with(f)) {
            assert!(checked.contains(&name), "{name} has no Rust twin");
        }
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
