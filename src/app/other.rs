//! Table B, the "other fit": the other shipped table unless the user loaded one. The lobe
//! overlay and the matrix panel show it beside table A, and the plane's side B shades with it
//! when two tables are compared.

use crate::ltc::lut::{Lut, Table};

pub struct OtherTable {
    pub lut: Lut,
    /// What it is, for labels: `point`, `classic`, or the file's path.
    pub name: String,
    /// Loaded by the user: it stays when table A changes (else it follows A's other).
    pub chosen: bool,
}

impl OtherTable {
    /// The shipped table that is not `a`.
    pub fn shipped_other(a: Table) -> Self {
        Self {
            lut: Lut::shipped(a.other()).clone(),
            name: a.other().name().to_string(),
            chosen: false,
        }
    }

    /// A table the user loaded.
    pub fn chosen(lut: Lut, name: String) -> Self {
        Self {
            lut,
            name,
            chosen: true,
        }
    }
}
