//! Tables A and B: the 2D tables each side shades isotropic materials with, and the 4D
//! tables each shades anisotropic ones with (docs/design.md §2.9), kept between runs as where
//! they came from.

use serde::{Deserialize, Serialize};

use crate::app::lab::part::Checked;
use crate::ltc::aniso::AnisoAxes;
use crate::ltc::aniso::source::AnisoSource;
use crate::ltc::lut::Table;
use crate::tables::{NamedTable, NamedTables, Source};

/// Which table a panel reads: A (shaded with) or B (compared with).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum TableId {
    #[default]
    A,
    B,
}

/// Tables A and B, and the shipped table A stands for (whose default B is B unless a file
/// is). Kept between runs as where they came from (`TableSources`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(from = "TableSources", into = "TableSources")]
pub struct Tables {
    pub shipped: Table,
    pub named: NamedTables,
    /// The 4D tables of A and B (their luts carry them).
    aniso: [AnisoSource; 2],
    /// What could not be read again when the tables were made from their sources (said
    /// where they enter the lab).
    lost: Vec<String>,
}

/// Where the tables came from: the shipped table, the files of A and B, and their 4D tables.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct TableSources {
    pub shipped: Table,
    pub a_file: Option<String>,
    pub b_file: Option<String>,
    pub aniso_a: AnisoSource,
    pub aniso_b: AnisoSource,
}

impl Default for TableSources {
    fn default() -> Self {
        let [aniso_a, aniso_b] = DEFAULT_ANISO;
        Self {
            shipped: Table::default(),
            a_file: None,
            b_file: None,
            aniso_a,
            aniso_b,
        }
    }
}

/// A shades anisotropic materials with the lab's 4D table and B with I3D 2022's (α_x, α_y)
/// table, the published one the lab's is measured against.
const DEFAULT_ANISO: [AnisoSource; 2] = [AnisoSource::Lab, AnisoSource::I3d(AnisoAxes::I3dAlphaXY)];

impl Default for Tables {
    fn default() -> Self {
        Self::shipped(Table::Classic)
    }
}

impl Tables {
    /// The shipped table `t` as A, and its default B.
    pub fn shipped(t: Table) -> Self {
        Self {
            shipped: t,
            named: NamedTables::shipped(t),
            aniso: DEFAULT_ANISO,
            lost: Vec::new(),
        }
        .carrying_aniso()
    }

    /// The 4D table side `id` shades anisotropic materials with.
    pub fn aniso(&self, id: TableId) -> &AnisoSource {
        &self.aniso[id as usize]
    }

    /// The same with `source` as side `id`'s 4D table; a file is read and checked first.
    pub fn with_aniso(&self, id: TableId, source: AnisoSource) -> crate::error::Result<Self> {
        let table = source.load()?;
        let mut out = self.clone();
        out.aniso[id as usize] = source;
        let named = match id {
            TableId::A => &mut out.named.a,
            TableId::B => &mut out.named.b,
        };
        named.lut = named.lut.clone().with_aniso(table);
        Ok(out)
    }

    /// Each side's lut with its 4D table; one that cannot be read (a file gone since) leaves
    /// the lab's in its place, and says so where the tables enter the lab.
    fn carrying_aniso(mut self) -> Self {
        for id in [TableId::A, TableId::B] {
            let source = self.aniso(id).clone();
            let table = source.load().unwrap_or_else(|e| {
                self.lost.push(format!(
                    "table {id:?}'s 4D table was {}, which cannot be read again ({e})",
                    source.name()
                ));
                self.aniso[id as usize] = AnisoSource::Lab;
                AnisoSource::lab_table()
            });
            let named = match id {
                TableId::A => &mut self.named.a,
                TableId::B => &mut self.named.b,
            };
            named.lut = named.lut.clone().with_aniso(table);
        }
        self
    }

    pub fn a(&self) -> &NamedTable {
        &self.named.a
    }

    pub fn b(&self) -> &NamedTable {
        &self.named.b
    }

    pub fn get(&self, id: TableId) -> &NamedTable {
        match id {
            TableId::A => self.a(),
            TableId::B => self.b(),
        }
    }

    /// Whether table B is the one A's shipped table is compared with (not one the user
    /// named).
    pub fn b_is_default(&self) -> bool {
        self.b().source == Source::Shipped(self.shipped.default_b())
    }

    /// The same with `a` as table A (standing in for `shipped`): a table B the user named
    /// stays, a default one follows A's shipped table.
    pub fn with_a(&self, a: NamedTable, shipped: Table) -> Self {
        let named = match self.b_is_default() {
            true => NamedTables::with_a(a, shipped),
            false => NamedTables {
                a,
                b: self.b().clone(),
            },
        };
        Self {
            shipped,
            named,
            aniso: self.aniso.clone(),
            lost: Vec::new(),
        }
        .carrying_aniso()
    }

    /// The same with `b` as table B (`None`: A's default B).
    pub fn with_b(&self, b: Option<NamedTable>) -> Self {
        let b = b.unwrap_or_else(|| NamedTable::shipped(self.shipped.default_b()));
        Self {
            named: NamedTables {
                a: self.a().clone(),
                b,
            },
            ..self.clone()
        }
        .carrying_aniso()
    }
}

impl From<Tables> for TableSources {
    fn from(t: Tables) -> Self {
        let file = |n: &NamedTable| match &n.source {
            Source::File(path) => Some(path.clone()),
            Source::Shipped(_) | Source::Given(_) => None,
        };
        Self {
            shipped: t.shipped,
            a_file: file(t.a()),
            b_file: file(t.b()),
            aniso_a: t.aniso(TableId::A).clone(),
            aniso_b: t.aniso(TableId::B).clone(),
        }
    }
}

impl From<TableSources> for Tables {
    /// The tables the sources name, their files read again; a file that cannot be read
    /// leaves the shipped table in its place, and says why where the tables enter the lab.
    fn from(s: TableSources) -> Self {
        let mut lost = Vec::new();
        let mut read = |file: &Option<String>, which: &str| {
            let path = file.as_ref()?;
            match NamedTable::from_file(path) {
                Ok((table, _)) => Some(table),
                Err(e) => {
                    lost.push(format!(
                        "table {which} was {path}, which cannot be read again ({e})"
                    ));
                    None
                }
            }
        };
        let (a, b) = (read(&s.a_file, "A"), read(&s.b_file, "B"));
        let a = a.unwrap_or_else(|| NamedTable::shipped(s.shipped));
        let tables = Tables {
            aniso: [s.aniso_a, s.aniso_b],
            ..Tables::shipped(s.shipped)
        };
        let mut tables = tables.with_a(a, s.shipped).with_b(b);
        lost.append(&mut tables.lost);
        Self { lost, ..tables }
    }
}

impl Checked for Tables {
    /// Every table was checked when it was read; what could not be read again is said.
    fn check(&mut self, _: &Self) -> Vec<String> {
        let lost = std::mem::take(&mut self.lost);
        if lost.is_empty() {
            return lost;
        }
        vec![format!(
            "{}: shading with the {} table, comparing with {}",
            lost.join("; "),
            self.a().name,
            self.b().name
        )]
    }
}
