//! What is drawn on and around the plane's image: the image with its error, the split's
//! divider, the lights' markers, the pinned pixel's marker, the progress line, the preview
//! note of a render in flight, and the hovered pixel's reading (and its numbers).

use egui::{Color32, Pos2, Vec2};
use glam::DVec3;

use crate::app::lab::Lab;
use crate::app::plane::shading::{FRAME_BUDGET_MS, Progress};
use crate::app::ui::display::ShownImage;
use crate::cpu::cases::clip_counts;
use crate::cpu::{Side, shade};
use crate::light::Shape;
use crate::metrics::luminance;
use crate::render::{RenderSettings, Tables};

/// The pixel inspector's numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelReading {
    /// LTC with table A.
    pub a: DVec3,
    /// The exact BRDF, or LTC with table B.
    pub b: DVec3,
    /// `|L_a − L_b| / L_b` on luminance.
    pub relative_error: f64,
    pub case1: usize,
    pub case2: usize,
}

/// The image on the screen and the render's size in pixels.
#[derive(Clone, Copy)]
pub struct Placed {
    pub rect: egui::Rect,
    pub size: (usize, usize),
}

impl Placed {
    /// A position in the render's pixels on the screen (`pixel`'s inverse).
    pub fn to_screen(&self, (x, y): (f64, f64)) -> Pos2 {
        let (width, height) = self.size;
        self.rect.min
            + Vec2::new(
                (x / width as f64) as f32 * self.rect.width(),
                (y / height as f64) as f32 * self.rect.height(),
            )
    }

    /// A screen position in the render's pixels.
    pub fn pixel(&self, pos: Pos2) -> (f64, f64) {
        let u = (pos - self.rect.min) / self.rect.size();
        (
            f64::from(u.x) * self.size.0 as f64,
            f64::from(u.y) * self.size.1 as f64,
        )
    }
}

/// "3 200 / 20 000 lights, 16% — 312 ms GPU over 40 frames" while the render fills, the
/// render's GPU time once it is done.
pub fn progress_line(ui: &mut egui::Ui, p: &Progress, hide_timings: bool) {
    let time = if hide_timings || p.gpu_ms <= 0.0 {
        String::new()
    } else {
        format!(" — {:.1} ms GPU over {} frames", p.gpu_ms, p.frames)
    };
    let text = if p.binning.is_some() {
        format!("{}{time}", p.describe())
    } else if p.complete() {
        format!("done: {}{time}", p.describe())
    } else {
        format!("rendering {}{time}", p.describe())
    };
    // One line, cut at the panel's edge: a line that wrapped as its text grew with the render
    // moved the image, and a new image size restarts the render.
    let line = egui::Label::new(egui::RichText::new(text).small()).truncate();
    ui.add(line).on_hover_text(format!(
        "The image is summed over frames in chunks of lights, each within {FRAME_BUDGET_MS:.0} ms \
            (GPU timestamp queries; the wall clock on a CPU driver), so that the window never waits \
            for it; a change restarts it"
    ));
}

/// An image in flight is marked as a preview in its corner, floating: a line in the layout
/// that came and went with the render moved the image, and a new image size restarts the
/// render (a real window then never finished).
pub fn preview_label(ui: &egui::Ui, rect: egui::Rect, p: &Progress) {
    let note = preview_note(p);
    if note.is_empty() {
        return;
    }
    egui::Area::new(ui.scope_id().with("plane image preview"))
        .fixed_pos(rect.left_top() + Vec2::splat(6.0))
        .interactable(false)
        .show(ui.ctx(), |ui| {
            egui::Frame::new()
                .fill(egui::Color32::from_black_alpha(170))
                .inner_margin(4.0)
                .show(ui, |ui| ui.label(egui::RichText::new(note).small()));
        });
}

/// What an image in flight shows: the partial sum scaled to every light, as a preview, and
/// the time left once the render has run a second.
pub fn preview_note(p: &Progress) -> String {
    let scaled = (p.preview_scale() > 1.0)
        .then(|| format!("preview: the sum so far × {:.3}", p.preview_scale()));
    let left = p.started.and_then(|t| p.time_left(t.elapsed()));
    let left = left.map(|d| format!("about {:.0} s left", d.as_secs_f64().ceil()));
    [scaled, left]
        .into_iter()
        .flatten()
        .collect::<Vec<_>>()
        .join(", ")
}

/// The render's texture over `rect`, and its error over that.
pub fn paint_image(
    painter: &egui::Painter,
    rect: egui::Rect,
    shown: ShownImage,
    error: Option<&str>,
) {
    if let Some(t) = shown.texture {
        painter.image(
            t,
            rect,
            egui::Rect::from_min_max(Pos2::ZERO, egui::pos2(1.0, 1.0)),
            Color32::WHITE,
        );
    }
    if let Some(e) = error {
        painter.text(
            rect.center(),
            egui::Align2::CENTER_CENTER,
            e,
            egui::FontId::proportional(13.0),
            Color32::LIGHT_RED,
        );
    }
}

/// The split's divider and the names of the sides beside it.
pub fn paint_divider(painter: &egui::Painter, rect: egui::Rect, x: f32, (a, b): (&str, &str)) {
    painter.vline(x, rect.y_range(), egui::Stroke::new(2.0, Color32::WHITE));
    for (side, dx, align) in [
        (a, -6.0, egui::Align2::RIGHT_TOP),
        (b, 6.0, egui::Align2::LEFT_TOP),
    ] {
        painter.text(
            egui::pos2(x + dx, rect.min.y + 4.0),
            align,
            side,
            egui::FontId::proportional(12.0),
            Color32::WHITE,
        );
    }
}

/// Where the lights' markers are on the screen (the first 200: beyond that they only hide
/// the image).
pub fn markers(lab: &Lab, placed: Placed) -> Vec<(usize, Pos2)> {
    let (rect, (width, height)) = (placed.rect, placed.size);
    let scene = lab.stage_scene();
    lab.lights()
        .list
        .iter()
        .enumerate()
        .take(200)
        .filter_map(|(k, l)| {
            scene
                .project(DVec3::from(l.position), width, height)
                .map(|p| (k, placed.to_screen(p)))
        })
        .filter(|(_, p)| rect.contains(*p))
        .collect()
}

/// The outline of each light with a size as the camera sees it (the sphere's silhouette
/// about its marker; the other shapes' own, `Shape::outline`, such as a rect's four edges
/// with a tick along its normal toward the side it lights): where its size is on the plane.
pub fn paint_outlines(
    painter: &egui::Painter,
    lab: &Lab,
    placed: Placed,
    markers: &[(usize, Pos2)],
) {
    // The lights' own list and the stage alone: no copy of every light each frame.
    let scene = lab.stage_scene();
    let (width, height) = placed.size;
    let (eye, _, _, up) = scene.camera_basis();
    let scale = placed.rect.width() / width as f32;
    let stroke = egui::Stroke::new(1.0, Color32::from_white_alpha(160));
    for (k, p) in markers {
        let Some(l) = lab.lights().list.get(*k) else {
            continue;
        };
        let centre = DVec3::from(l.position);
        match lab.overrides().shaded_shape(l) {
            Shape::Point => {}
            Shape::Sphere { radius } => {
                // The silhouette's radius, from the projection of a point one radius above
                // the centre across the view (exact for a sphere on the axis, within a few
                // percent over the lab's field of view).
                let (Some(a), Some(b)) = (
                    scene.project(centre, width, height),
                    scene.project(centre + up * radius, width, height),
                ) else {
                    continue;
                };
                let r = ((a.0 - b.0).hypot(a.1 - b.1) as f32 * scale).min(placed.rect.width());
                painter.circle_stroke(*p, r, stroke);
            }
            shape => {
                // A point behind the camera has no place on the image: no outline.
                let lines: Option<Vec<Vec<Pos2>>> = shape
                    .outline(centre, eye)
                    .iter()
                    .map(|line| {
                        line.iter()
                            .map(|&c| scene.project(c, width, height).map(|q| placed.to_screen(q)))
                            .collect()
                    })
                    .collect();
                for line in lines.unwrap_or_default() {
                    match line[..] {
                        [a, b] => painter.line_segment([a, b], stroke),
                        _ => painter.add(egui::Shape::line(line, stroke)),
                    };
                }
            }
        }
    }
}

/// The lights' markers in their colours, the selected one larger.
pub fn paint_markers(painter: &egui::Painter, lab: &Lab, markers: &[(usize, Pos2)]) {
    for (k, p) in markers {
        let Some(l) = lab.lights().list.get(*k) else {
            continue;
        };
        let c = Color32::from_rgb(
            (l.color[0] * 255.0) as u8,
            (l.color[1] * 255.0) as u8,
            (l.color[2] * 255.0) as u8,
        );
        let selected = lab.selection().light == Some(*k);
        painter.circle(
            *p,
            if selected { 6.0 } else { 4.0 },
            c,
            egui::Stroke::new(if selected { 2.0 } else { 1.0 }, Color32::BLACK),
        );
    }
}

/// The pinned pixel's marker: a ring with four ticks.
pub fn paint_pin(painter: &egui::Painter, p: Pos2) {
    let stroke = egui::Stroke::new(1.5, Color32::from_rgb(255, 240, 80));
    painter.circle_stroke(p, 6.0, stroke);
    painter.hline(p.x - 10.0..=p.x - 4.0, p.y, stroke);
    painter.hline(p.x + 4.0..=p.x + 10.0, p.y, stroke);
    painter.vline(p.x, p.y - 10.0..=p.y - 4.0, stroke);
    painter.vline(p.x, p.y + 4.0..=p.y + 10.0, stroke);
}

/// Side A's and side B's radiance at screen position `pos` of the render `settings` describes,
/// in f64 on the CPU: LTC with table A, against the exact BRDF or (two tables compared) LTC
/// with table B.
pub fn inspect(
    lab: &Lab,
    placed: Placed,
    pos: Pos2,
    settings: &RenderSettings,
) -> Option<PixelReading> {
    let tables = lab.tables();
    let scene = lab.shaded_scene();
    let (x, y) = placed.pixel(pos);
    let p = scene.surface_point_at(x, y, placed.size.0, placed.size.1)?;
    let pair = Tables {
        a: &tables.a().lut,
        b: &tables.b().lut,
    };
    let a = shade(&scene, &p, lab.rules(), &Side::a(settings, pair));
    let b = shade(&scene, &p, lab.rules(), &Side::b(settings, pair));
    let counts = clip_counts(&scene, &tables.a().lut, &p, &scene.lights);
    let lb = luminance(b);
    Some(PixelReading {
        a,
        b,
        relative_error: (luminance(a) - lb).abs() / lb.max(1e-12),
        case1: counts.lifted,
        case2: counts.pushed_below,
    })
}

/// The hovered pixel's reading, or what the image answers to, in the hint's height either
/// way: the hint wraps to more lines than the reading, and the table under them jumped when
/// the pointer left the image for it (a click aimed at a row landed on the next).
pub fn reading_line(ui: &mut egui::Ui, reading: Option<&PixelReading>, (a, b): (&str, &str)) {
    let hint = "hover a pixel to read it, click to pin it and open its lights; drag a light's marker to move it (Shift: its height), drag the divider";
    let text = match reading {
        Some(r) => format!(
            "pixel: {a} {:.4} | {b} {:.4} (luminance), relative difference {:.2}%; lights in case 1: {}, case 2: {}",
            luminance(r.a),
            luminance(r.b),
            100.0 * r.relative_error,
            r.case1,
            r.case2
        ),
        None => hint.to_string(),
    };
    let width = ui.available_width();
    let height = |t: &str| {
        egui::WidgetText::from(t)
            .into_galley(
                ui,
                Some(egui::TextWrapMode::Wrap),
                width,
                egui::TextStyle::Body,
            )
            .size()
            .y
    };
    let tallest = height(hint).max(height(&text));
    ui.allocate_ui(egui::vec2(width, tallest), |ui| {
        ui.set_min_height(tallest);
        ui.label(text);
    });
}
