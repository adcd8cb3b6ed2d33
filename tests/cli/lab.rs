//! `ltc-lab lab` arguments (the window itself: tests/lab_window.rs).

use crate::{assert_refused, ltc_lab};

#[test]
fn lab_refuses_bad_arguments_before_opening_a_window() {
    let o = ltc_lab(&["lab", "--panel", "everything"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("everything"));
    assert_refused(
        &ltc_lab(&["lab", "--screenshot", "/tmp/shot.jpg"]),
        "/tmp/shot.jpg",
    );
    assert_refused(
        &ltc_lab(&["lab", "--screenshot", "/nonexistent-dir/shot.png"]),
        "/nonexistent-dir/shot.png",
    );
    assert_refused(
        &ltc_lab(&["lab", "--scene", "/nonexistent.toml"]),
        "/nonexistent.toml",
    );
}
