//! One error type: every message names the input it is about, and says whether the input was
//! at fault (exit code 2) or the machine (exit code 1: no adapter, a GPU or I/O failure).

/// Who is at fault.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorKind {
    /// A file, argument or value that cannot be used.
    Input,
    /// The machine failed on good input: no adapter, a GPU error, a full disk.
    Machine,
}

/// What went wrong, and with what. The CLI prints it on one line.
#[derive(Debug, thiserror::Error)]
#[error("{input}: {message}")]
pub struct Error {
    pub kind: ErrorKind,
    /// The file, argument or value at fault (`scene.toml`, `--size`, `cases.csv line 3`).
    pub input: String,
    pub message: String,
}

impl Error {
    /// Bad input.
    pub fn input(input: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            kind: ErrorKind::Input,
            input: input.into(),
            message: message.into(),
        }
    }

    /// A failure of the machine on good input.
    pub fn machine(input: impl Into<String>, message: impl Into<String>) -> Self {
        Self {
            kind: ErrorKind::Machine,
            ..Self::input(input, message)
        }
    }

    /// An I/O error while `doing` something with `input`: the path's fault where it names
    /// something that is missing, forbidden or of the wrong kind; the machine's otherwise
    /// (a full disk, a device error).
    pub fn io(input: impl Into<String>, doing: &str, e: &std::io::Error) -> Self {
        use std::io::ErrorKind as K;
        let message = format!("cannot {doing}: {}", io_reason(e));
        match e.kind() {
            K::NotFound
            | K::PermissionDenied
            | K::AlreadyExists
            | K::IsADirectory
            | K::NotADirectory
            | K::InvalidInput
            | K::InvalidFilename
            | K::ReadOnlyFilesystem
            | K::InvalidData => Self::input(input, message),
            _ => Self::machine(input, message),
        }
    }

    /// The process exit code of docs/design.md §6: 2 for bad input, 1 for the machine.
    pub fn exit_code(&self) -> u8 {
        match self.kind {
            ErrorKind::Input => 2,
            ErrorKind::Machine => 1,
        }
    }
}

/// A number in a message as people write it: plainly near 1, in exponent form far from it
/// (`1e-300`, not Rust's 300 digits of `Display`), and always the shortest text that reads
/// back as the same value.
pub fn number<T>(x: T) -> String
where
    T: Copy + Into<f64> + std::fmt::Display + std::fmt::LowerExp,
{
    let magnitude = x.into().abs();
    if magnitude == 0.0 || !magnitude.is_finite() || (1e-4..1e6).contains(&magnitude) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The OS's words without Rust's "(os error 28)" suffix.
fn io_reason(e: &std::io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error") {
        Some(k) => text[..k].to_lowercase(),
        None => text,
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn numbers_read_as_people_write_them_and_read_back_exactly() {
        for (x, text) in [
            (f64::MIN_POSITIVE, "2.2250738585072014e-308"),
            (1e-300, "1e-300"),
            (0.5, "0.5"),
            (0.0, "0"),
            (123456.0, "123456"),
            (1e20, "1e20"),
            (f64::INFINITY, "inf"),
        ] {
            assert_eq!(number(x), text);
            if x.is_finite() {
                assert_eq!(number(x).parse::<f64>().unwrap(), x);
            }
        }
        assert_eq!(number(1e-5_f32), "1e-5");
        assert_eq!(number(0.1_f32), "0.1", "f32 keeps its own shortest form");
    }
}
