//! Images in the window: what a panel shows of a render (a GPU texture, or a CPU frame made
//! into an egui image with the same tone map and false colour as every PNG), and the
//! difference map's colour bar.

use egui::{Color32, Vec2};

use crate::colormap::{ColourScale, viridis};
use crate::output::{diff_scale_position, tone_map};
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
                (true, FrameKind::RelativeDifference) => viridis(diff_scale_position(p.x)),
            };
            Color32::from_rgb(r, g, b)
        })
        .collect();
    egui::ColorImage::new([frame.width, frame.height], pixels)
}

/// A horizontal colour bar for `scale`: its label, the bar with round tick values under it,
/// and the value under the pointer while one hovers it.
pub fn colour_bar(ui: &mut egui::Ui, scale: &ColourScale, width: f32) {
    ui.horizontal(|ui| {
        ui.small(&scale.label);
        let width = width.min(ui.available_width() - 4.0).max(60.0);
        let bar_h = 9.0;
        let (rect, response) =
            ui.allocate_exact_size(Vec2::new(width, bar_h + 13.0), egui::Sense::hover());
        let painter = ui.painter_at(rect.expand(2.0));
        let steps = width.round().max(2.0) as usize;
        for k in 0..steps {
            let [r, g, b] = scale.colour_at(k as f64 / (steps - 1) as f64);
            painter.vline(
                rect.min.x + k as f32 + 0.5,
                rect.min.y..=rect.min.y + bar_h,
                egui::Stroke::new(1.0, Color32::from_rgb(r, g, b)),
            );
        }
        let font = egui::FontId::proportional(10.0);
        let colour = ui.visuals().text_color();
        let mut last_right = f32::NEG_INFINITY;
        for (t, v) in scale.ticks() {
            let x = rect.min.x + t as f32 * (width - 1.0);
            painter.vline(
                x,
                rect.min.y + bar_h - 3.0..=rect.min.y + bar_h + 2.0,
                egui::Stroke::new(1.0, colour),
            );
            let text = scale.format(v);
            let galley = painter.layout_no_wrap(text, font.clone(), colour);
            let left = (x - galley.size().x / 2.0)
                .clamp(rect.min.x - 2.0, rect.max.x - galley.size().x + 2.0);
            // Labels that would overlap their neighbour are left out (the tick stays).
            if left > last_right + 3.0 {
                last_right = left + galley.size().x;
                painter.galley(egui::pos2(left, rect.min.y + bar_h + 2.0), galley, colour);
            }
        }
        if let Some(p) = response.hover_pos() {
            let t = f64::from((p.x - rect.min.x) / (width - 1.0)).clamp(0.0, 1.0);
            response.on_hover_text_at_pointer(scale.format(scale.value_at(t)));
        }
    });
}

/// The plane's difference map scale: the same as the PNGs' (`output::diff_scale_position`).
pub fn difference_scale(a: &str, b: &str) -> ColourScale {
    let [lo, .., hi] = crate::output::DIFF_SCALE_DECADES;
    ColourScale::log(lo, hi, format!("|L_{a} − L_{b}| / L_{b}")).in_percent()
}

/// A colour of the lab's maps as egui's.
pub fn rgb([r, g, b]: [u8; 3]) -> Color32 {
    Color32::from_rgb(r, g, b)
}
