//! Which 4D table a side shades anisotropic materials with (docs/design.md §2.9): the lab's
//! shipped one, one of the two I3D 2022 tables (embedded, read as an engine reads them), or
//! a table file of this project's 4D layout.

use std::path::PathBuf;
use std::sync::{Arc, OnceLock};

use crate::error::Result;
use crate::ltc::aniso::anchor;
use crate::ltc::aniso::{AnisoAxes, AnisoLut};

/// A 4D table by where it comes from.
#[derive(Clone, Debug, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub enum AnisoSource {
    /// The lab's shipped table (`luts/ltc_aniso.exr`).
    Lab,
    /// A published I3D 2022 table, by its axes (`I3dAlphaXY` or `I3dAlphaLambda`).
    I3d(AnisoAxes),
    /// A 4D table file (`ltc-lab fit --aniso`'s .exr).
    File(PathBuf),
}

impl AnisoSource {
    /// The names on the command line: `lab`, `i3d-alphax-alphay`, `i3d-alpha-lambda`, or a
    /// file's path.
    pub fn parse(s: &str) -> Self {
        match s {
            "lab" => Self::Lab,
            n if n == AnisoAxes::I3dAlphaXY.name() => Self::I3d(AnisoAxes::I3dAlphaXY),
            n if n == AnisoAxes::I3dAlphaLambda.name() => Self::I3d(AnisoAxes::I3dAlphaLambda),
            path => Self::File(PathBuf::from(path)),
        }
    }

    /// What a message calls it.
    pub fn name(&self) -> String {
        match self {
            Self::Lab => "the lab's 4D table (luts/ltc_aniso.exr)".into(),
            Self::I3d(axes) => format!("I3D 2022's {} table", axes.name()),
            Self::File(p) => p.display().to_string(),
        }
    }

    /// What a crowded header calls it.
    pub fn short_name(&self) -> String {
        match self {
            Self::Lab => "lab".into(),
            Self::I3d(axes) => axes.name().into(),
            Self::File(p) => p.file_name().map_or_else(
                || p.display().to_string(),
                |n| n.to_string_lossy().into_owned(),
            ),
        }
    }

    /// The lab's shipped table, shared.
    pub fn lab_table() -> Arc<AnisoLut> {
        shipped_arc(None)
    }

    /// The table; a file is read and checked (errors name it).
    pub fn load(&self) -> Result<Arc<AnisoLut>> {
        match self {
            Self::Lab => Ok(shipped_arc(None)),
            Self::I3d(axes) => Ok(shipped_arc(Some(*axes))),
            Self::File(path) => AnisoLut::read(path).map(Arc::new),
        }
    }
}

/// The embedded tables, each made once and shared: the lab's, and I3D 2022's two with the
/// lab's magnitudes (`anchor::shipped`).
fn shipped_arc(i3d: Option<AnisoAxes>) -> Arc<AnisoLut> {
    static LAB: OnceLock<Arc<AnisoLut>> = OnceLock::new();
    static XY: OnceLock<Arc<AnisoLut>> = OnceLock::new();
    static LAMBDA: OnceLock<Arc<AnisoLut>> = OnceLock::new();
    match i3d {
        None => LAB.get_or_init(|| Arc::new(AnisoLut::shipped().clone())),
        Some(AnisoAxes::I3dAlphaLambda) => LAMBDA.get_or_init(|| {
            Arc::new(anchor::shipped(
                AnisoAxes::I3dAlphaLambda,
                AnisoLut::shipped(),
            ))
        }),
        Some(_) => {
            XY.get_or_init(|| Arc::new(anchor::shipped(AnisoAxes::I3dAlphaXY, AnisoLut::shipped())))
        }
    }
    .clone()
}
