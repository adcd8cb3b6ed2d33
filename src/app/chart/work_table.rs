//! The work per light of each method, counted from its shader (docs/design.md §4.6), under
//! the chart's plots.

use egui::Color32;

use crate::app::chart::measure::Measurement;
use crate::colormap::short_number;
use crate::gpu::work::Work;
use crate::render::Method;

/// Each method's work per light (docs/design.md §4.10) beside its measured time per light at
/// the measurement's largest light count, and the time's ratio to `brdf`'s.
pub(super) fn work_table(
    ui: &mut egui::Ui,
    work: &Result<Vec<(Method, Work)>, String>,
    m: &Measurement,
) {
    let work = match work {
        Ok(w) => w,
        Err(e) => {
            ui.colored_label(Color32::LIGHT_RED, format!("cannot count: {e}"));
            return;
        }
    };
    // ns per light per pixel is the fps curve's last point: ms per frame over lights × pixels.
    let per_light = |method: Method| {
        let (_, curve) = m.scaling.iter().find(|(x, _)| *x == method)?;
        let &[lights, fps] = curve.last()?;
        Some((lights, 1e3 / fps / lights))
    };
    let brdf = per_light(Method::Brdf).map(|p| p.1);
    egui::Grid::new("chart work grid")
        .striped(true)
        .spacing([12.0, 2.0])
        .show(ui, |ui| {
            for (head, hover) in [
                ("method", "The method's function that adds one light"),
                ("arith.", "Additions, multiplications and the like per light (vectors per component)"),
                ("div.", "Divisions per light (about 9 arithmetic operations' issue slots on a GPU)"),
                ("special", "Roots and transcendental functions per light (about 8 arithmetic operations' issue slots on a GPU)"),
                ("reads", "Loads of memory outside the function per light"),
                ("ms / light", "Measured: ms per frame over lights, at the largest light count measured"),
                ("× brdf", "That time over brdf's"),
            ] {
                ui.small(head).on_hover_text(hover);
            }
            ui.end_row();
            for (method, w) in work {
                ui.monospace(method.name());
                for x in [w.arithmetic, w.divisions, w.special, w.reads] {
                    ui.monospace(x.to_string());
                }
                match per_light(*method) {
                    Some((lights, ms)) => {
                        ui.monospace(format!("{} ({lights:.0} lights)", short_number(ms)));
                        let ratio = brdf.map_or("–".into(), |b| format!("{:.2}", ms / b));
                        ui.monospace(ratio);
                    }
                    None => {
                        ui.monospace("–");
                        ui.monospace("–");
                    }
                }
                ui.end_row();
            }
        });
}
