//! `ltc-lab lab` arguments (the window itself: tests/lab_window.rs).

use crate::{assert_refused, ltc_lab, stderr};

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

/// Two outputs of one command never name the same file: `--screenshot X --frame-log X`
/// wrote the CSV over the screenshot and exited 0.
#[test]
fn lab_refuses_two_outputs_with_one_name() {
    let dir = tempfile::tempdir().unwrap();
    let shot = dir.path().join("x.png");
    let same = dir.path().join(".").join("x.png");
    let o = ltc_lab(&[
        "lab",
        "--screenshot",
        shot.to_str().unwrap(),
        "--frame-log",
        same.to_str().unwrap(),
    ]);
    assert_refused(&o, "--frame-log");
    assert!(!shot.exists());
}

/// A screenshot path that cannot be written is bad input, as in `render`: exit 2 before a
/// window opens (it exited 1, "cannot open the window: … operation not permitted"). Under
/// /sys even root may not create a file.
#[test]
fn an_unwritable_screenshot_path_is_bad_input() {
    let o = ltc_lab(&["lab", "--screenshot", "/sys/ltc-lab-shot.png"]);
    assert_refused(&o, "/sys/ltc-lab-shot.png");
}

/// A view that cannot be opened (cut short, not a view, a scene that cannot be shaded) is
/// refused by name before a window opens.
#[test]
fn lab_refuses_a_broken_view() {
    for view in ["v1.", "v1.AAAA", "hello", "v2.abc", "https://x/#view=v1.%%"] {
        assert_refused(&ltc_lab(&["lab", "--view", view]), "--view");
    }
}

/// A lesson that does not open, or a step it lacks, is refused by name before a window opens:
/// a shipped name that is not one, a missing file, a malformed file (its step and field named),
/// a step out of range; `--step` needs `--lesson`, which a view excludes.
#[test]
fn lab_refuses_a_lesson_that_does_not_open() {
    let dir = tempfile::tempdir().unwrap();
    let broken = dir.path().join("broken.lesson.toml");
    std::fs::write(
        &broken,
        "title = \"t\"\n[[step]]\ntitle = \"a\"\ntext = \"b\"\npanels = [\"teapot\"]\nview = \"v1.\"\n",
    )
    .unwrap();
    let broken = broken.to_str().unwrap();
    for (args, says) in [
        (&["--lesson", "teapot"][..], "--lesson"),
        (
            &["--lesson", "/nonexistent.lesson.toml"],
            "/nonexistent.lesson.toml",
        ),
        (&["--lesson", broken], "step 1: field `panels`"),
        (&["--lesson", "paper", "--step", "0"], "--step"),
        (&["--lesson", "paper", "--step", "99"], "--step"),
    ] {
        let o = ltc_lab(&[&["lab"][..], args].concat());
        assert_refused(&o, says);
    }
    for args in [
        &["--step", "2"][..],
        &["--lesson", "paper", "--view", "v1.x"],
    ] {
        let o = ltc_lab(&[&["lab"][..], args].concat());
        assert_eq!(o.status.code(), Some(2), "{args:?}");
    }
}

/// Every input file is read up to its stated limit, and only a regular file: a device that
/// never ends (`/dev/zero` filled memory until the process was killed, `/dev/urandom` never
/// returned) is refused naming its kind, and a file over the limit naming the limit, in one
/// line, as a lesson, a scene, a table and a cases CSV alike, exit 2.
#[cfg(unix)]
#[test]
fn endless_and_oversized_inputs_are_refused_at_their_limit() {
    let dir = tempfile::tempdir().unwrap();
    // One byte over a lesson's 4 MiB.
    let big = dir.path().join("big.lesson.toml");
    std::fs::write(&big, vec![b'#'; (4 << 20) + 1]).unwrap();
    let big = big.to_str().unwrap();
    for device in ["/dev/zero", "/dev/urandom"] {
        for args in [
            vec!["lab", "--lesson", device],
            vec!["render", "--scene", device, "--method", "ltc", "--cpu"],
            vec!["lut", "--lut", device],
            vec!["eval", "--cases", device],
        ] {
            let o = ltc_lab(&args);
            assert_refused(&o, device);
            assert!(
                stderr(&o).contains("character device, not a regular file"),
                "{args:?}: {}",
                stderr(&o)
            );
        }
    }
    let o = ltc_lab(&["lab", "--lesson", big]);
    assert_refused(&o, big);
    assert!(stderr(&o).contains("4 MiB"), "{}", stderr(&o));
}
