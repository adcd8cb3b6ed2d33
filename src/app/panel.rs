//! What a panel is: one door (`Panel::show`) and one name (`PanelId`), the side panel's and
//! the five of the grid. The registry that holds them is `panels`.

use serde::{Deserialize, Serialize};

use crate::app::lab::{Lab, SideB};
use crate::named::named_enum;

/// Every panel: it draws itself into `ui`, reads and edits the lab, and keeps its own state
/// and work.
pub trait Panel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab);

    /// Whether it is still computing something for the window.
    fn busy(&self) -> bool {
        false
    }

    /// Its caches (`app::work::cache`): each one's name and how many values it has made.
    fn caches(&self) -> Vec<(&'static str, u64)> {
        Vec::new()
    }
}

named_enum! {
    /// The panels: the side panel, then the grid's five.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
    pub enum PanelId {
        Controls = "controls",
        Lobe = "lobe",
        Matrix = "matrix",
        Plane = "plane",
        Clipping = "clipping",
        Chart = "chart",
    }
}

impl PanelId {
    /// The grid's panels: each can be shown alone (maximised, a tab, `lab --panel`).
    pub const GRID: [Self; 5] = [
        Self::Lobe,
        Self::Matrix,
        Self::Plane,
        Self::Clipping,
        Self::Chart,
    ];

    /// Its title on its frame and its tab: the plane's says what its two sides are.
    pub fn title(self, lab: &Lab) -> String {
        match self {
            Self::Controls => "Controls".into(),
            Self::Lobe => "Lobe on the sphere".into(),
            Self::Matrix => "Matrix and LUT".into(),
            Self::Plane => match **lab.side_b() {
                SideB::Brdf => "Plane: LTC | BRDF".into(),
                SideB::TableB => format!(
                    "Plane: table A ({}) | table B ({})",
                    lab.tables().a().short_name(),
                    lab.tables().b().short_name()
                ),
            },
            Self::Clipping => "Clipping (Figure 2)".into(),
            Self::Chart => "Speed vs accuracy".into(),
        }
    }

    /// The panel `name` names, one of the grid's.
    pub fn of_name(name: &str) -> Option<Self> {
        Self::from_name(name).filter(|p| Self::GRID.contains(p))
    }
}
