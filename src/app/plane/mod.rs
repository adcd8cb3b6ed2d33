//! The plane panel: the scene shaded on the window's GPU — summed over frames within a time
//! budget, with its progress — LTC left of a draggable divider and the exact BRDF (or LTC
//! with table B) right of it, or the difference map, or one alone; light markers to drag
//! (Shift: height), add where they are seen and remove; the pixel where the sides differ
//! most, pinned on request; a pixel inspector, shaded on the CPU in f64, with both
//! radiances, their relative difference and the lights in clipping cases 1 and 2.

mod interaction;
pub mod paint;
pub mod pixel_table;
mod save;
pub mod shading;
pub mod sphere_cases;
pub mod spots;
mod toolbar;

use egui::Vec2;
use serde::{Deserialize, Serialize};

use crate::app::lab::part::Notes;
use crate::app::lab::{Checked, Lab, SideB};
use crate::app::panel::Panel;
use crate::app::plane::paint::{
    Placed, inspect, markers, paint_divider, paint_image, paint_markers, paint_outlines, paint_pin,
    preview_label, progress_line, reading_line,
};
use crate::app::plane::pixel_table::{LightColumn, PinnedLights};
use crate::app::plane::shading::Shading;
use crate::app::plane::sphere_cases::SphereCases;
use crate::app::ui::display::{ShownImage, colour_bar, difference_scale};
use crate::gpu::GpuContext;
use crate::light::{Shape, ShapeKind};
use crate::render::ShapeMethods;
use crate::render::{Method, RenderSettings, View};
use interaction::image_area;
use toolbar::{below_plane_note, exposure_slider};

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
                    .on_hover_text("Colour each pixel by where its lights with a size are: above the surface, below it, cut \
                        by its horizon, or around the point (the failure cases of lights with a size)");
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
    let shapes = lab.shape_forms();
    let tables = **lab.side_b() == SideB::TableB;
    let ltc = shapes.ltc.with(forms.ltc);
    let brdf = shapes.brdf.with(forms.brdf);
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
    let kinds: Vec<ShapeKind> = lab
        .lights()
        .list
        .iter()
        .map(|l| o.shaded_shape(l).kind())
        .collect();
    // A side shading with the method file is named by the file, and so is each shape it shades.
    let file = lab.method_file();
    let name = |side: &str, m: ShapeMethods| {
        let by_file = |k| m.point() == Method::File && file.is_some_and(|f| f.shades(k));
        let mut out = match file.filter(|_| m.point() == Method::File) {
            Some(f) => f.name.clone(),
            None => side.to_string(),
        };
        for kind in ShapeKind::sized().filter(|k| kinds.contains(k)) {
            let method = if by_file(kind) {
                "file"
            } else {
                m.of(kind).name()
            };
            out += &format!("\n{}: {method}", kind.name());
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
