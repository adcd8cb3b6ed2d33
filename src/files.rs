//! Files in and out, so that nothing is lost: a named output is replaced only by a complete
//! one, a default name never replaces anything, and a set of outputs lands all together or
//! not at all.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// A text file, without a leading UTF-8 byte-order mark (spreadsheets write one).
pub fn read_text(path: &Path) -> Result<String> {
    let name = path.display().to_string();
    let text = fs::read_to_string(path).map_err(|e| Error::io(&name, "read", &e))?;
    Ok(match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_string(),
        None => text,
    })
}

/// The directory a file goes into (`.` for a bare name).
fn parent_dir(path: &Path) -> PathBuf {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Whether `path` can be written: its directory exists and it is not itself a directory.
/// Checked before long work, so that a typo costs nothing.
pub fn check_writable(path: &Path) -> Result<()> {
    let name = path.display().to_string();
    if !parent_dir(path).is_dir() {
        return Err(Error::input(name, "its directory does not exist"));
    }
    if path.is_dir() {
        return Err(Error::input(name, "is a directory"));
    }
    if path.file_name().is_none() {
        return Err(Error::input(name, "not a file path"));
    }
    Ok(())
}

/// A temporary name beside `path`, unique to this process.
fn temporary_beside(path: &Path) -> PathBuf {
    let file_name = path
        .file_name()
        .map_or("out".into(), |f| f.to_string_lossy());
    parent_dir(path).join(format!(".{file_name}.{}.partial", std::process::id()))
}

/// Writes `bytes` to `path` (a file the user named, which may be replaced) through a
/// temporary file beside it: a failure leaves no partial output and the old file intact.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    check_writable(path)?;
    let name = path.display().to_string();
    let tmp = temporary_beside(path);
    let result = fs::write(&tmp, bytes).and_then(|()| fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = fs::remove_file(&tmp);
        return Err(Error::io(name, "write", &e));
    }
    Ok(())
}

/// `path`, or `stem-2.ext`, `stem-3.ext`… : the candidates for a default output name.
fn numbered(path: &Path, k: usize) -> PathBuf {
    if k == 1 {
        return path.to_path_buf();
    }
    let stem = path
        .file_stem()
        .map_or("out".into(), |s| s.to_string_lossy());
    let name = match path.extension() {
        Some(ext) => format!("{stem}-{k}.{}", ext.to_string_lossy()),
        None => format!("{stem}-{k}"),
    };
    parent_dir(path).join(name)
}

/// How many numbered names a default output tries before giving up.
const MAX_NUMBERED: usize = 10_000;

/// Writes `bytes` under a default name that must never replace a file: `path` if it is
/// free, else the first free `stem-2.ext`, `stem-3.ext`… Each name is claimed with
/// `create_new` (O_EXCL), so two runs at once never share one. Returns the name written.
pub fn write_new(path: &Path, bytes: &[u8]) -> Result<PathBuf> {
    check_writable(path)?;
    for k in 1..=MAX_NUMBERED {
        let candidate = numbered(path, k);
        let name = candidate.display().to_string();
        let file = fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&candidate);
        match file {
            Ok(mut f) => {
                if let Err(e) = f.write_all(bytes).and_then(|()| f.sync_all()) {
                    drop(f);
                    let _ = fs::remove_file(&candidate);
                    return Err(Error::io(name, "write", &e));
                }
                return Ok(candidate);
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(Error::io(name, "create", &e)),
        }
    }
    Err(Error::input(
        path.display().to_string(),
        format!("it and {MAX_NUMBERED} numbered names beside it exist"),
    ))
}

/// The first of `base`, `base-2`, `base-3`… in which none of `names` exists yet: where a
/// command's default output directory goes so that an earlier run's files stay.
pub fn free_directory(base: &Path, names: &[&str]) -> Result<PathBuf> {
    (1..=MAX_NUMBERED)
        .map(|k| numbered(base, k))
        .find(|dir| names.iter().all(|n| !dir.join(n).exists()))
        .ok_or_else(|| {
            Error::input(
                base.display().to_string(),
                format!("it and {MAX_NUMBERED} numbered directories beside it are in use"),
            )
        })
}

/// Files that land together: each is written to a temporary file in the target directory
/// first, and all are renamed into place only by `commit`. Dropped without a commit (an
/// error on the way), it removes its temporary files, and the directory if it made it.
pub struct Outputs {
    dir: PathBuf,
    created_dir: bool,
    staged: Vec<(PathBuf, PathBuf)>,
}

impl Outputs {
    /// Outputs named `names` in `dir`, which is made if it does not exist (its parent must).
    /// Refused before any work if one of them is a directory.
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
        let created_dir = if dir.is_dir() {
            false
        } else if dir.exists() {
            return Err(Error::input(dir_name, "is a file, not a directory"));
        } else {
            fs::create_dir_all(dir).map_err(|e| Error::io(&dir_name, "create it", &e))?;
            true
        };
        Ok(Self {
            dir: dir.to_path_buf(),
            created_dir,
            staged: Vec::new(),
        })
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Writes one file's bytes to its temporary name.
    pub fn stage(&mut self, name: &str, bytes: &[u8]) -> Result<()> {
        let target = self.dir.join(name);
        let tmp = temporary_beside(&target);
        fs::write(&tmp, bytes).map_err(|e| {
            let _ = fs::remove_file(&tmp);
            Error::io(target.display().to_string(), "write", &e)
        })?;
        self.staged.push((tmp, target));
        Ok(())
    }

    /// Moves every staged file into place.
    pub fn commit(mut self) -> Result<()> {
        let staged = std::mem::take(&mut self.staged);
        for (k, (tmp, target)) in staged.iter().enumerate() {
            if let Err(e) = fs::rename(tmp, target) {
                for (t, _) in &staged[k..] {
                    let _ = fs::remove_file(t);
                }
                return Err(Error::io(target.display().to_string(), "write", &e));
            }
        }
        self.created_dir = false;
        Ok(())
    }
}

impl Drop for Outputs {
    fn drop(&mut self) {
        for (tmp, _) in &self.staged {
            let _ = fs::remove_file(tmp);
        }
        if self.created_dir {
            // Only if it is still empty: remove_dir refuses otherwise.
            let _ = fs::remove_dir(&self.dir);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_default_name_never_replaces_a_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.png");
        assert_eq!(write_new(&p, b"one").unwrap(), p);
        let second = write_new(&p, b"two").unwrap();
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

    #[test]
    fn a_byte_order_mark_is_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("bom.csv");
        fs::write(&p, "\u{feff}a,b\n").unwrap();
        assert_eq!(read_text(&p).unwrap(), "a,b\n");
    }
}
