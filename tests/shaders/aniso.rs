//! The anisotropic shaders' names: brdf_aniso.wgsl and ltc_aniso.wgsl mirror
//! `ltc_lab::brdf::aniso` and `ltc_lab::ltc::aniso` function by function.

use ltc_lab::gpu::plane_module_source;

use crate::{function_names, validate};

/// Anisotropic GGX and the 4D table's lookup carry their Rust names (a method
/// `AnisoAxes::fold` as `aniso_fold`, `AnisoLut::sample` as `aniso_sample`).
#[test]
fn anisotropic_functions_have_the_rust_names() {
    let module = validate("plane", &plane_module_source(false));
    let wgsl = function_names(&module);
    // Each exists in Rust under this name; the `use` fails to compile if one is renamed.
    #[allow(unused_imports)]
    use ltc_lab::brdf::aniso::{
        brdf_cos_aniso, d_ggx_aniso, g2_correlated_aniso, lambda_ggx_aniso, specular_cos_aniso,
    };
    #[allow(unused_imports)]
    use ltc_lab::ltc::aniso::stored::{from_pole_and_shape, turn_z_to};
    #[allow(unused_imports)]
    use ltc_lab::ltc::aniso::{AnisoAxes, AnisoLut, canonical::proper, mirror_frame};
    let _ = (
        AnisoAxes::fold,
        AnisoAxes::coordinates,
        AnisoLut::sample,
        AnisoLut::ltc,
    );
    let _ = ltc_lab::ltc::aniso::Stored::cos_from_brdf;
    for f in [
        "d_ggx_aniso",
        "lambda_ggx_aniso",
        "g2_correlated_aniso",
        "specular_cos_aniso",
        "brdf_cos_aniso",
        "aniso_fold",
        "aniso_coordinates",
        "aniso_sample",
        "aniso_cos_from_brdf",
        "mirror_frame",
        "turn_z_to",
        "from_pole_and_shape",
        "proper",
        "aniso_ltc",
    ] {
        assert!(wgsl.contains(&f), "{f} is missing from the WGSL");
    }
}
