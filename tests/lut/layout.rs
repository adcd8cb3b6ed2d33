//! What a lookup costs in each layout (docs/design.md §2.10), counted from the formats'
//! own sizes: RGBA texels of four values, RGB10A2 of three; 11 shader channels a cell.

use ltc_lab::ltc::lut::Encoding;
use ltc_lab::ltc::lut::layout::{Layout, layout_csv};

fn cost(name: &str, layout: Layout) -> Option<ltc_lab::ltc::lut::layout::LookupCost> {
    layout.cost(&Encoding::parse(name).unwrap(), 64)
}

#[test]
fn each_layout_counts_its_textures_samplers_and_fetches() {
    // ltc_code's layout widened to both lobes: specular M⁻¹, magnitudes, diffuse M⁻¹.
    let two = cost("f16", Layout::TwoTexture).unwrap();
    assert_eq!((two.textures, two.samplers, two.fetches), (3, 3, 3));
    assert_eq!(two.texture_bytes, 64 * 64 * 3 * 8);
    // The fewest samplers: one texture array, one sampler, the same three fetches.
    let fewest = cost("f16", Layout::Fewest).unwrap();
    assert_eq!(
        (fewest.textures, fewest.samplers, fewest.fetches),
        (1, 1, 3)
    );
    // RGB10A2 holds three values: 11 channels are four texels packed, five kept in groups.
    let packed = cost("unorm10", Layout::Fewest).unwrap();
    assert_eq!((packed.fetches, packed.texture_bytes), (4, 64 * 64 * 4 * 4));
    assert_eq!(cost("unorm10", Layout::TwoTexture).unwrap().textures, 5);
    // Fixed point costs a scale and a bias a channel after the fetches; floats none.
    let unorm = cost("unorm8-16", Layout::Fewest).unwrap();
    assert_eq!(unorm.multiply_adds, fewest.multiply_adds + 11);
    assert_eq!(unorm.texture_bytes, 16 * 16 * 3 * 4);
    // A table has no per-lookup form; a formula has, with no texture and its arithmetic.
    assert_eq!(cost("f32", Layout::PerLookup), None);
    let formula = cost("cheb16", Layout::PerLookup).unwrap();
    assert_eq!(
        (formula.textures, formula.samplers, formula.fetches),
        (0, 0, 0)
    );
    assert!(formula.multiply_adds >= 11 * 17 * 17);
    // A formula rebuilt into a texture ships its coefficients, holds the table's texels.
    let rebuilt = cost("cheb16-f16", Layout::Fewest).unwrap();
    assert_eq!(rebuilt.shipped_bytes, 4 * 11 * 17 * 17 + 11 * 2 * 4);
    assert_eq!(rebuilt.texture_bytes, fewest.texture_bytes);
}

#[test]
fn the_layouts_csv_has_a_row_per_encoding_and_layout_it_goes_with() {
    let mut encodings = Encoding::tables(64);
    encodings.push(Encoding::parse("cheb16").unwrap());
    let csv = layout_csv(&encodings, 64);
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    // 16 tables in two layouts each, the formula in three.
    assert_eq!(rows.len(), 16 * 2 + 3);
    assert!(rows.iter().all(|r| r.len() == 8));
    let f32_fewest = rows
        .iter()
        .find(|r| r[0] == "f32" && r[1] == "fewest")
        .unwrap();
    assert_eq!(f32_fewest[2..], ["180224", "196608", "1", "1", "3", "4"]);
}
