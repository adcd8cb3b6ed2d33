//! Images in the window: what a panel shows of a render (a GPU texture, or a CPU frame made
//! into an egui image with the same tone map and false colour as every PNG), and the
//! difference map's colour bar.

use egui::{Color32, Vec2};

use crate::output::{diff_scale_position, false_colour, tone_map};
use crate::render::{Frame, FrameKind};

/// A render as a panel shows it: the texture (when there is one yet) and the render's size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShownImage {
    pub texture: Option<egui::TextureId>,
    pub size: (usize, usize),
}

/// A frame for display: tone-mapped radiance, or the difference's false colour.
pub fn frame_image(frame: &Frame, exposure: f64) -> egui::ColorImage {
    let pixels = frame
        .pixels
        .iter()
        .zip(&frame.on_plane)
        .map(|(p, &on)| {
            let [r, g, b] = match (on, frame.kind) {
                (false, _) => [24, 24, 28],
                (true, FrameKind::Radiance) => tone_map(*p, exposure),
                (true, FrameKind::RelativeDifference) => false_colour(diff_scale_position(p.x)),
            };
            Color32::from_rgb(r, g, b)
        })
        .collect();
    egui::ColorImage::new([frame.width, frame.height], pixels)
}

/// The difference map's scale, as in `output::to_rgb8`'s colour bar.
pub fn colour_bar(ui: &mut egui::Ui) {
    ui.horizontal(|ui| {
        ui.small("0.1%");
        let (rect, _) = ui.allocate_exact_size(Vec2::new(160.0, 10.0), egui::Sense::hover());
        for k in 0..160 {
            let [r, g, b] = false_colour(f64::from(k) / 159.0);
            ui.painter().vline(
                rect.min.x + k as f32,
                rect.y_range(),
                egui::Stroke::new(1.0, Color32::from_rgb(r, g, b)),
            );
        }
        ui.small("1% … 10% … 100%");
    });
}
