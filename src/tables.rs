//! Tables A and B, each with its name and where it came from. Table A is the one shaded with;
//! table B is the one compared with: by default the other shipped table of A's
//! (`Table::default_b`), or one the user named (the lab's *as B*, `render --lut-b`). A render
//! borrows both as `render::Tables`. The lab and `render` read table files alike.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::ltc::formats;
use crate::ltc::lut::{Lut, Table};

/// Where a table came from.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Source {
    /// One of the tables embedded in the binary.
    Shipped(Table),
    /// A file, read again at the lab's next start.
    File(String),
    /// Files a browser's picker or a drop handed over by name: no later start can read them.
    Given(String),
}

/// A table, what it is called (`classic`, `point`, a file's path), and where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedTable {
    pub lut: Lut,
    pub name: String,
    pub source: Source,
}

impl NamedTable {
    pub fn shipped(t: Table) -> Self {
        Self {
            lut: Lut::shipped(t).clone(),
            name: t.name().to_string(),
            source: Source::Shipped(t),
        }
    }

    /// The name without its directories, for a title.
    pub fn short_name(&self) -> &str {
        Path::new(&self.name)
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or(&self.name)
    }

    /// A table read (`formats::Loaded`) named `name`, from `source`; its `spec.err` measured
    /// where its format had none (the lab's heat maps and refits show it). What the format
    /// could not hold, as ". note".
    pub fn read(mut loaded: formats::Loaded, name: &str, source: Source) -> (Self, String) {
        loaded.measure_spec_err(&|| {});
        let note = loaded.note.map(|n| format!(". {n}")).unwrap_or_default();
        let table = Self {
            lut: loaded.lut.into_owned(),
            name: name.to_string(),
            source,
        };
        (table, note)
    }

    /// The table in the file at `path`, named by the path.
    pub fn from_file(path: &str) -> crate::error::Result<(Self, String)> {
        let loaded = formats::read(Path::new(path))?;
        Ok(Self::read(loaded, path, Source::File(path.to_string())))
    }
}

/// Tables A and B.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedTables {
    pub a: NamedTable,
    pub b: NamedTable,
}

impl NamedTables {
    /// `a` as table A, and the other shipped table as B.
    pub fn shipped(a: Table) -> Self {
        Self::with_a(NamedTable::shipped(a), a)
    }

    /// `a` (standing in for the shipped `shipped_a`) as table A, and `shipped_a`'s default
    /// table B.
    pub fn with_a(a: NamedTable, shipped_a: Table) -> Self {
        Self {
            a,
            b: NamedTable::shipped(shipped_a.default_b()),
        }
    }

    /// Both, borrowed for a render.
    pub fn pair(&self) -> crate::render::Tables<'_> {
        crate::render::Tables {
            a: &self.a.lut,
            b: &self.b.lut,
        }
    }
}
