//! The shipped 4D table: what the file holds, read back exactly at its nodes, the mirror and
//! the quarter turn it folds by are symmetries of the lobe, no seam where the fold meets
//! itself, and no interpolated matrix anywhere singular or mirrored.

use glam::DVec3;
use ltc_lab::brdf::Alpha;
use ltc_lab::ltc::aniso::{AnisoAxes, AnisoLut, EMBEDDED_EXR, Stored, worst_blend};
use ltc_lab::ltc::{Clipping, Ltc, Normalization};
use proptest::prelude::*;

fn d(ltc: &Ltc, l: DVec3) -> f64 {
    ltc.ltc_eval(l, Clipping::CASE2, Normalization::Corrected)
}

fn unit(theta: f64, phi: f64) -> DVec3 {
    DVec3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}

/// Directions spread over the upper hemisphere, to compare two lobes by.
fn probes() -> Vec<DVec3> {
    (0..64)
        .map(|k| {
            unit(
                1.5 * ((k % 8) as f64 + 0.5) / 8.0,
                std::f64::consts::TAU * (k / 8) as f64 / 8.0 + 0.1,
            )
        })
        .collect()
}

/// Two lobes equal at every probe, relative to the larger value seen.
fn assert_same_lobe(a: &Ltc, b: &Ltc, rel: f64, what: &str) {
    let ps = probes();
    let scale = ps
        .iter()
        .map(|&l| d(a, l).abs().max(d(b, l).abs()))
        .fold(1e-300, f64::max);
    for l in ps {
        let (x, y) = (d(a, l), d(b, l));
        assert!((x - y).abs() <= rel * scale, "{what}: D({l}) = {x} vs {y}");
    }
}

#[test]
fn the_shipped_table_is_what_the_writer_writes() {
    let lut = AnisoLut::shipped();
    assert_eq!(lut.axes, AnisoAxes::Lab);
    assert_eq!(lut.stored, Stored::MirrorPole);
    // Written single-threaded and lossless with one attribute: the same table, the same bytes.
    assert_eq!(lut.to_exr_bytes(), EMBEDDED_EXR);
    let again = AnisoLut::from_exr_bytes(EMBEDDED_EXR, "again").unwrap();
    assert_eq!(&again, lut);
}

#[test]
fn every_node_reads_back_its_own_matrix() {
    let lut = AnisoLut::shipped();
    // At r = 0 every q is one material (α_x = α_y = α_min), whose lookup reads q = 0: the
    // other nodes of that column are not readable apart (nor need to be).
    for k in lut.nodes().filter(|k| k[0] > 0 || k[1] == 0) {
        let q = lut.node(k);
        let stored = lut.stored.cos_from_brdf(lut.cell(k).matrix(), q.view());
        let own = Ltc::from_cos_from_brdf(stored, 1.0, 0.0);
        let read = lut.ltc(q.alpha, q.view());
        // A node's axis coordinates come back within rounding of the node (exact inverses),
        // so its neighbours weigh ~1e-16; its view comes back through acos and atan2, moving
        // the lobe by ~1e-16/θ rad, which changes α_min's lobe (width 1e-4) by ~1e-8 of its
        // value: 1e-6 bounds both.
        assert_same_lobe(&own, &read, 1e-6, &format!("node {k:?}"));
    }
}

proptest! {
    /// Mirroring the view through the xz- or yz-plane mirrors the lobe, and a material
    /// rougher along its bitangent is the table turned by 90°: the lookup is exactly these
    /// symmetries of the exact lobe.
    #[test]
    fn the_fold_is_a_symmetry_of_the_lobe(theta in 0.05f64..1.5, phi in 0.0f64..std::f64::consts::TAU,
                                          ax in 0.01f64..1.0, ay in 0.01f64..1.0) {
        let lut = AnisoLut::shipped();
        let alpha = Alpha { x: ax, y: ay };
        let v = unit(theta, phi);
        let base = lut.ltc(alpha, v);
        for s in [DVec3::new(-1.0, 1.0, 1.0), DVec3::new(1.0, -1.0, 1.0)] {
            let mirrored = lut.ltc(alpha, v * s);
            for l in probes() {
                let (x, y) = (d(&base, l), d(&mirrored, l * s));
                prop_assert!((x - y).abs() <= 1e-9 * x.abs().max(1e-9), "{x} vs {y}");
            }
        }
        // Turned by 90° about n: the tangent frame's (x, y) becomes (y, −x).
        let turn = |w: DVec3| DVec3::new(w.y, -w.x, w.z);
        let turned = lut.ltc(Alpha { x: ay, y: ax }, turn(v));
        for l in probes() {
            let (x, y) = (d(&base, l), d(&turned, turn(l)));
            prop_assert!((x - y).abs() <= 1e-9 * x.abs().max(1e-9), "{x} vs {y}");
        }
    }
}

#[test]
fn the_fold_meets_itself_without_a_seam() {
    // Across φ = 0, φ = π/2 and α_x = α_y the lookup changes which quarter it reads (the
    // mirror, the turn): the lobes either side must agree as the points do.
    let lut = AnisoLut::shipped();
    let eps = 1e-7;
    for (ax, ay) in [(0.3, 0.05), (0.6, 0.2), (0.1, 0.01)] {
        for theta in [0.3, 0.9, 1.3] {
            for phi in [0.0, std::f64::consts::FRAC_PI_2] {
                let a = lut.ltc(Alpha { x: ax, y: ay }, unit(theta, phi - eps));
                let b = lut.ltc(Alpha { x: ax, y: ay }, unit(theta, phi + eps));
                // A 1e-7 move changes a lobe of width ≥ 0.01 by ~1e-5 of its peak.
                assert_same_lobe(
                    &a,
                    &b,
                    1e-4,
                    &format!("φ = {phi} at α = ({ax}, {ay}), θ = {theta}"),
                );
            }
            let a = lut.ltc(
                Alpha {
                    x: ax,
                    y: ax * (1.0 - eps),
                },
                unit(theta, 0.4),
            );
            let b = lut.ltc(
                Alpha {
                    x: ax * (1.0 - eps),
                    y: ax,
                },
                unit(theta, 0.4),
            );
            let iso = lut.ltc(Alpha::isotropic(ax), unit(theta, 0.4));
            assert_same_lobe(&a, &iso, 1e-4, "α_y just below α_x");
            assert_same_lobe(&b, &iso, 1e-4, "α_x just below α_y");
        }
    }
}

#[test]
fn no_interpolated_matrix_is_singular_or_mirrored() {
    let lut = AnisoLut::shipped();
    // The proof: every node's pole leans toward its mirror direction and its shape is
    // positive definite (`Stored::check`, which reading the file already asked), so every
    // blend of a cell's nodes is a proper lobe (`Stored::MirrorPole`).
    for k in lut.nodes() {
        assert_eq!(lut.stored.check(lut.cell(k).matrix()), Ok(()), "node {k:?}");
    }
    // And measured: 4⁴ points of every cell, as the lookup reads them.
    let (worst, at) = worst_blend(lut, 4);
    // A blend of positive definite shapes has a determinant at least the smallest corner's
    // times a factor set by how far the poles spread; 1e-3 of the corners' mean leaves that
    // room while no near-singular matrix could pass.
    assert!(
        worst > 1e-3,
        "det M⁻¹ at {at:?} is {worst:e} of its corners'"
    );
}
