//! The plane panel's toolbar: what side B is, the views, the exposure,
//! adding and removing lights, and the worst pixel pinned on request.

use super::{PlanePanel, side_names};
use crate::app::lab::{Exposure, Lab, Lights, LobeView, Selection, SideB};
use crate::app::plane::spots::{free_spot, worst_pixel};
use crate::light::Shape;
use crate::render::View;
use crate::scene::Light;

impl PlanePanel {
    /// The comparison's switch, the views, adding and removing lights, the worst pixel.
    pub(super) fn toolbar(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        let (a, b) = side_names(**lab.side_b());
        let b_name = lab.tables().b().name.clone();
        lab.edit(|side: &mut SideB| {
            ui.selectable_value(side, SideB::Brdf, "LTC | BRDF")
                .on_hover_text("Side B is the exact BRDF (the BRDF form in the side panel)");
            ui.selectable_value(side, SideB::TableB, "A | B tables")
                .on_hover_text(format!("Two tables compared: side B is the same LTC form with table B ({b_name}) instead of the \
                    BRDF; the difference map is then |L_A − L_B| / L_B"));
        });
        ui.separator();
        for (v, name, hover) in [
            (
                View::Split,
                "split".to_string(),
                format!("{a} left of the divider, {b} right of it; drag the divider"),
            ),
            (
                View::Diff,
                "difference".to_string(),
                format!("|L_{a} − L_{b}| / max(L_{b}, 1% of the mean), log colour scale 0.1%–100%"),
            ),
            (View::A, a.to_string(), format!("{a} alone")),
            (View::B, b.to_string(), format!("{b} alone")),
        ] {
            ui.selectable_value(&mut self.state.view, v, name)
                .on_hover_text(hover);
        }
        if ui
            .small_button("worst pixel")
            .on_hover_text(format!("Pin the pixel where {a} and {b} differ most: the largest |L_{a} − L_{b}| / max(L_{b}, 1% \
                of the mean) of the finished difference map (shown for it)"))
            .clicked()
        {
            self.state.view = View::Diff;
            self.worst_pending = true;
        }
        self.light_buttons(ui, lab);
    }

    /// *+ light* where it is seen, and *− light* for the selected one.
    pub(super) fn light_buttons(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        if ui
            .small_button("+ light")
            .on_hover_text("Add a light where it is seen: over the plane, away from the divider and from the other lights")
            .clicked()
        {
            let size = self.shown.map_or((1600, 900), |i| i.size);
            let position = free_spot(&lab.scene(), self.state.divider, size);
            lab.edit(|l: &mut Lights| {
                l.list.push(Light {
                    position,
                    color: [1.0; 3],
                    intensity: 0.2,
                    range: None,
                    shape: Shape::Point,
                });
            });
            let added = lab.lights().list.len().checked_sub(1);
            lab.edit(|s: &mut Selection| s.light = added);
        }
        if let Some(k) = lab.selection().light
            && ui
                .small_button("− light")
                .on_hover_text("Remove the selected light")
                .clicked()
        {
            lab.edit(|l: &mut Lights| {
                l.list.remove(k);
            });
            lab.edit(|s: &mut Selection| s.light = None);
        }
    }

    /// Pins the worst pixel once the difference view asked for by *worst pixel* is finished
    /// (the request goes if the view is left before).
    pub(super) fn pin_worst(&mut self, lab: &mut Lab) {
        if !self.worst_pending {
            return;
        }
        if self.state.view != View::Diff {
            self.worst_pending = false;
            return;
        }
        if self.shading.in_flight() {
            return;
        }
        let Some(frame) = self.shading.read() else {
            // The image is on its way back: asked for again next frame (`busy` until then).
            if !self.shading.read_pending() {
                self.worst_pending = false;
            }
            return;
        };
        self.worst_pending = false;
        if let Some((x, y)) = worst_pixel(&frame) {
            self.state.pinned = Some([
                (x as f64 + 0.5) / frame.width as f64,
                (y as f64 + 0.5) / frame.height as f64,
            ]);
            lab.set(Selection::default());
            lab.edit(|v: &mut LobeView| v.light = None);
        }
    }
}

/// A black plane is the right answer where every light is below it, but would look like a
/// fault: say why.
pub(super) fn below_plane_note(ui: &mut egui::Ui, lab: &Lab) {
    let lights = &lab.lights().list;
    let clipped = lab.rules().clipping.case1;
    if clipped && !lights.is_empty() && lights.iter().all(|l| l.position[2] <= 0.0) {
        ui.small(
            "every light is at or below the plane: the case-1 rule (n·l ≤ 0 -> 0) keeps it black; \
            turn the rule off, or see the Clipping panel, for the glow M^-1 would lift",
        );
    }
}

/// The scene's exposure: shown radiance and saved PNGs are `L · exposure` before the tone map.
pub(super) fn exposure_slider(ui: &mut egui::Ui, lab: &mut Lab) {
    // 1/64..64: six stops each way covers paper-100 (peaks near 1) down to the clipping
    // scenes' faint light without leaving the slider's fine range.
    let [lo, hi] = crate::app::lab::parts::EXPOSURE_RANGE;
    lab.edit(|e: &mut Exposure| {
        ui.add(
            egui::Slider::new(&mut e.0, lo..=hi)
                .logarithmic(true)
                .text("exposure"),
        )
        .on_hover_text(
            "Display only: each pixel shows L · exposure through the tone map x/(1+x) and sRGB; it \
        does not restart the render. Saved PNGs use it, EXRs keep L. The difference view has its \
        own fixed scale",
        )
    });
}
