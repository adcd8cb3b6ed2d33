//! Where an encoding fails, a preset shows it (docs/design.md §2.10): on each of
//! `ENCODING_FAILURES`' presets, the failing encoding changes the CPU render of the f32 table
//! by more than 1% relative RMSE, and by more than ten times what half floats change there, so
//! the failure is the encoding's and not the scene's.

use ltc_lab::cpu::render;
use ltc_lab::ltc::lut::{Encoding, Lut};
use ltc_lab::metrics::image_error;
use ltc_lab::render::{Method, RenderSettings};
use ltc_lab::scene::{ENCODING_FAILURES, TABLE_PRESETS, preset};

/// `preset` rendered on the CPU with `lut` by the LTC, at the size of the README's figures.
fn frame(name: &str, lut: &Lut) -> ltc_lab::render::Frame {
    render(
        &preset(name),
        lut,
        &RenderSettings::single(160, 90, Method::Ltc),
    )
}

/// The relative RMSE `encoding` adds to the f32 table's render of `name`.
fn added(name: &str, encoding: &str) -> f64 {
    let lut = Lut::embedded();
    let decoded = Encoding::parse(encoding).unwrap().decoded(lut);
    image_error(&frame(name, &decoded), &frame(name, lut)).rel_rmse
}

#[test]
fn each_failure_preset_shows_its_encodings_failure() {
    for f in ENCODING_FAILURES {
        assert!(TABLE_PRESETS.iter().any(|(n, _)| *n == f.preset), "{f:?}");
        let failing = added(f.preset, f.encoding);
        // f16 rounds each value by at most 2⁻¹¹ of itself (0.05%); a near-mirror lobe's
        // value moves by up to four times its matrix's relative change (D goes as
        // 1/|M⁻¹ l|⁴), so 0.2% bounds what half floats change here.
        let half = added(f.preset, "f16");
        assert!(half <= 2e-3, "{}: f16 adds {half}", f.preset);
        assert!(
            failing > 1e-2 && failing > 10.0 * half,
            "{} on {}: adds {failing}, f16 {half}",
            f.encoding,
            f.preset
        );
    }
}
