//! One error type for bad input: every message names the input it is about.

/// An input that cannot be used, and why. The CLI prints it on one line and exits with 2.
#[derive(Debug, thiserror::Error)]
#[error("{input}: {message}")]
pub struct InputError {
    /// The file, argument or value at fault (`scene.toml`, `--size`, `cases.csv line 3`).
    pub input: String,
    pub message: String,
}

impl InputError {
    pub fn new(input: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            input: input.into(),
            message: message.into(),
        }
    }
}

pub type Result<T, E = InputError> = std::result::Result<T, E>;

/// Writes `bytes` to `path` through a temporary file beside it, so that a failure leaves no
/// partial output behind and an existing file is replaced only by a complete one.
pub fn write_atomically(path: &std::path::Path, bytes: &[u8]) -> Result<()> {
    let name = path.display().to_string();
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    if !dir.is_dir() {
        return Err(InputError::new(name, "its directory does not exist"));
    }
    let file_name = path
        .file_name()
        .ok_or_else(|| InputError::new(&name, "not a file path"))?;
    let tmp = dir.join(format!(
        ".{}.{}.partial",
        file_name.to_string_lossy(),
        std::process::id()
    ));
    let result = std::fs::write(&tmp, bytes).and_then(|()| std::fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = std::fs::remove_file(&tmp);
        return Err(InputError::new(name, format!("cannot write: {e}")));
    }
    Ok(())
}
