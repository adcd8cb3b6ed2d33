//! The WGSL, without an adapter: naga parses and validates every file (in the order they are
//! composed), the Rust Pod types have the WGSL structs' layout, and the functions mirrored
//! between Rust and WGSL carry the same names.

use ltc_lab::gpu::scene::{GpuLight, Params};
use ltc_lab::gpu::{bin_module_source, brdf, ltc, plane_module_source};

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

#[test]
fn mirrored_functions_have_the_same_names() {
    let module = validate("plane", &plane_module_source(false));
    let wgsl: Vec<&str> = module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.as_deref())
        .collect();
    // Each exists in Rust under this name (src/brdf.rs, src/ltc/mod.rs, src/ltc/lut.rs); the
    // `use` below fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::brdf::{
        d_ggx, diffuse_cos, f_schlick, fd_burley, g2_correlated, irradiance_scale, lambda_ggx,
        specular_cos, v_smith_ggx_correlated, window_falloff_d2,
    };
    #[allow(unused_imports)]
    use ltc_lab::ltc::cos_from_brdf_from_entries;
    // Issue 22's horizon rules and the sampler's taps.
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
