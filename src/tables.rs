//! Tables A and B, each with its name: where it came from (a shipped table's name, or the
//! file's path). Table A is the one shaded with; table B is the one compared with: by default
//! the other shipped table, or one the user named (the lab's *as B*, `render --lut-b`). A
//! render borrows both as `render::Tables`.

use crate::ltc::lut::{Lut, Table};

/// A table and what it is called: `classic`, `point`, or the file's path.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedTable {
    pub lut: Lut,
    pub name: String,
}

impl NamedTable {
    pub fn shipped(t: Table) -> Self {
        Self {
            lut: Lut::shipped(t).clone(),
            name: t.name().to_string(),
        }
    }

    /// The name without its directories, for a title.
    pub fn short_name(&self) -> &str {
        std::path::Path::new(&self.name)
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or(&self.name)
    }
}

/// Tables A and B.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedTables {
    pub a: NamedTable,
    pub b: NamedTable,
    /// B was named by the user: it stays when A changes (else it follows A to A's other).
    pub b_chosen: bool,
}

impl NamedTables {
    /// `a` as table A, and the other shipped table as B.
    pub fn shipped(a: Table) -> Self {
        Self::with_a(NamedTable::shipped(a), a)
    }

    /// `a` (standing in for the shipped `shipped_a`) as table A, and `shipped_a`'s other as B.
    pub fn with_a(a: NamedTable, shipped_a: Table) -> Self {
        Self {
            a,
            b: NamedTable::shipped(shipped_a.default_b()),
            b_chosen: false,
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
