//! The side panel's shading rules: each side's form, clipping, normalization, the table's
//! filter and the horizon remedy.

use crate::app::lab::parts::{BRDF_FORMS, LTC_FORMS};
use crate::app::lab::{Forms, Lab};
use crate::app::ui::widgets::clipping_rules;
use crate::ltc::Normalization;
use crate::ltc::remedy::Horizon;
use crate::render::{LtcRules, Method};

pub(super) fn shading_rules(ui: &mut egui::Ui, lab: &mut Lab) {
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
        .on_hover_text("What LTC does for lights near the horizon, where eq. 30 is wrong by half: the clipping \
            panel plots one light over its elevation and each band's error");
    if let Some(h) = chosen.filter(|&h| h != current) {
        lab.use_horizon(h);
    }
}
