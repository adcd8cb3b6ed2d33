//! The files module's rules, each with the registry checked after it.

use super::unfinished::{remove_all, unfinished};
use super::*;

#[test]
fn a_default_name_never_replaces_a_file() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("a.png");
    let write_new = |bytes: &[u8]| Claim::first_free(&p)?.fill(bytes);
    assert_eq!(write_new(b"one").unwrap(), p);
    let second = write_new(b"two").unwrap();
    assert_eq!(second, dir.path().join("a-2.png"));
    assert_eq!(fs::read(&p).unwrap(), b"one");
    assert_eq!(fs::read(&second).unwrap(), b"two");
}

#[test]
fn outputs_land_together_or_not_at_all() {
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("new");
    {
        let mut out = Outputs::new(&dir, &["a.csv", "b.png"]).unwrap();
        out.stage("a.csv", b"a").unwrap();
        // Dropped before the commit: nothing lands, the directory it made goes too.
    }
    assert!(!dir.exists());
    let mut out = Outputs::new(&dir, &["a.csv", "b.png"]).unwrap();
    out.stage("a.csv", b"a").unwrap();
    out.stage("b.png", b"b").unwrap();
    assert!(!dir.join("a.csv").exists(), "visible before the commit");
    out.commit().unwrap();
    assert_eq!(fs::read(dir.join("b.png")).unwrap(), b"b");
    assert_eq!(
        fs::read_dir(&dir).unwrap().count(),
        2,
        "temporary files left"
    );
    fs::create_dir(dir.join("c.png")).unwrap();
    assert!(Outputs::new(&dir, &["c.png"]).is_err());
}

/// Whether `path` is listed as unfinished (tests run in parallel threads, each in its
/// own temporary directory, so each asks only about its own paths).
fn listed(path: &Path) -> bool {
    unfinished().iter().any(|p| p == path)
}

/// What an interrupt would remove now among the paths under `root`, oldest first.
fn listed_under(root: &Path) -> Vec<PathBuf> {
    let list = unfinished();
    list.iter()
        .filter(|p| p.starts_with(root))
        .cloned()
        .collect()
}

#[test]
fn a_claim_is_taken_once_and_removed_unless_filled() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("ltc.exr");
    let claim = Claim::exactly(&p).unwrap().expect("the name is free");
    assert!(p.exists() && listed(&p), "not claimed at once");
    assert!(Claim::exactly(&p).unwrap().is_none(), "claimed twice");
    // The numbered form passes over the claimed name.
    let second = Claim::first_free(&p).unwrap();
    assert_eq!(second.path(), dir.path().join("ltc-2.exr"));
    drop(second);
    assert!(
        !dir.path().join("ltc-2.exr").exists(),
        "an unfilled claim stayed"
    );
    assert!(!listed(&dir.path().join("ltc-2.exr")));
    assert_eq!(claim.fill(b"table").unwrap(), p);
    assert_eq!(fs::read(&p).unwrap(), b"table");
    assert!(
        !listed(&p),
        "a finished output would be removed by an interrupt"
    );
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1, "files left");
}

#[test]
fn a_claim_that_cannot_be_made_is_bad_input_naming_it() {
    let e = Claim::exactly(Path::new("/nonexistent-dir/ltc.exr")).unwrap_err();
    assert_eq!(e.exit_code(), 2);
    assert!(e.input.contains("/nonexistent-dir/ltc.exr"), "{e}");
}

/// Two default directories claimed at once (two `study` runs) are two directories; a
/// directory holding one of the names is passed over and kept as it was.
#[test]
fn default_directories_are_claimed_at_once() {
    let root = tempfile::tempdir().unwrap();
    let base = root.path().join("study");
    fs::create_dir(&base).unwrap();
    fs::write(base.join("a.csv"), "earlier").unwrap();
    let names = ["a.csv", "b.png"];
    let first = Outputs::claim_free_directory(&base, &names).unwrap();
    let second = Outputs::claim_free_directory(&base, &names).unwrap();
    assert_eq!(first.dir(), root.path().join("study-2"));
    assert_eq!(second.dir(), root.path().join("study-3"));
    assert!(first.dir().join("b.png").exists(), "not claimed at once");
    assert_eq!(fs::read_to_string(base.join("a.csv")).unwrap(), "earlier");
    assert!(
        !base.join("b.png").exists(),
        "a claim left in a passed-over directory"
    );
    drop(second);
    assert!(
        !root.path().join("study-3").exists(),
        "the claimed directory stayed"
    );
    let mut first = first;
    first.stage("a.csv", b"a").unwrap();
    first.commit().unwrap();
    let dir = root.path().join("study-2");
    assert_eq!(fs::read(dir.join("a.csv")).unwrap(), b"a");
    // Nothing was staged for b.png: its empty claim is not an output.
    assert!(!dir.join("b.png").exists());
    assert!(
        listed_under(root.path()).is_empty(),
        "finished outputs listed"
    );
}

/// What the interrupt handler removes (`remove_all` on the registry) is everything an
/// unfinished set of outputs made: temporary files, claims and directories, none of them
/// left behind, and nothing that was there before.
#[test]
fn an_interrupt_removes_everything_unfinished() {
    let root = tempfile::tempdir().unwrap();
    fs::write(root.path().join("before.txt"), "kept").unwrap();
    let named = root.path().join("made/for/it");
    let mut out = Outputs::new(&named, &["a.csv"]).unwrap();
    out.stage("a.csv", b"a").unwrap();
    let mut claimed = Outputs::claim_free_directory(&root.path().join("s"), &["x"]).unwrap();
    claimed.stage("x", b"x").unwrap();
    let claim = Claim::first_free(&root.path().join("c.png")).unwrap();
    let mut list = listed_under(root.path());
    // made, made/for, made/for/it, its temporary file, s, s/x, its temporary file, c.png.
    assert_eq!(list.len(), 8, "{list:?}");
    assert_eq!(remove_all(&mut list), 8);
    let left: Vec<_> = fs::read_dir(root.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["before.txt"]);
    // The handler would exit here; the Drops find their paths gone, which is fine.
    drop((out, claimed, claim));
    assert!(listed_under(root.path()).is_empty());
}

#[test]
fn an_interrupt_keeps_a_directory_someone_else_filled() {
    let root = tempfile::tempdir().unwrap();
    let dir = root.path().join("d");
    fs::create_dir(&dir).unwrap();
    fs::write(dir.join("theirs"), "x").unwrap();
    let mut list = vec![dir.clone(), dir.join("mine")];
    fs::write(dir.join("mine"), "y").unwrap();
    assert_eq!(remove_all(&mut list), 1);
    assert!(dir.join("theirs").exists() && !dir.join("mine").exists());
    assert!(list.is_empty());
}

#[test]
fn a_written_file_leaves_nothing_listed_or_behind() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("a.csv");
    fs::write(&p, "old").unwrap();
    write_atomically(&p, b"new").unwrap();
    assert_eq!(fs::read(&p).unwrap(), b"new");
    assert_eq!(
        fs::read_dir(dir.path()).unwrap().count(),
        1,
        "a temporary file left"
    );
    assert!(listed_under(dir.path()).is_empty());
    let a = temporary_beside(&p);
    assert_ne!(
        a,
        temporary_beside(&p),
        "two writes in one process share a name"
    );
}

/// Root may write anywhere permissions are concerned; /sys and /proc take no new files
/// even for root. Either is the path's fault (exit 2), found before any work.
#[cfg(target_os = "linux")]
#[test]
fn a_directory_that_takes_no_files_is_refused_up_front() {
    for p in ["/sys/ltc-lab-test.png", "/proc/ltc-lab-test.png"] {
        let e = check_writable(Path::new(p)).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{e}");
        assert_eq!(e.input, p);
    }
    let dir = tempfile::tempdir().unwrap();
    check_writable(&dir.path().join("x.png")).unwrap();
    assert_eq!(
        fs::read_dir(dir.path()).unwrap().count(),
        0,
        "the probe stayed"
    );
}

#[test]
fn two_outputs_naming_one_file_are_refused() {
    let root = tempfile::tempdir().unwrap();
    let r = root.path();
    fs::create_dir(r.join("sub")).unwrap();
    let a = r.join("a.png");
    let dotted = r.join("sub/../a.png");
    let e = check_distinct(&[("--screenshot", &a), ("--frame-log", &dotted)]).unwrap_err();
    assert_eq!((e.exit_code(), e.input.as_str()), (2, "--frame-log"));
    assert!(
        e.message.contains("--screenshot") && e.message.contains("a.png"),
        "{e}"
    );
    // Through a link to the same directory: only the real directories agree.
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(r, r.join("link")).unwrap();
        let linked = r.join("link/a.png");
        assert!(check_distinct(&[("--x", &a), ("--y", &linked)]).is_err());
    }
    // `./a.png` and `a.png` relative to the working directory.
    let e = check_distinct(&[("--x", Path::new("./a.png")), ("--y", Path::new("a.png"))]);
    assert!(e.is_err());
    let other = r.join("b.png");
    check_distinct(&[("--x", &a), ("--y", &other), ("--z", &r.join("sub/a.png"))]).unwrap();
}

#[test]
fn a_byte_order_mark_is_dropped() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("bom.csv");
    fs::write(&p, "\u{feff}a,b\n").unwrap();
    assert_eq!(read_text(&p, 1 << 10).unwrap(), "a,b\n");
}

#[test]
fn a_file_is_read_up_to_its_limit_and_refused_past_it() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("big.toml");
    fs::write(&p, vec![b'#'; 1025]).unwrap();
    // One byte over: refused as bad input, naming the file and the limit.
    let e = read_bytes(&p, 1024).unwrap_err();
    assert_eq!(e.exit_code(), 2, "{e}");
    let m = e.to_string();
    assert!(m.contains("big.toml") && m.contains("1 kiB"), "{m}");
    // At the limit: read whole.
    assert_eq!(read_bytes(&p, 1025).unwrap().len(), 1025);
    // A directory is not a file.
    assert_eq!(read_bytes(dir.path(), 1024).unwrap_err().exit_code(), 2);
    // Bytes that are not UTF-8 are bad input too.
    fs::write(&p, [0xff, 0xfe, 0x00]).unwrap();
    assert_eq!(read_text(&p, 1024).unwrap_err().exit_code(), 2);
}

/// A special file is refused at once, naming what it is: a device that never ends
/// (`/dev/zero` would fill memory, `/dev/urandom` never return) and a FIFO (opening it waits
/// for a writer forever).
#[cfg(unix)]
#[test]
fn special_files_are_refused_naming_their_kind() {
    for (device, kind) in [
        ("/dev/zero", "character device"),
        ("/dev/urandom", "character device"),
    ] {
        let e = read_text(Path::new(device), 1 << 20).unwrap_err();
        assert_eq!(e.exit_code(), 2, "{device}: {e}");
        assert!(e.to_string().contains(device), "{e}");
        assert!(e.to_string().contains(kind), "{e}");
    }
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("scene.toml");
    nix::unistd::mkfifo(&fifo, nix::sys::stat::Mode::S_IRWXU).unwrap();
    let e = read_bytes(&fifo, 1024).unwrap_err();
    assert_eq!(e.exit_code(), 2, "{e}");
    assert!(e.to_string().contains("FIFO"), "{e}");
}
