//! `ltc-lab render`'s default output names: taken when the render starts, never replacing
//! a file, and removed again when the render does not fill them.

use std::path::Path;

use crate::{assert_refused, edited_scene, exe, ltc_lab_in, preset, stderr};

/// With no --out, `<scene>-<method>.png` is taken only if free; else the next free
/// `-2`, `-3`… Two runs at once each get their own file.
#[test]
fn a_default_output_name_never_replaces_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let args = [
        "render",
        "--cpu",
        "--scene",
        &preset("figure2-normal.toml"),
        "--method",
        "ltc",
        "--size",
        "8x8",
    ];
    std::fs::write(dir.path().join("figure2-normal-ltc.png"), b"mine").unwrap();
    let o = ltc_lab_in(dir.path(), &args);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("figure2-normal-ltc-2.png"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        std::fs::read(dir.path().join("figure2-normal-ltc.png")).unwrap(),
        b"mine"
    );
    let runs: Vec<_> = (0..2)
        .map(|_| exe().current_dir(dir.path()).args(args).spawn().unwrap())
        .collect();
    for mut r in runs {
        assert!(r.wait().unwrap().success());
    }
    for name in [
        "figure2-normal-ltc-2.png",
        "figure2-normal-ltc-3.png",
        "figure2-normal-ltc-4.png",
    ] {
        assert_eq!(
            image::open(dir.path().join(name)).unwrap().width(),
            8,
            "{name}"
        );
    }
}

/// Spawns a default-named CPU render of `scene` in `dir`, its stderr piped.
fn spawn_default_render(dir: &Path, scene: &Path) -> std::process::Child {
    exe()
        .current_dir(dir)
        .args([
            "render", "--cpu", "--method", "ltc", "--size", "8x8", "--scene",
        ])
        .arg(scene)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap()
}

/// A scene whose render holds the process for seconds: a million lights on the CPU (64
/// pixels × 10⁶ lights of f64 LTC, seconds on two cores). A FIFO held it at a known point
/// before; a FIFO is refused now, as every special file is (docs/design.md §5.13).
fn held_scene(dir: &Path, name: &str) -> std::path::PathBuf {
    let path = dir.join(name);
    let text = std::fs::read_to_string(preset("paper-100.toml"))
        .unwrap()
        .replace("count = 100", "count = 1000000");
    std::fs::write(&path, text).unwrap();
    path
}

/// The default name is taken when the render starts (it was taken only when the image was
/// written): while a long render runs, its empty claim is there and a second render of that
/// name writes `-2`. Filled, the claim is the image the render reports.
#[test]
fn a_default_render_claims_its_name_at_the_start() {
    let dir = tempfile::tempdir().unwrap();
    let held = held_scene(dir.path(), "held.toml");
    let claimed = dir.path().join("held-ltc.png");
    let mut first = spawn_default_render(dir.path(), &held);
    crate::study::wait_until(&mut first, "held-ltc.png claimed", || claimed.exists());
    // Another scene of the same name, which does not wait.
    std::fs::create_dir(dir.path().join("other")).unwrap();
    let same_name = dir.path().join("other/held.toml");
    std::fs::copy(preset("figure2-normal.toml"), &same_name).unwrap();
    let second = spawn_default_render(dir.path(), &same_name)
        .wait_with_output()
        .unwrap();
    let first = first.wait_with_output().unwrap();
    for (o, name) in [(&second, "held-ltc-2.png"), (&first, "held-ltc.png")] {
        assert!(o.status.success(), "{}", stderr(o));
        assert!(
            stderr(o).contains(&format!("wrote {name}")),
            "{}",
            stderr(o)
        );
    }
    for name in ["held-ltc.png", "held-ltc-2.png"] {
        assert_eq!(
            image::open(dir.path().join(name)).unwrap().width(),
            8,
            "{name}"
        );
    }
}

/// A claim that is never filled goes again: on a refused scene, and on SIGTERM (exit 130
/// through the handler) while the render runs.
#[test]
fn an_unfilled_default_name_is_removed() {
    let dir = tempfile::tempdir().unwrap();
    let bad = edited_scene(dir.path(), "bad.toml", |g| {
        g.replace("alpha = 0.5", "alpha = 0")
    });
    let o = spawn_default_render(dir.path(), &bad)
        .wait_with_output()
        .unwrap();
    assert_refused(&o, "bad.toml");
    assert!(!dir.path().join("bad-ltc.png").exists(), "the claim stayed");
    let held = held_scene(dir.path(), "held.toml");
    let claimed = dir.path().join("held-ltc.png");
    let mut child = spawn_default_render(dir.path(), &held);
    crate::study::wait_until(&mut child, "held-ltc.png claimed", || claimed.exists());
    crate::study::terminate(&child);
    let status = crate::study::wait_for_exit(&mut child);
    let o = child.wait_with_output().unwrap();
    assert_eq!(status.code(), Some(130), "{}", stderr(&o));
    assert!(stderr(&o).contains("interrupted"), "{}", stderr(&o));
    assert!(!claimed.exists(), "the interrupted render left its claim");
}
