//! The plane panel: the scene shaded on the window's GPU — summed over frames within a time
//! budget, with its progress — LTC left of a draggable divider and the exact BRDF (or LTC
//! with table B) right of it, or the difference map, or one alone; light markers to drag
//! (Shift: height), add where they are seen and remove; the pixel where the sides differ
//! most, pinned on request; a pixel inspector, shaded on the CPU in f64, with both
//! radiances, their relative difference and the lights in clipping cases 1 and 2.

use egui::{Color32, Pos2, Vec2};
use glam::DVec3;

use crate::app::display::{ShownImage, colour_bar, difference_scale};
use crate::app::other::OtherTable;
use crate::app::pixel_table;
use crate::app::shading::Shading;
use crate::app::state::{Compare, LabState, PanelId};
use crate::cpu::{clip_counts, shade_exact, shade_ltc};
use crate::ltc::lut::Lut;
use crate::metrics::luminance;
use crate::render::{Frame, FrameKind, LutFilter, RenderSettings, View};
use crate::scene::{Light, Scene};

/// The largest image the panel shades (its pixels beyond are upscaled): 960 px wide fills
/// 20 000 lights in under a minute on a CPU driver (lavapipe, ~0.2 G light-px/s), and in
/// milliseconds on a GPU.
pub const MAX_RENDER_WIDTH: f32 = 960.0;

/// The image's aspect ratio, width over height.
const ASPECT: f32 = 16.0 / 9.0;

enum Drag {
    Divider,
    Light(usize),
}

#[derive(Default)]
pub struct PlanePanel {
    /// The last image shown, and the render's size.
    pub shown: Option<ShownImage>,
    drag: Option<Drag>,
    /// The pinned pixel's lights, as last shown, and what they were computed for.
    pinned: Option<(pixel_table::PinnedKey, Option<crate::pixel::PixelTerms>)>,
    /// *worst pixel* was pressed: the pixel is pinned when the difference view is done.
    worst_pending: bool,
}

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

impl PlanePanel {
    /// What the plane renders: LTC (A) against the BRDF form, or — two tables compared — the
    /// same LTC form with table A against it with table B.
    pub fn settings(s: &LabState, width: usize, height: usize) -> RenderSettings {
        let tables = s.compare == Compare::TableB;
        RenderSettings {
            method_b: if tables { s.method_ltc } else { s.method_brdf },
            table_b: tables,
            view: s.view,
            clipping: s.clipping,
            normalization: s.normalization,
            divider: s.divider,
            cull: s.cull,
            ..RenderSettings::single(width, height, s.method_ltc)
        }
    }

    /// The pinned pixel's lights, as last shown.
    pub fn pinned(&self) -> Option<&crate::pixel::PixelTerms> {
        self.pinned.as_ref().and_then(|(_, terms)| terms.as_ref())
    }

    pub fn show(
        &mut self,
        ui: &mut egui::Ui,
        s: &mut LabState,
        shading: &mut Shading,
        (lut, other): (&Lut, &OtherTable),
    ) {
        let (a, b) = side_names(s.compare);
        ui.horizontal_wrapped(|ui| self.toolbar(ui, s, other));
        ui.horizontal_wrapped(|ui| {
            exposure_slider(ui, s);
            progress_line(ui, shading, !s.show_gpu_times);
        });
        // A black plane is the right answer here, but would look like a fault.
        let lights = &s.scene.lights;
        if s.clipping.horizon && !lights.is_empty() && lights.iter().all(|l| l.position[2] <= 0.0) {
            ui.small("every light is at or below the plane: the case-1 rule (n·l ≤ 0 -> 0) keeps it black; turn the rule off, or see the Clipping panel, for the glow M^-1 would lift");
        }
        // A fixed strip under the image for the readout (and the pinned pixel's lights), so
        // that nothing covers it and the image does not jump when it changes.
        let table_h = if s.pinned.is_some() {
            (ui.available_height() * 0.35).clamp(60.0, 220.0)
        } else {
            0.0
        };
        let strip = 44.0
            + if s.pinned.is_some() {
                table_h + 24.0
            } else {
                0.0
            };
        let avail = ui.available_size() - Vec2::new(0.0, strip);
        let size = if avail.x / avail.y > ASPECT {
            Vec2::new(avail.y * ASPECT, avail.y)
        } else {
            Vec2::new(avail.x, avail.x / ASPECT)
        }
        .max(Vec2::new(32.0, 18.0));
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::click_and_drag());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "plane image"));
        let ppp = ui.ctx().pixels_per_point();
        let width = (size.x * ppp).min(MAX_RENDER_WIDTH).round().max(16.0) as usize;
        let height = ((width as f32) / ASPECT).round().max(9.0) as usize;
        let shown = shading.update(
            ui.ctx(),
            &s.shaded_scene(),
            &Self::settings(s, width, height),
        );
        self.shown = Some(shown);
        self.pin_worst(s, shading);
        let painter = ui.painter_at(rect);
        paint_image(&painter, rect, shown, shading.error.as_deref());
        preview_label(ui, rect, &shading.progress);
        let divider_x = rect.min.x + rect.width() * s.divider as f32;
        if s.view == View::Split {
            paint_divider(&painter, rect, divider_x, (a, b));
        }
        let markers = paint_markers(&painter, s, rect, (width, height));
        self.interact(&response, s, rect, width, height, &markers, divider_x);
        if let Some([u, v]) = s.pinned {
            paint_pin(
                &painter,
                rect.min + Vec2::new(u as f32 * rect.width(), v as f32 * rect.height()),
            );
        }
        let b_table = (s.compare == Compare::TableB).then_some(&other.lut);
        pixel_table::update_pinned(&mut self.pinned, s, (lut, b_table), (width, height));
        if s.view == View::Diff {
            colour_bar(ui, &difference_scale(a, b), 220.0);
        }
        // No tooltip on the image: it would cover the reading below it while one hovers.
        // Read afresh every frame, so that it follows every change; none off the image.
        let inspected = response.hover_pos().and_then(|pos| {
            let x = f64::from((pos.x - rect.min.x) / rect.width()) * width as f64;
            let y = f64::from((pos.y - rect.min.y) / rect.height()) * height as f64;
            inspect(s, (lut, b_table), x, y, width, height)
        });
        reading_line(ui, inspected.as_ref(), (a, b));
        pixel_table::show(ui, s, self.pinned(), table_h);
    }

    /// The comparison's switch, the views, adding and removing lights, the worst pixel.
    fn toolbar(&mut self, ui: &mut egui::Ui, s: &mut LabState, other: &OtherTable) {
        let (a, b) = side_names(s.compare);
        ui.selectable_value(&mut s.compare, Compare::Brdf, "LTC | BRDF")
            .on_hover_text("Side B is the exact BRDF (the BRDF form in the side panel)");
        ui.selectable_value(&mut s.compare, Compare::TableB, "A | B tables")
            .on_hover_text(format!("Two tables compared: side B is the same LTC form with table B ({}) instead of the BRDF; the difference map is then |L_A − L_B| / L_B", other.name));
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
            ui.selectable_value(&mut s.view, v, name)
                .on_hover_text(hover);
        }
        if ui
            .small_button("worst pixel")
            .on_hover_text(format!("Pin the pixel where {a} and {b} differ most: the largest |L_{a} − L_{b}| / max(L_{b}, 1% of the mean) of the finished difference map (shown for it)"))
            .clicked()
        {
            s.view = View::Diff;
            self.worst_pending = true;
        }
        if ui
            .small_button("+ light")
            .on_hover_text("Add a light where it is seen: over the plane, away from the divider and from the other lights")
            .clicked()
        {
            let size = self.shown.map_or((1600, 900), |i| i.size);
            s.scene.lights.push(Light {
                position: free_spot(&s.scene, s.divider, size),
                color: [1.0; 3],
                intensity: 0.2,
                range: None,
            });
            s.selected_light = Some(s.scene.lights.len() - 1);
            s.light_count = s.scene.lights.len();
        }
        if let Some(k) = s.selected_light.filter(|&k| k < s.scene.lights.len())
            && ui
                .small_button("− light")
                .on_hover_text("Remove the selected light")
                .clicked()
        {
            s.scene.lights.remove(k);
            s.selected_light = None;
            s.light_count = s.scene.lights.len();
        }
    }

    /// Pins the worst pixel once the difference view asked for by *worst pixel* is finished
    /// (the request goes if the view is left before).
    fn pin_worst(&mut self, s: &mut LabState, shading: &Shading) {
        if !self.worst_pending {
            return;
        }
        if s.view != View::Diff {
            self.worst_pending = false;
            return;
        }
        if shading.in_flight() {
            return;
        }
        self.worst_pending = false;
        let Some(frame) = shading.read() else {
            return;
        };
        if let Some((x, y)) = worst_pixel(&frame) {
            s.pinned = Some([
                (x as f64 + 0.5) / frame.width as f64,
                (y as f64 + 0.5) / frame.height as f64,
            ]);
            s.lobe_light = None;
            s.selected_light = None;
        }
    }

    fn interact(
        &mut self,
        response: &egui::Response,
        s: &mut LabState,
        rect: egui::Rect,
        width: usize,
        height: usize,
        markers: &[(usize, Pos2)],
        divider_x: f32,
    ) {
        // Where the press began: by the time egui calls it a drag, the pointer has moved.
        if response.drag_started()
            && let Some(pos) = response.ctx.input(|i| i.pointer.press_origin())
        {
            let nearest = markers
                .iter()
                .map(|(k, p)| (*k, p.distance(pos)))
                .filter(|(_, d)| *d < 8.0)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            self.drag = match nearest {
                Some((k, _)) => {
                    s.selected_light = Some(k);
                    Some(Drag::Light(k))
                }
                None if s.view == View::Split && (pos.x - divider_x).abs() < 8.0 => {
                    Some(Drag::Divider)
                }
                None => None,
            };
        }
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            s.selected_light = markers
                .iter()
                .find(|(_, p)| p.distance(pos) < 8.0)
                .map(|(k, _)| *k);
            // A click beside the markers pins the pixel under it.
            if s.selected_light.is_none() {
                let u = f64::from((pos.x - rect.min.x) / rect.width());
                let v = f64::from((pos.y - rect.min.y) / rect.height());
                s.pinned = Some([u.clamp(0.0, 1.0), v.clamp(0.0, 1.0)]);
                s.lobe_light = None;
            }
        }
        if response.dragged()
            && let Some(pos) = response.interact_pointer_pos()
        {
            match self.drag {
                Some(Drag::Divider) => {
                    s.divider = f64::from((pos.x - rect.min.x) / rect.width()).clamp(0.0, 1.0);
                }
                Some(Drag::Light(k)) if k < s.scene.lights.len() => {
                    let shift = response.ctx.input(|i| i.modifiers.shift);
                    if shift {
                        s.scene.lights[k].position[2] -= f64::from(response.drag_delta().y) * 0.01;
                    } else {
                        // Keep the height; follow the pointer's ray to that height.
                        let x = f64::from((pos.x - rect.min.x) / rect.width()) * width as f64;
                        let y = f64::from((pos.y - rect.min.y) / rect.height()) * height as f64;
                        let (eye, dir) = s.scene.camera_ray(x, y, width, height);
                        let h = s.scene.plane.half_size * 1.5;
                        let light = &mut s.scene.lights[k];
                        let t = (light.position[2] - eye.z) / dir.z;
                        if dir.z != 0.0 && t > 0.0 {
                            let p = eye + t * dir;
                            light.position[0] = p.x.clamp(-h, h);
                            light.position[1] = p.y.clamp(-h, h);
                        }
                    }
                }
                _ => {}
            }
        }
        if response.drag_stopped() {
            self.drag = None;
        }
    }

    /// Writes the finished image's linear values as EXR (only the path the user named).
    pub fn save_exr(
        shading: &Shading,
        path: &std::path::Path,
        exposure: f64,
    ) -> Result<(), String> {
        let frame = shading.read().ok_or(
            "the image is still being rendered, or there is none: try again when it is done",
        )?;
        crate::output::write_frame(&frame, path, exposure).map_err(|e| e.to_string())
    }
}

/// The scene's exposure: shown radiance and saved PNGs are `L · exposure` before the tone map.
fn exposure_slider(ui: &mut egui::Ui, s: &mut LabState) {
    // 1/64..64: six stops each way covers paper-100 (peaks near 1) down to the clipping
    // scenes' faint light without leaving the slider's fine range.
    ui.add(
        egui::Slider::new(&mut s.scene.exposure, 1.0 / 64.0..=64.0)
            .logarithmic(true)
            .text("exposure"),
    )
    .on_hover_text("Display only: each pixel shows L · exposure through the tone map x/(1+x) and sRGB; it does not restart the render. Saved PNGs use it, EXRs keep L. The difference view has its own fixed scale");
}

/// "3 200 / 20 000 lights, 16% — 312 ms GPU over 40 frames" while the render fills, the
/// render's GPU time once it is done.
fn progress_line(ui: &mut egui::Ui, shading: &Shading, hide_timings: bool) {
    let p = shading.progress;
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
    ui.label(egui::RichText::new(text).small()).on_hover_text(format!(
        "The image is summed over frames in chunks of lights, each within {:.0} ms (GPU timestamp queries; the wall clock on a CPU driver), so that the window never waits for it; a change restarts it",
        shading.budget_ms
    ));
}

/// An image in flight is marked as a preview in its corner, floating: a line in the layout
/// that came and went with the render moved the image, and a new image size restarts the
/// render (a real window then never finished).
fn preview_label(ui: &egui::Ui, rect: egui::Rect, p: &crate::app::shading::Progress) {
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
fn preview_note(p: &crate::app::shading::Progress) -> String {
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

/// Side A's and side B's radiance at an image position, in f64 on the CPU: LTC with table A,
/// against the exact BRDF or (`b_table`) LTC with table B.
fn inspect(
    s: &LabState,
    (lut, b_table): (&Lut, Option<&Lut>),
    x: f64,
    y: f64,
    width: usize,
    height: usize,
) -> Option<PixelReading> {
    let scene = s.shaded_scene();
    let p = scene.surface_point_at(x, y, width, height)?;
    let ltc = |table| {
        shade_ltc(
            &scene,
            table,
            &p,
            &scene.lights,
            s.clipping,
            s.normalization,
            LutFilter::Bilinear,
        )
    };
    let a = ltc(lut);
    let b = match b_table {
        Some(t) => ltc(t),
        None => shade_exact(&scene, &p, &scene.lights),
    };
    let counts = clip_counts(&scene, lut, &p, &scene.lights);
    let lb = luminance(b);
    Some(PixelReading {
        a,
        b,
        relative_error: (luminance(a) - lb).abs() / lb.max(1e-12),
        case1: counts.lifted,
        case2: counts.pushed_below,
    })
}

/// What sides A and B of the plane are called.
fn side_names(compare: Compare) -> (&'static str, &'static str) {
    match compare {
        Compare::Brdf => ("LTC", "BRDF"),
        Compare::TableB => ("A", "B"),
    }
}

/// The panel's title: what its two sides are (`table_a`: table A's name, a shipped table's
/// or a file's path; the file's name is shown).
pub fn title(s: &LabState, table_a: &str, other: &OtherTable) -> String {
    let short = |name: &str| {
        std::path::Path::new(name)
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or(name)
            .to_string()
    };
    match s.compare {
        Compare::Brdf => PanelId::Plane.title().to_string(),
        Compare::TableB => format!(
            "Plane: table A ({}) | table B ({})",
            short(table_a),
            short(&other.name)
        ),
    }
}

/// The plane pixel where a difference frame is largest (the first of equals); `None` for a
/// radiance frame or one without plane pixels.
pub fn worst_pixel(frame: &Frame) -> Option<(usize, usize)> {
    if frame.kind != FrameKind::RelativeDifference {
        return None;
    }
    let k = (0..frame.pixels.len())
        .filter(|&k| frame.on_plane[k] && !frame.pixels[k].x.is_nan())
        .reduce(|best, k| {
            if frame.pixels[k].x > frame.pixels[best].x {
                k
            } else {
                best
            }
        })?;
    Some((k % frame.width, k / frame.width))
}

/// Where *+ light* puts a light, a quarter of the plane's half size above it: of a 9 × 9 grid
/// over the plane, the point whose light and its foot are seen well inside a `size` image
/// and whose light lies farthest (in the image) from the divider column and from every other
/// light's image; above the centre where no point is seen.
pub fn free_spot(scene: &Scene, divider: f64, (width, height): (usize, usize)) -> [f64; 3] {
    const STEPS: usize = 9;
    let half = scene.plane.half_size;
    let z = 0.25 * half;
    let (w, h) = (width as f64, height as f64);
    // 5% of the width from the image's edges: a marker there is seen whole, not cut.
    let margin = 0.05 * w;
    let inside = |p: [f64; 3]| {
        scene
            .project(DVec3::from(p), width, height)
            .filter(|&(x, y)| x >= margin && x <= w - margin && y >= margin && y <= h - margin)
    };
    let others: Vec<(f64, f64)> = scene
        .lights
        .iter()
        .filter_map(|l| scene.project(DVec3::from(l.position), width, height))
        .collect();
    let divider_x = divider * w;
    let mut best: Option<(f64, [f64; 3])> = None;
    for j in 0..STEPS {
        for i in 0..STEPS {
            let at = |k: usize| half * (-0.9 + 1.8 * k as f64 / (STEPS - 1) as f64);
            let (x, y) = (at(i), at(j));
            let (Some(q), Some(_)) = (inside([x, y, z]), inside([x, y, 0.0])) else {
                continue;
            };
            let clearance = others
                .iter()
                .map(|o| (o.0 - q.0).hypot(o.1 - q.1))
                .fold((q.0 - divider_x).abs(), f64::min);
            if best.is_none_or(|(c, _)| clearance > c) {
                best = Some((clearance, [x, y, z]));
            }
        }
    }
    best.map_or([0.0, 0.0, z], |(_, p)| p)
}

/// The render's texture over `rect`, and its error over that.
fn paint_image(painter: &egui::Painter, rect: egui::Rect, shown: ShownImage, error: Option<&str>) {
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
fn paint_divider(painter: &egui::Painter, rect: egui::Rect, x: f32, (a, b): (&str, &str)) {
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

/// The lights' markers (the first 200: beyond that they only hide the image), and where
/// they are on the screen.
fn paint_markers(
    painter: &egui::Painter,
    s: &LabState,
    rect: egui::Rect,
    (width, height): (usize, usize),
) -> Vec<(usize, Pos2)> {
    let to_screen = |(x, y): (f64, f64)| {
        rect.min
            + Vec2::new(
                (x / width as f64) as f32 * rect.width(),
                (y / height as f64) as f32 * rect.height(),
            )
    };
    let markers: Vec<(usize, Pos2)> = s
        .scene
        .lights
        .iter()
        .enumerate()
        .take(200)
        .filter_map(|(k, l)| {
            s.scene
                .project(DVec3::from(l.position), width, height)
                .map(|p| (k, to_screen(p)))
        })
        .filter(|(_, p)| rect.contains(*p))
        .collect();
    for (k, p) in &markers {
        let l = &s.scene.lights[*k];
        let c = Color32::from_rgb(
            (l.color[0] * 255.0) as u8,
            (l.color[1] * 255.0) as u8,
            (l.color[2] * 255.0) as u8,
        );
        let selected = s.selected_light == Some(*k);
        painter.circle(
            *p,
            if selected { 6.0 } else { 4.0 },
            c,
            egui::Stroke::new(if selected { 2.0 } else { 1.0 }, Color32::BLACK),
        );
    }
    markers
}

/// The pinned pixel's marker: a ring with four ticks.
fn paint_pin(painter: &egui::Painter, p: Pos2) {
    let stroke = egui::Stroke::new(1.5, Color32::from_rgb(255, 240, 80));
    painter.circle_stroke(p, 6.0, stroke);
    painter.hline(p.x - 10.0..=p.x - 4.0, p.y, stroke);
    painter.hline(p.x + 4.0..=p.x + 10.0, p.y, stroke);
    painter.vline(p.x, p.y - 10.0..=p.y - 4.0, stroke);
    painter.vline(p.x, p.y + 4.0..=p.y + 10.0, stroke);
}

/// The hovered pixel's reading, or what the image answers to.
fn reading_line(ui: &mut egui::Ui, reading: Option<&PixelReading>, (a, b): (&str, &str)) {
    match reading {
        Some(r) => ui.label(format!(
            "pixel: {a} {:.4} | {b} {:.4} (luminance), relative difference {:.2}%; lights in case 1: {}, case 2: {}",
            luminance(r.a),
            luminance(r.b),
            100.0 * r.relative_error,
            r.case1,
            r.case2
        )),
        None => ui.label("hover a pixel to read it, click to pin it and open its lights; drag a light's marker to move it (Shift: its height), drag the divider"),
    };
}
