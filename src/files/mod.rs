//! Files in and out, so that nothing is lost: a named output is replaced only by a complete
//! one, a default name never replaces anything, and a set of outputs lands all together or
//! not at all.
//!
//! A default name is claimed when the command starts (an empty file, or a directory, made
//! exclusively), so that two runs at once never pick the same one and a file that appears
//! while the command works is never replaced; the output replaces the claim at the end.
//!
//! Everything unfinished (temporary files, claimed names, directories made for outputs) is
//! listed in one registry while it exists, so that an interrupt can remove it all
//! ([`exit_interrupted`]): a signal skips every `Drop`. Each such path is made and finished
//! (renamed into place or removed) while the registry is locked, so an interrupt sees every
//! path either listed or finished, never in between.

mod claim;
mod outputs;
#[cfg(test)]
mod tests;
mod unfinished;

use std::fs;
use std::path::{Component, Path, PathBuf};

use crate::error::{Error, Result};
use unfinished::{next_serial, rename_into_place, unfinished, write_listed};

pub use claim::Claim;
pub use outputs::Outputs;
pub use unfinished::exit_interrupted;

/// The bytes of the file at `path`, read up to `limit`: a longer file is refused as bad input
/// naming the file and the limit once `limit + 1` bytes were read, and anything that is not a
/// regular file (a directory, a FIFO, a device such as `/dev/zero`, a socket) is refused at
/// once naming what it is, before it is opened (opening a FIFO waits for a writer), so no input
/// can hold the program for longer or take more memory than its limit. Every file the lab and
/// the CLI read comes through here.
pub fn read_bytes(path: &Path, limit: u64) -> Result<Vec<u8>> {
    use std::io::Read;
    let name = path.display().to_string();
    let meta = fs::metadata(path).map_err(|e| Error::io(&name, "read", &e))?;
    check_regular(&name, &meta.file_type())?;
    let file = fs::File::open(path).map_err(|e| Error::io(&name, "read", &e))?;
    // Checked again on what was opened: the path may have been replaced in between.
    let opened = file.metadata().map_err(|e| Error::io(&name, "read", &e))?;
    check_regular(&name, &opened.file_type())?;
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| Error::io(&name, "read", &e))?;
    check_length(&name, bytes.len(), limit)?;
    Ok(bytes)
}

/// Refuses the input `name` unless `kind` is a regular file, naming what it is.
fn check_regular(name: &str, kind: &fs::FileType) -> Result<()> {
    if kind.is_file() {
        return Ok(());
    }
    let what = if kind.is_dir() {
        "a directory"
    } else {
        special_kind(kind)
    };
    Err(Error::input(name, format!("is {what}, not a regular file")))
}

/// What a file that is neither regular nor a directory is, in words.
#[cfg(unix)]
fn special_kind(kind: &fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    match kind {
        k if k.is_fifo() => "a FIFO (named pipe)",
        k if k.is_char_device() => "a character device",
        k if k.is_block_device() => "a block device",
        k if k.is_socket() => "a socket",
        _ => "a special file",
    }
}

#[cfg(not(unix))]
fn special_kind(_: &fs::FileType) -> &'static str {
    "a special file"
}

/// Refuses `len` bytes of the input `name` past `limit` (a file read whole elsewhere, such
/// as one dropped on the window or picked in a browser, is held to the same limit).
pub fn check_length(name: &str, len: usize, limit: u64) -> Result<()> {
    if len as u64 > limit {
        return Err(Error::input(
            name,
            format!(
                "is longer than the {} this program reads of such a file",
                size_in_words(limit)
            ),
        ));
    }
    Ok(())
}

/// `limit` bytes in words: `4 MiB`, `512 kiB`, `100 bytes`.
fn size_in_words(limit: u64) -> String {
    match limit {
        l if l >= 1 << 20 && l % (1 << 20) == 0 => format!("{} MiB", l >> 20),
        l if l >= 1 << 10 && l % (1 << 10) == 0 => format!("{} kiB", l >> 10),
        l => format!("{l} bytes"),
    }
}

/// A text file read up to `limit` bytes (`read_bytes`), without a leading UTF-8 byte-order
/// mark (spreadsheets write one).
pub fn read_text(path: &Path, limit: u64) -> Result<String> {
    let name = path.display().to_string();
    text_of(read_bytes(path, limit)?, &name)
}

/// Bytes as UTF-8 text without a leading byte-order mark; refused naming `name` otherwise.
pub fn text_of(bytes: Vec<u8>, name: &str) -> Result<String> {
    let text = String::from_utf8(bytes)
        .map_err(|e| Error::input(name, format!("is not UTF-8 text ({e})")))?;
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

/// Whether `path` can be written: its directory exists and takes new files (a file is made
/// and removed there: permissions alone do not tell, e.g. for root in /sys), and it is not
/// itself a directory. Checked before long work, so that a typo costs nothing.
pub fn check_writable(path: &Path) -> Result<()> {
    let name = path.display().to_string();
    let dir = parent_dir(path);
    if !dir.is_dir() {
        return Err(Error::input(name, "its directory does not exist"));
    }
    if path.is_dir() {
        return Err(Error::input(name, "is a directory"));
    }
    if path.file_name().is_none() {
        return Err(Error::input(name, "not a file path"));
    }
    probe_directory(&dir).map_err(|e| Error::io(name, "write into its directory", &e))
}

/// Makes and removes a uniquely named file in `dir`. The registry is held throughout, so an
/// interrupt cannot fall between the two and leave the probe behind.
pub(super) fn probe_directory(dir: &Path) -> std::io::Result<()> {
    let probe = dir.join(format!(
        ".ltc-lab.{}-{}.probe",
        std::process::id(),
        next_serial()
    ));
    let _list = unfinished();
    fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)?;
    fs::remove_file(&probe)
}

/// Whether `path` ends in `.exr` (any case): an OpenEXR file by its name.
pub fn is_exr(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"))
}

/// Refuses two outputs of one command that name the same file (the second would replace
/// the first): `outputs` are (flag, path) pairs, and the later flag of a pair is named.
/// Paths match if they are equal once made absolute and rid of `.` and `..`, or if their
/// directories exist and are the same directory (through links) and the file names agree.
pub fn check_distinct(outputs: &[(&str, &Path)]) -> Result<()> {
    for (k, &(flag, path)) in outputs.iter().enumerate() {
        if let Some(&(earlier, first)) = outputs[..k].iter().find(|(_, p)| same_file(p, path)) {
            return Err(Error::input(
                flag,
                format!("names the same file as {earlier} ({})", first.display()),
            ));
        }
    }
    Ok(())
}

fn same_file(a: &Path, b: &Path) -> bool {
    if lexical(a) == lexical(b) {
        return true;
    }
    let real = |p: &Path| Some(fs::canonicalize(parent_dir(p)).ok()?.join(p.file_name()?));
    matches!((real(a), real(b)), (Some(x), Some(y)) if x == y)
}

/// `path` made absolute, with `.` dropped and `..` taken off the path lexically.
fn lexical(path: &Path) -> PathBuf {
    let absolute = std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf());
    let mut out = PathBuf::new();
    for c in absolute.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// A temporary name beside `path`, unique to this process and call.
pub(super) fn temporary_beside(path: &Path) -> PathBuf {
    let file_name = path
        .file_name()
        .map_or("out".into(), |f| f.to_string_lossy());
    parent_dir(path).join(format!(
        ".{file_name}.{}-{}.partial",
        std::process::id(),
        next_serial()
    ))
}

/// Writes `bytes` to `path` (a file the user named, which may be replaced) through a
/// temporary file beside it: a failure leaves no partial output and the old file intact.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<()> {
    check_writable(path)?;
    let name = path.display().to_string();
    let tmp = temporary_beside(path);
    write_listed(&tmp, bytes)
        .and_then(|()| rename_into_place(&tmp, path))
        .map_err(|e| Error::io(name, "write", &e))
}

/// `path`, or `stem-2.ext`, `stem-3.ext`… : the candidates for a default output name.
pub(super) fn numbered(path: &Path, k: usize) -> PathBuf {
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
    // A bare name stays bare (`study-2`, not `./study-2`): it is what the command reports.
    path.with_file_name(name)
}

/// How many numbered names a default output tries before giving up.
pub(super) const MAX_NUMBERED: usize = 10_000;
