//! The page's map of the lab's texts (`index.html?texts`): every text the last frame drew and
//! where, as JSON in the page's `#lab-texts` element. A tool finds a button by its label and
//! clicks it where a user would (the browser test does, as egui_kittest's queries do on the
//! desktop). Off unless asked for: it reads every frame's shapes.

use egui::epaint::{ClippedShape, Shape};
use egui::{Context, FullOutput, Rect};
use ltc_lab::app::browser;

/// Whether the page's address asks for the map (`?texts`).
pub fn requested() -> bool {
    web_sys::window()
        .and_then(|w| w.location().search().ok())
        .is_some_and(|q| q.trim_start_matches('?').split('&').any(|p| p == "texts"))
}

/// An egui plugin that writes the map after each frame whose texts changed.
#[derive(Default)]
pub struct TextMap {
    written: String,
}

impl egui::Plugin for TextMap {
    fn debug_name(&self) -> &'static str {
        "ltc-lab text map"
    }

    fn output_hook(&mut self, ctx: &Context, output: &mut FullOutput) {
        let mut texts = Vec::new();
        for ClippedShape {
            clip_rect, shape, ..
        } in &output.shapes
        {
            collect(shape, *clip_rect, &mut texts);
        }
        // Shapes are in points; the page's pixels are points times the zoom.
        let zoom = ctx.zoom_factor();
        let entries: Vec<String> = texts
            .iter()
            .map(|(text, r)| {
                let [x0, y0, x1, y1] = [r.min.x, r.min.y, r.max.x, r.max.y].map(|v| v * zoom);
                format!(
                    "{{\"text\": {}, \"rect\": [{x0:.1}, {y0:.1}, {x1:.1}, {y1:.1}]}}",
                    crate::page::json_string(text)
                )
            })
            .collect();
        let json = format!("[{}]", entries.join(",\n"));
        if json != self.written {
            browser::write_element("lab-texts", &json);
            self.written = json;
        }
    }
}

/// The texts of `shape` that show through `clip`, with the part of each that shows.
fn collect(shape: &Shape, clip: Rect, out: &mut Vec<(String, Rect)>) {
    match shape {
        Shape::Vec(shapes) => shapes.iter().for_each(|s| collect(s, clip, out)),
        Shape::Text(t) => {
            let shown = t.galley.rect.translate(t.pos.to_vec2()).intersect(clip);
            let text = t.galley.text();
            if shown.is_positive() && !text.trim().is_empty() {
                out.push((text.to_owned(), shown));
            }
        }
        _ => {}
    }
}
