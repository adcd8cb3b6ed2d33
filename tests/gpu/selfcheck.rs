//! The browser page's self-check (`gpu::selfcheck`), run here as the page runs it: stepped,
//! never waiting, on lavapipe (GL with WGPU_BACKEND=gl) — both methods agree with the CPU at
//! the parity tolerance, and a device that renders wrong is caught.

use crate::gpu_common::gpu;
use ltc_lab::gpu::selfcheck::{METHODS, Report, SelfCheck};

/// Steps the check to its end, polling the device between steps as the browser's event loop
/// would run its callbacks.
fn run(check: &mut SelfCheck) -> Report {
    for _ in 0..100_000 {
        if let Some(report) = check.step().expect("the self-check runs") {
            return report;
        }
        std::thread::sleep(std::time::Duration::from_micros(200));
    }
    panic!("the self-check did not finish");
}

#[test]
fn the_self_check_agrees_with_the_cpu() {
    let Some(g) = gpu() else { return };
    let mut check = SelfCheck::new(g.ctx.clone()).unwrap();
    assert_eq!(check.frames_read(), 0);
    let report = run(&mut check);
    assert_eq!(check.frames_read(), METHODS.len());
    let names: Vec<_> = report.methods.iter().map(|m| m.method).collect();
    assert_eq!(names, METHODS);
    report.check().unwrap();
    for m in &report.methods {
        // A blank or missing image would compare as a difference of 1 or more.
        assert!(m.parity.max_rel_diff.is_finite());
        assert!(m.parity.pixels == 160 * 120);
    }
    // Once done, it stays done.
    assert!(check.step().unwrap().is_none());
}

/// The measure the check reports catches one wrong pixel: 1e-3 off (5× the tolerance), a
/// NaN, a pixel off the plane in one image too many.
#[test]
fn parity_catches_a_wrong_pixel() {
    use ltc_lab::measure::parity::Parity;
    use ltc_lab::render::{Method, RenderSettings};
    let scene = ltc_lab::scene::preset("paper-100");
    let lut = ltc_lab::ltc::lut::Lut::embedded();
    let cpu = ltc_lab::cpu::render(
        &scene,
        lut,
        &RenderSettings::single(40, 30, Method::LtcFast),
    );
    assert_eq!(Parity::of(&cpu, &cpu).max_rel_diff, 0.0);
    let k = cpu.on_plane.iter().rposition(|&p| p).unwrap();
    let mut off = cpu.clone();
    off.pixels[k] *= 1.0 + 1e-3;
    assert!(Parity::of(&off, &cpu).check().is_err());
    off.pixels[k] = glam::DVec3::NAN;
    assert!(Parity::of(&off, &cpu).max_rel_diff.is_infinite());
    let mut holes = cpu.clone();
    for p in holes.on_plane.iter_mut().take(cpu.pixels.len() / 50) {
        *p = !*p;
    }
    assert!(
        Parity::of(&holes, &cpu)
            .check()
            .unwrap_err()
            .contains("coverage")
    );
}
