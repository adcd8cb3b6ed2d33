//! The side panel: every global control, each with a tooltip naming what it changes in the
//! equations. It edits the lab's parts; a file to read or write is a request the app carries
//! out.

use std::path::PathBuf;

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::app::files::Purpose;
use crate::app::lab::parts::{BRDF_FORMS, LTC_FORMS, RADIUS_RANGE, RANGE_RANGE};
use crate::app::lab::{
    DiskForms, Forms, Lab, LobeView, Overrides, RectForms, Request, SphereForms,
};
use crate::app::panel::Panel;
use crate::app::ui::widgets::{clipping_rules, explain, name};
use crate::light::Shape;
use crate::light::disk::DiskMethod;
use crate::light::rect::RectMethod;
use crate::light::sphere::SphereMethod;
use crate::ltc::Normalization;
use crate::ltc::lut::{ALPHA_MIN, Table};
use crate::ltc::remedy::Horizon;
use crate::render::{LtcRules, Method};
use crate::scene::{
    DISK_PRESETS, Light, MIN_RADIUS, Material, PRESETS, RECT_PRESETS, SPHERE_PRESETS, preset,
};
use crate::tables::Source;

/// The light counts the slider offers, at most (and at most what the adapter shades).
pub const MAX_LIGHT_SLIDER: usize = 100_000;

/// The side panel's files, kept between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct ControlsState {
    pub scene_path: String,
    pub screenshot_path: String,
    /// A LUT file to shade with; empty: the embedded table.
    pub lut_path: String,
    /// A method file's path (the path alone is kept, never its code).
    pub method_path: String,
}

impl Default for ControlsState {
    fn default() -> Self {
        Self {
            scene_path: "scene.toml".into(),
            screenshot_path: "ltc-lab.png".into(),
            lut_path: String::new(),
            method_path: String::new(),
        }
    }
}

/// Whether the load buttons open the browser's file picker (the web build) instead of
/// reading the path in their field (the desktop).
const PICKS: bool = cfg!(target_arch = "wasm32");

/// The side panel.
#[derive(Default)]
pub struct ControlsPanel {
    state: ControlsState,
}

impl ControlsPanel {
    pub fn new(state: ControlsState) -> Self {
        Self { state }
    }

    pub fn state(&self) -> &ControlsState {
        &self.state
    }
}

impl Panel for ControlsPanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        ui.heading("LTC Lab");
        ui.label(egui::RichText::new(lab.describe_device()).small())
            .on_hover_text("The adapter the plane and chart panels shade on");
        if let Some(e) = lab.device_error() {
            ui.colored_label(
                egui::Color32::from_rgb(230, 120, 60),
                format!(
                    "GPU unavailable — the plane is drawn by the CPU reference at reduced size. {e}"
                ),
            );
        }
        ui.separator();
        material(ui, lab);
        ui.separator();
        lights(ui, lab);
        ui.separator();
        shading_rules(ui, lab);
        ui.separator();
        ui.strong("Scene");
        scene_files(ui, lab, &mut self.state);
        table(ui, lab, &mut self.state);
        method_file(ui, lab, &mut self.state);
        save_buttons(ui, lab, &mut self.state);
    }
}

fn material(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.strong("Material");
    lab.edit(|m: &mut Material| {
        ui.add(egui::Slider::new(&mut m.alpha, 1e-3..=1.0).logarithmic(true).text("α"))
            .on_hover_text("GGX α: D = α² / (π ((n·h)²(α²−1)+1)²), Λ = (−1+sqrt(1+α² tan²θ))/2; also the LUT column (r = sqrt α) the LTC comes from");
        let mut r = m.alpha.sqrt();
        if ui
            .add(egui::Slider::new(&mut r, 0.0316..=1.0).text("roughness r = √α"))
            .on_hover_text("Perceptual roughness; α = r². Burley's FD = 0.5 + 2α(l·h)² uses the paper's α (ltc_code and Unity use √α)")
            .changed()
        {
            m.alpha = (r * r).max(ALPHA_MIN);
        }
    });
    lab.edit(|v: &mut LobeView| {
        ui.add(egui::Slider::new(&mut v.theta_o_deg, 0.0..=90.0).text("θo (°)"))
            .on_hover_text("View angle of the lobe and matrix panels: v = (sin θo, 0, cos θo); the LUT row is sqrt(1 − cos θo)")
    });
    lab.edit(|m: &mut Material| {
        ui.add(egui::Slider::new(&mut m.f0, 0.0..=1.0).text("F0"))
            .on_hover_text("Schlick: F = F0 + (1 − F0)(1 − v·h)⁵; in the LTC, the specular magnitude F0·n_s + (1 − F0)·f_s");
        ui.horizontal(|ui| {
            let mut c = m.base_color.map(|x| x as f32);
            if ui
                .color_edit_button_rgb(&mut c)
                .on_hover_text("Base colour c: fd = c/π (…)(…); in the LTC, c · n_d · D_d")
                .changed()
            {
                m.base_color = c.map(f64::from);
            }
            ui.label("base colour");
        });
    });
}

fn lights(ui: &mut egui::Ui, lab: &mut Lab) {
    let max = lab.max_lights().min(MAX_LIGHT_SLIDER);
    ui.strong("Lights");
    lab.edit(|o: &mut Overrides| {
        ui.add(
            egui::Slider::new(&mut o.intensity_scale, 0.01..=100.0)
                .logarithmic(true)
                .text("intensity ×"),
        )
        .on_hover_text("Multiplies every light's I in E = I/d² · w(d)");
        explain(ui, "× every light's I (not saved to the scene)");
        let range = ui
            .add(egui::Slider::new(&mut o.range, 0.0..=RANGE_RANGE[1]).text("range R"))
            .on_hover_text("The window w(d) = clamp(1 − (d/R)⁴, 0, 1)²; 0 keeps each light's own range (absent = ∞)");
        // In steps of the smallest range it shows (0.01): a range between 0 (each light's
        // own) and that showed as "0.00" beside a black plane.
        if range.changed() {
            o.range = (o.range / RANGE_RANGE[0]).round() * RANGE_RANGE[0];
        }
        explain(
            ui,
            if o.range > 0.0 {
                "every light fades to 0 at distance R"
            } else {
                "0: each light's own range from the scene"
            },
        );
    });
    if let Some(k) = lab.selection().light {
        let half_size = lab.stage().plane.half_size;
        lab.edit_light(k, |l| light_position(ui, k, l, half_size));
    }
    let mut count = lab.lights().list.len();
    ui.horizontal(|ui| {
        if ui
            .add(egui::Slider::new(&mut count, 0..=max).logarithmic(true).text("lights"))
            .on_hover_text(format!("Regenerates the lights with the seeded generator (replaces the current ones): N point lights over the plane, heights 0.05–0.6, range 2, paper-100's intensities (past 100 lights scaled down so that the total power stays paper-100's). At most {max} here: {}", if max < MAX_LIGHT_SLIDER { "this adapter's limit" } else { "the slider's" }))
            .changed()
        {
            lab.set_light_count(count);
        }
    });
    // The slider clamps a typed count without a word: say it where it was typed.
    if max < MAX_LIGHT_SLIDER && lab.lights().list.len() >= max {
        ui.small(format!("at most {max} lights: this adapter's limit"));
    }
    lab.edit(|f: &mut Forms| {
        ui.checkbox(&mut f.cull, "cull by range")
            .on_hover_text("Tiled culling: each 16×16 tile of the plane sums only the lights whose range reaches it. The image is the same to the bit; with short ranges it is much faster")
    });
    egui::CollapsingHeader::new("lights with a size")
        .id_salt("sized lights")
        .show(ui, |ui| sized_lights(ui, lab));
}

/// A shape's methods: all of them, each one's name and its description.
type Methods<M> = (&'static [M], fn(M) -> &'static str, fn(M) -> &'static str);

/// A side's method for a light shape, picked from `all` (each described on hover).
fn method_combo<M: Copy + PartialEq>(
    ui: &mut egui::Ui,
    (label, hover): (&str, &str),
    method: &mut M,
    (all, name, describe): Methods<M>,
) {
    egui::ComboBox::from_label(label)
        .selected_text(name(*method))
        .show_ui(ui, |ui| {
            for &m in all {
                ui.selectable_value(method, m, name(m))
                    .on_hover_text(describe(m));
            }
        })
        .response
        .on_hover_text(hover);
}

/// How each side shades a rect light, and the rects' failure presets (docs/design.md §1.11).
fn rect_lights(ui: &mut egui::Ui, lab: &mut Lab) {
    lab.edit(|f: &mut RectForms| {
        for (label, method, hover) in [
            (
                "rect LTC side",
                &mut f.ltc,
                "How the LTC side (and table B) shades a rect light",
            ),
            (
                "rect reference side",
                &mut f.brdf,
                "How the BRDF side shades a rect light",
            ),
        ] {
            method_combo(
                ui,
                (label, hover),
                method,
                (&RectMethod::ALL, RectMethod::name, RectMethod::describe),
            );
        }
    });
    explain(
        ui,
        "A rect emits toward half_u × half_v with radiance I/A: far away it is the oriented point light of intensity I cos θe",
    );
    preset_buttons(
        ui,
        lab,
        &RECT_PRESETS,
        "Load this failure case of rect lights",
    );
}

/// How each side shades a disk light, and the disks' failure preset (docs/design.md §1.12).
fn disk_lights(ui: &mut egui::Ui, lab: &mut Lab) {
    lab.edit(|f: &mut DiskForms| {
        for (label, method, hover) in [
            (
                "disk LTC side",
                &mut f.ltc,
                "How the LTC side (and table B) shades a disk light",
            ),
            (
                "disk reference side",
                &mut f.brdf,
                "How the BRDF side shades a disk light",
            ),
        ] {
            method_combo(
                ui,
                (label, hover),
                method,
                (&DiskMethod::ALL, DiskMethod::name, DiskMethod::describe),
            );
        }
    });
    explain(
        ui,
        "A disk emits toward its normal with radiance I/(π r²): far away it is the oriented point light of intensity I cos θe",
    );
    preset_buttons(
        ui,
        lab,
        &DISK_PRESETS,
        "Load this failure case of disk lights",
    );
}

/// Every light's radius, how each side shades a light with one, and the failure presets
/// (docs/design.md §1.10); then the same for rects (§1.11) and disks (§1.12).
fn sized_lights(ui: &mut egui::Ui, lab: &mut Lab) {
    lab.edit(|o: &mut Overrides| {
        ui.add(
            egui::Slider::new(&mut o.radius, 0.0..=RADIUS_RANGE[1])
                .logarithmic(true)
                .smallest_positive(RADIUS_RANGE[0])
                .text("radius r"),
        )
        .on_hover_text("Every light a sphere of radius r, lighting a distant point as its point light does (radiance I/(π r²)); 0 keeps each light's own radius (absent = a point)");
        explain(
            ui,
            if o.radius > 0.0 {
                "every light a sphere of radius r"
            } else {
                "0: each light's own radius from the scene"
            },
        );
    });
    lab.edit(|f: &mut SphereForms| {
        for (label, method, hover) in [
            (
                "LTC side",
                &mut f.ltc,
                "How the LTC side (and table B) shades a light with a size",
            ),
            (
                "reference side",
                &mut f.brdf,
                "How the BRDF side shades a light with a size",
            ),
        ] {
            method_combo(
                ui,
                (label, hover),
                method,
                (
                    &SphereMethod::ALL,
                    SphereMethod::name,
                    SphereMethod::describe,
                ),
            );
        }
    });
    preset_buttons(
        ui,
        lab,
        &SPHERE_PRESETS,
        "Load this failure case of lights with a size",
    );
    ui.separator();
    rect_lights(ui, lab);
    ui.separator();
    disk_lights(ui, lab);
}

fn shading_rules(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.strong("Shading");
    // The method file is offered on either side once one is loaded.
    let file = lab.method_file().map(|f| f.name.clone());
    let offered = |forms: [Method; 2]| forms.into_iter().chain(file.iter().map(|_| Method::File));
    lab.edit(|f: &mut Forms| {
        egui::ComboBox::from_label("LTC form")
            .selected_text(f.ltc.name())
            .show_ui(ui, |ui| {
                for m in offered(LTC_FORMS) {
                    ui.selectable_value(&mut f.ltc, m, m.name());
                }
            })
            .response
            .on_hover_text("ltc: the paper's eq. 30 per light; ltc-fast: M^-1 folded with the frame, unnormalized u, eq. 27's factoring");
        egui::ComboBox::from_label("BRDF form")
            .selected_text(f.brdf.name())
            .show_ui(ui, |ui| {
                for m in offered(BRDF_FORMS) {
                    ui.selectable_value(&mut f.brdf, m, m.name());
                }
            })
            .response
            .on_hover_text(
                "brdf: eq. 28 as docs/design.md §1 writes it; brdf-fast: Filament's V_SmithGGXCorrelated",
            );
    });
    clipping_rules(
        ui,
        lab,
        [
            (
                "clip case 1 (n·l ≤ 0)",
                "Eq. 30's first rule: a light below the surface contributes nothing. Off: M^-1 can lift it above the horizon (the glow of Figure 2c)",
            ),
            (
                "clip case 2 ((M^-1l).z ≤ 0)",
                "max(ω'.z, 0) in D: a light pushed below the horizon by M^-1 contributes nothing. Off: it contributes negative light",
            ),
        ],
    );
    horizon_remedy(ui, lab);
    lab.edit(|r: &mut LtcRules| {
        let mut paper = r.normalization == Normalization::PaperLiteral;
        ui.checkbox(&mut paper, "paper-literal normalization")
            .on_hover_text("The paper's eq. 25 as printed: no 1/π in D and no magnitudes n_s, f_s, n_d (docs/design.md §1 corrects both)");
        r.normalization = if paper {
            Normalization::PaperLiteral
        } else {
            Normalization::Corrected
        };
    });
}

/// The horizon remedy (docs/design.md §4.8): eq. 30 alone, a table fitted for the horizon, or
/// a rule per light.
fn horizon_remedy(ui: &mut egui::Ui, lab: &mut Lab) {
    let current = lab.horizon_remedy();
    let mut chosen = None;
    egui::ComboBox::from_label("horizon")
        .selected_text(current.name())
        .show_ui(ui, |ui| {
            for h in Horizon::ALL {
                if ui
                    .selectable_label(h == current, h.name())
                    .on_hover_text(h.describe())
                    .clicked()
                {
                    chosen = Some(h);
                }
            }
        })
        .response
        .on_hover_text("What LTC does for lights near the horizon, where eq. 30 is wrong by half: the clipping panel plots one light over its elevation and each band's error");
    if let Some(h) = chosen.filter(|&h| h != current) {
        lab.use_horizon(h);
    }
}

/// Light `k`'s x, y (over the plane) and z, typed or dragged.
fn light_position(ui: &mut egui::Ui, k: usize, light: &mut Light, half_size: f64) {
    ui.horizontal(|ui| {
        ui.label(format!("light {k}"));
        for (i, (axis, range, hover)) in [
            ("x", -half_size..=half_size, "Across the plane"),
            ("y", -half_size..=half_size, "Along the plane, away from the camera"),
            ("z", -1.0..=3.0, "Height: below 0 the light is under the plane (clipping case 1). Shift-drag its marker for the same"),
        ]
        .into_iter()
        .enumerate()
        {
            let label = ui.label(axis);
            ui.add(egui::DragValue::new(&mut light.position[i]).speed(0.01).range(range).max_decimals(4))
                .labelled_by(label.id)
                .on_hover_text(hover);
        }
        if let Shape::Rect { half_u, half_v } = &mut light.shape {
            rect_size(ui, half_u, half_v);
            return;
        }
        if let Shape::Disk { radius, .. } = &mut light.shape {
            // A disk keeps its size: its radius from the scene's least, never 0.
            let label = ui.label("r");
            ui.add(egui::DragValue::new(radius).speed(0.004).range(RADIUS_RANGE[0]..=RADIUS_RANGE[1]).max_decimals(4))
                .labelled_by(label.id)
                .on_hover_text("The disk's radius, 0.0001 to 1 (a value typed beyond is brought into that range): it keeps its normal and its intensity, so a larger disk lights a distant point alike and is dimmer per area");
            return;
        }
        // The shape by its radius: 0 a point, more a sphere.
        let label = ui.label("r");
        let mut radius = light.shape.radius();
        ui.add(egui::DragValue::new(&mut radius).speed(0.001).range(0.0..=RADIUS_RANGE[1]).max_decimals(4))
            .labelled_by(label.id)
            .on_hover_text("Radius: 0 is the paper's point light; from 0.0001 a sphere, shaded by each side's method for lights with a size");
        light.shape = Shape::of_radius(radius);
    });
}

/// A rect's width and height (its edges' full lengths), each dragged along its own
/// direction: the orientation stays.
fn rect_size(ui: &mut egui::Ui, half_u: &mut DVec3, half_v: &mut DVec3) {
    for (name, edge, hover) in [
        (
            "w",
            half_u,
            "Width: the length of the rect's first edge (2 |half_u|)",
        ),
        (
            "h",
            half_v,
            "Height: the length of its second edge (2 |half_v|)",
        ),
    ] {
        let label = ui.label(name);
        let length = edge.length();
        let mut full = 2.0 * length;
        // From 2·MIN_RADIUS, so that a square keeps the scene's least area, to 4 (the
        // default plane's side).
        ui.add(
            egui::DragValue::new(&mut full)
                .speed(0.005)
                .range(2.0 * MIN_RADIUS..=4.0)
                .max_decimals(4),
        )
        .labelled_by(label.id)
        .on_hover_text(hover);
        if length > 0.0 && full != 2.0 * length {
            *edge *= 0.5 * full / length;
        }
    }
}

/// A button per preset of `presets`, each loading its scene.
fn preset_buttons(ui: &mut egui::Ui, lab: &mut Lab, presets: &[(&str, &str)], hover: &str) {
    ui.horizontal_wrapped(|ui| {
        for (name, _) in presets {
            if ui.small_button(*name).on_hover_text(hover).clicked() {
                lab.use_scene(preset(name));
            }
        }
    });
}

/// The presets, and a scene file to load or save (only the file named is written).
fn scene_files(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    preset_buttons(ui, lab, &PRESETS, "Load this shipped preset");
    ui.horizontal(|ui| {
        let field = ui
            .add(egui::TextEdit::singleline(&mut files.scene_path).desired_width(120.0))
            .on_hover_text(
                "A scene TOML file to load, or to save to (only the file named here is written)",
            );
        name(ui, &field, "scene file");
        if ui
            .small_button("load")
            .on_hover_text(if PICKS {
                "Pick a scene .toml file (or drop one on the window)"
            } else {
                "Read the scene file named on the left (or drop one on the window)"
            })
            .clicked()
        {
            lab.request(Request::Open(Purpose::Scene, files.scene_path.clone()));
        }
        if ui
            .small_button("save")
            .on_hover_text(if PICKS {
                "Download the scene as the file named on the left"
            } else {
                "Write the scene to the file named on the left (and no other)"
            })
            .clicked()
        {
            lab.request(Request::SaveScene(PathBuf::from(&files.scene_path)));
        }
    });
}

/// The shipped table switch, and a LUT file to shade with or to compare with (table B).
fn table(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    // Wrapped: four tables in one row would widen the side panel.
    ui.horizontal_wrapped(|ui| {
        ui.label("LTC table:");
        for (t, hover) in [
            (Table::Classic, "ltc_code's fit (luts/ltc.exr): made for area lights' integrals"),
            (Table::Point, "The point-light fit (luts/ltc_point.exr): minimizes ∫|n·D − f·cos| / ∫ f·cos, what one point light sees"),
            (Table::Arrival, "The arrival fit (luts/ltc_arrival.exr): the point-light objective weighted by where lights above a plane arrive from, the horizon included (the arrival-fit remedy)"),
            (Table::Constrained, "The constrained fit (luts/ltc_constrained.exr): the point-light objective with m20 = 0, so M^-1 never carries a light across the horizon (the constrained-fit remedy)"),
        ] {
            // A shipped table is lit only while no file shades instead of it.
            let chosen = lab.tables().a().source == Source::Shipped(t);
            if ui.selectable_label(chosen, t.name()).on_hover_text(hover).clicked() && !chosen {
                files.lut_path.clear();
                lab.use_shipped(t);
            }
        }
    });
    if let Source::File(file) | Source::Given(file) = &lab.tables().a().source {
        ui.small(format!("table A: {file}"));
    }
    ui.horizontal(|ui| {
        // A browser picks the file instead.
        if !PICKS {
            let field = ui.add(egui::TextEdit::singleline(&mut files.lut_path).desired_width(120.0).hint_text("embedded LUT"))
                .on_hover_text("An LTC table: .exr as `ltc-lab fit` writes it, ltc_code's ltc.js (or three.js's copy), or its ltc_1.dds/ltc_2.dds (either file or their directory); empty for the embedded one");
            name(ui, &field, "table file");
        }
        if ui.small_button("use LUT").on_hover_text("Shade with the table named on the left (table A), or one dropped on the window; a missing or broken file is reported here and the current table stays").clicked() {
            lab.request(Request::Open(Purpose::Table, files.lut_path.clone()));
        }
        if ui.small_button("as B").on_hover_text("Make the table named on the left table B, the other fit: the lobe overlay, the matrix panel and the plane's A | B comparison show it beside table A").clicked() {
            lab.request(Request::Open(Purpose::TableB, files.lut_path.clone()));
        }
    });
    ui.horizontal(|ui| {
        ui.small(format!("table B: {}", lab.tables().b().name))
            .on_hover_text("The other fit: the lobe overlay and the matrix panel show it beside table A, and the plane's A | B comparison shades with it");
        if !lab.tables().b_is_default() && ui.small_button("reset").on_hover_text("Table B back to the other shipped table").clicked() {
            lab.use_table_b(None);
        }
    });
}

/// The screenshot field (`.png` saves the window, `.exr` the plane's radiance), and the
/// view shared as a link.
fn save_buttons(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    ui.horizontal(|ui| {
        let field = ui
            .add(egui::TextEdit::singleline(&mut files.screenshot_path).desired_width(120.0))
            .on_hover_text(
                "Screenshot file: .png saves the window, .exr the plane's linear radiance",
            );
        name(ui, &field, "screenshot file");
        if ui.small_button("screenshot").clicked() {
            let path = PathBuf::from(&files.screenshot_path);
            let exr = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
            lab.request(if exr {
                Request::SaveExr(path)
            } else {
                Request::Screenshot(path)
            });
        }
    });
    let hover = if PICKS {
        "Put this view (scene, settings, open panel) in the page's address and copy the link"
    } else {
        "Copy this view (scene, settings, open panel) as a string for `ltc-lab lab --view`, or for a browser link after #view="
    };
    if ui.small_button("share view").on_hover_text(hover).clicked() {
        lab.request(Request::Share);
    }
}

/// The method file: its path and *load method* (the browser's picker), or a dropped .wgsl;
/// its code runs only from here, never from a link or a lesson (docs/design.md §5.13).
fn method_file(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    let loaded = lab
        .method_file()
        .map(|f| format!("{} (shades {})", f.name, f.shapes()));
    ui.horizontal(|ui| {
        if !PICKS {
            let field = ui
                .add(
                    egui::TextEdit::singleline(&mut files.method_path)
                        .desired_width(120.0)
                        .hint_text("your method .wgsl"),
                )
                .on_hover_text("A method of your own: a WGSL file of functions under the interface of docs/design.md §5.13 (assets/methods/ has examples)");
            name(ui, &field, "method file");
        }
        if ui
            .small_button("load method")
            .on_hover_text(if PICKS {
                "Pick a method .wgsl file (or drop one on the window): it shades as the method `file`"
            } else {
                "Read the method .wgsl named on the left (or drop one on the window): it shades as the method `file`"
            })
            .clicked()
        {
            lab.request(Request::Open(Purpose::Method, files.method_path.clone()));
        }
    });
    if let Some(name) = loaded {
        ui.small(format!("method file: {name}"));
    }
}
