//! The registry of unfinished outputs: temporary files, claimed names and directories made
//! for outputs, listed while they exist so that an interrupt can remove them all (a signal
//! skips every `Drop`). Each path is made and finished (renamed into place or removed) while
//! the registry is locked, so an interrupt sees every path either listed or finished.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// The unfinished paths of this process, oldest first.
pub(super) static UNFINISHED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The registry. A panic while it was held leaves the list itself valid, so poisoning is
/// ignored: the clean-up must still run.
pub(super) fn unfinished() -> MutexGuard<'static, Vec<PathBuf>> {
    UNFINISHED.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Drops the newest listing of `path` (a path listed twice is two unfinished things).
pub(super) fn forget(list: &mut Vec<PathBuf>, path: &Path) {
    if let Some(k) = list.iter().rposition(|p| p == path) {
        list.remove(k);
    }
}

/// Removes a file, or a directory only if it is empty (one that holds something someone
/// else put there stays). Whether something was removed.
pub(super) fn remove_path(path: &Path) -> bool {
    match fs::symlink_metadata(path) {
        Ok(m) if m.is_dir() => fs::remove_dir(path).is_ok(),
        Ok(_) => fs::remove_file(path).is_ok(),
        Err(_) => false,
    }
}

/// Removes every listed path, newest first (files before the directories that hold them),
/// and empties the list. How many were there to remove.
pub(super) fn remove_all(list: &mut Vec<PathBuf>) -> usize {
    list.drain(..).rev().filter(|p| remove_path(p)).count()
}

/// What an interrupt does: removes every unfinished output, tells `report` how many there
/// were, and ends the process with `code`. The registry stays locked until the end, so the
/// command, still running on its own thread, cannot rename a file into place afterwards.
pub fn exit_interrupted(code: i32, report: impl FnOnce(usize)) -> ! {
    let mut list = unfinished();
    report(remove_all(&mut list));
    std::process::exit(code)
}

/// Makes `path` with `create` and lists it, as one step for an interrupt.
pub(super) fn create_listed<T>(
    path: &Path,
    create: impl FnOnce(&Path) -> std::io::Result<T>,
) -> std::io::Result<T> {
    let mut list = unfinished();
    let made = create(path)?;
    list.push(path.to_path_buf());
    Ok(made)
}

/// Removes a listed path and its listing, as one step.
pub(super) fn discard(path: &Path) {
    let mut list = unfinished();
    remove_path(path);
    forget(&mut list, path);
}

/// Renames a listed temporary file onto `target`, which is then finished too (it may be a
/// claimed name); on failure the temporary file is removed. As one step.
pub(super) fn rename_into_place(tmp: &Path, target: &Path) -> std::io::Result<()> {
    let mut list = unfinished();
    let renamed = fs::rename(tmp, target);
    match renamed {
        Ok(()) => forget(&mut list, target),
        Err(_) => {
            let _ = fs::remove_file(tmp);
        }
    }
    forget(&mut list, tmp);
    renamed
}

/// Writes `bytes` to a new listed file `tmp` (created exclusively: a leftover of another
/// run is never reused); on failure it is removed again.
pub(super) fn write_listed(tmp: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut file = create_listed(tmp, |p| {
        fs::OpenOptions::new().write(true).create_new(true).open(p)
    })?;
    // Synced before the rename: a crash must not leave an empty file under the real name.
    let written = file.write_all(bytes).and_then(|()| file.sync_all());
    if written.is_err() {
        drop(file);
        discard(tmp);
    }
    written
}

/// A number unique within this process, for temporary names.
pub(super) fn next_serial() -> usize {
    static SERIAL: AtomicUsize = AtomicUsize::new(0);
    SERIAL.fetch_add(1, Ordering::Relaxed)
}
