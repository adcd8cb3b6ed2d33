//! The functions mirrored between Rust and WGSL carry the same names (docs/design.md §5.1):
//! the BRDF's and the LTC's, the sphere light's and the disk light's.

use ltc_lab::gpu::plane_module_source;

use crate::{function_names, lights_source, validate};

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
    let module = validate("sphere_light", &lights_source());
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
        fd_toward, mirror, region::cap_polar, region::cap_rule, sphere_ltc_disk, sphere_point,
        sphere_radiance, sphere_representative_point, sphere_rule,
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
        "sphere_rule",
        "cap_rule",
        "cap_polar",
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
    let module = validate("disk_light", &lights_source());
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

/// tube_light.wgsl's and tube_band.wgsl's functions carry the Rust names of `light::tube` (a method `Tube::f` as
/// `tube_f`, `Band::f` as `band_f`).
#[test]
fn tube_light_functions_have_the_rust_names() {
    let module = validate("tube_light", &lights_source());
    let wgsl = function_names(&module);
    // Each exists in Rust under this name; the `use` fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::light::tube::band::{Band, band_integral, tube_band};
    #[allow(unused_imports)]
    use ltc_lab::light::tube::line::{
        clip_segment, diffuse_line, line_irradiance, ltc_line, tube_ltc_line,
    };
    #[allow(unused_imports)]
    use ltc_lab::light::tube::{
        Tube, ray_distance2, tube_light, tube_point, tube_representative_point,
    };
    let _ = (
        Tube::length,
        Tube::axis,
        Tube::centre,
        Tube::area,
        Tube::projected_area,
        Tube::nearest_to_ray,
        Tube::distance_to_segment,
        Tube::encloses_origin,
        Tube::below_horizon,
        Tube::angular_size,
        Band::of,
        Band::hemisphere,
        Band::along,
        Band::longitude,
        Band::half_width,
        Band::cuts,
    );
    for f in [
        "tube_length",
        "tube_axis",
        "tube_centre",
        "tube_area",
        "tube_projected_area",
        "tube_nearest_to_ray",
        "tube_distance_to_segment",
        "tube_encloses_origin",
        "tube_below_horizon",
        "tube_angular_size",
        "ray_distance2",
        "band_of",
        "band_hemisphere",
        "band_along",
        "band_longitude",
        "band_half_width",
        "band_cuts",
        "band_integral",
        "tube_band",
        "clip_segment",
        "diffuse_line",
        "ltc_line",
        "line_irradiance",
        "tube_ltc_line",
        "tube_point",
        "tube_representative_point",
        "tube_light",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}

/// The renders' exact rule carries its Rust names in polar.wgsl, boundary.wgsl, fan.wgsl and the shapes'
/// files (a
/// method `Bounds::f` as `bounds_f`, `Lobe::f` as `lobe_f`, `Polar::f` as `polar_f`, `Arc::f`
/// as `arc_f`).
#[test]
fn exact_rule_functions_have_the_rust_names() {
    let module = validate("plane", &plane_module_source(false));
    let wgsl = function_names(&module);
    // Each exists in Rust under this name; the `use` fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::light::boundary::{Arc, brightest};
    #[allow(unused_imports)]
    use ltc_lab::light::fan::fan_integral;
    #[allow(unused_imports)]
    use ltc_lab::light::polar::{
        Bounds, Lobe, Polar, cap_meridian, mirror, plane_meridian, rule, rule_nodes, toward,
    };
    #[allow(unused_imports)]
    use ltc_lab::light::rect::region::{polygon_polar, rect_rule};
    let _ = (
        Bounds::above,
        Bounds::push,
        Bounds::contains,
        Bounds::meridian,
        Lobe::round,
        Lobe::specular,
        Lobe::within::<Bounds>,
        Polar::<Bounds>::new,
        Polar::<Bounds>::cut_toward,
        Polar::<Bounds>::cut_both,
        Arc::at,
        Arc::tangent,
    );
    for f in [
        "bounds_above",
        "bounds_push",
        "bounds_contains",
        "bounds_meridian",
        "plane_meridian",
        "cap_meridian",
        "lobe_round",
        "lobe_specular",
        "lobe_within",
        "polar_new",
        "polar_cut_toward",
        "polar_cut_both",
        "polar_integral",
        "arc_at",
        "arc_tangent",
        "brightest",
        "fan_integral",
        "rule",
        "rule_nodes",
        "toward",
        "mirror",
        "rect_rule",
        "polygon_polar",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}
