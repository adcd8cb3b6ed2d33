//! Files the lab reads and writes, as a vocabulary every part of the app shares: what a
//! given file is for (`Purpose`), given files grouped by it, and saving to the file the user
//! named (a download of that name in the browser; docs/design.md §5.8). Reading them into
//! the lab is the app's (`file_io`).

use std::path::Path;

/// What a lesson file's name ends with (a dropped `.toml` without it is a scene).
pub const LESSON_EXTENSION: &str = ".lesson.toml";

/// The most bytes of a lesson file the lab reads (`crate::files::read_text`): a lesson's 200
/// steps of 4 000 characters (up to 4 bytes each) with their views fit in 4 MiB.
pub const LESSON_MAX_BYTES: u64 = 4 << 20;

/// What a given file is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purpose {
    Scene,
    /// Table A, shaded with.
    Table,
    /// Table B, compared with.
    TableB,
    /// A `study.csv` for the chart.
    Study,
    /// A lesson (`*.lesson.toml`).
    Lesson,
    /// A method of the user's own (`*.wgsl`, docs/design.md §5.13): shader code, so only
    /// ever a file the user picked, dropped or named.
    Method,
}

impl Purpose {
    /// The most bytes of such a file the lab reads, from a path, a drop or a picker.
    pub fn max_bytes(self) -> u64 {
        match self {
            Self::Scene => crate::scene::MAX_FILE_BYTES,
            Self::Table | Self::TableB => crate::ltc::lut::MAX_FILE_BYTES,
            Self::Study => crate::measure::study::MAX_FILE_BYTES,
            Self::Lesson => LESSON_MAX_BYTES,
            Self::Method => crate::gpu::method_file::MAX_BYTES as u64,
        }
    }

    /// The most bytes of any file the lab reads (a dropped file's, before its name says what
    /// it is for).
    pub fn largest_max_bytes() -> u64 {
        [
            Self::Scene,
            Self::Table,
            Self::Study,
            Self::Lesson,
            Self::Method,
        ]
        .map(Self::max_bytes)
        .into_iter()
        .max()
        .unwrap_or(0)
    }

    /// What a dropped file is for, by its extension: a lesson, a scene, a table (A) or a
    /// study.
    pub fn of_name(name: &str) -> Option<Self> {
        if name.to_ascii_lowercase().ends_with(LESSON_EXTENSION) {
            return Some(Self::Lesson);
        }
        let ext = Path::new(name)
            .extension()?
            .to_string_lossy()
            .to_ascii_lowercase();
        match ext.as_str() {
            "toml" => Some(Self::Scene),
            "exr" | "js" | "dds" => Some(Self::Table),
            "csv" => Some(Self::Study),
            "wgsl" => Some(Self::Method),
            _ => None,
        }
    }

    /// The browser file picker's filter.
    pub fn accept(self) -> &'static str {
        match self {
            // A lesson's name ends in .lesson.toml, which a picker cannot filter by.
            Self::Scene | Self::Lesson => ".toml",
            Self::Table | Self::TableB => ".exr,.js,.dds,.txt",
            Self::Study => ".csv",
            Self::Method => ".wgsl",
        }
    }

    /// More than one file: a DDS pair (with its header sidecar).
    pub fn multiple(self) -> bool {
        matches!(self, Self::Table | Self::TableB)
    }
}

/// A file's name and bytes.
pub type Given = (String, Vec<u8>);

/// Given files grouped by what they are for (by their names: the files of a DDS pair
/// together, its header sidecar with them), and why any cannot be taken.
pub fn group(files: Vec<Given>) -> (Vec<(Purpose, Vec<Given>)>, Vec<String>) {
    let mut groups: Vec<(Purpose, Vec<Given>)> = Vec::new();
    let mut refused = Vec::new();
    let mut sidecars = Vec::new();
    for (name, bytes) in files {
        let Some(purpose) = Purpose::of_name(&name) else {
            if name.ends_with(crate::ltc::formats::DDS_HEADER_FILE) {
                sidecars.push((name, bytes));
            } else {
                refused.push(format!(
                    "{name}: not a file the lab reads (a scene .toml, a table .exr/.js/.dds, a study .csv, a lesson .lesson.toml, a method .wgsl)"
                ));
            }
            continue;
        };
        match groups.iter_mut().find(|(p, _)| *p == purpose) {
            Some(g) if purpose == Purpose::Table => g.1.push((name, bytes)),
            _ => groups.push((purpose, vec![(name, bytes)])),
        }
    }
    if let Some(g) = groups.iter_mut().find(|(p, _)| *p == Purpose::Table) {
        g.1.extend(sidecars);
    }
    (groups, refused)
}

/// Saves `bytes` as the file the user named, `path`: that file and no other is written on
/// the desktop; the browser offers a download of its name. What was done, for the message.
pub fn save(path: &Path, bytes: &[u8], mime: &str) -> Result<String, String> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = mime;
        crate::files::write_atomically(path, bytes).map_err(|e| e.to_string())?;
        Ok(format!("saved {}", path.display()))
    }
    #[cfg(target_arch = "wasm32")]
    {
        let name = path
            .file_name()
            .map_or_else(|| "ltc-lab".into(), |n| n.to_string_lossy().into_owned());
        crate::app::browser::download(&name, bytes, mime)?;
        Ok(format!("downloaded {name}"))
    }
}
