//! Widgets more than one panel shows: eq. 30's two rules as checkboxes (the side panel and
//! the clipping panel word them for their place), the notices bar, and a line that says what
//! a control does.

use crate::app::lab::{Lab, Message};
use crate::render::LtcRules;

/// Eq. 30's two rules as checkboxes, each with its label and tooltip.
pub fn clipping_rules(ui: &mut egui::Ui, lab: &mut Lab, [case1, case2]: [(&str, &str); 2]) {
    lab.edit(|r: &mut LtcRules| {
        ui.checkbox(&mut r.clipping.case1, case1.0)
            .on_hover_text(case1.1);
        ui.checkbox(&mut r.clipping.case2, case2.0)
            .on_hover_text(case2.1);
    });
}

/// The last notice, in a bar along the bottom of the window: always in view, even in a
/// small window, and it moves no control (the panels' contents hang from their tops; at the
/// top of the side panel it pushed every control down under the pointer). Whether it was
/// dismissed.
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

/// A small grey line under a control saying what it does, where a tooltip alone would hide
/// it.
pub fn explain(ui: &mut egui::Ui, text: &str) {
    ui.label(egui::RichText::new(text).weak());
}

/// Gives a widget without a visible label (a text field beside its button) an accessible
/// name: what a screen reader says, and what a test finds it by.
pub fn name(ui: &egui::Ui, response: &egui::Response, name: &str) {
    ui.ctx()
        .accesskit_node_builder(response.id, |node| node.set_label(name));
}
