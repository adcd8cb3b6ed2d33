//! A default output name, taken for this run when it starts.

use std::fs;
use std::path::{Path, PathBuf};

use super::unfinished::{create_listed, discard, rename_into_place, write_listed};
use super::{MAX_NUMBERED, check_writable, numbered, temporary_beside};
use crate::error::{Error, Result};

/// Makes `path` as an empty file, exclusively (O_EXCL), and lists it; `false` where
/// something of that name exists.
pub(super) fn create_placeholder(path: &Path) -> Result<bool> {
    let made = create_listed(path, |p| {
        fs::OpenOptions::new().write(true).create_new(true).open(p)
    });
    match made {
        Ok(_) => Ok(true),
        Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => Ok(false),
        Err(e) => Err(Error::io(path.display().to_string(), "create", &e)),
    }
}

/// A default output name taken for this run when it starts, as an empty file: no other run
/// takes it, and nothing that appears meanwhile is replaced. `fill` puts the output in its
/// place; dropped unfilled (an error on the way), the empty file is removed.
#[derive(Debug)]
pub struct Claim {
    path: PathBuf,
    filled: bool,
}

impl Claim {
    /// `path` itself; `None` where it exists.
    pub fn exactly(path: &Path) -> Result<Option<Self>> {
        check_writable(path)?;
        Ok(create_placeholder(path)?.then(|| Self {
            path: path.to_path_buf(),
            filled: false,
        }))
    }

    /// `path` if it is free, else the first free `stem-2.ext`, `stem-3.ext`…
    pub fn first_free(path: &Path) -> Result<Self> {
        check_writable(path)?;
        for k in 1..=MAX_NUMBERED {
            let candidate = numbered(path, k);
            if create_placeholder(&candidate)? {
                return Ok(Self {
                    path: candidate,
                    filled: false,
                });
            }
        }
        Err(Error::input(
            path.display().to_string(),
            format!("it and {MAX_NUMBERED} numbered names beside it exist"),
        ))
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Replaces the empty file with `bytes` (through a temporary file, so that the name
    /// never holds a partial output); the name written.
    pub fn fill(mut self, bytes: &[u8]) -> Result<PathBuf> {
        let tmp = temporary_beside(&self.path);
        write_listed(&tmp, bytes)
            .and_then(|()| rename_into_place(&tmp, &self.path))
            .map_err(|e| Error::io(self.path.display().to_string(), "write", &e))?;
        self.filled = true;
        Ok(std::mem::take(&mut self.path))
    }
}

impl Drop for Claim {
    fn drop(&mut self) {
        if !self.filled {
            discard(&self.path);
        }
    }
}
