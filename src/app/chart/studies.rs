//! The studies the lab ships, for the chart to plot and the lesson to quote: each a
//! `study.csv` made by `ltc-lab study` on one machine, its device and set-up in its comment
//! lines.

use crate::app::chart::measure::Measurement;
use crate::named::named_enum;

named_enum! {
    /// The studies the lab ships, each made by `ltc-lab study` (its `# made with:` line says
    /// how): on this project's CPU driver (lavapipe, the chart's default), and on a lent
    /// NVIDIA H100, so that a machine without a GPU can still show what a GPU measures.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum ShippedStudy {
        Lavapipe = "lavapipe",
        H100 = "H100",
    }
}

impl ShippedStudy {
    /// Its file in the repository.
    pub fn path(self) -> &'static str {
        match self {
            Self::Lavapipe => "assets/study/reference.csv",
            Self::H100 => "assets/study/h100.csv",
        }
    }

    /// Its file's text, embedded.
    pub fn text(self) -> &'static str {
        match self {
            Self::Lavapipe => include_str!("../../../assets/study/reference.csv"),
            Self::H100 => include_str!("../../../assets/study/h100.csv"),
        }
    }

    /// The device its `# device:` line names.
    pub fn device(self) -> &'static str {
        self.text()
            .lines()
            .find_map(|l| l.strip_prefix("# device: "))
            .unwrap_or("unknown device")
    }

    /// The study as the chart plots it.
    pub fn measurement(self) -> Option<Measurement> {
        let rows = crate::measure::study::parse_csv(self.text(), self.path()).ok()?;
        let mut m = Measurement::from_study(&rows, self.path());
        let label = match self {
            Self::Lavapipe => "reference",
            Self::H100 => self.name(),
        };
        m.device = format!("{label} study ({})", self.device());
        m.study = Some(self.name().into());
        Some(m)
    }
}

/// The chart's default: the study on this project's CPU driver.
pub fn reference_study() -> Option<Measurement> {
    ShippedStudy::Lavapipe.measurement()
}
