//! The 4D table in an encoding's storage (docs/design.md §2.10): f32 is the table itself, a
//! half float each value within half a step of f16, a fixed-point value within half a step of
//! its channel's range; the grid is the table's own whatever the encoding's size; and where
//! fixed point breaks the table (nodes no longer a proper lobe), that is counted.

use ltc_lab::ltc::aniso::AnisoLut;
use ltc_lab::ltc::aniso::encoded::{NODE_VALUES, bytes, improper_nodes, stored_in};
use ltc_lab::ltc::lut::{Encoding, Lut, Storage};

/// A node's values as `stored_in` reads them: the stored matrix's nine, then the magnitudes.
fn values(t: &AnisoLut) -> Vec<[f64; NODE_VALUES]> {
    t.cells
        .iter()
        .map(|c| {
            let mut v = [0.0; NODE_VALUES];
            for (k, x) in c.m.iter().chain([&c.norm, &c.fresnel]).enumerate() {
                v[k] = f64::from(*x);
            }
            v
        })
        .collect()
}

#[test]
fn each_storage_gives_back_the_4d_table_within_its_rounding() {
    let table = AnisoLut::shipped();
    assert_eq!(&stored_in(table, Storage::F32), table);
    let original = values(table);
    for storage in [Storage::F16, Storage::Unorm8, Storage::Unorm10] {
        let back = values(&stored_in(table, storage));
        for k in 0..NODE_VALUES {
            let column: Vec<f64> = original.iter().map(|v| v[k]).collect();
            let (lo, hi) = column
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
                    (l.min(x), h.max(x))
                });
            for (node, (a, b)) in column.iter().zip(back.iter().map(|v| v[k])).enumerate() {
                // Half a step of the storage, and f32's own rounding of the value read back
                // (2⁻²⁴ relative): f16's step is 2⁻¹⁰ of the value's binade (relative 2⁻¹¹
                // of the value, or its subnormal step 2⁻²⁴); fixed point's is the range over
                // its steps.
                let half_step = match storage.steps() {
                    None => (a.abs() * 2f64.powi(-11)).max(2f64.powi(-25)),
                    Some(steps) => 0.5 * (hi - lo) / steps,
                };
                let tolerance = half_step + 2f64.powi(-24) * a.abs().max(lo.abs().max(hi.abs()));
                assert!(
                    (a - b).abs() <= tolerance,
                    "{} node {node} value {k}: {a} read back as {b}",
                    storage.name()
                );
            }
        }
    }
}

#[test]
fn the_4d_table_takes_the_storage_and_keeps_its_grid() {
    let lut = Lut::embedded();
    let shipped = lut.aniso();
    // A size and a formula are the 2D table's: in f32, the 4D table is untouched.
    for name in ["f32-16", "cheb16"] {
        let e = Encoding::parse(name).unwrap();
        assert_eq!(e.decoded(lut).aniso(), shipped, "{name}");
    }
    for name in ["f16", "f16-8", "cheb16-f16", "unorm8-32"] {
        let e = Encoding::parse(name).unwrap();
        let decoded = e.decoded(lut);
        assert_eq!(decoded.aniso().dims, shipped.dims, "{name}");
        assert_eq!(*decoded.aniso(), stored_in(shipped, e.storage), "{name}");
    }
    let nodes: usize = shipped.dims.iter().product();
    assert_eq!(bytes(shipped.dims, Storage::F32), nodes * NODE_VALUES * 4);
    assert_eq!(bytes(shipped.dims, Storage::F16), nodes * NODE_VALUES * 2);
    // Fixed point: the values, and a scale and a bias (f32) per value.
    assert_eq!(
        bytes(shipped.dims, Storage::Unorm8),
        nodes * NODE_VALUES + NODE_VALUES * 8
    );
}

/// Where fixed point breaks the 4D table, and f16 does not: the shipped table's nodes are all
/// proper lobes (its file is checked on reading), half floats keep every one, and 8 bits
/// round the smallest entries of the nodes near α → 0 away, leaving shapes that are no
/// longer positive definite. The lab and the command line say how many.
#[test]
fn fixed_point_breaks_the_4d_tables_nodes_near_alpha_zero() {
    let shipped = AnisoLut::shipped();
    assert_eq!(improper_nodes(shipped), 0);
    assert_eq!(improper_nodes(&stored_in(shipped, Storage::F16)), 0);
    let eight = improper_nodes(&stored_in(shipped, Storage::Unorm8));
    let ten = improper_nodes(&stored_in(shipped, Storage::Unorm10));
    assert!(eight > 0, "8 bits keep every node");
    assert!(
        ten <= eight,
        "10 bits break more nodes ({ten}) than 8 ({eight})"
    );
    let (_, note) = Encoding::parse("unorm8")
        .unwrap()
        .decoded_saying(Lut::embedded());
    assert!(
        note.unwrap()
            .contains(&format!("{eight} of the 4D table's")),
        "the note counts them"
    );
}
