//! The plane panel: the scene shaded on the GPU, LTC left of a draggable divider and the
//! exact BRDF right of it (or the difference map, or one alone); light markers to drag
//! (Shift: height), add and remove; a pixel inspector with both radiances, their relative
//! error and the lights in clipping cases 1 and 2; each method's GPU time, live.

use egui::{Color32, Pos2, Vec2};
use glam::DVec3;

use crate::app::shading::Shading;
use crate::app::state::LabState;
use crate::cpu::{clip_counts, shade_exact, shade_ltc};
use crate::ltc::lut::Lut;
use crate::metrics::luminance;
use crate::output::{diff_scale_position, false_colour, tone_map};
use crate::render::{Frame, FrameKind, LutFilter, RenderSettings, View};
use crate::scene::{Light, Scene};

/// The largest image the panel shades (its pixels beyond are upscaled): 960 px wide keeps a
/// 20 000-light frame under a second even on lavapipe's ~0.25 G light-px/s.
pub const MAX_RENDER_WIDTH: f32 = 960.0;

/// What a render depends on; a new render happens only when it changes.
#[derive(Clone, Debug, PartialEq)]
struct RenderKey {
    scene: Scene,
    settings: RenderSettings,
}

enum Drag {
    Divider,
    Light(usize),
}

#[derive(Default)]
pub struct PlanePanel {
    key: Option<RenderKey>,
    pub frame: Option<Frame>,
    texture: Option<egui::TextureHandle>,
    /// GPU ms of the LTC form and the BRDF form alone, at the panel's size.
    pub times: Option<(f64, f64)>,
    pub error: Option<String>,
    drag: Option<Drag>,
    /// The inspector's last reading, for tests.
    pub inspected: Option<PixelReading>,
    /// Hide the live GPU times (they change run to run; snapshot tests hide them).
    pub hide_timings: bool,
    /// When to time each method alone: once the image has stayed the same for a moment, so
    /// that dragging a slider pays only for the render.
    times_due: Option<std::time::Instant>,
}

/// How long the image must stay unchanged before the methods are timed.
const TIMING_DELAY: std::time::Duration = std::time::Duration::from_millis(300);

/// The pixel inspector's numbers.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelReading {
    pub exact: DVec3,
    pub ltc: DVec3,
    pub relative_error: f64,
    pub case1: usize,
    pub case2: usize,
}

impl PlanePanel {
    pub fn settings(s: &LabState, width: usize, height: usize) -> RenderSettings {
        RenderSettings {
            method_b: s.method_brdf,
            view: s.view,
            clipping: s.clipping,
            normalization: s.normalization,
            divider: s.divider,
            ..RenderSettings::single(width, height, s.method_ltc)
        }
    }

    pub fn show(&mut self, ui: &mut egui::Ui, s: &mut LabState, shading: &mut Shading, lut: &Lut) {
        ui.horizontal_wrapped(|ui| {
            for (v, name, hover) in [
                (View::Split, "split", "LTC left of the divider, exact BRDF right of it; drag the divider"),
                (View::Diff, "difference", "|L_ltc − L_brdf| / max(L_brdf, 1% of the mean), log colour scale 0.1%–100%"),
                (View::A, "LTC", "The LTC form alone"),
                (View::B, "BRDF", "The BRDF form alone"),
            ] {
                ui.selectable_value(&mut s.view, v, name).on_hover_text(hover);
            }
            if ui.small_button("+ light").on_hover_text("Add a light 0.5 above the plane's centre").clicked() {
                s.scene.lights.push(Light {
                    position: [0.0, 0.0, 0.5],
                    color: [1.0; 3],
                    intensity: 0.2,
                    range: None,
                });
                s.selected_light = Some(s.scene.lights.len() - 1);
                s.light_count = s.scene.lights.len();
            }
            if let Some(k) = s.selected_light.filter(|&k| k < s.scene.lights.len())
                && ui.small_button("− light").on_hover_text("Remove the selected light").clicked()
            {
                s.scene.lights.remove(k);
                s.selected_light = None;
                s.light_count = s.scene.lights.len();
            }
            if let Some((ltc_ms, brdf_ms)) = self.times.filter(|_| !self.hide_timings) {
                ui.label(format!("GPU: {} {ltc_ms:.2} ms, {} {brdf_ms:.2} ms ({:.2}×)", s.method_ltc.name(), s.method_brdf.name(), brdf_ms / ltc_ms))
                    .on_hover_text("Each method alone on this scene at this size (timestamp queries), re-measured when the image changes");
            }
        });
        let avail = ui.available_size() - Vec2::new(0.0, 40.0);
        let aspect = 16.0 / 9.0;
        let size = if avail.x / avail.y > aspect {
            Vec2::new(avail.y * aspect, avail.y)
        } else {
            Vec2::new(avail.x, avail.x / aspect)
        }
        .max(Vec2::new(32.0, 18.0));
        let (rect, response) = ui.allocate_exact_size(size, egui::Sense::click_and_drag());
        response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "plane image"));
        let ppp = ui.ctx().pixels_per_point();
        let width = (size.x * ppp).min(MAX_RENDER_WIDTH).round().max(16.0) as usize;
        let height = ((width as f32) / aspect).round().max(9.0) as usize;
        self.ensure_rendered(ui.ctx(), s, shading, width, height);
        self.time_methods_when_due(ui.ctx(), s, shading);
        let painter = ui.painter_at(rect);
        if let Some(t) = &self.texture {
            painter.image(
                t.id(),
                rect,
                egui::Rect::from_min_max(Pos2::ZERO, egui::pos2(1.0, 1.0)),
                Color32::WHITE,
            );
        }
        if let Some(e) = &self.error {
            painter.text(
                rect.center(),
                egui::Align2::CENTER_CENTER,
                e,
                egui::FontId::proportional(13.0),
                Color32::LIGHT_RED,
            );
        }
        let to_screen = |(x, y): (f64, f64)| {
            rect.min
                + Vec2::new(
                    (x / width as f64) as f32 * rect.width(),
                    (y / height as f64) as f32 * rect.height(),
                )
        };
        let divider_x = rect.min.x + rect.width() * s.divider as f32;
        if s.view == View::Split {
            painter.vline(
                divider_x,
                rect.y_range(),
                egui::Stroke::new(2.0, Color32::WHITE),
            );
            painter.text(
                egui::pos2(divider_x - 6.0, rect.min.y + 4.0),
                egui::Align2::RIGHT_TOP,
                "LTC",
                egui::FontId::proportional(12.0),
                Color32::WHITE,
            );
            painter.text(
                egui::pos2(divider_x + 6.0, rect.min.y + 4.0),
                egui::Align2::LEFT_TOP,
                "BRDF",
                egui::FontId::proportional(12.0),
                Color32::WHITE,
            );
        }
        // Light markers (the first 200: beyond that they only hide the image).
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
        self.interact(&response, s, rect, width, height, &markers, divider_x);
        if s.view == View::Diff {
            colour_bar(ui);
        }
        let response = response.on_hover_text("Drag a light's marker to move it over the plane, Shift-drag to change its height; drag the divider; hover a pixel to inspect it");
        if let Some(pos) = response.hover_pos() {
            let x = f64::from((pos.x - rect.min.x) / rect.width()) * width as f64;
            let y = f64::from((pos.y - rect.min.y) / rect.height()) * height as f64;
            self.inspected = inspect(s, lut, x, y, width, height);
        }
        match &self.inspected {
            Some(r) => ui.label(format!(
                "pixel: BRDF {:.4} | LTC {:.4} (luminance), relative error {:.2}%; lights in case 1: {}, case 2: {}",
                luminance(r.exact),
                luminance(r.ltc),
                100.0 * r.relative_error,
                r.case1,
                r.case2
            )),
            None => ui.label("hover the plane to inspect a pixel"),
        };
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

    /// Renders when the inputs changed, and times each method alone.
    fn ensure_rendered(
        &mut self,
        ctx: &egui::Context,
        s: &LabState,
        shading: &mut Shading,
        width: usize,
        height: usize,
    ) {
        let key = RenderKey {
            scene: s.shaded_scene(),
            settings: Self::settings(s, width, height),
        };
        if self.key.as_ref() == Some(&key) {
            return;
        }
        match shading.render(&key.scene, &key.settings) {
            Ok(shaded) => {
                let image = frame_image(&shaded.frame, key.scene.exposure);
                match &mut self.texture {
                    Some(t) => t.set(image, egui::TextureOptions::LINEAR),
                    None => {
                        self.texture =
                            Some(ctx.load_texture("plane", image, egui::TextureOptions::LINEAR));
                    }
                }
                self.frame = Some(shaded.frame);
                self.error = None;
                self.times_due = Some(std::time::Instant::now() + TIMING_DELAY);
            }
            Err(e) => self.error = Some(e),
        }
        self.key = Some(key);
    }

    /// Times the LTC and BRDF forms alone on the current image, once it has been still.
    fn time_methods_when_due(&mut self, ctx: &egui::Context, s: &LabState, shading: &mut Shading) {
        let (Some(due), Some(key)) = (self.times_due, &self.key) else {
            return;
        };
        let now = std::time::Instant::now();
        if now < due {
            ctx.request_repaint_after(due - now);
            return;
        }
        self.times = shading
            .time_method(&key.scene, &key.settings, s.method_ltc, 1)
            .zip(shading.time_method(&key.scene, &key.settings, s.method_brdf, 1));
        self.times_due = None;
    }

    /// Forgets the last render, so that the next frame renders again (a new LUT).
    pub fn invalidate(&mut self) {
        self.key = None;
    }

    /// Writes the last frame's linear values as EXR (only the path the user named).
    pub fn save_exr(&self, path: &std::path::Path, exposure: f64) -> Result<(), String> {
        let frame = self.frame.as_ref().ok_or("nothing rendered yet")?;
        crate::output::write_frame(frame, path, exposure).map_err(|e| e.to_string())
    }
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
fn colour_bar(ui: &mut egui::Ui) {
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

/// The exact and LTC radiance at an image position, computed on the CPU reference.
fn inspect(
    s: &LabState,
    lut: &Lut,
    x: f64,
    y: f64,
    width: usize,
    height: usize,
) -> Option<PixelReading> {
    let scene = s.shaded_scene();
    let p = scene.surface_point_at(x, y, width, height)?;
    let exact = shade_exact(&scene, &p, &scene.lights);
    let ltc = shade_ltc(
        &scene,
        lut,
        &p,
        &scene.lights,
        s.clipping,
        s.normalization,
        LutFilter::Bilinear,
    );
    let counts = clip_counts(&scene, lut, &p, &scene.lights);
    let le = luminance(exact);
    Some(PixelReading {
        exact,
        ltc,
        relative_error: (luminance(ltc) - le).abs() / le.max(1e-12),
        case1: counts.below_horizon,
        case2: counts.pushed_below,
    })
}
