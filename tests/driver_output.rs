//! Standard error held back while an adapter opens (`gpu::driver_output`): the drivers'
//! chatter is kept from the user, but nothing else is lost with it. Each test runs itself
//! again as a child process, as holding back redirects the process's own standard error.
#![cfg(unix)]

use std::io::Write;
use std::process::{Command, Output};

use ltc_lab::gpu::driver_output;

/// Set in the child: do the holding, instead of checking it.
const CHILD: &str = "LTC_LAB_DRIVER_OUTPUT_CHILD";

fn in_child() -> bool {
    std::env::var_os(CHILD).is_some()
}

/// Runs the test `name` alone in a child process, unfiltered output.
fn run_child(name: &str) -> Output {
    Command::new(std::env::current_exe().unwrap())
        .args(["--exact", name, "--nocapture", "--test-threads", "1"])
        .env(CHILD, "1")
        .output()
        .unwrap()
}

/// A driver writes to the file descriptor itself, not through the test harness's capture.
fn driver_says(text: &str) {
    std::io::stderr().write_all(text.as_bytes()).unwrap();
}

#[test]
fn what_is_written_while_held_is_handed_over_and_not_shown() {
    if in_child() {
        let ((), said) = driver_output::held_back(|| driver_says("error: chatter\n"));
        driver_says(&format!("handed over: [{said}]\n"));
        return;
    }
    let o = run_child("what_is_written_while_held_is_handed_over_and_not_shown");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{}: {err}", o.status);
    assert_eq!(err.trim(), "handed over: [error: chatter]");
}

/// A panic while the window's adapter opens (winit, a driver) must not vanish with the held
/// file: the process would end with nothing said.
#[test]
fn a_panic_while_held_is_seen_with_what_the_driver_said() {
    if in_child() {
        driver_output::hold();
        driver_says("error: chatter\n");
        panic!("the window could not open");
    }
    let o = run_child("a_panic_while_held_is_seen_with_what_the_driver_said");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "the child's panic was not a failure");
    assert!(err.contains("the window could not open"), "{err}");
    assert!(err.contains("(the driver said: error: chatter)"), "{err}");
}

#[test]
fn giving_back_what_was_never_held_says_nothing() {
    if in_child() {
        driver_says(&format!("[{}]\n", driver_output::give_back()));
        return;
    }
    let o = run_child("giving_back_what_was_never_held_says_nothing");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{}: {err}", o.status);
    assert_eq!(err.trim(), "[]");
}
