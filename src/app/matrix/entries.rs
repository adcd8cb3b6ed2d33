//! A matrix as the matrix panel prints it: entries in a fixed width, rows in a grid.

use glam::DMat3;

use crate::ltc::mat3_rows;

/// A matrix entry in a fixed width: fixed-point where four decimals read it, else scientific
/// (a -9995.0363 beside a 0.0000 ran together).
pub fn entry(x: f64) -> String {
    if x != 0.0 && !(1e-3..1e4).contains(&x.abs()) {
        format!("{x:>11.3e}")
    } else {
        format!("{x:>11.4}")
    }
}

/// A 3×3 matrix under its title, by rows, each entry in `entry`'s fixed width.
pub fn matrix(ui: &mut egui::Ui, title: &str, m: DMat3, hover: &str) {
    ui.vertical(|ui| {
        // A number is never broken across lines (the panel wraps its long lines).
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Extend);
        ui.small(title).on_hover_text(hover);
        egui::Grid::new(title)
            .striped(true)
            .spacing([8.0, 2.0])
            .show(ui, |ui| {
                for row in mat3_rows(m) {
                    for x in row {
                        ui.monospace(entry(x));
                    }
                    ui.end_row();
                }
            });
    });
}
