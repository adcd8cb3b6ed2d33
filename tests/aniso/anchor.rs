//! The I3D 2022 tables read as an engine reads them, and measured beside the lab's table:
//! the `.npy` reader takes their files and refuses broken ones; read at their own nodes they
//! give their own matrices; and on the lobe error against the exact anisotropic lobe the
//! lab's table is at most theirs at their nodes on average, and below theirs between them.

use glam::DVec3;
use ltc_lab::ltc::aniso::anchor::{ALPHA_LAMBDA_NPY, ALPHA_XY_NPY, read_npy, shipped};
use ltc_lab::ltc::aniso::{AnisoAxes, AnisoLut, Stored};
use ltc_lab::ltc::lobe::strata;
use ltc_lab::measure::aniso_table::{LobePoint, domain_points, lobe_errors};
use rayon::prelude::*;

#[test]
fn the_published_tables_read_as_forward_matrices() {
    for (bytes, axes) in [
        (ALPHA_XY_NPY, AnisoAxes::I3dAlphaXY),
        (ALPHA_LAMBDA_NPY, AnisoAxes::I3dAlphaLambda),
    ] {
        let lut = read_npy(bytes, "anchor", axes).unwrap();
        assert_eq!(lut.dims, [8; 4]);
        assert_eq!(lut.stored, Stored::BrdfFromCos);
        // Their README: the last column normalized (`M`'s image of the pole, unit length).
        for c in &lut.cells {
            let z = c.matrix().z_axis.length();
            assert!((z - 1.0).abs() < 1e-4, "|M e_z| = {z}");
        }
    }
}

#[test]
fn broken_npy_files_are_refused_by_name() {
    let good = ALPHA_XY_NPY;
    let header_end = 10 + u16::from_le_bytes([good[8], good[9]]) as usize;
    let patched = |from: &str, to: &str| {
        let mut v = good.to_vec();
        let at = good[..header_end]
            .windows(from.len())
            .position(|w| w == from.as_bytes())
            .expect("in the header");
        v[at..at + from.len()].copy_from_slice(to.as_bytes());
        v
    };
    let mut version = good.to_vec();
    version[6] = 9;
    let cases: Vec<(Vec<u8>, &str)> = vec![
        (b"PK\x03\x04not numpy".to_vec(), "not a NumPy"),
        (good[..good.len() - 4].to_vec(), "bytes of data"),
        (good[..40].to_vec(), "header runs past"),
        (patched("<f4", "<f8"), "f32"),
        (patched("False", "True "), "Fortran"),
        (version, "version"),
    ];
    for (bytes, what) in cases {
        let e = read_npy(&bytes, "bad.npy", AnisoAxes::I3dAlphaXY).unwrap_err();
        assert_eq!(e.input, "bad.npy");
        assert!(e.message.contains(what), "{what}: {e}");
    }
    // A shape claiming 99 nodes an axis is refused before anything is allocated.
    let big = patched("(8, 8, 8, 8, 3, 3)", "(99,8, 8, 8, 3, 3)");
    let e = read_npy(&big[..header_end], "big.npy", AnisoAxes::I3dAlphaXY).unwrap_err();
    assert!(e.message.contains("2 to 64"), "{e}");
}

#[test]
fn their_tables_read_their_own_matrices_at_their_nodes() {
    let ours = AnisoLut::shipped();
    for axes in [AnisoAxes::I3dAlphaXY, AnisoAxes::I3dAlphaLambda] {
        let theirs = shipped(axes, ours);
        // The α,λ table's first column holds one material at every λ (α_x = α_y = 1e-4): the
        // lookup of that material reads its λ = 1 node, so the others are not readable apart.
        let ambiguous = |k: [usize; 4]| axes == AnisoAxes::I3dAlphaLambda && k[0] == 0 && k[1] != 7;
        for k in theirs.nodes().step_by(7).filter(|&k| !ambiguous(k)) {
            let q = theirs.node(k);
            let s = theirs.sample(&q);
            let stored = theirs.cell(k).matrix();
            let d = (s.matrix - stored)
                .to_cols_array()
                .iter()
                .fold(0.0f64, |a, x| a.max(x.abs()));
            // Their first nodes sit at α = 1e-4 (not 0): the coordinate maps them back exactly.
            assert!(
                d < 1e-6,
                "node {k:?} of {axes:?} reads {d} away from its own matrix"
            );
        }
    }
}

/// Mean lobe error of (ours, theirs) over a set of points, with a quadrature finer than
/// neither table's own fit nodes (96² strata, no node shared with the fit's 64²).
fn mean_errors(
    ours: &AnisoLut,
    theirs: &AnisoLut,
    points: &[ltc_lab::ltc::aniso::AnisoPoint],
) -> (f64, f64) {
    let quadrature = strata(96);
    let errors: Vec<Vec<f64>> = points
        .par_iter()
        .map(|q| lobe_errors(&[ours, theirs], &LobePoint::of(q), &quadrature))
        .collect();
    let n = errors.len() as f64;
    (
        errors.iter().map(|e| e[0]).sum::<f64>() / n,
        errors.iter().map(|e| e[1]).sum::<f64>() / n,
    )
}

#[test]
fn the_lab_table_is_at_most_theirs_at_their_nodes_and_below_between() {
    let ours = AnisoLut::shipped();
    for axes in [AnisoAxes::I3dAlphaXY, AnisoAxes::I3dAlphaLambda] {
        let theirs = shipped(axes, ours);
        let nodes = domain_points(axes, theirs.dims, false);
        let (o, t) = mean_errors(ours, &theirs, &nodes);
        assert!(o <= t, "{axes:?} nodes: ours {o} above theirs {t}");
        let centres = domain_points(axes, theirs.dims, true);
        let (o, t) = mean_errors(ours, &theirs, &centres);
        assert!(
            o < t,
            "{axes:?} cell centres: ours {o} not below theirs {t}"
        );
    }
}

#[test]
fn the_measure_is_the_lobe_error_of_docs_4_1() {
    // An independent check of `lobe_errors`: for one point and both tables, the relative L1
    // by brute quadrature over the sphere (tests/common's rule) against the measure's.
    let ours = AnisoLut::shipped();
    let theirs = shipped(AnisoAxes::I3dAlphaXY, ours);
    let point = LobePoint {
        alpha: ltc_lab::brdf::Alpha { x: 0.5, y: 0.15 },
        view: DVec3::new(0.5, 0.3, (1.0f64 - 0.34).sqrt()),
    };
    let measured = lobe_errors(&[ours, &theirs], &point, &strata(256));
    for (table, m) in [ours, &theirs].iter().zip(measured) {
        let ltc = table.ltc(point.alpha, point.view);
        let exact = |l: DVec3| {
            ltc_lab::brdf::brdf_cos_aniso(point.view.to_array(), l.to_array(), point.alpha, 1.0)
                .specular
        };
        let mirror = DVec3::new(-point.view.x, -point.view.y, point.view.z);
        let norm = crate::common::sphere_integral(mirror, 500, exact);
        let l1 = crate::common::sphere_integral(mirror, 500, |l| {
            let d = ltc.ltc_eval(
                l,
                ltc_lab::ltc::Clipping::CASE2,
                ltc_lab::ltc::Normalization::Corrected,
            );
            (norm * d - exact(l)).abs()
        }) / norm;
        // Two quadratures of the same integral, one by the lobe's sampling and one by rings:
        // 2e-3 absolute on an error of tens of percent.
        assert!((l1 - m).abs() < 2e-3, "brute {l1} vs measured {m}");
    }
}
