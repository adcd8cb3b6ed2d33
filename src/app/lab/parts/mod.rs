//! The parts the panels share, each a value of its own type with the checks it passes where
//! it enters the lab: the scene as four parts (its lights, its material, the stage — plane and
//! camera — and the exposure it is shown with), the view of the lobe and matrix panels, the
//! shading forms, how each side shades lights with a size, side B, the lights' overrides, the
//! LTC rules, the tables, the selection and the last refit (`scene.rs`, `shading.rs`,
//! `view.rs`). The lab holds each in a `Part` (`app::lab`).

mod scene;
mod shading;
mod view;

pub use scene::{EXPOSURE_RANGE, Exposure, Lights, Stage, scene, shaded};
pub use shading::{
    BRDF_FORMS, Forms, INTENSITY_RANGE, LTC_FORMS, Overrides, RANGE_RANGE, ShapeForms, SideB,
};
pub use view::{LastRefit, LobeView, Selection};

pub use crate::app::lab::light_check::RADIUS_RANGE;
