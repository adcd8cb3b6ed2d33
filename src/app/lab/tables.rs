//! Tables A and B: the 2D tables each side shades isotropic materials with, each as an
//! encoding gives it back (docs/design.md §2.10), and the 4D tables each shades anisotropic
//! ones with (§2.9), kept between runs as where they came from.

use serde::{Deserialize, Serialize};

use crate::app::lab::part::Checked;
use crate::ltc::aniso::AnisoAxes;
use crate::ltc::aniso::encoded::improper_nodes;
use crate::ltc::aniso::source::AnisoSource;
use crate::ltc::lut::{Encoding, Table};
use crate::scene::{EncodingFailure, preset};
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
    /// What each side shades with: its table as its encoding gives it back.
    pub named: NamedTables,
    /// The tables as read, before their encodings.
    plain: NamedTables,
    /// Each side's encoding (`None`: the table as read). B's, while B is the default, is
    /// table A's table in that encoding, as `render --encoding-b` makes it: the split then
    /// shows one table in two encodings.
    encodings: [Option<Encoding>; 2],
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
    /// Each side's encoding by name (`Encoding::parse`), checked where the state enters.
    pub encoding_a: Option<String>,
    pub encoding_b: Option<String>,
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
            encoding_a: None,
            encoding_b: None,
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
            plain: NamedTables::shipped(t),
            encodings: [None; 2],
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
        let plain = out.plain_mut(id);
        plain.lut = plain.lut.clone().with_aniso(table);
        Ok(out.encoded())
    }

    /// Side `id`'s table as read.
    fn plain_mut(&mut self, id: TableId) -> &mut NamedTable {
        match id {
            TableId::A => &mut self.plain.a,
            TableId::B => &mut self.plain.b,
        }
    }

    /// Side `id`'s encoding (`None`: its table as read).
    pub fn encoding(&self, id: TableId) -> Option<Encoding> {
        self.encodings[id as usize]
    }

    /// The same with `encoding` as side `id`'s.
    pub fn with_encoding(&self, id: TableId, encoding: Option<Encoding>) -> Self {
        let mut out = self.clone();
        out.encodings[id as usize] = encoding;
        out.encoded()
    }

    /// Each side's shaded table made from its table as read and its encoding: B's, where B is
    /// the default and has an encoding, from table A's table.
    fn encoded(mut self) -> Self {
        let [a, b] = self.encodings;
        let b_base = match (b, self.b_is_default()) {
            (Some(_), true) => &self.plain.a,
            _ => &self.plain.b,
        };
        // Side B's anisotropic materials keep B's own 4D table (in B's encoding), whichever
        // 2D table it reads.
        let mut b_base = b_base.clone();
        b_base.lut.aniso = self.plain.b.lut.aniso.clone();
        self.named = NamedTables {
            a: encode(&self.plain.a, a),
            b: encode(&b_base, b),
        };
        self
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
            let plain = self.plain_mut(id);
            plain.lut = plain.lut.clone().with_aniso(table);
        }
        self.encoded()
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
        self.plain.b.source == Source::Shipped(self.shipped.default_b())
    }

    /// The same with `a` as table A (standing in for `shipped`): a table B the user named
    /// stays, a default one follows A's shipped table.
    pub fn with_a(&self, a: NamedTable, shipped: Table) -> Self {
        let plain = match self.b_is_default() {
            true => NamedTables::with_a(a, shipped),
            false => NamedTables {
                a,
                b: self.plain.b.clone(),
            },
        };
        Self {
            shipped,
            named: plain.clone(),
            plain,
            encodings: self.encodings,
            aniso: self.aniso.clone(),
            lost: Vec::new(),
        }
        .carrying_aniso()
    }

    /// The same with `b` as table B (`None`: A's default B).
    pub fn with_b(&self, b: Option<NamedTable>) -> Self {
        let b = b.unwrap_or_else(|| NamedTable::shipped(self.shipped.default_b()));
        Self {
            plain: NamedTables {
                a: self.plain.a.clone(),
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
        let encoding = |id: TableId| t.encoding(id).map(|e| e.name());
        Self {
            shipped: t.shipped,
            a_file: file(&t.plain.a),
            b_file: file(&t.plain.b),
            aniso_a: t.aniso(TableId::A).clone(),
            aniso_b: t.aniso(TableId::B).clone(),
            encoding_a: encoding(TableId::A),
            encoding_b: encoding(TableId::B),
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
        for (id, name) in [(TableId::A, &s.encoding_a), (TableId::B, &s.encoding_b)] {
            let Some(name) = name else { continue };
            match Encoding::parse(name) {
                Ok(e) => tables = tables.with_encoding(id, Some(e)),
                Err(e) => lost.push(format!("table {id:?}'s encoding is not one ({e})")),
            }
        }
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

/// `table` as `encoding` gives it back, named for both (`classic as unorm8`).
fn encode(table: &NamedTable, encoding: Option<Encoding>) -> NamedTable {
    match encoding {
        None => table.clone(),
        Some(e) => NamedTable {
            lut: e.decoded(&table.lut),
            name: format!("{} as {}", table.name, e.name()),
            source: table.source.clone(),
        },
    }
}

impl super::Lab {
    /// Shows where an encoding fails: `failure`'s preset, table A as read against table A in
    /// the failing encoding as side B, on the plane's *A | B tables*.
    pub fn show_encoding_failure(&mut self, failure: EncodingFailure) {
        let Ok(encoding) = Encoding::parse(failure.encoding) else {
            return;
        };
        self.use_scene(preset(failure.preset));
        self.use_encoding(TableId::A, None);
        self.use_encoding(TableId::B, Some(encoding));
        self.set(super::SideB::TableB);
    }

    /// Shades side `id` with its table as `encoding` gives it back from now on (`None`: as
    /// read); cells the encoding turns inside out are said, as the command line says them.
    pub fn use_encoding(&mut self, id: TableId, encoding: Option<Encoding>) {
        let tables = self.tables().with_encoding(id, encoding);
        let lut = &tables.get(id).lut;
        let inside_out = lut.inside_out_cells();
        let improper = improper_nodes(lut.aniso());
        let name = tables.get(id).name.clone();
        self.set(tables);
        if inside_out > 0 || improper > 0 {
            self.say(super::Message::note(format!(
                "{name}: {inside_out} cells have an M^-1 flat or turned inside out (a \
                 determinant not above 0), and {improper} nodes of its 4D table no longer \
                 hold a proper lobe, where the encoding's error passes the small entries near \
                 α = 0 or at grazing"
            )));
        }
    }
}
