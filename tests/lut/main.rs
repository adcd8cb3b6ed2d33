//! The LUT file and its sampler: bit-exact EXR round trip, cell values at cell centres,
//! GPU-style clamping at the edges, and clear errors for broken files; and the table's
//! encodings (docs/design.md §2.10): storages, formulas, layouts, exports, the 4D table's
//! storage and the presets where encodings fail.

use ltc_lab::ltc::fit::{FitSettings, fit_table};
use ltc_lab::ltc::lut::{Channel, Lut, LutCell};

mod aniso_encoding;
#[path = "../common/mod.rs"]
mod common;
mod encoding_failures;
mod export;
mod formula;
mod layout;

#[test]
fn embedded_lut_is_the_shipped_64x64_table() {
    let lut = Lut::embedded();
    assert_eq!(lut.size, 64);
    let file =
        Lut::read(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("luts/ltc.exr")).unwrap();
    assert_eq!(&file, lut);
}

#[test]
fn exr_round_trip_is_bit_exact() {
    let lut = fit_table(
        &FitSettings {
            size: 4,
            ..FitSettings::default()
        },
        &|| {},
    )
    .lut;
    let back = Lut::from_exr_bytes(&lut.to_exr_bytes(), "memory").unwrap();
    assert_eq!(back.size, lut.size);
    assert_eq!(back.alpha_min.to_bits(), lut.alpha_min.to_bits());
    for (a, b) in lut.cells.iter().zip(&back.cells) {
        assert_eq!(a.0.map(f32::to_bits), b.0.map(f32::to_bits));
    }
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("t.exr");
    lut.write(&path).unwrap();
    assert_eq!(Lut::read(&path).unwrap(), lut);
}

#[test]
fn sampler_returns_cell_values_at_cell_centres() {
    let lut = Lut::embedded();
    for j in 0..lut.size {
        for i in 0..lut.size {
            // The cell's own (α, cos θo) — the sampler's uv lands on the texel centre.
            let cos = 1.0 - (j as f64 / (lut.size - 1) as f64).powi(2);
            let r = i as f64 / (lut.size - 1) as f64;
            let s = lut.sample(r * r, cos);
            let cell = lut.cell(i, j);
            for c in 0..Channel::COUNT {
                let want = f64::from(cell.0[c]);
                // The uv arithmetic rounds (a few ulps of 1.0); the bilinear weight of the
                // neighbour is then ~1e-15, times channel differences of order 1.
                assert!(
                    (s.0[c] - want).abs() <= 1e-12 * want.abs().max(1.0),
                    "cell ({i},{j}) channel {c}"
                );
            }
        }
    }
}

#[test]
fn sampler_interpolates_between_cells_and_clamps_outside() {
    let mut lut = Lut {
        nl_terms: Default::default(),
        aniso: None,
        size: 2,
        alpha_min: 1e-4,
        cells: vec![LutCell([0.0; Channel::COUNT]); 4],
    };
    for (k, v) in [1.0f32, 2.0, 3.0, 5.0].iter().enumerate() {
        lut.cells[k].0[Channel::SpecNorm as usize] = *v;
        // The classic table's scale: the magnitude filtered is the magnitude itself.
        lut.cells[k].0[Channel::SpecScale as usize] = 1.0;
    }
    let at = |u: f64, v: f64| lut.sample_uv(u, v).get(Channel::SpecNorm);
    // Texel centres of a 2×2 texture at 0.25 and 0.75.
    assert_eq!(at(0.25, 0.25), 1.0);
    assert_eq!(at(0.75, 0.75), 5.0);
    assert!((at(0.5, 0.5) - 2.75).abs() < 1e-12);
    assert!((at(0.5, 0.25) - 1.5).abs() < 1e-12);
    // Clamp to edge: anything outside the centres takes the edge texels, as a GPU sampler
    // with ClampToEdge addressing does; out-of-range and non-finite inputs stay in the table.
    assert_eq!(at(-3.0, 0.0), 1.0);
    assert_eq!(at(7.0, 7.0), 5.0);
    assert!(at(f64::NAN, 0.75).is_finite());
    // (α, cos θo) beyond the table map onto its edges.
    assert_eq!(lut.sample(4.0, -1.0), lut.sample(1.0, 0.0));
    assert_eq!(lut.sample(0.0, 2.0), lut.sample(0.0, 1.0));
}

#[test]
fn broken_files_are_refused_with_their_name() {
    let err = Lut::from_exr_bytes(b"not an exr at all", "bad.exr").unwrap_err();
    assert!(err.to_string().starts_with("bad.exr: "), "{err}");

    let mut lut = Lut::embedded().clone();
    lut.cells[70].0[Channel::DiffNorm as usize] = f32::NAN;
    let err = Lut::from_exr_bytes(&lut.to_exr_bytes(), "nan.exr").unwrap_err();
    assert!(
        err.to_string().contains("diff.norm") && err.to_string().contains("i=6, j=1"),
        "{err}"
    );

    let mut lut = Lut::embedded().clone();
    lut.cells[5].0[Channel::SpecM00 as usize] = 0.0;
    lut.cells[5].0[Channel::SpecM02 as usize] = 1.0;
    lut.cells[5].0[Channel::SpecM20 as usize] = 1.0;
    let err = Lut::from_exr_bytes(&lut.to_exr_bytes(), "singular.exr").unwrap_err();
    assert!(err.to_string().contains("determinant"), "{err}");

    let bytes = Lut::embedded().to_exr_bytes();
    let err = Lut::from_exr_bytes(&bytes[..bytes.len() / 2], "cut.exr").unwrap_err();
    assert!(err.to_string().starts_with("cut.exr: "), "{err}");

    let err = Lut::read(std::path::Path::new("/nonexistent/ltc.exr")).unwrap_err();
    assert!(
        err.to_string()
            .starts_with("/nonexistent/ltc.exr: cannot read"),
        "{err}"
    );
}

/// The table's channels but `skip`, as an EXR (what an older or a foreign writer makes).
fn exr_without(lut: &Lut, skip: &str) -> Vec<u8> {
    exr_written(lut, skip, exr::prelude::AttributeValue::F64(lut.alpha_min))
}

/// The table as another writer might make it: without channel `skip`, α_min as `alpha_min`.
fn exr_written(lut: &Lut, skip: &str, alpha_min: exr::prelude::AttributeValue) -> Vec<u8> {
    use exr::prelude::*;
    let channels = Channel::ALL
        .iter()
        .filter(|c| c.name() != skip)
        .map(|&c| {
            AnyChannel::new(
                c.name(),
                FlatSamples::F32(lut.cells.iter().map(|cell| cell.get(c)).collect()),
            )
        })
        .collect();
    let mut attributes = LayerAttributes::named("ltc");
    attributes
        .other
        .insert(Text::from("ltc.alpha_min"), alpha_min);
    let layer = Layer::new(
        (lut.size, lut.size),
        attributes,
        Encoding::default(),
        AnyChannels::sort(channels),
    );
    let mut out = std::io::Cursor::new(Vec::new());
    Image::from_layer(layer)
        .write()
        .to_buffered(&mut out)
        .unwrap();
    out.into_inner()
}

/// docs/design.md §2's 13 channels make a complete table: without `spec.scale` (the point fit's
/// addition) the magnitudes are used as they are; any other missing channel is refused, and a
/// scale that is not positive too.
#[test]
fn design_layout_without_the_scale_reads_with_scale_one() {
    let point = Lut::embedded_point();
    let read = Lut::from_exr_bytes(&exr_without(point, "spec.scale"), "design.exr").unwrap();
    for (a, b) in point.cells.iter().zip(&read.cells) {
        assert_eq!(b.get(Channel::SpecScale), 1.0);
        for c in 0..Channel::COUNT {
            if c != Channel::SpecScale as usize {
                assert_eq!(a.0[c].to_bits(), b.0[c].to_bits());
            }
        }
    }
    let err = Lut::from_exr_bytes(&exr_without(point, "diff.err"), "short.exr").unwrap_err();
    assert!(
        err.to_string()
            .starts_with("short.exr: channel diff.err is missing"),
        "{err}"
    );
    let mut lut = point.clone();
    lut.cells[9].0[Channel::SpecScale as usize] = 0.0;
    let err = Lut::from_exr_bytes(&lut.to_exr_bytes(), "zero.exr").unwrap_err();
    assert!(err.to_string().contains("spec.scale"), "{err}");
}

/// α_min written as f32 (1e-4 is not exactly representable there) reads as that f32 value;
/// out of (0, 1), or not a number, it is refused with the attribute's name.
#[test]
fn alpha_min_may_be_written_as_f32() {
    use exr::prelude::AttributeValue;
    let lut = Lut::embedded();
    let read =
        Lut::from_exr_bytes(&exr_written(lut, "", AttributeValue::F32(1e-4)), "f32.exr").unwrap();
    assert_eq!(read.alpha_min, f64::from(1e-4f32));
    assert_eq!(read.cells, lut.cells);
    for bad in [AttributeValue::F32(0.0), AttributeValue::F64(1.5)] {
        let err = Lut::from_exr_bytes(&exr_written(lut, "", bad), "bad.exr").unwrap_err();
        assert!(err.to_string().contains("ltc.alpha_min"), "{err}");
    }
}

/// The point table's fitted scale is folded into its magnitudes per cell before filtering (as
/// its export in ltc_code's layout stores them), so that both shade the same: between cells
/// the product is interpolated, not the scale and the magnitude apart.
#[test]
fn the_specular_magnitude_is_filtered_as_the_product_of_scale_and_albedo() {
    let mut lut = Lut {
        nl_terms: Default::default(),
        aniso: None,
        size: 2,
        alpha_min: 1e-4,
        cells: vec![LutCell([0.0; Channel::COUNT]); 4],
    };
    let (norms, scales) = ([0.2f32, 0.9, 0.4, 0.8], [1.0f32, 0.5, 0.8, 0.6]);
    for k in 0..4 {
        let cell = &mut lut.cells[k].0;
        for (c, x) in [
            (Channel::SpecM00, 1.0),
            (Channel::SpecM22, 1.0),
            (Channel::DiffM00, 1.0),
            (Channel::DiffM22, 1.0),
            (Channel::SpecNorm, norms[k]),
            (Channel::SpecFresnel, 0.5 * norms[k]),
            (Channel::SpecScale, scales[k]),
        ] {
            cell[c as usize] = x;
        }
    }
    // At the centre every cell weighs 1/4: the mean of the products, computed here in f64.
    let products: f64 = (0..4)
        .map(|k| f64::from(norms[k]) * f64::from(scales[k]))
        .sum::<f64>()
        / 4.0;
    let mean_scale = scales.iter().map(|&s| f64::from(s)).sum::<f64>() / 4.0;
    let mean_norm = norms.iter().map(|&n| f64::from(n)).sum::<f64>() / 4.0;
    assert!(
        (products - mean_scale * mean_norm).abs() > 1e-3,
        "the test must tell the two rules apart"
    );
    let sample = lut.sample_uv(0.5, 0.5);
    let spec = sample.ltc_pair().spec;
    // A handful of f64 roundings (blend, divide, multiply): 1e-15.
    assert!(
        (spec.magnitude() - products).abs() <= 1e-15,
        "{}",
        spec.magnitude()
    );
    assert!((sample.get(Channel::SpecScale) - mean_scale).abs() <= 1e-15);
    assert!((sample.ltc_pair().spec_magnitude(0.0) - 0.5 * products).abs() <= 1e-15);
}

/// A cell's channels are one enum: its order is the cell's (and the file's `--dump` columns),
/// each name is the file's and says the lobe the channel belongs to.
#[test]
fn each_channel_knows_its_place_name_and_lobe() {
    use ltc_lab::ltc::lobe::Lobe;
    let names: Vec<&str> = Channel::ALL.iter().map(|c| c.name()).collect();
    assert_eq!(
        names.join(" "),
        "spec.m00 spec.m02 spec.m20 spec.m22 spec.norm spec.fresnel spec.err \
         diff.m00 diff.m02 diff.m20 diff.m22 diff.norm diff.err spec.scale",
        "docs/design.md §2.4's order"
    );
    for (k, c) in Channel::ALL.into_iter().enumerate() {
        assert_eq!(c as usize, k, "{} is not at its place", c.name());
        let prefix = match c.lobe() {
            Lobe::Specular => "spec.",
            Lobe::Diffuse => "diff.",
        };
        assert!(
            c.name().starts_with(prefix),
            "{} is of the {:?} lobe",
            c.name(),
            c.lobe()
        );
        assert_eq!(c.is_err(), c.name().ends_with(".err"));
    }
}

/// Every encoding's name reads back as itself; a wrong storage or size is refused naming it.
#[test]
fn an_encoding_is_named_as_it_is_read() {
    use ltc_lab::ltc::lut::encoding::SIZES;
    use ltc_lab::ltc::lut::{Encoding, Storage};
    for storage in Storage::ALL {
        for size in SIZES.map(Some).into_iter().chain([None]) {
            let e = Encoding {
                storage,
                size,
                formula: None,
            };
            assert_eq!(Encoding::parse(&e.name()), Ok(e));
        }
    }
    assert!(Encoding::parse("f8").unwrap_err().contains("f8"));
    assert!(Encoding::parse("f16-12").unwrap_err().contains("`12`"));
    assert!(Encoding::parse("f16-").is_err());
}

/// What each storage gives back, value by value, within the bound its format states: f32 is
/// the table itself; f16 rounds each value to 11 significant bits (a relative error of at
/// most 2⁻¹¹, or 2⁻²⁵ absolute among its subnormals); 8 bits over a channel's range
/// `[lo, hi]` round to within half a step, `(hi − lo)/510`; and f32's own rounding of the
/// value, and of it divided by the scale and multiplied back (`LutCell::shaded`), 2⁻²³
/// relative. The classic table's spec.scale is 1; the point table's is not, so the
/// magnitudes' division by it is checked too.
#[test]
fn each_storage_gives_back_its_values_within_its_rounding() {
    use ltc_lab::ltc::lut::{Encoding, Storage, Table};
    for table in [Table::Classic, Table::Point] {
        stored_within_rounding(Lut::shipped(table));
    }
    // Bytes an engine stores: 11 channels of 64² values, and 8-bit tables' ranges.
    assert_eq!(Encoding::default().bytes(64), 64 * 64 * 11 * 4);
    let half32 = Encoding::parse("f16-32").unwrap();
    assert_eq!(half32.bytes(64), 32 * 32 * 11 * 2);
    let byte8 = Encoding {
        storage: Storage::Unorm8,
        size: Some(8),
        formula: None,
    };
    assert_eq!(byte8.bytes(64), 8 * 8 * 11 + 11 * 2 * 4);
    // 10-bit values three to a 4-byte texel: 11 channels in 4 texels.
    let packed = Encoding::parse("unorm10").unwrap();
    assert_eq!(packed.bytes(64), 64 * 64 * 4 * 4 + 11 * 2 * 4);
}

fn stored_within_rounding(lut: &Lut) {
    use ltc_lab::ltc::lut::Encoding;
    use ltc_lab::ltc::lut::encoding::SHADER_CHANNELS;
    let f32_table = Encoding::default().decoded(lut);
    assert_eq!(&f32_table, lut);
    let half = Encoding::parse("f16").unwrap().decoded(lut);
    let byte = Encoding::parse("unorm8").unwrap().decoded(lut);
    let packed = Encoding::parse("unorm10").unwrap().decoded(lut);
    for c in SHADER_CHANNELS {
        let values: Vec<f64> = lut.cells.iter().map(|cell| cell.shaded(c)).collect();
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        for (k, &v) in values.iter().enumerate() {
            let (h, b) = (half.cells[k].shaded(c), byte.cells[k].shaded(c));
            let f32_rounding = 2f64.powi(-23) * v.abs().max(h.abs()).max(b.abs());
            assert!(
                (h - v).abs() <= 2f64.powi(-11) * v.abs() + 2f64.powi(-25) + f32_rounding,
                "f16 {c:?} cell {k}: {v} read back as {h}"
            );
            assert!(
                (b - v).abs() <= (hi - lo) / 510.0 + 2f64.powi(-23) * (hi.abs() + lo.abs()),
                "unorm8 {c:?} cell {k}: {v} read back as {b} over [{lo}, {hi}]"
            );
            let p = packed.cells[k].shaded(c);
            assert!(
                (p - v).abs() <= (hi - lo) / 2046.0 + 2f64.powi(-23) * (hi.abs() + lo.abs()),
                "unorm10 {c:?} cell {k}: {v} read back as {p} over [{lo}, {hi}]"
            );
            assert!(h.is_finite() && b.is_finite() && p.is_finite());
        }
    }
}

/// A table resampled to its own size is itself (each new cell sits on an old one's centre);
/// to a smaller size, each new cell is the old table filtered where the new cell sits, so the
/// corners, which sit on old cells at every size, are kept.
#[test]
fn a_resampled_table_keeps_the_cells_it_lands_on() {
    use ltc_lab::ltc::lut::encoding::resampled;
    let lut = Lut::embedded();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-6 * a.abs().max(b.abs()).max(1e-30);
    let same = resampled(lut, lut.size);
    for (a, b) in lut.cells.iter().zip(&same.cells) {
        for c in Channel::ALL {
            assert!(close(a.shaded(c), b.shaded(c)), "{c:?}: {a:?} {b:?}");
        }
    }
    // 8 cells a side land on every ninth of the 64 (63 = 7 × 9): every cell is an old one,
    // within f32's rounding of the magnitudes divided by the scale and back (2⁻²³ relative).
    let eight = resampled(lut, 8);
    for (i, j) in (0..8).flat_map(|j| (0..8).map(move |i| (i, j))) {
        for c in Channel::ALL {
            let (a, b) = (lut.cell(9 * i, 9 * j).shaded(c), eight.cell(i, j).shaded(c));
            let bound = 2f64.powi(-23) * a.abs();
            assert!((a - b).abs() <= bound, "8² ({i}, {j}) {c:?}: {a} {b}");
        }
    }
    for size in [32, 16, 8] {
        let small = resampled(lut, size);
        assert_eq!((small.size, small.cells.len()), (size, size * size));
        let last = lut.size - 1;
        for (i, j) in [(0, 0), (size - 1, 0), (0, size - 1), (size - 1, size - 1)] {
            let (oi, oj) = (i * last / (size - 1), j * last / (size - 1));
            for c in Channel::ALL {
                let (a, b) = (lut.cell(oi, oj).shaded(c), small.cell(i, j).shaded(c));
                assert!(close(a, b), "{size}² corner ({i}, {j}) {c:?}: {a} {b}");
            }
        }
    }
}
