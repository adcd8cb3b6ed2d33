//! The plane panel: the scene shaded on the window's GPU — summed over frames within a time
//! budget, with its progress — LTC left of a draggable divider and the exact BRDF (or LTC
//! with table B) right of it, or the difference map, or one alone; light markers to drag
//! (Shift: height), add where they are seen and remove; the pixel where the sides differ
//! most, pinned on request; a pixel inspector, shaded on the CPU in f64, with both
//! radiances, their relative difference and the lights in clipping cases 1 and 2.

pub mod paint;
pub mod pixel_table;
pub mod shading;
pub mod sphere_cases;
pub mod spots;

use egui::{Pos2, Vec2};
use serde::{Deserialize, Serialize};

use crate::app::lab::part::Notes;
use crate::app::lab::{Checked, Exposure, Lab, Lights, LobeView, Selection, SideB};
use crate::app::panel::Panel;
use crate::app::plane::paint::{
    Placed, inspect, markers, paint_divider, paint_image, paint_markers, paint_outlines, paint_pin,
    preview_label, progress_line, reading_line,
};
use crate::app::plane::pixel_table::{LightColumn, PinnedLights};
use crate::app::plane::shading::Shading;
use crate::app::plane::sphere_cases::SphereCases;
use crate::app::plane::spots::{free_spot, worst_pixel};
use crate::app::ui::display::{ShownImage, colour_bar, difference_scale};
use crate::gpu::GpuContext;
use crate::light::Shape;
use crate::render::ShapeMethods;
use crate::render::{Frame, Method, RenderSettings, View};
use crate::scene::Light;

/// The largest image the panel shades (its pixels beyond are upscaled): 960 px wide fills
/// 20 000 lights in under a minute on a CPU driver (lavapipe, ~0.2 G light-px/s), and in
/// milliseconds on a GPU.
pub const MAX_RENDER_WIDTH: f32 = 960.0;

/// The image's aspect ratio, width over height.
const ASPECT: f32 = 16.0 / 9.0;

/// The plane panel's own settings, kept between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PlaneState {
    /// Split (A | B), difference map, or one side alone.
    pub view: View,
    pub divider: f64,
    /// The pinned pixel, in image coordinates (0–1), opened into its lights.
    pub pinned: Option<[f64; 2]>,
    /// The pinned pixel's lights table: the column sorted by, and whether descending.
    pub light_sort: (LightColumn, bool),
    /// The live GPU times in the progress line (off for a slide or a screenshot that must
    /// not change run to run).
    pub show_gpu_times: bool,
    /// The map of sphere cases over the plane (offered where a light has a size).
    pub sphere_cases: bool,
}

impl Default for PlaneState {
    fn default() -> Self {
        Self {
            view: View::Split,
            divider: 0.5,
            pinned: None,
            light_sort: (LightColumn::ErrorShare, true),
            show_gpu_times: true,
            sphere_cases: false,
        }
    }
}

impl Checked for PlaneState {
    fn check(&mut self, previous: &Self) -> Vec<String> {
        let mut n = Notes(Vec::new());
        n.number(
            "the divider",
            &mut self.divider,
            previous.divider,
            [0.0, 1.0],
        );
        if let Some(p) = &mut self.pinned {
            if p.iter().all(|x| x.is_finite()) {
                n.numbers("the pinned pixel", p, &[0.5; 2], [0.0, 1.0]);
            } else {
                n.say("the pinned pixel: not a place on the image, refused".into());
                self.pinned = None;
            }
        }
        n.0
    }
}

enum Drag {
    Divider,
    Light(usize),
}

pub struct PlanePanel {
    state: PlaneState,
    /// The renderer, on the window's GPU or the CPU.
    shading: Shading,
    /// The last image shown, and the render's size.
    shown: Option<ShownImage>,
    drag: Option<Drag>,
    /// The pinned pixel's lights, as last shown.
    pinned: PinnedLights,
    /// *worst pixel* was pressed: the pixel is pinned when the difference view is done.
    worst_pending: bool,
    /// The map of sphere cases, where it is shown.
    cases: SphereCases,
}

impl Panel for PlanePanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        let (a, b) = side_names(**lab.side_b());
        ui.horizontal_wrapped(|ui| self.toolbar(ui, lab));
        ui.horizontal_wrapped(|ui| {
            exposure_slider(ui, lab);
            ui.checkbox(&mut self.state.show_gpu_times, "GPU times")
                .on_hover_text("The GPU milliseconds in the progress line; off for a slide or a screenshot that should not change from run to run");
            if sized(lab) {
                ui.checkbox(&mut self.state.sphere_cases, "sphere cases")
                    .on_hover_text("Colour each pixel by where its lights with a size are: above the surface, below it, cut by its horizon, or around the point (the failure cases of lights with a size)");
            }
        });
        progress_line(ui, self.shading.progress(), !self.state.show_gpu_times);
        below_plane_note(ui, lab);
        // A fixed strip under the image for the readout (and the pinned pixel's lights), so
        // that nothing covers it and the image does not jump when it changes.
        let pinned = self.state.pinned.is_some();
        let table_h = if pinned {
            (ui.available_height() * 0.35).clamp(60.0, 220.0)
        } else {
            0.0
        };
        let strip = 44.0 + if pinned { table_h + 24.0 } else { 0.0 };
        let avail = ui.available_size();
        let (placed, response) = image_area(
            ui,
            avail - Vec2::new(0.0, strip),
            avail - Vec2::new(0.0, 44.0),
        );
        let settings = self.settings(lab, placed.size);
        let shown = self.shading.update(ui.ctx(), lab, &settings);
        self.shown = Some(shown);
        let show_cases = self.cases_shown(lab);
        if show_cases {
            self.cases.update(ui.ctx(), lab, placed.size);
        }
        self.pin_worst(lab);
        if self.worst_pending {
            ui.ctx().request_repaint();
        }
        self.paint(ui, lab, placed, shown, (a, b));
        let markers = markers(lab, placed);
        self.interact(&response, lab, placed, &markers);
        self.shading.tell(lab);
        self.pinned.update(lab, self.state.pinned, placed.size);
        let shading = &mut self.shading;
        self.pinned
            .update_file(lab, self.state.pinned, |at| shading.probe_file(at));
        if self.state.view == View::Diff {
            colour_bar(ui, &difference_scale(a, b), 220.0);
        }
        if show_cases {
            self.cases.legend(ui);
        }
        // No tooltip on the image: it would cover the reading below it while one hovers.
        // Read afresh every frame, so that it follows every change; none off the image.
        let inspected = response
            .hover_pos()
            .and_then(|pos| inspect(lab, placed, pos, &settings));
        reading_line(ui, inspected.as_ref(), (a, b));
        let (a, b) = sized_side_names(lab, &self.state, (a, b));
        let table = (&mut self.state.pinned, &mut self.state.light_sort);
        let terms = (self.pinned.terms(), self.pinned.file());
        pixel_table::show(ui, table, lab, terms, ((&a, &b), table_h));
    }

    /// Whether the render is still being summed (or its worst pixel read back).
    fn busy(&self) -> bool {
        self.shading.in_flight() || self.worst_pending
    }

    fn caches(&self) -> Vec<(&'static str, u64)> {
        let mut caches = self.shading.caches().to_vec();
        caches.push(self.pinned.count());
        caches.push(self.cases.count());
        caches
    }
}

impl PlanePanel {
    /// The panel with its kept settings, shading on `gpu` (the lab's device and the window's
    /// render state) where there is one: else on the CPU, and why.
    pub fn new(
        state: PlaneState,
        gpu: Option<(&GpuContext, &egui_wgpu::RenderState)>,
    ) -> (Self, Option<String>) {
        let (shading, why) = Shading::new(gpu);
        let panel = Self {
            state,
            shading,
            shown: None,
            drag: None,
            pinned: PinnedLights::default(),
            worst_pending: false,
            cases: SphereCases::default(),
        };
        (panel, why)
    }

    pub fn state(&self) -> &PlaneState {
        &self.state
    }

    /// The pinned pixel opened into its lights, as last shown.
    pub fn pinned_terms(&self) -> Option<&crate::pixel::PixelTerms> {
        self.pinned.terms()
    }

    /// Its settings from a view (a lesson's step), checked by the caller.
    pub fn set_state(&mut self, state: PlaneState) {
        self.state = state;
        // A *worst pixel* asked for before would pin over the view's pixel.
        self.worst_pending = false;
    }

    /// Whether its image's read-back is on its way (`save_exr` will have it).
    pub fn read_pending(&self) -> bool {
        self.shading.read_pending()
    }

    /// Its render's size in pixels, once it has shown one.
    pub fn size(&self) -> Option<(usize, usize)> {
        self.shown.map(|s| s.size)
    }

    /// How far its render is.
    pub fn progress(&self) -> &crate::app::plane::shading::Progress {
        self.shading.progress()
    }

    fn settings(&self, lab: &Lab, size: (usize, usize)) -> RenderSettings {
        render_settings(lab, &self.state, size)
    }

    /// The image, its preview note, the divider, the lights' markers and the pin.
    fn paint(
        &self,
        ui: &egui::Ui,
        lab: &Lab,
        placed: Placed,
        shown: ShownImage,
        sides: (&str, &str),
    ) {
        let rect = placed.rect;
        let painter = ui.painter_at(rect);
        paint_image(&painter, rect, shown, self.shading.error());
        if self.cases_shown(lab) {
            self.cases.paint(&painter, rect);
        }
        preview_label(ui, rect, self.shading.progress());
        if self.state.view == View::Split {
            let (a, b) = sized_side_names(lab, &self.state, sides);
            paint_divider(&painter, rect, self.divider_x(rect), (&a, &b));
        }
        let markers = markers(lab, placed);
        paint_outlines(&painter, lab, placed, &markers);
        paint_markers(&painter, lab, &markers);
        if let Some([u, v]) = self.state.pinned {
            paint_pin(
                &painter,
                rect.min + Vec2::new(u as f32 * rect.width(), v as f32 * rect.height()),
            );
        }
    }

    /// Whether the map of sphere cases is over the image: asked for, and a light has a size.
    fn cases_shown(&self, lab: &Lab) -> bool {
        self.state.sphere_cases && sized(lab)
    }

    fn divider_x(&self, rect: egui::Rect) -> f32 {
        rect.min.x + rect.width() * self.state.divider as f32
    }

    /// The comparison's switch, the views, adding and removing lights, the worst pixel.
    fn toolbar(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        let (a, b) = side_names(**lab.side_b());
        let b_name = lab.tables().b().name.clone();
        lab.edit(|side: &mut SideB| {
            ui.selectable_value(side, SideB::Brdf, "LTC | BRDF")
                .on_hover_text("Side B is the exact BRDF (the BRDF form in the side panel)");
            ui.selectable_value(side, SideB::TableB, "A | B tables")
                .on_hover_text(format!("Two tables compared: side B is the same LTC form with table B ({b_name}) instead of the BRDF; the difference map is then |L_A − L_B| / L_B"));
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
            .on_hover_text(format!("Pin the pixel where {a} and {b} differ most: the largest |L_{a} − L_{b}| / max(L_{b}, 1% of the mean) of the finished difference map (shown for it)"))
            .clicked()
        {
            self.state.view = View::Diff;
            self.worst_pending = true;
        }
        self.light_buttons(ui, lab);
    }

    /// *+ light* where it is seen, and *− light* for the selected one.
    fn light_buttons(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
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
    fn pin_worst(&mut self, lab: &mut Lab) {
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

    /// A press on a marker or the divider starts dragging it; a click selects a light or
    /// pins the pixel under it; a drag moves what it started on.
    fn interact(
        &mut self,
        response: &egui::Response,
        lab: &mut Lab,
        placed: Placed,
        markers: &[(usize, Pos2)],
    ) {
        let near = |pos: Pos2| {
            markers
                .iter()
                .map(|(k, p)| (*k, p.distance(pos)))
                .filter(|(_, d)| *d < 8.0)
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(k, _)| k)
        };
        // Where the press began: by the time egui calls it a drag, the pointer has moved.
        if response.drag_started()
            && let Some(pos) = response.ctx.input(|i| i.pointer.press_origin())
        {
            let on_divider =
                self.state.view == View::Split && (pos.x - self.divider_x(placed.rect)).abs() < 8.0;
            self.drag = match near(pos) {
                Some(k) => {
                    lab.edit(|s: &mut Selection| s.light = Some(k));
                    Some(Drag::Light(k))
                }
                None if on_divider => Some(Drag::Divider),
                None => None,
            };
        }
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            let hit = near(pos);
            lab.edit(|s: &mut Selection| s.light = hit);
            // A click beside the markers pins the pixel under it.
            if hit.is_none() {
                let u = (pos - placed.rect.min) / placed.rect.size();
                self.state.pinned = Some([
                    f64::from(u.x.clamp(0.0, 1.0)),
                    f64::from(u.y.clamp(0.0, 1.0)),
                ]);
                lab.edit(|v: &mut LobeView| v.light = None);
            }
        }
        if response.dragged()
            && let Some(pos) = response.interact_pointer_pos()
        {
            match self.drag {
                Some(Drag::Divider) => {
                    let u = (pos.x - placed.rect.min.x) / placed.rect.width();
                    self.state.divider = f64::from(u).clamp(0.0, 1.0);
                }
                Some(Drag::Light(k)) => drag_light(response, lab, placed, pos, k),
                None => {}
            }
        }
        if response.drag_stopped() {
            self.drag = None;
        }
    }

    /// Writes the finished image's linear values as EXR (only the path the user named), once
    /// it is read back: `None` until then.
    pub fn save_exr(
        &mut self,
        path: &std::path::Path,
        exposure: f64,
    ) -> Option<Result<String, String>> {
        if self.shading.in_flight() {
            return Some(Err(
                "the image is still being rendered: try again when it is done".into(),
            ));
        }
        match self.shading.read() {
            Some(frame) => Some(encode_exr(&frame, path, exposure)),
            None if self.shading.read_pending() => None,
            None => Some(Err("there is no image to save yet".into())),
        }
    }
}

/// What the plane renders at `size` with the panel's settings `state`: LTC (A) against the
/// BRDF form, or — two tables compared — the same LTC form with table A against it with
/// table B.
pub fn render_settings(
    lab: &Lab,
    state: &PlaneState,
    (width, height): (usize, usize),
) -> RenderSettings {
    let forms = **lab.forms();
    let spheres = **lab.spheres();
    let rects = **lab.rects();
    let disks = **lab.disks();
    let tables = **lab.side_b() == SideB::TableB;
    let ltc = ShapeMethods {
        point: forms.ltc,
        sphere: spheres.ltc,
        rect: rects.ltc,
        disk: disks.ltc,
    };
    let brdf = ShapeMethods {
        point: forms.brdf,
        sphere: spheres.brdf,
        rect: rects.brdf,
        disk: disks.brdf,
    };
    RenderSettings {
        a: ltc,
        b: if tables { ltc } else { brdf },
        b_reads_table_b: tables,
        view: state.view,
        rules: **lab.rules(),
        divider: state.divider,
        cull: forms.cull,
        ..RenderSettings::single(width, height, forms.ltc)
    }
}

/// `frame` saved as the EXR the user named.
fn encode_exr(frame: &Frame, path: &std::path::Path, exposure: f64) -> Result<String, String> {
    let format = crate::output::ImageFormat::of(path).map_err(|e| e.to_string())?;
    let bytes = crate::output::frame_bytes(frame, format, exposure);
    crate::app::files::save(path, &bytes, "image/x-exr")
}

/// Moves light `k` with the pointer at `pos`: along the plane at its height, or (Shift) up
/// and down.
fn drag_light(response: &egui::Response, lab: &mut Lab, placed: Placed, pos: Pos2, k: usize) {
    let shift = response.ctx.input(|i| i.modifiers.shift);
    let dy = f64::from(response.drag_delta().y);
    let (x, y) = placed.pixel(pos);
    let (width, height) = placed.size;
    // Keep the height; follow the pointer's ray to that height.
    let (eye, dir) = lab.scene_camera_ray(x, y, (width, height));
    let h = lab.stage().plane.half_size * 1.5;
    lab.edit_light(k, |light| {
        if shift {
            light.position[2] -= dy * 0.01;
            return;
        }
        let t = (light.position[2] - eye.z) / dir.z;
        if dir.z != 0.0 && t > 0.0 {
            let p = eye + t * dir;
            light.position[0] = p.x.clamp(-h, h);
            light.position[1] = p.y.clamp(-h, h);
        }
    });
}

/// The image's place: as large as fits `avail` at 16:9; the render's size in pixels: as
/// large as the image would be in `unpinned`, the area without the pinned pixel's table, so
/// that pinning a pixel shows the same render smaller instead of restarting it at a new size
/// (and the pinned pixel stays the pixel it was).
fn image_area(ui: &mut egui::Ui, avail: Vec2, unpinned: Vec2) -> (Placed, egui::Response) {
    let fit = |avail: Vec2| {
        if avail.x / avail.y > ASPECT {
            Vec2::new(avail.y * ASPECT, avail.y)
        } else {
            Vec2::new(avail.x, avail.x / ASPECT)
        }
        .max(Vec2::new(32.0, 18.0))
    };
    let (rect, response) = ui.allocate_exact_size(fit(avail), egui::Sense::click_and_drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "plane image"));
    let ppp = ui.ctx().pixels_per_point();
    let width = (fit(unpinned).x * ppp)
        .min(MAX_RENDER_WIDTH)
        .round()
        .max(16.0) as usize;
    let height = ((width as f32) / ASPECT).round().max(9.0) as usize;
    let placed = Placed {
        rect,
        size: (width, height),
    };
    (placed, response)
}

/// A black plane is the right answer where every light is below it, but would look like a
/// fault: say why.
fn below_plane_note(ui: &mut egui::Ui, lab: &Lab) {
    let lights = &lab.lights().list;
    let clipped = lab.rules().clipping.case1;
    if clipped && !lights.is_empty() && lights.iter().all(|l| l.position[2] <= 0.0) {
        ui.small("every light is at or below the plane: the case-1 rule (n·l ≤ 0 -> 0) keeps it black; turn the rule off, or see the Clipping panel, for the glow M^-1 would lift");
    }
}

/// The scene's exposure: shown radiance and saved PNGs are `L · exposure` before the tone map.
fn exposure_slider(ui: &mut egui::Ui, lab: &mut Lab) {
    // 1/64..64: six stops each way covers paper-100 (peaks near 1) down to the clipping
    // scenes' faint light without leaving the slider's fine range.
    let [lo, hi] = crate::app::lab::parts::EXPOSURE_RANGE;
    lab.edit(|e: &mut Exposure| ui.add(
        egui::Slider::new(&mut e.0, lo..=hi)
            .logarithmic(true)
            .text("exposure"),
    )
    .on_hover_text("Display only: each pixel shows L · exposure through the tone map x/(1+x) and sRGB; it does not restart the render. Saved PNGs use it, EXRs keep L. The difference view has its own fixed scale"));
}

/// What sides A and B of the plane are called.
fn side_names(side_b: SideB) -> (&'static str, &'static str) {
    match side_b {
        SideB::Brdf => ("LTC", "BRDF"),
        SideB::TableB => ("A", "B"),
    }
}

/// The split's side names with, under each, how each side shades each shape with a size the
/// scene holds ("rect: ltc-polygon"): the plane's two sides differ by those methods too.
pub fn sized_side_names(lab: &Lab, state: &PlaneState, (a, b): (&str, &str)) -> (String, String) {
    let settings = render_settings(lab, state, (1, 1));
    let o = lab.overrides();
    let shapes: Vec<Shape> = lab
        .lights()
        .list
        .iter()
        .map(|l| o.shaded_shape(l))
        .collect();
    let has = |f: fn(&Shape) -> bool| shapes.iter().any(f);
    // A side shading with the method file is named by the file, and so is each shape it shades.
    let file = lab.method_file();
    let name = |side: &str, m: ShapeMethods| {
        let by_file = |k: usize| m.point == Method::File && file.is_some_and(|f| f.shades[k]);
        let method = |k: usize, own: &'static str| if by_file(k) { "file" } else { own };
        let mut out = match file.filter(|_| m.point == Method::File) {
            Some(f) => f.name.clone(),
            None => side.to_string(),
        };
        if has(|s| matches!(s, Shape::Sphere { .. })) {
            out += &format!("\nsphere: {}", method(1, m.sphere.name()));
        }
        if has(|s| matches!(s, Shape::Rect { .. })) {
            out += &format!("\nrect: {}", method(2, m.rect.name()));
        }
        if has(|s| matches!(s, Shape::Disk { .. })) {
            out += &format!("\ndisk: {}", method(3, m.disk.name()));
        }
        out
    };
    (name(a, settings.a), name(b, settings.b))
}

/// Whether some light of the lab's scene, as shaded, is a sphere (whose cases the map shows).
fn sized(lab: &Lab) -> bool {
    let o = lab.overrides();
    lab.lights()
        .list
        .iter()
        .any(|l| matches!(o.shaded_shape(l), Shape::Sphere { .. }))
}
