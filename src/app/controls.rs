//! The side panel: every global control, each with a tooltip naming what it changes in the
//! equations. It edits the state; what reaches beyond the state (a new table, a file to
//! write) comes back as an `Action` for the app to carry out.

use std::path::{Path, PathBuf};

use crate::app::other::OtherTable;
use crate::app::shading::Shading;
use crate::app::state::LabState;
use crate::ltc::Normalization;
use crate::ltc::formats;
use crate::ltc::lut::{Lut, Table};
use crate::render::Method;
use crate::scene::{PRESETS, Scene, preset};

/// What the side panel asks of the app.
pub enum Action {
    /// Shade with this table (named so) from now on.
    UseLut(Lut, String),
    /// Compare with this table as table B from now on.
    UseOther(crate::app::other::OtherTable),
    /// Save the plane's linear radiance to this EXR file (named by the user).
    SaveExr(PathBuf),
    /// Save the window to this PNG file (named by the user).
    Screenshot(PathBuf),
}

/// A line under the controls: a notice, or an error (shown in red).
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    pub is_error: bool,
    pub text: String,
}

impl Message {
    pub fn note(text: impl Into<String>) -> Self {
        Self {
            is_error: false,
            text: text.into(),
        }
    }

    pub fn error(text: impl Into<String>) -> Self {
        Self {
            is_error: true,
            text: text.into(),
        }
    }
}

/// The light counts the slider offers, at most (and at most what the adapter shades).
pub const MAX_LIGHT_SLIDER: usize = 100_000;

/// The side panel; returns what the app must do beyond the state.
pub fn show(
    ui: &mut egui::Ui,
    s: &mut LabState,
    shading: &Shading,
    other: &OtherTable,
    message: &mut Option<Message>,
) -> Option<Action> {
    ui.heading("LTC Lab");
    ui.label(egui::RichText::new(shading.describe()).small())
        .on_hover_text("The adapter the plane and chart panels shade on");
    if let Some(e) = &shading.gpu_error {
        ui.colored_label(
            egui::Color32::from_rgb(230, 120, 60),
            format!(
                "GPU unavailable — the plane is drawn by the CPU reference at reduced size. {e}"
            ),
        );
    }
    ui.separator();
    material(ui, s);
    ui.separator();
    lights(ui, s, shading.max_lights().min(MAX_LIGHT_SLIDER));
    ui.separator();
    shading_rules(ui, s);
    ui.separator();
    ui.strong("Scene");
    scene_files(ui, s, shading.max_lights(), message);
    let action = table(ui, s, other, message);
    action.or_else(|| save_buttons(ui, s))
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

fn material(ui: &mut egui::Ui, s: &mut LabState) {
    ui.strong("Material");
    let mut alpha = s.scene.material.alpha;
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
    ui.add(egui::Slider::new(&mut s.theta_o_deg, 0.0..=90.0).text("θo (°)"))
        .on_hover_text("View angle of the lobe and matrix panels: v = (sin θo, 0, cos θo); the LUT row is sqrt(1 − cos θo)");
    ui.add(egui::Slider::new(&mut s.scene.material.f0, 0.0..=1.0).text("F0"))
        .on_hover_text("Schlick: F = F0 + (1 − F0)(1 − v·h)⁵; in the LTC, the specular magnitude F0·n_s + (1 − F0)·f_s");
    ui.horizontal(|ui| {
        let mut c = s.scene.material.base_color.map(|x| x as f32);
        ui.color_edit_button_rgb(&mut c)
            .on_hover_text("Base colour c: fd = c/π (…)(…); in the LTC, c · n_d · D_d");
        s.scene.material.base_color = c.map(f64::from);
        ui.label("base colour");
    });
}

fn lights(ui: &mut egui::Ui, s: &mut LabState, max: usize) {
    ui.strong("Lights");
    ui.add(
        egui::Slider::new(&mut s.intensity_scale, 0.01..=100.0)
            .logarithmic(true)
            .text("intensity ×"),
    )
    .on_hover_text("Multiplies every light's I in E = I/d² · w(d)");
    explain(ui, "× every light's I (not saved to the scene)");
    ui.add(egui::Slider::new(&mut s.range_override, 0.0..=10.0).text("range R"))
        .on_hover_text("The window w(d) = clamp(1 − (d/R)⁴, 0, 1)²; 0 keeps each light's own range (absent = ∞)");
    explain(
        ui,
        if s.range_override > 0.0 {
            "every light fades to 0 at distance R"
        } else {
            "0: each light's own range from the scene"
        },
    );
    if let Some(k) = s.selected_light.filter(|&k| k < s.scene.lights.len()) {
        light_position(
            ui,
            k,
            &mut s.scene.lights[k].position,
            s.scene.plane.half_size,
        );
    }
    let mut count = s.light_count;
    ui.horizontal(|ui| {
        if ui
            .add(egui::Slider::new(&mut count, 0..=max).logarithmic(true).text("lights"))
            .on_hover_text(format!("Regenerates the lights with the seeded generator (replaces the current ones): N point lights over the plane, heights 0.05–0.6, range 2, paper-100's intensities (past 100 lights scaled down so that the total power stays paper-100's). At most {max} here: {}", if max < MAX_LIGHT_SLIDER { "this adapter's limit" } else { "the slider's" }))
            .changed()
        {
            s.set_light_count(count);
        }
    });
    // The slider clamps a typed count without a word: say it where it was typed.
    if max < MAX_LIGHT_SLIDER && s.light_count >= max {
        ui.small(format!("at most {max} lights: this adapter's limit"));
    }
    ui.checkbox(&mut s.cull, "cull by range")
        .on_hover_text("Tiled culling: each 16×16 tile of the plane sums only the lights whose range reaches it. The image is the same to the bit; with short ranges it is much faster");
    ui.checkbox(&mut s.show_gpu_times, "show GPU times")
        .on_hover_text("The plane's GPU milliseconds in its progress line; off for a slide or a screenshot that should not change from run to run");
}

fn shading_rules(ui: &mut egui::Ui, s: &mut LabState) {
    ui.strong("Shading");
    egui::ComboBox::from_label("LTC form")
        .selected_text(s.method_ltc.name())
        .show_ui(ui, |ui| {
            for m in [Method::Ltc, Method::LtcFast] {
                ui.selectable_value(&mut s.method_ltc, m, m.name());
            }
        })
        .response
        .on_hover_text("ltc: the paper's eq. 30 per light; ltc-fast: M^-1 folded with the frame, unnormalized u, eq. 27's factoring");
    egui::ComboBox::from_label("BRDF form")
        .selected_text(s.method_brdf.name())
        .show_ui(ui, |ui| {
            for m in [Method::Brdf, Method::BrdfFast] {
                ui.selectable_value(&mut s.method_brdf, m, m.name());
            }
        })
        .response
        .on_hover_text(
            "brdf: eq. 28 as docs/design.md §1 writes it; brdf-fast: Filament's V_SmithGGXCorrelated",
        );
    ui.checkbox(&mut s.clipping.horizon, "clip case 1 (n·l ≤ 0)")
        .on_hover_text("Eq. 30's first rule: a light below the surface contributes nothing. Off: M^-1 can lift it above the horizon (the glow of Figure 2c)");
    ui.checkbox(&mut s.clipping.transformed, "clip case 2 ((M^-1l).z ≤ 0)")
        .on_hover_text("max(ω'.z, 0) in D: a light pushed below the horizon by M^-1 contributes nothing. Off: it contributes negative light");
    let mut paper = s.normalization == Normalization::PaperLiteral;
    ui.checkbox(&mut paper, "paper-literal normalization")
        .on_hover_text("The paper's eq. 25 as printed: no 1/π in D and no magnitudes n_s, f_s, n_d (docs/design.md §1 corrects both)");
    s.normalization = if paper {
        Normalization::PaperLiteral
    } else {
        Normalization::Corrected
    };
}

/// The selected light's x, y (over the plane) and z, typed or dragged.
fn light_position(ui: &mut egui::Ui, k: usize, position: &mut [f64; 3], half_size: f64) {
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
            ui.add(egui::DragValue::new(&mut position[i]).speed(0.01).range(range).max_decimals(4))
                .labelled_by(label.id)
                .on_hover_text(hover);
        }
    });
}

/// The presets, and a scene file to load or save (only the file named is written).
fn scene_files(
    ui: &mut egui::Ui,
    s: &mut LabState,
    max_lights: usize,
    message: &mut Option<Message>,
) {
    ui.horizontal_wrapped(|ui| {
        for (name, _) in PRESETS {
            if ui
                .small_button(name)
                .on_hover_text("Load this shipped preset")
                .clicked()
            {
                *message = s.use_scene(preset(name), max_lights).map(Message::error);
            }
        }
    });
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut s.scene_path).desired_width(120.0))
            .on_hover_text(
                "A scene TOML file to load, or to save to (only the file named here is written)",
            );
        if ui
            .small_button("load")
            .on_hover_text("Read the scene file named on the left")
            .clicked()
        {
            *message = Some(match Scene::load(Path::new(&s.scene_path)) {
                Ok(scene) => match s.use_scene(scene, max_lights) {
                    Some(cut) => Message::error(format!("loaded {}; {cut}", s.scene_path)),
                    None => Message::note(format!("loaded {}", s.scene_path)),
                },
                Err(e) => Message::error(e.to_string()),
            });
        }
        if ui
            .small_button("save")
            .on_hover_text("Write the scene to the file named on the left (and no other)")
            .clicked()
        {
            // The view becomes what the file holds.
            s.scene = s.scene.rounded_for_saving();
            let text = s.scene.to_toml();
            *message = Some(
                match crate::files::write_atomically(Path::new(&s.scene_path), text.as_bytes()) {
                    Ok(()) => Message::note(format!("saved {}", s.scene_path)),
                    Err(e) => Message::error(e.to_string()),
                },
            );
        }
    });
}

/// The shipped table switch, and a LUT file to shade with.
fn table(
    ui: &mut egui::Ui,
    s: &mut LabState,
    other: &OtherTable,
    message: &mut Option<Message>,
) -> Option<Action> {
    let mut action = None;
    ui.horizontal(|ui| {
        ui.label("LTC table:");
        for (t, hover) in [
            (Table::Classic, "ltc_code's fit (luts/ltc.exr): made for area lights' integrals"),
            (Table::Point, "The point-light fit (luts/ltc_point.exr): minimizes ∫|n·D − f·cos| / ∫ f·cos, what one point light sees"),
        ] {
            // A shipped table is lit only while no file shades instead of it.
            let chosen = s.table_file.is_none() && s.table == t;
            if ui.selectable_label(chosen, t.name()).on_hover_text(hover).clicked() && !chosen {
                s.table = t;
                s.table_file = None;
                s.lut_path.clear();
                action = Some(Action::UseLut(Lut::shipped(t).clone(), t.name().into()));
            }
        }
    });
    if let Some(file) = &s.table_file {
        ui.small(format!("table A: {file}"));
    }
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut s.lut_path).desired_width(120.0).hint_text("embedded LUT"))
            .on_hover_text("An LTC table: .exr as `ltc-lab fit` writes it, ltc_code's ltc.js (or three.js's copy), or its ltc_1.dds/ltc_2.dds (either file or their directory); empty for the embedded one");
        if ui.small_button("use LUT").on_hover_text("Shade with the table named on the left (table A); a missing or broken file is reported here and the current table stays").clicked() {
            *message = Some(match load(&s.lut_path) {
                Ok((lut, name, note)) => {
                    let text = format!("shading with {name}{note}");
                    // The embedded table (an empty field) is the shipped classic one.
                    s.table_file = (!s.lut_path.trim().is_empty()).then(|| s.lut_path.trim().to_string());
                    if s.table_file.is_none() {
                        s.table = Table::Classic;
                    }
                    action = Some(Action::UseLut(lut, name));
                    Message::note(text)
                }
                Err(e) => Message::error(format!("{e} — still using the previous table")),
            });
        }
        if ui.small_button("as B").on_hover_text("Make the table named on the left table B, the other fit: the lobe overlay, the matrix panel and the plane's A | B comparison show it beside table A").clicked() {
            *message = Some(match load(&s.lut_path) {
                Ok((lut, name, note)) => {
                    let text = format!("table B is {name}{note}");
                    action = Some(Action::UseOther(OtherTable::chosen(lut, name)));
                    Message::note(text)
                }
                Err(e) => Message::error(format!("{e} — table B stays")),
            });
        }
    });
    ui.horizontal(|ui| {
        ui.small(format!("table B: {}", other.name))
            .on_hover_text("The other fit: the lobe overlay and the matrix panel show it beside table A, and the plane's A | B comparison shades with it");
        if other.chosen && ui.small_button("reset").on_hover_text("Table B back to the other shipped table").clicked() {
            action = Some(Action::UseOther(OtherTable::shipped_other(s.table)));
        }
    });
    action
}

/// The table in the file at `path` (the embedded one where empty), its name for labels, and
/// what the file could not hold (ltc_code's layout has no diffuse lobe), as ". note".
pub(crate) fn load(path: &str) -> Result<(Lut, String, String), String> {
    let path = path.trim();
    let mut loaded = if path.is_empty() {
        formats::load(None, Table::Classic)
    } else {
        formats::read(Path::new(path))
    }
    .map_err(|e| e.to_string())?;
    // The matrix panel's heat maps show spec.err.
    loaded.measure_spec_err(&|| {});
    let name = if path.is_empty() {
        "the embedded LUT"
    } else {
        path
    };
    let note = loaded.note.map(|n| format!(". {n}")).unwrap_or_default();
    Ok((loaded.lut.into_owned(), name.to_string(), note))
}

/// The screenshot field: `.png` saves the window, `.exr` the plane's radiance.
fn save_buttons(ui: &mut egui::Ui, s: &mut LabState) -> Option<Action> {
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut s.screenshot_path).desired_width(120.0))
            .on_hover_text(
                "Screenshot file: .png saves the window, .exr the plane's linear radiance",
            );
        if !ui.small_button("screenshot").clicked() {
            return None;
        }
        let path = PathBuf::from(&s.screenshot_path);
        Some(
            if path
                .extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("exr"))
            {
                Action::SaveExr(path)
            } else {
                Action::Screenshot(path)
            },
        )
    })
    .inner
}

/// A small grey line under a control saying what it does, where a tooltip alone would hide it.
fn explain(ui: &mut egui::Ui, text: &str) {
    ui.label(egui::RichText::new(text).weak());
}
