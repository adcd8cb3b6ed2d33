//! The clipping panel: the paper's Figure 2 for both clipping cases — per case, (a) LTC and
//! (b) BRDF with the light above the plane, (c) LTC and (d) BRDF with the case's light —
//! each picture exposed to its own content with its factor printed, negative light in the
//! diverging map; each case's four-class case map with a legend and counts; and a profile
//! along a line dragged on any picture (by default through the case's strongest artifact) on
//! a symmetric log axis; below, a rect's polygon clipped at the surface's horizon and its
//! image under M^-1 at the cosine's (`polygon`). The rules are the lab's own; α, the light and
//! the table are edited here.

pub mod elevation;
pub mod polygon;
pub mod rows;
pub mod setup;

use egui::{Color32, Pos2, Vec2};

use crate::app::clipping::elevation::ElevationView;
use crate::app::clipping::rows::{
    CaseRow, PICTURE, ROWS, RowsInput, RowsWorker, class_colour, sample,
};
use crate::app::clipping::setup::{ClipScene, ClipSetup, ClippingState, LIGHT_REACH};
use crate::app::lab::{Lab, TableId};
use crate::app::panel::Panel;
use crate::app::ui::axes::symlog_y;
use crate::app::ui::widgets::clipping_rules;
use crate::app::work::cache::{Cached, Own};
use crate::colormap::{round_sig, short_number};
use crate::cpu::cases::ClipCounts;
use crate::ltc::ClipCase;
use crate::render::Frame;

pub struct ClippingPanel {
    state: ClippingState,
    /// Both case rows as last made.
    rows: Vec<CaseRow>,
    /// The rows' making, started again when what they are made from changes.
    started: Cached<()>,
    worker: RowsWorker,
    /// One light over its elevation at the lab's (θo, α).
    elevation: ElevationView,
    /// The user's profile line (picture coordinates, 0–1), while one is drawn.
    line: Option<[Pos2; 2]>,
    drag_from: Option<Pos2>,
}

impl Panel for ClippingPanel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        ui.horizontal_wrapped(|ui| self.toolbar(ui, lab));
        self.ensure(ui.ctx(), lab);
        let size = picture_size(ui);
        egui::ScrollArea::vertical()
            .auto_shrink([false; 2])
            .show(ui, |ui| {
                let first = self.state.elevation_first;
                if first {
                    self.elevation.show(ui, lab, self.state.setup.table);
                    ui.separator();
                }
                for (r, &row) in ROWS.iter().enumerate() {
                    self.row_controls(ui, row);
                    self.row_pictures(ui, r, row, size);
                }
                self.legend(ui);
                self.profile(ui);
                if !first {
                    ui.separator();
                    self.elevation.show(ui, lab, self.state.setup.table);
                }
                ui.separator();
                egui::CollapsingHeader::new("rect clipping: P and M^-1 P")
                    .show(ui, |ui| polygon::show(ui, lab, self.state.setup.table));
            });
    }

    /// Whether the pictures are being made.
    fn busy(&self) -> bool {
        self.worker.busy()
    }

    fn caches(&self) -> Vec<(&'static str, u64)> {
        let [bands, spheres] = self.elevation.counts();
        vec![self.started.count(), bands, spheres]
    }
}

impl ClippingPanel {
    pub fn new(state: ClippingState) -> Self {
        Self {
            state,
            rows: Vec::new(),
            started: Cached::new("clipping.pictures"),
            worker: RowsWorker::default(),
            elevation: ElevationView::default(),
            line: None,
            drag_from: None,
        }
    }

    pub fn state(&self) -> &ClippingState {
        &self.state
    }

    /// Its settings from a view (a lesson's step), checked by the caller.
    pub fn set_state(&mut self, state: ClippingState) {
        self.state = state;
    }

    /// The lab's two rules, the table, and a reset.
    fn toolbar(&mut self, ui: &mut egui::Ui, lab: &mut Lab) {
        clipping_rules(
            ui,
            lab,
            [
                (
                    "case 1 rule (n·l ≤ 0 -> 0)",
                    "The lab's rule (the side panel's \"clip case 1\"). Off: the light below the plane is \
                        lifted above the horizon by M^-1 and the LTC glows (c), while the BRDF (d) stays black",
                ),
                (
                    "case 2 rule ((M^-1 l).z ≤ 0 -> 0)",
                    "The lab's rule (the side panel's \"clip case 2\"). Off: a light above the horizon that \
                        M^-1 pushes below contributes negative light (blue)",
                ),
            ],
        );
        ui.separator();
        let setup = &mut self.state.setup;
        ui.label("table");
        ui.selectable_value(&mut setup.table, TableId::A, "A")
            .on_hover_text("Table A, the one the lab shades with");
        ui.selectable_value(
            &mut setup.table,
            TableId::B,
            format!("B ({})", lab.tables().b().name),
        )
        .on_hover_text("Table B, the other fit");
        ui.toggle_value(&mut self.state.elevation_first, "elevation on top")
            .on_hover_text("The elevation view (one light's error over its height above the surface, by band) above \
                the Figure 2 pictures instead of under them");
        if ui
            .small_button("reset")
            .on_hover_text("The presets' α and lights")
            .clicked()
        {
            *setup = ClipSetup::default();
            self.line = None;
        }
    }

    /// The row's title, α and light position.
    fn row_controls(&mut self, ui: &mut egui::Ui, row: ClipScene) {
        let k = row.index();
        ui.horizontal_wrapped(|ui| {
            let selected = self.state.clip_scene == row;
            let title = match row {
                ClipScene::Case2 => "case 2: light above, pushed below by M^-1",
                _ => "case 1: light below, lifted by M^-1",
            };
            if ui
                .selectable_label(selected, egui::RichText::new(title).strong())
                .on_hover_text("Show this case's legend and profile")
                .clicked()
            {
                self.state.clip_scene = row;
                self.line = None;
            }
            let setup = &mut self.state.setup;
            ui.add(
                egui::DragValue::new(&mut setup.alpha[k])
                    .range(crate::ltc::lut::ALPHA_MIN..=1.0)
                    .speed(0.005)
                    .prefix("α "),
            )
            .on_hover_text("This case's roughness (all four pictures of the row)");
            ui.label("light");
            for (c, axis) in ["x ", "y ", "z "].into_iter().enumerate() {
                ui.add(
                    egui::DragValue::new(&mut setup.light[k][c])
                        .range(-LIGHT_REACH..=LIGHT_REACH)
                        .speed(0.005)
                        .max_decimals(4)
                        .prefix(axis),
                )
                .on_hover_text("The case light's position, scene units (the plane spans ±2)");
            }
        });
    }

    /// A row's four pictures and its case map; drag on any to draw the profile's line.
    fn row_pictures(&mut self, ui: &mut egui::Ui, r: usize, row: ClipScene, size: Vec2) {
        let line = (self.state.clip_scene == row).then(|| self.line_or_default());
        let Some(case_row) = self.rows.get(r) else {
            return;
        };
        let mut drawn: Option<(Pos2, Pos2, bool)> = None;
        ui.horizontal(|ui| {
            for k in 0..=case_row.thumbs.len() {
                ui.vertical(|ui| {
                    ui.set_width(size.x);
                    drawn = picture(ui, case_row, (row, k), size, line).or(drawn);
                });
            }
        });
        match drawn {
            Some((from, to, true)) => {
                self.drag_from = Some(from);
                self.state.clip_scene = row;
                self.line = Some([from, to]);
            }
            Some((_, to, false)) => {
                if let Some(from) = self.drag_from {
                    self.state.clip_scene = row;
                    self.line = Some([from, to]);
                }
            }
            None => {}
        }
    }

    /// The four classes' colours, names and pixel counts for both cases.
    fn legend(&self, ui: &mut egui::Ui) {
        for (name, counts) in ["case 1", "case 2"]
            .into_iter()
            .zip(self.rows.iter().map(|r| r.class_counts))
        {
            ui.horizontal_wrapped(|ui| {
                ui.small(format!(
                    "case map of {name} (pixels of {}×{}; the rest is off the plane):",
                    PICTURE.0, PICTURE.1
                ));
                for case in ClipCase::ALL {
                    let (rect, _) = ui.allocate_exact_size(Vec2::splat(10.0), egui::Sense::hover());
                    ui.painter().rect_filled(rect, 2.0, class_colour(case));
                    ui.small(format!("{} {}", case.name(), counts[case.index()]))
                        .on_hover_text(class_hover(case));
                }
            });
        }
        let Some(row) = self.selected_row() else {
            return;
        };
        if let Some(t) = row.thumbs.get(2) {
            let positive = t.factor.is_finite() && t.factor > 0.0;
            let text = match t.negative_factor {
                Some(n) if !positive => format!(
                    "(c): all negative light, in blue ×{} (exposed to its own peak)",
                    short_number(round_sig(n))
                ),
                Some(n) => format!(
                    "(c): orange positive ×{}, blue negative light ×{} (each part exposed to its own peak)",
                    short_number(round_sig(t.factor)),
                    short_number(round_sig(n))
                ),
                None => "each picture is exposed so that its brightest pixel is white; its factor is printed under it".into(),
            };
            ui.small(text);
            ui.small("(a), (b): the same light moved above the plane, for reference; (c), (d): this case's light; hover a picture to read it");
        }
    }

    /// Luminance along the line on a symmetric log axis: the BRDF, LTC with both rules, as
    /// toggled, and without the case's rule.
    fn profile(&mut self, ui: &mut egui::Ui) {
        let line = self.line_or_default();
        let Some(row) = self.selected_row() else {
            return;
        };
        let curves: Vec<Vec<[f64; 2]>> = row
            .profile_frames
            .iter()
            .map(|f| profile_along(f, line))
            .collect();
        let peak = curves
            .iter()
            .flatten()
            .fold(0.0f64, |m, p| m.max(p[1].abs()))
            .max(1e-30);
        // Five decades under the peak: case 1's glow is ~1e-3 of the dip beside it.
        let c = peak * 1e-5;
        let names = [
            ("BRDF", Color32::from_rgb(240, 150, 60)),
            ("LTC, both rules (eq. 30)", Color32::from_rgb(70, 140, 255)),
            ("LTC, rules as toggled", Color32::from_rgb(90, 210, 120)),
            (
                if self.state.clip_scene == ClipScene::Case2 {
                    "LTC without the case-2 rule"
                } else {
                    "LTC without the case-1 rule"
                },
                Color32::from_rgb(220, 80, 200),
            ),
        ];
        if ui
            .small_button("line through the strongest artifact")
            .on_hover_text("Drag on any picture to draw another line")
            .clicked()
        {
            self.line = None;
        }
        let plot = egui_plot::Plot::new("clip profile")
            .legend(egui_plot::Legend::default())
            .x_axis_label("distance along the line (pixels of the pictures)")
            // Ticks every 10, 50 and 100 pixels (the default's 10s and 100s label one tick).
            .x_grid_spacer(egui_plot::uniform_grid_spacer(|_| [10.0, 50.0, 100.0]))
            .y_axis_label("luminance (symlog)")
            .min_size(Vec2::new(80.0, 140.0))
            // Half of what is left: the elevation plot below shares the panel's height.
            .height((ui.available_height() * 0.5).max(140.0))
            .allow_scroll(false);
        symlog_y(plot, c).show(ui, |p| {
            for (k, (points, (name, colour))) in curves.into_iter().zip(names).enumerate() {
                let points: Vec<[f64; 2]> = points
                    .into_iter()
                    .map(|[x, y]| [x, crate::colormap::symlog(y, c)])
                    .collect();
                let mut line = egui_plot::Line::new(name, points).color(colour);
                if k == 3 {
                    line = line.style(egui_plot::LineStyle::dashed_loose());
                }
                p.line(line);
            }
        });
    }

    fn selected_row(&self) -> Option<&CaseRow> {
        let r = if self.state.clip_scene == ClipScene::Case2 {
            1
        } else {
            0
        };
        self.rows.get(r)
    }

    /// The user's line, or the selected case's default.
    fn line_or_default(&self) -> [Pos2; 2] {
        self.line.unwrap_or_else(|| {
            self.selected_row()
                .map_or([egui::pos2(0.0, 0.5), egui::pos2(1.0, 0.5)], |r| {
                    r.default_line
                })
        })
    }

    /// Makes both rows again (on the worker) when the rules, α, a light or the table
    /// changed; takes them in once made.
    fn ensure(&mut self, ctx: &egui::Context, lab: &Lab) {
        let inputs = (lab.rules(), lab.tables(), Own(self.state.setup.clone()));
        let worker = &mut self.worker;
        self.started.get(inputs, |(rules, tables, Own(setup))| {
            let input = RowsInput {
                rules: **rules,
                lut: tables.get(setup.table).lut.clone(),
                setup,
            };
            worker.start(ctx, input);
        });
        if let Some(rows) = self.worker.poll(ctx) {
            self.rows = rows;
        }
    }
}

/// Picture `k` of a row (the case map after the four), `size` points large, with the
/// profile's `line` where this row is shown; a drag's start (`true`) or move on it.
fn picture(
    ui: &mut egui::Ui,
    case_row: &CaseRow,
    (row, k): (ClipScene, usize),
    size: Vec2,
    line: Option<[Pos2; 2]>,
) -> Option<(Pos2, Pos2, bool)> {
    let (texture, caption, frame) = match case_row.thumbs.get(k) {
        Some(t) => (t.texture.id(), t.caption.clone(), Some(&t.frame)),
        None => (case_row.map_texture.id(), "case map".to_string(), None),
    };
    let (rect, response) = ui.allocate_exact_size(size, egui::Sense::click_and_drag());
    let name = format!("{} picture {k}", row.preset());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &name));
    let painter = ui.painter_at(rect);
    let uv = egui::Rect::from_min_max(Pos2::ZERO, egui::pos2(1.0, 1.0));
    painter.image(texture, rect, uv, Color32::WHITE);
    let to_unit = |p: Pos2| {
        let u = (p - rect.min) / rect.size();
        egui::pos2(u.x.clamp(0.0, 1.0), u.y.clamp(0.0, 1.0))
    };
    if let Some(line) = line {
        let a = rect.min + line[0].to_vec2() * rect.size();
        let b = rect.min + line[1].to_vec2() * rect.size();
        let stroke = egui::Stroke::new(1.5, Color32::from_rgb(255, 240, 80));
        painter.line_segment([a, b], stroke);
        painter.circle_filled(a, 2.5, stroke.color);
    }
    let mut drawn = None;
    if response.drag_started()
        && let Some(p) = response.ctx.input(|i| i.pointer.press_origin())
    {
        drawn = Some((to_unit(p), to_unit(p), true));
    } else if response.dragged()
        && let Some(p) = response.interact_pointer_pos()
    {
        drawn = Some((Pos2::ZERO, to_unit(p), false));
    }
    ui.small(caption);
    // The reading on its own line, under the caption, so that neither hides the other;
    // blank (but kept) when the pointer is elsewhere.
    let reading = response.hover_pos().map(|p| {
        let u = to_unit(p);
        match frame {
            Some(frame) => format!(
                "luminance {} (linear, scene units)",
                short_number(sample(frame, u).unwrap_or(0.0))
            ),
            None => class_at(&case_row.case_map, u)
                .map_or("off the plane".into(), |c| c.name().to_string()),
        }
    });
    ui.small(reading.unwrap_or_default());
    drawn
}

/// The pictures' size: five abreast within the panel's width (its scroll bar and the gaps
/// between them included), and small enough in a short panel that both rows, the legend and
/// the profile's plot fit its height.
fn picture_size(ui: &egui::Ui) -> Vec2 {
    let spacing = ui.spacing();
    let across =
        ui.available_width() - 4.0 * spacing.item_spacing.x - spacing.scroll.bar_width - 8.0;
    // Per row: its controls and the two caption lines (about 70 points); then the legend's
    // lines and the profile's 140-point plot with its buttons (about 230).
    let down = (ui.available_height() - 2.0 * 70.0 - 230.0) / 2.0;
    let aspect = PICTURE.1 as f32 / PICTURE.0 as f32;
    // Not below 110 points, where the glow and the case map stop being readable: a short
    // panel scrolls to the profile instead.
    let w = (across / 5.0)
        .min((down / aspect).max(110.0))
        .clamp(40.0, 320.0);
    Vec2::new(w, w * aspect)
}

/// The class of the case map at picture coordinates `u`.
fn class_at(map: &[Option<ClipCounts>], u: Pos2) -> Option<ClipCase> {
    let (w, h) = PICTURE;
    let x = ((u.x * w as f32) as usize).min(w - 1);
    let y = ((u.y * h as f32) as usize).min(h - 1);
    map.get(y * w + x)
        .copied()
        .flatten()
        .and_then(|c| c.class())
}

/// Luminance along `line` (picture coordinates), x in picture pixels from its start.
pub fn profile_along(frame: &Frame, line: [Pos2; 2]) -> Vec<[f64; 2]> {
    let px = Vec2::new(frame.width as f32, frame.height as f32);
    let length = ((line[1] - line[0]) * px).length();
    let steps = (length.ceil() as usize).max(2);
    (0..=steps)
        .filter_map(|k| {
            let t = k as f32 / steps as f32;
            let u = line[0] + (line[1] - line[0]) * t;
            sample(frame, u).map(|l| [f64::from(t * length), l])
        })
        .collect()
}

fn class_hover(case: ClipCase) -> &'static str {
    match case {
        ClipCase::Visible => "Above the horizon before and after M^-1: shaded as fitted",
        ClipCase::Lifted => {
            "Below the horizon but lifted above it by M^-1 (of either lobe, specular or diffuse): \
                glows unless the case-1 rule clips it. The other lobe may stay below: with both rules \
                off, that part is negative"
        }
        ClipCase::PushedBelow => {
            "Above the horizon but pushed below by M^-1 (of either lobe): negative light unless the case-2 rule clips it"
        }
        ClipCase::StaysBelow => {
            "Below the horizon and still below after M^-1: either rule removes it; with both rules off it is negative light"
        }
    }
}
