//! Files that land together, or not at all.

use std::fs;
use std::path::{Path, PathBuf};

use super::claim::create_placeholder;
use super::unfinished::{create_listed, discard, forget, remove_path, unfinished, write_listed};
use super::{MAX_NUMBERED, numbered, probe_directory, temporary_beside};
use crate::error::{Error, Result};

/// Makes `dir` and whichever of its ancestors are missing, each listed; the ones made,
/// outermost first. On failure, the ones made are removed again.
fn make_directories(dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let missing: Vec<&Path> = dir
        .ancestors()
        .take_while(|d| !d.as_os_str().is_empty() && !d.exists())
        .collect();
    let mut made = Vec::new();
    for d in missing.into_iter().rev() {
        match create_listed(d, |p| fs::create_dir(p)) {
            Ok(()) => made.push(d.to_path_buf()),
            // Made meanwhile by someone else: theirs, not ours to remove.
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists && d.is_dir() => {}
            Err(e) => {
                made.iter().rev().for_each(|m| discard(m));
                return Err(e);
            }
        }
    }
    Ok(made)
}

/// Files that land together: each is written to a temporary file in the target directory
/// first, and all are renamed into place only by `commit`. Dropped without a commit (an
/// error on the way), it removes its temporary files, its claimed names, and the
/// directories it made.
pub struct Outputs {
    dir: PathBuf,
    /// Directories made for these outputs, outermost first.
    created: Vec<PathBuf>,
    /// Default names taken at the start (empty files until their output replaces them).
    claimed: Vec<PathBuf>,
    /// (temporary file, target) of each staged output.
    staged: Vec<(PathBuf, PathBuf)>,
}

impl Outputs {
    /// Outputs named `names` in `dir` (a directory the user named: files in it are
    /// replaced), which is made if it does not exist. Refused before any work if one of
    /// them is a directory, or if the directory cannot take files.
    pub fn new(dir: &Path, names: &[&str]) -> Result<Self> {
        let dir_name = dir.display().to_string();
        for n in names {
            let target = dir.join(n);
            if target.is_dir() {
                return Err(Error::input(
                    target.display().to_string(),
                    "is a directory, not a file that can be written",
                ));
            }
        }
        if dir.exists() && !dir.is_dir() {
            return Err(Error::input(dir_name, "is a file, not a directory"));
        }
        let created = make_directories(dir).map_err(|e| Error::io(&dir_name, "create it", &e))?;
        let outputs = Self {
            dir: dir.to_path_buf(),
            created,
            claimed: Vec::new(),
            staged: Vec::new(),
        };
        probe_directory(dir).map_err(|e| Error::io(&dir_name, "write into it", &e))?;
        Ok(outputs)
    }

    /// Outputs under a default directory name, which must never replace a file: the first
    /// of `base`, `base-2`, `base-3`… in which none of `names` exists, claimed at once by
    /// making each of `names` there as an empty file (and the directory, where it is
    /// missing), so that two runs at once never pick the same one.
    pub fn claim_free_directory(base: &Path, names: &[&str]) -> Result<Self> {
        for k in 1..=MAX_NUMBERED {
            if let Some(outputs) = Self::try_claim(&numbered(base, k), names)? {
                return Ok(outputs);
            }
        }
        Err(Error::input(
            base.display().to_string(),
            format!("it and {MAX_NUMBERED} numbered directories beside it are in use"),
        ))
    }

    /// `dir` with every one of `names` claimed; `None` (and nothing left behind) where one
    /// of them exists, or `dir` is a file.
    fn try_claim(dir: &Path, names: &[&str]) -> Result<Option<Self>> {
        if dir.exists() && !dir.is_dir() {
            return Ok(None);
        }
        let dir_name = dir.display().to_string();
        let created = make_directories(dir).map_err(|e| Error::io(&dir_name, "create it", &e))?;
        let mut outputs = Self {
            dir: dir.to_path_buf(),
            created,
            claimed: Vec::new(),
            staged: Vec::new(),
        };
        for n in names {
            let target = dir.join(n);
            if !create_placeholder(&target)? {
                // Dropped: the names claimed so far and the directory made go again.
                return Ok(None);
            }
            outputs.claimed.push(target);
        }
        Ok(Some(outputs))
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Writes one file's bytes to its temporary name.
    pub fn stage(&mut self, name: &str, bytes: &[u8]) -> Result<()> {
        let target = self.dir.join(name);
        let tmp = temporary_beside(&target);
        write_listed(&tmp, bytes)
            .map_err(|e| Error::io(target.display().to_string(), "write", &e))?;
        self.staged.push((tmp, target));
        Ok(())
    }

    /// Moves every staged file into place, at once for an interrupt: it removes all of
    /// them or none. A claimed name that nothing was staged for is removed.
    pub fn commit(mut self) -> Result<()> {
        let mut list = unfinished();
        let landed = self.land(&mut list);
        // Released before `self` drops: its Drop takes the registry too.
        drop(list);
        landed
    }

    fn land(&mut self, list: &mut Vec<PathBuf>) -> Result<()> {
        let staged = std::mem::take(&mut self.staged);
        for (k, (tmp, target)) in staged.iter().enumerate() {
            if let Err(e) = fs::rename(tmp, target) {
                for (t, _) in &staged[k..] {
                    let _ = fs::remove_file(t);
                    forget(list, t);
                }
                // What landed stays; Drop removes the other claims and the directories.
                return Err(Error::io(target.display().to_string(), "write", &e));
            }
            forget(list, tmp);
            if let Some(c) = self.claimed.iter().position(|c| c == target) {
                forget(list, &self.claimed.remove(c));
            }
        }
        for c in std::mem::take(&mut self.claimed) {
            let _ = fs::remove_file(&c);
            forget(list, &c);
        }
        for d in std::mem::take(&mut self.created) {
            forget(list, &d);
        }
        Ok(())
    }
}

impl Drop for Outputs {
    fn drop(&mut self) {
        let mut list = unfinished();
        let tmps = self.staged.iter().map(|(tmp, _)| tmp);
        // Newest first: files before the directories that hold them.
        for p in tmps
            .chain(self.claimed.iter().rev())
            .chain(self.created.iter().rev())
        {
            remove_path(p);
            forget(&mut list, p);
        }
    }
}
