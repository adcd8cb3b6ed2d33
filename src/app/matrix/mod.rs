//! The matrix panel: for the chosen (θo, α), M⁻¹ as stored, M, the paper's form, |M⁻¹|, the
//! magnitudes and the fit error; every LUT channel as a heat map with a crosshair on the
//! chosen cell (click a cell to choose it); and "refit this cell", which runs the fitter live
//! and plots the Nelder–Mead objective iteration by iteration.

pub mod aniso;
mod entries;
pub mod refit;

use egui::{Color32, Pos2, Vec2};

use crate::app::lab::refit_result::{Objective, RefitResult};
use crate::app::lab::{Lab, LastRefit, LobeView};
use crate::app::matrix::aniso::AnisoSlice;
use crate::app::matrix::entries::{entry, matrix};
use crate::app::matrix::refit::Refit;
use crate::app::panel::Panel;
use crate::app::ui::axes::log_axis;
use crate::app::ui::display::{colour_bar, rgb};
use crate::app::work::cache::Cached;
use crate::colormap::{ColourScale, short_number};
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Channel, Lut, axes, cell_theta};
use crate::ltc::mat3_rows;
use crate::scene::Material;

/// Heat maps per row (14 channels: three rows).
const MAPS_PER_ROW: usize = 5;

pub struct MatrixPanel {
    /// Table A's channels as heat maps, made again when the tables change.
    maps: Cached<HeatMaps>,
    /// The channel whose colour bar is shown (the last one clicked).
    focus: Channel,
    /// The reading under the pointer at the last frame.
    hovered: Option<Reading>,
    /// A refit under way (its result goes to the lab).
    refit: Option<Refit>,
    /// The 4D tables' slice, shown while the material is anisotropic.
    aniso: AnisoSlice,
}

impl Default for MatrixPanel {
    fn default() -> Self {
        Self {
            maps: Cached::new("matrix.heat_maps"),
            focus: Channel::err(Lobe::Specular),
            hovered: None,
            refit: None,
            aniso: AnisoSlice::default(),
        }
    }
}

/// A channel's value at a cell: (channel, column, row, value).
type Reading = (Channel, usize, usize, f64);

/// Every channel of a table as a texture, with its colour scale: viridis, diverging for
/// signed channels, log for errors.
struct HeatMaps {
    scales: Vec<ColourScale>,
    textures: Vec<egui::TextureHandle>,
}

impl HeatMaps {
    fn new(lut: &Lut, ctx: &egui::Context) -> Self {
        let n = lut.size;
        let scales: Vec<ColourScale> = Channel::ALL.map(|c| channel_scale(lut, c)).to_vec();
        let textures = scales
            .iter()
            .zip(Channel::ALL)
            .map(|(scale, c)| {
                // Row j = 0 (normal view) at the top, column i = 0 (α_min) at the left.
                let pixels = lut
                    .cells
                    .iter()
                    .map(|cell| rgb(scale.colour(f64::from(cell.get(c)))))
                    .collect();
                let image = egui::ColorImage::new([n, n], pixels);
                ctx.load_texture(c.name(), image, egui::TextureOptions::NEAREST)
            })
            .collect();
        Self { scales, textures }
    }
}

impl Panel for MatrixPanel {
    /// Table A at the lab's (θo, α), with table B's cell beside it.
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        self.poll_refit(ui.ctx(), lab);
        let ctx = ui.ctx().clone();
        self.maps
            .get(lab.tables(), |t| HeatMaps::new(&t.a().lut, &ctx));
        egui::ScrollArea::vertical()
            .auto_shrink([false; 2])
            .show(ui, |ui| {
                // Long lines wrap at the panel's edge rather than run past it.
                ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Wrap);
                if lab.material().is_anisotropic() {
                    self.aniso.show(ui, lab);
                    ui.separator();
                    ui.small("The 2D table below shades the diffuse lobe (at Burley's α = (α_x + α_y)/2) and isotropic materials.");
                }
                cell_readout(ui, lab);
                self.refit_controls(ui, lab);
                ui.separator();
                self.heat_maps(ui, lab);
            });
    }

    fn busy(&self) -> bool {
        self.refit.is_some()
    }

    fn caches(&self) -> Vec<(&'static str, u64)> {
        vec![self.maps.count()]
    }
}

/// The cell at the lab's (θo, α): M^-1, M and the paper's form, the magnitudes and the
/// error of table A, and both tables' entries side by side.
fn cell_readout(ui: &mut egui::Ui, lab: &Lab) {
    let lut = &lab.tables().a().lut;
    let (theta, alpha, lobe) = (lab.theta_o(), lab.alpha(), lab.lobe_view().lobe);
    let cell = lab.nearest_cell();
    let sample = lut.sample(alpha, theta.cos());
    let pair = sample.ltc_pair();
    let ltc = *pair.lobe(lobe);
    let err = sample.get(Channel::err(lobe));
    ui.label(format!(
        "{} lobe at θo = {:.1}°, α = {:.4} (r = {:.3}); bilinear between cells, nearest cell ({}, {})",
        if lobe == Lobe::Specular { "specular" } else { "diffuse" },
        lab.lobe_view().theta_o_deg,
        alpha,
        alpha.sqrt(),
        cell.0,
        cell.1
    ));
    let inv = ltc.cos_from_brdf;
    let m22 = mat3_rows(inv)[2][2];
    let matrices = [
        (
            "M^-1 at (θo, α), bilinear (÷ middle)",
            inv,
            "cos_from_brdf: maps a lobe direction to the clamped-cosine domain; the LUT stores it \
                divided by its middle element, and this is the four cells about (θo, α) interpolated as \
                the shader does",
        ),
        (
            "M (its inverse)",
            ltc.brdf_from_cos,
            "brdf_from_cos: maps the clamped cosine onto the lobe",
        ),
        (
            "M^-1 in the paper's form (÷ m22)",
            inv * (1.0 / m22),
            "[[a,0,b],[0,c,0],[d,0,1]]: the same M^-1 divided by its bottom-right element",
        ),
    ];
    // As many matrices per row as fit: each about 300 points wide in monospace with the gap
    // after it (260 cut the third column of a matrix with five-digit entries).
    let per_row = ((ui.available_width() / 300.0) as usize).clamp(1, 3);
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
        if lobe == Lobe::Specular { ltc.fresnel } else { 0.0 },
        ltc.scale,
        100.0 * err
    ))
    .on_hover_text("norm = ∫ f·cos (the albedo, F = 1 / c = 1); fresnel = ∫ (1 − v·h)⁵ f·cos; scale = the \
        point fit's factor on the magnitude (1 in the classic table); error = ∫|s·n·D − f·cos| / \
        ∫ f·cos (docs/design.md §4)");
    both_tables(ui, lab);
}

/// Tables A and B at the lab's (θo, α), side by side: M^-1's entries, scale and error.
fn both_tables(ui: &mut egui::Ui, lab: &Lab) {
    let (a, b) = (lab.tables().a(), lab.tables().b());
    let (cos_theta, alpha, lobe) = (lab.theta_o().cos(), lab.alpha(), lab.lobe_view().lobe);
    ui.vertical(|ui| {
        for (which, name, table) in [("A", &a.name, &a.lut), ("B", &b.name, &b.lut)] {
            let t = table.sample(alpha, cos_theta);
            let (m, e) = (Channel::entries(lobe), Channel::err(lobe));
            let scale = if lobe == Lobe::Specular { t.get(Channel::SpecScale) } else { 1.0 };
            let e4 = |c| entry(t.get(c)).trim().to_string();
            ui.label(format!(
                "{which} ({name}): M^-1 = [[{}, 0, {}], [0, 1, 0], [{}, 0, {}]], scale {:.3}, error {:.1}%",
                e4(m[0]),
                e4(m[1]),
                e4(m[2]),
                e4(m[3]),
                scale,
                100.0 * t.get(e)
            ))
            .on_hover_text("Table A (the one shaded with) and table B (the other fit: the other shipped table, or \
                one loaded with \"as B\") at this (θo, α), bilinear; error is each table's pointwise \
                error (docs/design.md §4) of this lobe");
        }
    });
}

impl MatrixPanel {
    /// Takes a finished refit into the lab.
    fn poll_refit(&mut self, ctx: &egui::Context, lab: &mut Lab) {
        let Some(r) = &mut self.refit else {
            return;
        };
        match r.poll() {
            Some(result) => {
                lab.set(LastRefit(Some(result)));
                self.refit = None;
            }
            None => ctx.request_repaint(),
        }
    }

    /// Every channel as an N×N heat map (crosshair on the chosen cell; click to choose a
    /// cell), then the focused channel's colour bar, the value under the pointer and a jump to
    /// the worst cell.
    fn heat_maps(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        let chosen = self.maps_header(ui, &lab.tables().a().lut);
        let uv = axes(lab.alpha(), lab.theta_o().cos());
        let lut = &lab.tables().a().lut;
        // The visible width, not the scroll area's content width (a wide row above widens it).
        let visible = ui
            .available_width()
            .min(ui.clip_rect().right() - ui.cursor().left());
        // Less the gaps between the maps and the scroll bar beside them.
        let gaps = (MAPS_PER_ROW - 1) as f32 * ui.spacing().item_spacing.x;
        let side = ((visible - gaps - ui.spacing().scroll.bar_width - 4.0) / MAPS_PER_ROW as f32)
            .clamp(40.0, 160.0);
        let channels = Channel::ALL;
        let mut hovered = None;
        let mut clicked = chosen;
        // Rows of fixed length: a wrapping layout cannot know a column's size before it is
        // drawn, and ran the last map off the panel's edge.
        for row in channels.chunks(MAPS_PER_ROW) {
            ui.horizontal(|ui| {
                for &c in row {
                    let (hover, click) = self.heat_map(ui, lut, (c, side), uv);
                    hovered = hover.or(hovered);
                    clicked = click.or(clicked);
                }
            });
        }
        self.hovered = hovered;
        if let Some(cell) = clicked {
            choose_cell(lab, cell);
        }
    }

    /// What the maps show, the focused channel's colour bar, the reading under the pointer
    /// and the worst cell's jump: above the maps, so that no scrolling hides them. The cell
    /// the jump chose, if it was pressed.
    fn maps_header(&self, ui: &mut egui::Ui, lut: &Lut) -> Option<(usize, usize)> {
        let n = lut.size;
        ui.small(format!(
            "each map: x: r = √α from 0 to 1 (α = {} … 1), y (down) θo from 0° (top) to {:.0}° (rows by sqrt(1 − cos θo))",
            short_number(lut.alpha(0)),
            cell_theta(n - 1, n).to_degrees()
        ));
        // The reading is last frame's hover.
        let scales = &self.maps.last()?.scales;
        let scale = &scales[self.focus as usize];
        colour_bar(ui, scale, 260.0);
        ui.horizontal(|ui| {
            let text = match self.hovered {
                Some((c, i, j, x)) => format!(
                    "{} at cell ({i}, {j}): α = {}, θo = {:.1}°: {}",
                    c.name(),
                    short_number(lut.alpha(i)),
                    cell_theta(j, n).to_degrees(),
                    scales[c as usize].format(x)
                ),
                None => "hover a map to read a cell; click one to choose it (and its channel's colour bar)".into(),
            };
            // One line, truncated: a reading that wrapped would move the maps under the
            // pointer between the hover and the click.
            ui.add(egui::Label::new(egui::RichText::new(text).small()).truncate());
        });
        let err = Channel::err(self.focus.lobe());
        let jump = ui
            .small_button(format!("worst cell of {}", err.name()))
            .on_hover_text(
                "Jump to the cell with the largest pointwise error of the shown channel's lobe",
            )
            .clicked();
        jump.then(|| {
            let k = (0..lut.cells.len())
                .max_by(|&a, &b| lut.cells[a].get(err).total_cmp(&lut.cells[b].get(err)))
                .unwrap_or(0);
            (k % n, k / n)
        })
    }

    /// Channel `c`'s map, `side` points wide, with the chosen (u, v) crossed; the cell and
    /// value under the pointer, and the cell clicked (which the channel's colour bar follows).
    fn heat_map(
        &mut self,
        ui: &mut egui::Ui,
        lut: &Lut,
        (c, side): (Channel, f32),
        (u, v): (f64, f64),
    ) -> (Option<Reading>, Option<(usize, usize)>) {
        let n = lut.size;
        let (mut hovered, mut clicked) = (None, None);
        let Some(maps) = self.maps.last() else {
            return (None, None);
        };
        let texture = &maps.textures[c as usize];
        ui.vertical(|ui| {
            let title = if c == self.focus {
                egui::RichText::new(c.name()).small().strong()
            } else {
                egui::RichText::new(c.name()).small()
            };
            ui.label(title);
            let (rect, response) = ui.allocate_exact_size(Vec2::splat(side), egui::Sense::click());
            ui.painter().image(
                texture.id(),
                rect,
                egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0)),
                Color32::WHITE,
            );
            // Texel centres sit at (k + ½)/N, the LUT's own uv mapping (docs/design.md §2).
            let to_screen = |t: f64| ((t * (n - 1) as f64 + 0.5) / n as f64) as f32 * side;
            let p = rect.min + Vec2::new(to_screen(u), to_screen(v));
            let stroke = egui::Stroke::new(1.0, Color32::WHITE);
            ui.painter().hline(rect.x_range(), p.y, stroke);
            ui.painter().vline(p.x, rect.y_range(), stroke);
            let name = format!("{} heat map", c.name());
            response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &name));
            let cell_at = |pos: Pos2| {
                let cell = ((pos - rect.min) / side * n as f32).floor();
                (
                    (cell.x.max(0.0) as usize).min(n - 1),
                    (cell.y.max(0.0) as usize).min(n - 1),
                )
            };
            if let Some(pos) = response.hover_pos() {
                let (i, j) = cell_at(pos);
                hovered = Some((c, i, j, f64::from(lut.cell(i, j).get(c))));
            }
            if response.clicked()
                && let Some(pos) = response.interact_pointer_pos()
            {
                self.focus = c;
                clicked = Some(cell_at(pos));
            }
        });
        (hovered, clicked)
    }

    /// The refit's button, its progress and cancel, then the result: stored and refitted
    /// matrices and errors side by side, and the objective per iteration.
    fn refit_controls(&mut self, ui: &mut egui::Ui, lab: &Lab) {
        self.refit_buttons(ui, lab);
        let (cell, lobe) = (lab.nearest_cell(), lab.lobe_view().lobe);
        let last = lab.refit().0.as_ref();
        let Some(r) = last.filter(|r| r.cell == cell && r.lobe == lobe) else {
            if let Some(r) = last {
                ui.small(format!(
                    "(last refit: cell ({}, {}), {} lobe)",
                    r.cell.0,
                    r.cell.1,
                    r.lobe.name()
                ));
            }
            return;
        };
        refit_result(ui, r);
        objective_plot(ui, r);
    }

    /// The refit's progress and cancel, or a button per objective.
    fn refit_buttons(&mut self, ui: &mut egui::Ui, lab: &Lab) {
        let lut = &lab.tables().a().lut;
        let (lobe, cell) = (lab.lobe_view().lobe, lab.nearest_cell());
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
                    let made_by = Objective::of_lut(lut);
                    ui.label("refit this cell:");
                    for objective in Objective::ALL {
                        let what = match objective {
                            Objective::LtcCode => "ltc_code's fit (Nelder–Mead on m00, m22, m02 from 32² strata of both distributions, |·|³ error)",
                            Objective::Point => "the point fit (Nelder–Mead on m00, m02, m20, m22 and the specular scale, relative L1 \
                                error by a 64² quadrature that follows the lobe, three restarts)",
                        };
                        let made = if objective == made_by { " Table A minimizes this objective." } else { "" };
                        if ui
                            .add(egui::Button::new(objective.name()).selected(objective == made_by))
                            .on_hover_text(format!("Runs {what} on the nearest cell from the stored cell's parameters, live; then compares \
                                stored and refitted lobes by the same pointwise error.{made}"))
                            .clicked()
                        {
                            self.refit = Some(Refit::start(lobe, cell, lut, objective));
                        }
                    }
                }
            }
        });
    }
}

/// Chooses cell (i, j) of table A: the lab's α and θo move to its centre.
fn choose_cell(lab: &mut Lab, (i, j): (usize, usize)) {
    let lut = &lab.tables().a().lut;
    let (alpha, theta) = (lut.alpha(i), cell_theta(j, lut.size).to_degrees());
    lab.edit(|m: &mut Material| m.alpha = alpha);
    lab.edit(|v: &mut LobeView| v.theta_o_deg = theta);
}

/// A channel's colour scale: errors over decades (0.1% … their largest), a channel with both
/// signs diverging about zero, any other viridis from its least to its largest value.
fn channel_scale(lut: &Lut, c: Channel) -> ColourScale {
    let values = lut.cells.iter().map(|cell| f64::from(cell.get(c)));
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    let name = c.name();
    if c.is_err() {
        // 0.1%: the fit's own noise floor (64² strata, docs/design.md §4); errors below read alike.
        ColourScale::log(1e-3, hi, format!("{name} (log)")).in_percent()
    } else if lo < 0.0 && hi > 0.0 {
        ColourScale::signed(lo.abs().max(hi), name)
    } else {
        ColourScale::linear(lo, hi, name)
    }
}

/// A refit's stored and refitted matrices, scale and pointwise error.
fn refit_result(ui: &mut egui::Ui, r: &RefitResult) {
    ui.horizontal(|ui| {
        matrix(
            ui,
            &format!("cell ({}, {}) as stored (÷ middle)", r.cell.0, r.cell.1),
            crate::ltc::mat3_from_rows(r.stored),
            "The table's cell as stored",
        );
        matrix(
            ui,
            &format!("cell ({}, {}) refitted (÷ middle)", r.cell.0, r.cell.1),
            crate::ltc::mat3_from_rows(r.cos_from_brdf),
            "The refit's result",
        );
    });
    let how = match (r.cancelled, r.objective, r.converged) {
        (true, ..) => "cancelled",
        (false, Objective::Point, _) => "its restarts done",
        (false, Objective::LtcCode, true) => "converged",
        (false, Objective::LtcCode, false) => "stopped at the iteration limit",
    };
    if r.scale != 1.0 || r.stored_scale != 1.0 {
        ui.label(format!(
            "spec scale s: stored {:.3}, refitted {:.3}",
            r.stored_scale, r.scale
        ))
        .on_hover_text("The point fit's factor on the specular magnitude (spec.scale)");
    }
    ui.label(format!(
        "pointwise error: stored {:.2}%, refitted {:.2}% ({}: {} iterations, {how})",
        100.0 * r.stored_error,
        100.0 * r.error,
        r.objective.name(),
        r.iterations
    ))
    .on_hover_text(
        "∫|s·n·D − f·cos| / ∫ f·cos (docs/design.md §4), both lobes measured alike with 64² \
            strata from both distributions, whichever objective the refit minimized",
    );
}

/// The refit's objective per iteration, on a log axis.
fn objective_plot(ui: &mut egui::Ui, r: &RefitResult) {
    let points: Vec<[f64; 2]> = r
        .history
        .iter()
        .map(|&[i, f]| [i, f.max(1e-300).log10()])
        .collect();
    ui.add_space(4.0);
    let plot = egui_plot::Plot::new("nelder-mead")
        .height(110.0)
        .x_axis_label("iteration")
        .y_axis_label(match r.objective {
            // ltc_code's sum is not normalized: it scales with the lobe's peak cubed,
            // 1e10 and more for the sharpest cells.
            Objective::LtcCode => "|·|^3 (log)",
            Objective::Point => "L1 (log)",
        })
        .allow_scroll(false)
        .include_x(0.0)
        .include_x((points.len() as f64 - 1.0).max(1.0));
    // 0.2 decades beyond the curve each way: 0.4 decades always hold a 1, 2 or 5 × 10^k
    // tick (the widest gap, 2 to 5, is 0.398 decades), so a flat curve has a label.
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p[1]), hi.max(p[1]))
        });
    let plot = if lo.is_finite() {
        plot.include_y(lo - 0.2).include_y(hi + 0.2)
    } else {
        plot
    };
    let colour = Color32::from_rgb(70, 140, 255);
    log_axis(plot, false).show(ui, |p| {
        // Markers too: a fit that stops at its first iteration is one point, and a line
        // through one point draws nothing.
        p.points(
            egui_plot::Points::new("objective", points.clone())
                .radius(2.0)
                .color(colour),
        );
        p.line(egui_plot::Line::new("objective", points).color(colour));
    });
}
