//! The side panel's files: the scene, the table, a method file, and what the lab saves.

use std::path::PathBuf;

use crate::app::files::Purpose;
use crate::app::lab::{Lab, Request, TableId};
use crate::app::ui::widgets::name;
use crate::ltc::aniso::AnisoAxes;
use crate::ltc::aniso::source::AnisoSource;
use crate::ltc::lut::{Encoding, Table};
use crate::scene::{ENCODING_FAILURES, EncodingFailure, PRESETS};
use crate::tables::Source;

use super::lights::preset_buttons;
use super::{ControlsState, PICKS};

/// The presets, and a scene file to load or save (only the file named is written).
pub(super) fn scene_files(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
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
pub(super) fn table(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    // Wrapped: four tables in one row would widen the side panel.
    ui.horizontal_wrapped(|ui| {
        ui.label("LTC table:");
        for (t, hover) in [
            (Table::Classic, "ltc_code's fit (luts/ltc.exr): made for area lights' integrals"),
            (Table::Point, "The point-light fit (luts/ltc_point.exr): minimizes ∫|n·D − f·cos| / ∫ f·cos, what one point light sees"),
            (Table::Arrival, "The arrival fit (luts/ltc_arrival.exr): the point-light objective weighted by where \
                lights above a plane arrive from, the horizon included (the arrival-fit remedy)"),
            (Table::Constrained, "The constrained fit (luts/ltc_constrained.exr): the point-light objective with m20 = 0, \
                so M^-1 never carries a light across the horizon (the constrained-fit remedy)"),
        ] {
            // A shipped table is lit only while no file shades instead of it.
            let chosen = lab.tables().a().source == Source::Shipped(t);
            if ui.selectable_label(chosen, t.name()).on_hover_text(hover).clicked() && !chosen {
                files.lut_path.clear();
                lab.use_shipped(t);
            }
        }
        // On the row's wrapped end, which holds one table's name: no row of its own.
        encoding(ui, lab, TableId::A);
    });
    if let Source::File(file) | Source::Given(file) = &lab.tables().a().source {
        ui.small(format!("table A: {file}"));
    }
    ui.horizontal(|ui| {
        // A browser picks the file instead.
        if !PICKS {
            let field = ui.add(egui::TextEdit::singleline(&mut files.lut_path).desired_width(120.0).hint_text("embedded LUT"))
                .on_hover_text("An LTC table: .exr as `ltc-lab fit` writes it, ltc_code's ltc.js (or three.js's copy), \
                    or its ltc_1.dds/ltc_2.dds (either file or their directory); empty for the embedded one");
            name(ui, &field, "table file");
        }
        if ui.small_button("use LUT").on_hover_text("Shade with the table named on the left (table A), or one dropped on the window; a \
            missing or broken file is reported here and the current table stays").clicked() {
            lab.request(Request::Open(Purpose::Table, files.lut_path.clone()));
        }
        if ui.small_button("as B").on_hover_text("Make the table named on the left table B, the other fit: the lobe overlay, the matrix \
            panel and the plane's A | B comparison show it beside table A").clicked() {
            lab.request(Request::Open(Purpose::TableB, files.lut_path.clone()));
        }
    });
    ui.horizontal_wrapped(|ui| {
        ui.small(format!("table B: {}", lab.tables().b().name))
            .on_hover_text("The other fit: the lobe overlay and the matrix panel show it beside table A, and the plane's A | B comparison shades with it");
        if !lab.tables().b_is_default() && ui.small_button("reset").on_hover_text("Table B back to the other shipped table").clicked() {
            lab.use_table_b(None);
        }
        encoding(ui, lab, TableId::B);
    });
    // The 4D tables matter only to an anisotropic material.
    if lab.material().is_anisotropic() {
        aniso_tables(ui, lab);
    }
}

/// The encodings offered per side (docs/design.md §2.10): every storage at every size, and
/// three.js #34611's Chebyshev form at three degrees (the rational fits, slower to fit and
/// worse, stay on the command line: `lut --encodings --formulas`).
fn offered_encodings(size: usize) -> Vec<Encoding> {
    let formulas = ["cheb16-f16", "cheb24", "cheb40"].map(|n| Encoding::parse(n).ok());
    let mut all = Encoding::tables(size);
    all.extend(formulas.into_iter().flatten());
    all
}

/// Side `id`'s encoding, each offered with the bytes an engine ships for it.
fn encoding(ui: &mut egui::Ui, lab: &mut Lab, id: TableId) {
    let size = lab.tables().a().lut.size;
    let name = |e: Option<Encoding>| e.map_or("as read".to_string(), |e| e.name());
    let hover = match id {
        TableId::A => {
            "Shade side A with table A as an engine storing it in this encoding reads it back \
                (docs/design.md §2.10), with the bytes it ships; `ltc-lab lut --encodings` measures each \
                on every light shape"
        }
        TableId::B => {
            "Compare with table B as this encoding gives it back; while B is the default table, B \
                becomes table A's table in this encoding, so that the A | B split shows one table in two \
                encodings. Its first entries load a scene where an encoding fails, A as read against B \
                in that encoding"
        }
    };
    let current = lab.tables().encoding(id);
    let mut chosen = current;
    let mut failure = None;
    egui::ComboBox::from_label(format!("encoding {id:?}"))
        .selected_text(name(current))
        .width(90.0)
        .height(480.0)
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut chosen, None, name(None));
            // B's failure cases first: the list below them scrolls.
            if id == TableId::B {
                failure = failure_entries(ui);
            }
            for e in offered_encodings(size) {
                let bytes = format!("{} · {:.1} KB", e.name(), e.bytes(size) as f64 / 1024.0);
                ui.selectable_value(&mut chosen, Some(e), bytes);
            }
        })
        .response
        .on_hover_text(hover);
    if let Some(f) = failure {
        lab.show_encoding_failure(f);
    } else if chosen != current {
        lab.use_encoding(id, chosen);
    }
}

/// Encoding B's first entries: the presets where an encoding fails, each loading its scene
/// with table A against its failing encoding (docs/design.md §2.10).
fn failure_entries(ui: &mut egui::Ui) -> Option<EncodingFailure> {
    ui.label("where one fails (a scene):");
    let mut picked = None;
    for f in ENCODING_FAILURES {
        ui.selectable_value(
            &mut picked,
            Some(f),
            format!("{}: {}", f.encoding, f.preset),
        )
        .on_hover_text(f.what);
    }
    ui.separator();
    picked
}

/// The 4D tables anisotropic materials shade with on each side: the lab's or one of I3D
/// 2022's (a 4D table file is the command line's: `--aniso-lut`).
fn aniso_tables(ui: &mut egui::Ui, lab: &mut Lab) {
    let choices = [
        (
            AnisoSource::Lab,
            "The lab's 4D table (luts/ltc_aniso.exr): 8⁴ over (α_x, α_y, θo, φo), stored by its mirror pole so that every blend is a proper matrix",
        ),
        (
            AnisoSource::I3d(AnisoAxes::I3dAlphaXY),
            "I3D 2022's (α_x, α_y) table, read as an engine reads it, with the lab's magnitudes",
        ),
        (
            AnisoSource::I3d(AnisoAxes::I3dAlphaLambda),
            "I3D 2022's (α, λ) table, read as an engine reads it, with the lab's magnitudes",
        ),
    ];
    for id in [TableId::A, TableId::B] {
        ui.horizontal_wrapped(|ui| {
            ui.small(format!("4D table {id:?}:")).on_hover_text(
                "The table an anisotropic material's specular lobe comes from, on this side",
            );
            for (source, hover) in &choices {
                let chosen = lab.tables().aniso(id) == source;
                let label = ui.selectable_label(chosen, source.short_name());
                if label.on_hover_text(*hover).clicked() && !chosen {
                    lab.use_aniso(id, source.clone());
                }
            }
        });
    }
}

/// The screenshot field (`.png` saves the window, `.exr` the plane's radiance), and the
/// view shared as a link.
pub(super) fn save_buttons(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
    ui.horizontal(|ui| {
        let field = ui
            .add(egui::TextEdit::singleline(&mut files.screenshot_path).desired_width(120.0))
            .on_hover_text(
                "Screenshot file: .png saves the window, .exr the plane's linear radiance",
            );
        name(ui, &field, "screenshot file");
        if ui.small_button("screenshot").clicked() {
            let path = PathBuf::from(&files.screenshot_path);
            lab.request(if crate::files::is_exr(&path) {
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
pub(super) fn method_file(ui: &mut egui::Ui, lab: &mut Lab, files: &mut ControlsState) {
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
