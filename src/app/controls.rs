//! The side panel: every global control, each with a tooltip naming what it changes in the
//! equations. It edits the state; what reaches beyond the state (a new table, a file to
//! write) comes back as an `Action` for the app to carry out.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::app::file_io::{Purpose, save};
use crate::app::lab::{Aspect, Lab, Message, Panel, Request};
use crate::ltc::Normalization;
use crate::ltc::formats;
use crate::ltc::lut::Table;
use crate::ltc::remedy::Horizon;
use crate::render::Method;
use crate::scene::{PRESETS, Scene, preset};
use crate::tables::NamedTable;

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
}

impl Default for ControlsState {
    fn default() -> Self {
        Self {
            scene_path: "scene.toml".into(),
            screenshot_path: "ltc-lab.png".into(),
            lut_path: String::new(),
        }
    }
}

/// Whether the load buttons open the browser's file picker (the web build) instead of
/// reading the path in their field (the desktop).
const PICKS: bool = cfg!(target_arch = "wasm32");

/// The side panel.
#[derive(Default)]
pub struct ControlsPanel {
    pub state: ControlsState,
}

impl ControlsPanel {
    pub fn new(state: ControlsState) -> Self {
        Self { state }
    }
}

impl Panel for ControlsPanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        ui.heading("LTC Lab");
        ui.label(egui::RichText::new(lab.describe_device()).small())
            .on_hover_text("The adapter the plane and chart panels shade on");
        if let Some(e) = &lab.gpu_error {
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
        save_buttons(ui, lab, &mut self.state);
    }
}

/// The last file operation's outcome, in a bar along the bottom of the window: always in
/// view, even in a small window, and it moves no control (the panels' contents hang from
/// their tops; at the top of the side panel it pushed every control down under the pointer).
/// Whether it was dismissed.
pub fn message_bar(ui: &mut egui::Ui, m: &Message) -> bool {
    let colour = if m.is_error {
        egui::Color32::from_rgb(230, 90, 80)
    } else {
        ui.visuals().text_color()
    };
    ui.horizontal(|ui| {
        let dismissed = ui
            .small_button("×")
            .on_hover_text("Dismiss this notice")
            .clicked();
        ui.colored_label(colour, &m.text);
        dismissed
    })
    .inner
}

fn material(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.strong("Material");
    lab.edit(Aspect::Scene, |s| {
        let before = s.scene.material.alpha;
        let mut alpha = before;
        ui.add(egui::Slider::new(&mut alpha, 1e-3..=1.0).logarithmic(true).text("α"))
            .on_hover_text("GGX α: D = α² / (π ((n·h)²(α²−1)+1)²), Λ = (−1+sqrt(1+α² tan²θ))/2; also the LUT column (r = sqrt α) the LTC comes from");
        let mut r = alpha.sqrt();
        if ui
            .add(egui::Slider::new(&mut r, 0.0316..=1.0).text("roughness r = √α"))
            .on_hover_text("Perceptual roughness; α = r². Burley's FD = 0.5 + 2α(l·h)² uses the paper's α (ltc_code and Unity use √α)")
            .changed()
        {
            alpha = r * r;
        }
        s.scene.material.alpha = alpha.clamp(crate::ltc::lut::ALPHA_MIN, 1.0);
        s.scene.material.alpha != before
    });
    lab.edit(Aspect::LobeView, |s| {
        ui.add(egui::Slider::new(&mut s.theta_o_deg, 0.0..=90.0).text("θo (°)"))
            .on_hover_text("View angle of the lobe and matrix panels: v = (sin θo, 0, cos θo); the LUT row is sqrt(1 − cos θo)")
    });
    lab.edit(Aspect::Scene, |s| {
        ui.add(egui::Slider::new(&mut s.scene.material.f0, 0.0..=1.0).text("F0"))
            .on_hover_text("Schlick: F = F0 + (1 − F0)(1 − v·h)⁵; in the LTC, the specular magnitude F0·n_s + (1 − F0)·f_s")
    });
    ui.horizontal(|ui| {
        lab.edit(Aspect::Scene, |s| {
            let mut c = s.scene.material.base_color.map(|x| x as f32);
            let r = ui
                .color_edit_button_rgb(&mut c)
                .on_hover_text("Base colour c: fd = c/π (…)(…); in the LTC, c · n_d · D_d");
            s.scene.material.base_color = c.map(f64::from);
            r
        });
        ui.label("base colour");
    });
}

fn lights(ui: &mut egui::Ui, lab: &mut Lab) {
    let max = lab.max_lights().min(MAX_LIGHT_SLIDER);
    ui.strong("Lights");
    lab.edit(Aspect::Shading, |s| {
        ui.add(
            egui::Slider::new(&mut s.intensity_scale, 0.01..=100.0)
                .logarithmic(true)
                .text("intensity ×"),
        )
        .on_hover_text("Multiplies every light's I in E = I/d² · w(d)")
    });
    explain(ui, "× every light's I (not saved to the scene)");
    lab.edit(Aspect::Shading, |s| {
        ui.add(egui::Slider::new(&mut s.range_override, 0.0..=10.0).text("range R"))
            .on_hover_text("The window w(d) = clamp(1 − (d/R)⁴, 0, 1)²; 0 keeps each light's own range (absent = ∞)")
    });
    explain(
        ui,
        if lab.shared().range_override > 0.0 {
            "every light fades to 0 at distance R"
        } else {
            "0: each light's own range from the scene"
        },
    );
    let selected = lab.shared().selected_light;
    if let Some(k) = selected.filter(|&k| k < lab.shared().scene.lights.len()) {
        lab.edit(Aspect::Scene, |s| {
            let half_size = s.scene.plane.half_size;
            light_position(ui, k, &mut s.scene.lights[k].position, half_size)
        });
    }
    let mut count = lab.shared().scene.lights.len();
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
    if max < MAX_LIGHT_SLIDER && lab.shared().scene.lights.len() >= max {
        ui.small(format!("at most {max} lights: this adapter's limit"));
    }
    lab.edit(Aspect::Shading, |s| {
        ui.checkbox(&mut s.cull, "cull by range")
            .on_hover_text("Tiled culling: each 16×16 tile of the plane sums only the lights whose range reaches it. The image is the same to the bit; with short ranges it is much faster")
    });
}

fn shading_rules(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.strong("Shading");
    lab.edit(Aspect::Shading, |s| {
        let ltc = egui::ComboBox::from_label("LTC form")
            .selected_text(s.method_ltc.name())
            .show_ui(ui, |ui| {
                [Method::Ltc, Method::LtcFast]
                    .map(|m| ui.selectable_value(&mut s.method_ltc, m, m.name()).changed())
                    .contains(&true)
            });
        ltc.response.on_hover_text("ltc: the paper's eq. 30 per light; ltc-fast: M^-1 folded with the frame, unnormalized u, eq. 27's factoring");
        let brdf = egui::ComboBox::from_label("BRDF form")
            .selected_text(s.method_brdf.name())
            .show_ui(ui, |ui| {
                [Method::Brdf, Method::BrdfFast]
                    .map(|m| ui.selectable_value(&mut s.method_brdf, m, m.name()).changed())
                    .contains(&true)
            });
        brdf.response.on_hover_text(
            "brdf: eq. 28 as docs/design.md §1 writes it; brdf-fast: Filament's V_SmithGGXCorrelated",
        );
        ltc.inner == Some(true) || brdf.inner == Some(true)
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
    lab.edit(Aspect::Rules, |s| {
        let mut paper = s.normalization == Normalization::PaperLiteral;
        let r = ui.checkbox(&mut paper, "paper-literal normalization")
            .on_hover_text("The paper's eq. 25 as printed: no 1/π in D and no magnitudes n_s, f_s, n_d (docs/design.md §1 corrects both)");
        s.normalization = if paper {
            Normalization::PaperLiteral
        } else {
            Normalization::Corrected
        };
        r
    });
}

/// The horizon remedy (docs/design.md §4.7): eq. 30 alone, a table fitted for the horizon, or
/// a rule per light.
fn horizon_remedy(ui: &mut egui::Ui, lab: &mut Lab) {
    let current = lab.shared().horizon_remedy();
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

/// Eq. 30's two rules as checkboxes, each with its label and tooltip (the side panel and the
/// clipping panel word them for their place).
pub fn clipping_rules(ui: &mut egui::Ui, lab: &mut Lab, [case1, case2]: [(&str, &str); 2]) {
    lab.edit(Aspect::Rules, |s| {
        ui.checkbox(&mut s.clipping.case1, case1.0)
            .on_hover_text(case1.1)
    });
    lab.edit(Aspect::Rules, |s| {
        ui.checkbox(&mut s.clipping.case2, case2.0)
            .on_hover_text(case2.1)
    });
}

/// The selected light's x, y (over the plane) and z, typed or dragged; whether one changed.
fn light_position(ui: &mut egui::Ui, k: usize, position: &mut [f64; 3], half_size: f64) -> bool {
    ui.horizontal(|ui| {
        ui.label(format!("light {k}"));
        let mut changed = false;
        for (i, (axis, range, hover)) in [
            ("x", -half_size..=half_size, "Across the plane"),
            ("y", -half_size..=half_size, "Along the plane, away from the camera"),
            ("z", -1.0..=3.0, "Height: below 0 the light is under the plane (clipping case 1). Shift-drag its marker for the same"),
        ]
        .into_iter()
        .enumerate()
        {
            let label = ui.label(axis);
            changed |= ui.add(egui::DragValue::new(&mut position[i]).speed(0.01).range(range).max_decimals(4))
                .labelled_by(label.id)
                .on_hover_text(hover)
                .changed();
        }
        changed
    })
    .inner
}

/// The presets, and a scene file to load or save (only the file named is written).
fn scene_files(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    ui.horizontal_wrapped(|ui| {
        for (name, _) in PRESETS {
            if ui
                .small_button(name)
                .on_hover_text("Load this shipped preset")
                .clicked()
            {
                lab.message = lab.use_scene(preset(name)).map(Message::error);
            }
        }
    });
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut files.scene_path).desired_width(120.0))
            .on_hover_text(
                "A scene TOML file to load, or to save to (only the file named here is written)",
            );
        if ui
            .small_button("load")
            .on_hover_text(if PICKS {
                "Pick a scene .toml file (or drop one on the window)"
            } else {
                "Read the scene file named on the left (or drop one on the window)"
            })
            .clicked()
        {
            if PICKS {
                lab.request = Some(Request::Pick(Purpose::Scene));
                return;
            }
            let path = &files.scene_path;
            let message = use_loaded_scene(lab, Scene::load(Path::new(path)), path);
            lab.say(message);
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
            // The view becomes what the file holds.
            let rounded = lab.shared().scene.rounded_for_saving();
            let changed = rounded != lab.shared().scene;
            lab.edit(Aspect::Scene, |s| {
                s.scene = rounded;
                changed
            });
            let text = lab.shared().scene.to_toml();
            let path = Path::new(&files.scene_path);
            lab.say(match save(path, text.as_bytes(), "application/toml") {
                Ok(done) => Message::note(done),
                Err(e) => Message::error(e),
            });
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
            let chosen = lab.shared().table_file.is_none() && lab.shared().table == t;
            if ui.selectable_label(chosen, t.name()).on_hover_text(hover).clicked() && !chosen {
                files.lut_path.clear();
                lab.use_shipped(t);
            }
        }
    });
    if let Some(file) = &lab.shared().table_file {
        ui.small(format!("table A: {file}"));
    }
    ui.horizontal(|ui| {
        // A browser picks the file instead.
        if !PICKS {
            ui.add(egui::TextEdit::singleline(&mut files.lut_path).desired_width(120.0).hint_text("embedded LUT"))
                .on_hover_text("An LTC table: .exr as `ltc-lab fit` writes it, ltc_code's ltc.js (or three.js's copy), or its ltc_1.dds/ltc_2.dds (either file or their directory); empty for the embedded one");
        }
        if ui.small_button("use LUT").on_hover_text("Shade with the table named on the left (table A), or one dropped on the window; a missing or broken file is reported here and the current table stays").clicked() {
            if PICKS {
                lab.request = Some(Request::Pick(Purpose::Table));
                return;
            }
            let message = match (load(&files.lut_path), files.lut_path.trim()) {
                // The embedded table (an empty field) is the shipped classic one.
                (Ok((table, note)), "") => {
                    lab.use_shipped(Table::Classic);
                    Message::note(format!("shading with {}{note}", table.name))
                }
                (Ok(loaded), file) => use_loaded_table(lab, loaded, Some(file.to_string()), false),
                (Err(e), _) => Message::error(format!("{e} — still using the previous table")),
            };
            lab.say(message);
        }
        if ui.small_button("as B").on_hover_text("Make the table named on the left table B, the other fit: the lobe overlay, the matrix panel and the plane's A | B comparison show it beside table A").clicked() {
            if PICKS {
                lab.request = Some(Request::Pick(Purpose::TableB));
                return;
            }
            let message = match files.lut_path.trim() {
                "" => Message::error("as B: name a table file in the field first — table B stays"),
                file => match load(file) {
                    Ok(loaded) => use_loaded_table(lab, loaded, Some(file.to_string()), true),
                    Err(e) => Message::error(format!("{e} — table B stays")),
                },
            };
            lab.say(message);
        }
    });
    ui.horizontal(|ui| {
        ui.small(format!("table B: {}", lab.tables().b.name))
            .on_hover_text("The other fit: the lobe overlay and the matrix panel show it beside table A, and the plane's A | B comparison shades with it");
        if lab.tables().b_chosen && ui.small_button("reset").on_hover_text("Table B back to the other shipped table").clicked() {
            lab.reset_table_b();
        }
    });
}

/// Shades `loaded` (the scene read from `name`) from now on; what was done, or why the scene
/// stays.
pub(crate) fn use_loaded_scene(
    lab: &mut Lab,
    loaded: crate::error::Result<Scene>,
    name: &str,
) -> Message {
    match loaded {
        Ok(scene) => match lab.use_scene(scene) {
            Some(cut) => Message::error(format!("loaded {name}; {cut}")),
            None => Message::note(format!("loaded {name}")),
        },
        Err(e) => Message::error(e.to_string()),
    }
}

/// Makes `table` (read from `file`, with its `note`) table A, or B; what was done.
pub(crate) fn use_loaded_table(
    lab: &mut Lab,
    (table, note): (NamedTable, String),
    file: Option<String>,
    as_b: bool,
) -> Message {
    let text = if as_b {
        format!("table B is {}{note}", table.name)
    } else {
        format!("shading with {}{note}", table.name)
    };
    if as_b {
        lab.use_file_b(table, file);
    } else {
        lab.use_file(table, file);
    }
    Message::note(text)
}

/// The table in the file at `path` (the embedded one where empty), named for labels, and
/// what the file could not hold (ltc_code's layout has no diffuse lobe), as ". note".
pub(crate) fn load(path: &str) -> Result<(NamedTable, String), String> {
    let path = path.trim();
    let loaded = if path.is_empty() {
        formats::load(None, Table::Classic)
    } else {
        formats::read(Path::new(path))
    }
    .map_err(|e| e.to_string())?;
    let name = if path.is_empty() {
        "the embedded LUT"
    } else {
        path
    };
    Ok(named_table(loaded, name))
}

/// A table read, named for labels, its `spec.err` measured (the matrix panel's heat maps
/// show it), and what its file could not hold as ". note".
pub(crate) fn named_table(mut loaded: formats::Loaded, name: &str) -> (NamedTable, String) {
    loaded.measure_spec_err(&|| {});
    let note = loaded.note.map(|n| format!(". {n}")).unwrap_or_default();
    let table = NamedTable {
        lut: loaded.lut.into_owned(),
        name: name.to_string(),
    };
    (table, note)
}

/// The screenshot field (`.png` saves the window, `.exr` the plane's radiance), and the
/// view shared as a link.
fn save_buttons(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut files.screenshot_path).desired_width(120.0))
            .on_hover_text(
                "Screenshot file: .png saves the window, .exr the plane's linear radiance",
            );
        if ui.small_button("screenshot").clicked() {
            let path = PathBuf::from(&files.screenshot_path);
            let exr = path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("exr"));
            lab.request = Some(if exr {
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
        lab.request = Some(Request::Share);
    }
}

/// A small grey line under a control saying what it does, where a tooltip alone would hide it.
fn explain(ui: &mut egui::Ui, text: &str) {
    ui.label(egui::RichText::new(text).weak());
}
