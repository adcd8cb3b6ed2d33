//! `ltc-lab fit`.

use std::path::Path;
use std::time::{Duration, Instant};

use ltc_lab::ltc::lut::Lut;

use crate::{assert_refused, exe, ltc_lab, ltc_lab_in, stderr};

#[test]
fn fit_writes_a_readable_table() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("small.exr");
    let o = ltc_lab(&["fit", "--size", "4", "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("spec.err"),
        "no summary: {}",
        stderr(&o)
    );
    assert_eq!(Lut::read(&out).unwrap().size, 4);
}

#[test]
fn fit_refuses_bad_arguments() {
    assert_refused(
        &ltc_lab(&["fit", "--size", "1", "--out", "/tmp/never.exr"]),
        "--size",
    );
    let dir = tempfile::tempdir().unwrap();
    // An EXR written into a .txt file would mislead whoever opens it.
    let txt = dir.path().join("a.txt");
    assert_refused(
        &ltc_lab(&["fit", "--size", "2", "--out", txt.to_str().unwrap()]),
        "a.txt",
    );
    assert!(!txt.exists());
    let o = ltc_lab(&["fit", "--objective", "best", "--size", "2"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

/// A missing directory is found before the fit, not after it: a 1024² fit takes hours on
/// any machine, so an answer within two minutes can only come from the check up front (the
/// bound is about order, not speed: it is 1000× what the check takes).
#[test]
fn fit_refuses_a_missing_directory_before_fitting() {
    let start = Instant::now();
    let mut child = exe()
        .args(["fit", "--size", "1024", "--out", "/nonexistent-dir/x.exr"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(120) {
            child.kill().unwrap();
            panic!("fit started fitting into a directory that does not exist");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    assert_refused(&child.wait_with_output().unwrap(), "/nonexistent-dir/x.exr");
}

/// With no --out, `luts/ltc.exr` (relative to the working directory) is written only if it
/// does not exist, or with --force.
#[test]
fn fit_never_replaces_the_default_table_unasked() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("luts")).unwrap();
    let table = dir.path().join("luts/ltc.exr");
    std::fs::write(&table, b"the user's table").unwrap();
    let o = ltc_lab_in(dir.path(), &["fit", "--size", "2"]);
    assert_refused(&o, "luts/ltc.exr");
    assert!(stderr(&o).contains("--force"), "{}", stderr(&o));
    assert_eq!(std::fs::read(&table).unwrap(), b"the user's table");
    let o = ltc_lab_in(dir.path(), &["fit", "--size", "2", "--force"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(Lut::read(&table).unwrap().size, 2);
    // Where the default does not exist yet, it is simply written.
    let o = ltc_lab_in(dir.path(), &["fit", "--size", "2", "--objective", "point"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(Path::new(&dir.path().join("luts/ltc_point.exr")).exists());
}

/// Without --out, `luts/ltc.exr` is taken when the fit starts, not when it ends (so a table
/// that appears meanwhile is not replaced): while a fit runs, its
/// empty claim is there, and a second default fit is refused rather than sharing the name.
/// SIGTERM then removes the claim (exit 130, through the handler). A 1024² fit takes hours,
/// so it is still running whenever the claim is looked at.
#[test]
fn a_default_fit_claims_its_table_at_the_start() {
    let dir = tempfile::tempdir().unwrap();
    let luts = dir.path().join("luts");
    std::fs::create_dir(&luts).unwrap();
    let table = luts.join("ltc.exr");
    let mut child = exe()
        .current_dir(dir.path())
        .args(["fit", "--size", "1024"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    crate::study::wait_until(&mut child, "luts/ltc.exr claimed", || table.exists());
    let claim_len = std::fs::metadata(&table).unwrap().len();
    let second = ltc_lab_in(dir.path(), &["fit", "--size", "2"]);
    // Ended before anything is asserted, so that a failure leaves no fit running for hours.
    crate::study::terminate(&child);
    let status = crate::study::wait_for_exit(&mut child);
    let o = child.wait_with_output().unwrap();
    assert_eq!(claim_len, 0, "not an empty claim");
    assert_refused(&second, "luts/ltc.exr");
    assert_eq!(status.code(), Some(130), "{}", stderr(&o));
    assert!(
        std::fs::read_dir(&luts).unwrap().next().is_none(),
        "the claim or a temporary file was left"
    );
}
