//! How the window lays the panels out: the side panel (unless folded), then the grid's
//! panels — one maximised, all five in a grid, or, below the grid's size, one at a time under
//! tabs — each in a frame with its title; and egui's zoom fitted to the window.

use crate::app::LabApp;
use crate::app::panel::PanelId;

/// The smallest central area that shows all five panels at once: below it each panel is
/// too small to read (the clipping pictures and the matrix numbers first), so they go
/// under tabs.
const GRID_MIN: egui::Vec2 = egui::vec2(1100.0, 640.0);

/// The grid: three panels on top (lobe, matrix, plane) and two below (clipping, chart), each
/// with its share of its row's width.
const GRID_ROWS: [&[(PanelId, f32)]; 2] = [
    &[
        (PanelId::Lobe, 0.28),
        (PanelId::Matrix, 0.30),
        (PanelId::Plane, 0.42),
    ],
    &[(PanelId::Clipping, 0.55), (PanelId::Chart, 0.45)],
];

impl LabApp {
    /// The side panel and the central area.
    pub(super) fn layout(&mut self, ui: &mut egui::Ui) {
        self.lesson_panel(ui);
        if !self.window.controls_hidden {
            egui::Panel::left("controls")
                .resizable(true)
                .default_size(250.0)
                .show(ui, |ui| {
                    egui::ScrollArea::vertical()
                        .show(ui, |ui| self.show_panel(ui, PanelId::Controls));
                });
        }
        egui::CentralPanel::default().show(ui, |ui| {
            let size = ui.available_size();
            let tabs = size.x < GRID_MIN.x || size.y < GRID_MIN.y;
            // Wrapped: the tabs and the bar's buttons overflow a small window in one row.
            ui.horizontal_wrapped(|ui| self.top_bar(ui, tabs));
            if self.lesson().is_some() {
                return self.lesson_panels(ui);
            }
            match (self.window.maximised, tabs) {
                (Some(id), _) => self.panel_frame(ui, id),
                (None, true) => {
                    let id = self.window.tab;
                    self.panel_frame(ui, id);
                }
                (None, false) => self.grid(ui),
            }
        });
    }

    /// The side panel's fold, and the tabs where the panels do not fit side by side.
    fn top_bar(&mut self, ui: &mut egui::Ui, tabs: bool) {
        let label = if self.window.controls_hidden {
            ">> controls"
        } else {
            "<< controls"
        };
        if ui
            .small_button(label)
            .on_hover_text("Fold the side panel away, or back")
            .clicked()
        {
            self.window.controls_hidden = !self.window.controls_hidden;
        }
        // The shipped lessons by title: each step opens its view, outlines its panel and
        // says what to try.
        let mut chosen = None;
        if self.lesson().is_none() {
            ui.menu_button("lesson", |ui| {
                for (name, _) in crate::app::lesson::SHIPPED {
                    let Some(lesson) = crate::app::lesson::Lesson::shipped(name) else {
                        continue;
                    };
                    let link = format!("#lesson={name}, or ltc-lab lab --lesson {name}");
                    if ui.button(&lesson.title).on_hover_text(link).clicked() {
                        chosen = Some((lesson, name));
                        ui.close();
                    }
                }
            })
            .response
            .on_hover_text("Walk a shipped lesson step by step: the paper's derivation, or the polygon lights it is about");
        }
        if let Some((lesson, name)) = chosen {
            self.open_lesson(lesson, name, 0);
        }
        if tabs && self.window.maximised.is_none() && self.lesson().is_none() {
            for id in PanelId::GRID {
                let title = id.title(&self.lab);
                ui.selectable_value(&mut self.window.tab, id, title);
            }
        }
    }

    fn grid(&mut self, ui: &mut egui::Ui) {
        let full = ui.available_rect_before_wrap();
        let gap = 6.0;
        let top_h = (full.height() * 0.55).floor();
        let rows = [
            egui::Rect::from_min_size(full.min, egui::vec2(full.width(), top_h - gap)),
            egui::Rect::from_min_max(egui::pos2(full.min.x, full.min.y + top_h), full.max),
        ];
        for (row, panels) in rows.into_iter().zip(GRID_ROWS) {
            let mut x = row.min.x;
            for &(id, fraction) in panels {
                let w = row.width() * fraction;
                let rect = egui::Rect::from_min_size(
                    egui::pos2(x, row.min.y),
                    egui::vec2(w - gap, row.height()),
                );
                x += w;
                let mut child = ui.new_child(egui::UiBuilder::new().max_rect(rect).id_salt(id));
                child.set_clip_rect(rect);
                self.panel_frame(&mut child, id);
            }
        }
        ui.allocate_rect(full, egui::Sense::hover());
    }

    /// One panel in a frame with its title and a maximise/restore button.
    pub(super) fn panel_frame(&mut self, ui: &mut egui::Ui, id: PanelId) {
        egui::Frame::group(ui.style()).show(ui, |ui| {
            ui.set_min_size(ui.available_size());
            ui.horizontal(|ui| {
                ui.strong(id.title(&self.lab));
                // In a lesson the step lays the panels out.
                let lesson = self.lesson().is_some();
                ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                    if lesson {
                        return;
                    }
                    let maximised = self.window.maximised == Some(id);
                    let label = if maximised { "restore" } else { "maximise" };
                    if ui
                        .small_button(label)
                        .on_hover_text("Show this panel alone, or all five again")
                        .clicked()
                    {
                        self.window.maximised = if maximised { None } else { Some(id) };
                    }
                });
            });
            ui.separator();
            self.show_panel(ui, id);
        });
    }

    /// Panel `id`, timed for the frame log.
    fn show_panel(&mut self, ui: &mut egui::Ui, id: PanelId) {
        let started = web_time::Instant::now();
        self.shown.push(id);
        self.panels.get_mut(id).show(ui, &mut self.lab);
        self.part_ms[id as usize] = started.elapsed().as_secs_f64() * 1e3;
    }

    /// Fits egui's zoom to the window when the window's size changes (`auto_zoom`). A change
    /// of the size in points that keeps the size at zoom 1 is a zoom (the user's Ctrl + / −,
    /// or the one set here, which the window's size follows a frame late): it stands.
    pub(super) fn fit_zoom(&mut self, ctx: &egui::Context) {
        let points = ctx.input(|i| i.viewport_rect().size());
        let logical = points * ctx.zoom_factor();
        let key = |v: egui::Vec2| [v.x.round() as u32, v.y.round() as u32];
        let (points_key, logical_key) = (key(points), key(logical));
        match self.zoomed_for {
            Some((p, _)) if p == points_key => {}
            Some((_, l)) if l == logical_key => self.zoomed_for = Some((points_key, l)),
            _ => {
                self.zoomed_for = Some((points_key, logical_key));
                ctx.set_zoom_factor(auto_zoom(logical));
            }
        }
    }
}

/// The zoom for a window `size` points large at zoom 1: 1 up to 1920×1080, the size the
/// panels are laid out for, and growing with the window beyond it (2 at 3840×2160), so that
/// pictures and text grow with a large screen instead of floating small in empty space.
pub fn auto_zoom(size: egui::Vec2) -> f32 {
    // At most 3: beyond it a wall-sized window is better served by Ctrl + / −.
    (size.x / 1920.0).min(size.y / 1080.0).clamp(1.0, 3.0)
}
