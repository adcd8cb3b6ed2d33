//! The page's map of the lab's texts (`index.html?texts`): every text the last frame drew and
//! where, as JSON in the page's `#lab-texts` element. A tool finds a button by its label and
//! clicks it where a user would (the browser test does, as egui_kittest's queries do on the
//! desktop). Off unless asked for: it reads every frame's shapes.

use egui::epaint::{ClippedShape, Shape};
use egui::{Context, FullOutput, Rect};
use ltc_lab::app::browser;
use serde::Serialize;

/// Whether the page's address asks for the map (`?texts`).
pub fn requested() -> bool {
    web_sys::window()
        .and_then(|w| w.location().search().ok())
        .is_some_and(|q| q.trim_start_matches('?').split('&').any(|p| p == "texts"))
}

/// One text drawn, and the part of it that shows in the page's pixels: `[x0, y0, x1, y1]`.
#[derive(Serialize)]
struct TextAt {
    text: String,
    rect: [f32; 4],
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
        let entries: Vec<TextAt> = texts
            .into_iter()
            .map(|(text, r)| TextAt {
                text,
                rect: [r.min.x, r.min.y, r.max.x, r.max.y].map(|v| v * zoom),
            })
            .collect();
        let Ok(json) = serde_json::to_string(&entries) else {
            return;
        };
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
