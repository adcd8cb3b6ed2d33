//! The matrix panel: for the chosen (θo, α), M⁻¹ as stored, M, the paper's form, |M⁻¹|, the
//! magnitudes and the fit error; every LUT channel as a heat map with a crosshair on the
//! chosen cell (click a cell to choose it); and "refit this cell", which runs the fitter live
//! and plots the Nelder–Mead objective iteration by iteration.

use egui::{Color32, Vec2};
use glam::DMat3;

use crate::app::other::OtherTable;
use crate::app::refit::Refit;
use crate::app::state::LabState;
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{CHANNEL_COUNT, CHANNEL_NAMES, Channel, Lut, cell_theta};
use crate::ltc::{Ltc, mat3_rows};
use crate::output::false_colour;

/// Heat maps per row (14 channels: three rows).
const MAPS_PER_ROW: usize = 5;

pub struct MatrixPanel {
    /// Each channel's heat map, made once from the LUT.
    maps: Vec<egui::ColorImage>,
    textures: Vec<Option<egui::TextureHandle>>,
    /// A refit under way (its result goes to the lab's state).
    pub refit: Option<Refit>,
    /// The cell nearest the chosen (θo, α) at the last frame.
    pub current_cell: (usize, usize),
}

impl MatrixPanel {
    pub fn new(lut: &Lut) -> Self {
        let n = lut.size;
        let maps = (0..CHANNEL_COUNT)
            .map(|c| {
                let values: Vec<f64> = lut.cells.iter().map(|cell| f64::from(cell.0[c])).collect();
                let (lo, hi) = values
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                        (a.min(x), b.max(x))
                    });
                let span = (hi - lo).max(1e-12);
                // Row j = 0 (normal view) at the top, column i = 0 (α_min) at the left.
                let pixels = values
                    .iter()
                    .map(|&x| {
                        let [r, g, b] = false_colour((x - lo) / span);
                        Color32::from_rgb(r, g, b)
                    })
                    .collect();
                egui::ColorImage::new([n, n], pixels)
            })
            .collect();
        Self {
            maps,
            textures: vec![None; CHANNEL_COUNT],
            refit: None,
            current_cell: (0, 0),
        }
    }

    /// The refitted lobe, while the chosen cell is the one refitted.
    pub fn refit_ltc(&self, s: &LabState) -> Option<(Lobe, Ltc)> {
        let r = s.refit.as_ref()?;
        (r.cell == self.current_cell).then(|| (r.lobe, r.ltc()))
    }

    /// Whether a refit is under way.
    pub fn busy(&self) -> bool {
        self.refit.is_some()
    }

    /// The panel for table A (`lut`, named `a_name`), with table B's cell beside it.
    pub fn show(
        &mut self,
        ui: &mut egui::Ui,
        s: &mut LabState,
        (lut, a_name, other): (&Lut, &str, &OtherTable),
    ) {
        if let Some(r) = &mut self.refit {
            if let Some(result) = r.poll() {
                s.refit = Some(result);
                self.refit = None;
            } else {
                ui.ctx().request_repaint();
            }
        }
        let n = lut.size;
        let theta = s.theta_o_deg.to_radians().min(crate::ltc::lut::THETA_MAX);
        let (u, v) = (s.alpha().sqrt(), (1.0 - theta.cos()).max(0.0).sqrt());
        let col = (u * (n - 1) as f64).round() as usize;
        let row = (v * (n - 1) as f64).round() as usize;
        self.current_cell = (col.min(n - 1), row.min(n - 1));
        let sample = lut.sample(s.alpha(), theta.cos());
        let pair = sample.ltc_pair();
        let ltc = match s.lobe {
            Lobe::Specular => pair.spec,
            Lobe::Diffuse => pair.diff,
        };
        let err = sample.get(Channel::err(s.lobe));
        egui::ScrollArea::vertical().auto_shrink([false; 2]).show(ui, |ui| {
            ui.label(format!(
                "{} lobe at θo = {:.1}°, α = {:.4} (r = {:.3}); bilinear between cells, nearest cell ({}, {})",
                if s.lobe == Lobe::Specular { "specular" } else { "diffuse" },
                s.theta_o_deg,
                s.alpha(),
                s.alpha().sqrt(),
                self.current_cell.0,
                self.current_cell.1
            ));
            let inv = ltc.cos_from_brdf;
            let m22 = mat3_rows(inv)[2][2];
            let matrices = [
                ("M^-1 as stored (÷ middle)", inv, "cos_from_brdf: maps a lobe direction to the clamped-cosine domain; the LUT stores it divided by its middle element"),
                ("M", ltc.brdf_from_cos, "brdf_from_cos: maps the clamped cosine onto the lobe"),
                ("paper's form (÷ m22)", inv * (1.0 / m22), "[[a,0,b],[0,c,0],[d,0,1]]: the same M^-1 divided by its bottom-right element"),
            ];
            // As many matrices per row as fit (each ~200 points wide in monospace).
            let per_row = ((ui.available_width() / 200.0) as usize).clamp(1, 3);
            for row in matrices.chunks(per_row) {
                ui.horizontal(|ui| {
                    for (title, m, hover) in row {
                        matrix(ui, title, *m, hover);
                        ui.add_space(12.0);
                    }
                });
            }
            ui.label(format!(
                "|M^-1| = {:.4e}   norm = {:.4}   fresnel = {:.4}   scale = {:.3}   pointwise error = {:.1}%",
                ltc.det_cos_from_brdf,
                ltc.norm,
                if s.lobe == Lobe::Specular { ltc.fresnel } else { 0.0 },
                ltc.scale,
                100.0 * err
            ))
            .on_hover_text("norm = ∫ f·cos (the albedo, F = 1 / c = 1); fresnel = ∫ (1 − v·h)⁵ f·cos; scale = the point fit's factor on the magnitude (1 in the classic table); error = ∫|s·n·D − f·cos| / ∫ f·cos (DESIGN §4)");
            // Tables A and B at this (θo, α), side by side.
            ui.vertical(|ui| {
                for (which, name, table) in [("A", a_name, lut), ("B", other.name.as_str(), &other.lut)] {
                    let t = table.sample(s.alpha(), theta.cos());
                    let (m, e) = (Channel::entries(s.lobe), Channel::err(s.lobe));
                    let scale = if s.lobe == Lobe::Specular { t.get(Channel::SpecScale) } else { 1.0 };
                    ui.label(format!(
                        "{which} ({name}): M^-1 = [[{:.3}, 0, {:.3}], [0, 1, 0], [{:.3}, 0, {:.3}]], scale {:.3}, error {:.1}%",
                        t.get(m[0]),
                        t.get(m[1]),
                        t.get(m[2]),
                        t.get(m[3]),
                        scale,
                        100.0 * t.get(e)
                    ))
                    .on_hover_text("Table A (the one shaded with) and table B (the other fit: the other shipped table, or one loaded with \"as B\") at this (θo, α), bilinear; error is each table's pointwise error (DESIGN §4) of this lobe");
                }
            });
            self.refit_controls(ui, s, lut);
            ui.separator();
            self.heat_maps(ui, s, lut, (u, v));
        });
    }

    /// Every channel as an N×N heat map (min to max of the channel), crosshair on the chosen
    /// (r, sqrt(1 − cos θo)); click to choose a cell.
    fn heat_maps(&mut self, ui: &mut egui::Ui, s: &mut LabState, lut: &Lut, (u, v): (f64, f64)) {
        let n = lut.size;
        let side = ((ui.available_width() - 30.0) / MAPS_PER_ROW as f32).clamp(40.0, 160.0);
        let channels: Vec<usize> = (0..CHANNEL_COUNT).collect();
        // Rows of fixed length: a wrapping layout cannot know a column's size before it is
        // drawn, and ran the last map off the panel's edge.
        for row in channels.chunks(MAPS_PER_ROW) {
            ui.horizontal(|ui| {
            for &c in row {
                let texture = self.textures[c].get_or_insert_with(|| {
                    ui.ctx().load_texture(CHANNEL_NAMES[c], self.maps[c].clone(), egui::TextureOptions::NEAREST)
                });
                ui.vertical(|ui| {
                    ui.small(CHANNEL_NAMES[c]);
                    let (rect, response) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::click());
                    ui.painter().image(texture.id(), rect, egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0)), Color32::WHITE);
                    // Texel centres sit at (k + ½)/N, the LUT's own uv mapping (DESIGN §2).
                    let to_screen = |t: f64| ((t * (n - 1) as f64 + 0.5) / n as f64) as f32 * side;
                    let p = rect.min + Vec2::new(to_screen(u), to_screen(v));
                    let stroke = egui::Stroke::new(1.0, Color32::WHITE);
                    ui.painter().hline(rect.x_range(), p.y, stroke);
                    ui.painter().vline(p.x, rect.y_range(), stroke);
                    let name = format!("{} heat map", CHANNEL_NAMES[c]);
                    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &name));
                    let response = response.on_hover_text(format!("{}: x = r = √α (column), y = sqrt(1 − cos θo) (row). Click to choose a cell", CHANNEL_NAMES[c]));
                    if response.clicked()
                        && let Some(pos) = response.interact_pointer_pos()
                    {
                        let cell = ((pos - rect.min) / side * n as f32).floor();
                        let i = (cell.x.max(0.0) as usize).min(n - 1);
                        let j = (cell.y.max(0.0) as usize).min(n - 1);
                        s.scene.material.alpha = lut.alpha(i);
                        s.theta_o_deg = cell_theta(j, n).to_degrees();
                    }
                });
            }
            });
        }
    }

    /// The refit's button, its progress and cancel, then the result: stored and refitted
    /// matrices and errors side by side, and the objective per iteration.
    fn refit_controls(&mut self, ui: &mut egui::Ui, s: &mut LabState, lut: &Lut) {
        ui.horizontal_wrapped(|ui| {
            match &self.refit {
                Some(r) => {
                    ui.add(egui::ProgressBar::new(r.progress()).desired_width(80.0))
                        .on_hover_text("Iterations used of the fitter's limit");
                    ui.small(format!("refitting cell ({}, {})… iteration {}", r.cell.0, r.cell.1, r.history.len()));
                    if ui.small_button("cancel").on_hover_text("Stop the fit at its next iteration").clicked() {
                        r.cancel();
                    }
                }
                None => {
                    if ui
                        .button("refit this cell")
                        .on_hover_text("Runs ltc_code's fit (Nelder–Mead, 32×32 strata from both distributions, |·|³ error) on the nearest cell, from the stored cell's parameters, live; then compares stored and refitted lobes by their pointwise error")
                        .clicked()
                    {
                        self.refit = Some(Refit::start(s.lobe, self.current_cell, lut));
                    }
                }
            }
        });
        let Some(r) = s
            .refit
            .as_ref()
            .filter(|r| r.cell == self.current_cell && r.lobe == s.lobe)
        else {
            if let Some(r) = &s.refit {
                ui.small(format!(
                    "(last refit: cell ({}, {}), {} lobe)",
                    r.cell.0,
                    r.cell.1,
                    r.lobe.name()
                ));
            }
            return;
        };
        ui.horizontal(|ui| {
            matrix(
                ui,
                "stored M^-1 (÷ middle)",
                crate::ltc::mat3_from_rows(r.stored),
                "The table's cell as stored",
            );
            matrix(
                ui,
                "refitted M^-1 (÷ middle)",
                crate::ltc::mat3_from_rows(r.cos_from_brdf),
                "The refit's result",
            );
        });
        let how = if r.cancelled {
            "cancelled"
        } else if r.converged {
            "converged"
        } else {
            "stopped at the iteration limit"
        };
        ui.label(format!(
            "pointwise error: stored {:.2}%, refitted {:.2}% — {} iterations, {how}",
            100.0 * r.stored_error,
            100.0 * r.error,
            r.iterations
        ))
        .on_hover_text("∫|n·D − f·cos| / ∫ f·cos (DESIGN §4), both measured with 64² strata from both distributions");
        let points: Vec<[f64; 2]> = r
            .history
            .iter()
            .map(|&[i, f]| [i, f.max(1e-300).log10()])
            .collect();
        egui_plot::Plot::new("nelder-mead")
            .height(90.0)
            .x_axis_label("iteration")
            .y_axis_label("log10 objective")
            .allow_scroll(false)
            .show(ui, |p| p.line(egui_plot::Line::new("objective", points)));
    }

    /// Blocks until a running refit is done (tests).
    pub fn wait_for_refit(&mut self, s: &mut LabState) {
        while let Some(r) = &mut self.refit {
            if let Some(result) = r.poll() {
                s.refit = Some(result);
                self.refit = None;
            } else {
                std::thread::sleep(std::time::Duration::from_millis(5));
            }
        }
    }
}

fn matrix(ui: &mut egui::Ui, title: &str, m: DMat3, hover: &str) {
    ui.vertical(|ui| {
        ui.small(title).on_hover_text(hover);
        egui::Grid::new(title).striped(true).show(ui, |ui| {
            for row in mat3_rows(m) {
                for x in row {
                    ui.monospace(format!("{x:>9.4}"));
                }
                ui.end_row();
            }
        });
    });
}
