//! The lesson bar (docs/design.md §5.11): a lesson's step — its title, its text with the
//! lab's readings, its equations, the panel it outlines and the control it names, and its
//! *try this*, ticked when done — beside the panels, in type that reads on a projector. It
//! moves no control: *back* and *next* stay where they are whatever a step says (the text
//! scrolls below them), and the bar's width is fixed. What it asks (another step, a step
//! written, a file) is an `Action` the app carries out.

use std::path::PathBuf;

use crate::app::lesson::readings::read;
use crate::app::lesson::{Lesson, Now, Step, StepView};
use crate::app::panel::PanelId;
use crate::app::ui::widgets::name;
use crate::app::work::cache::{Cached, Own};
use crate::gpu::work::{Work, work_per_light};
use crate::render::Method;

/// Type sizes in points: at 1280×720 (zoom 1) a point is a pixel, and the issue's
/// projector asks for text of at least 18 px to read from the back of a room.
pub const TEXT_SIZE: f32 = 19.0;
const TITLE_SIZE: f32 = 26.0;
const SMALL_SIZE: f32 = 18.0;

/// The bar's width: 38% of the window (every step of the shipped lesson fits at 1280×720),
/// within what a line of text at `TEXT_SIZE` reads comfortably in (about 35 to 65
/// characters).
pub fn bar_width(window_width: f32) -> f32 {
    (window_width * 0.38).clamp(340.0, 640.0)
}

/// What the bar asks of the app.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// Show step `k` (from 0): its view opened.
    Go(usize),
    /// Leave the lesson; the view stays.
    Close,
    /// A step of the current view after this one, with the title and text written.
    AddStep,
    /// This step removed.
    RemoveStep,
    /// The lesson to the file named (a download in the browser); whether the user named it
    /// (typed into the field) rather than left the field's default.
    Save(PathBuf, bool),
    /// A lesson from the file named (the browser's picker on the web).
    Load(String),
}

/// A teacher's step being written, and the lesson's file.
#[derive(Clone, Debug)]
struct Writing {
    title: String,
    text: String,
    path: String,
    /// The file's field was typed into: its name is the user's, not the default.
    named: bool,
}

/// A lesson being walked.
pub struct LessonBar {
    lesson: Lesson,
    /// Where it came from: a shipped lesson's name, or a file's.
    source: String,
    /// The step shown, from 0.
    step: usize,
    /// Each step's *try this*, once done.
    done: Vec<bool>,
    /// Why the step's view could not be opened, where it could not.
    view_error: Option<String>,
    /// The step's condition was seen not to hold: only then can it tick (a view that already
    /// satisfies it, or a value left from before, ticks nothing the student did).
    armed: bool,
    /// The chart's finished measurements when the step was opened.
    measurements_before: Option<u64>,
    /// The step changed: its words are shown from their top.
    scroll_to_top: bool,
    /// The step's text with its readings.
    text: Cached<String>,
    /// Each method's work per light, counted from the shaders once a text asks for it.
    work: Option<Result<Vec<(Method, Work)>, String>>,
    writing: Writing,
}

impl LessonBar {
    pub fn new(lesson: Lesson, source: &str) -> Self {
        let n = lesson.steps.len();
        Self {
            lesson,
            source: source.to_string(),
            step: 0,
            done: vec![false; n],
            view_error: None,
            armed: false,
            measurements_before: None,
            scroll_to_top: true,
            text: Cached::new("lesson.text"),
            work: None,
            writing: Writing {
                title: String::new(),
                text: String::new(),
                path: "my.lesson.toml".into(),
                named: false,
            },
        }
    }

    pub fn lesson(&self) -> &Lesson {
        &self.lesson
    }

    pub fn source(&self) -> &str {
        &self.source
    }

    /// The step shown, from 0.
    pub fn step(&self) -> usize {
        self.step
    }

    pub fn current(&self) -> &Step {
        &self.lesson.steps[self.step]
    }

    /// Whether step `k`'s *try this* was done.
    pub fn done(&self, k: usize) -> bool {
        self.done.get(k).copied().unwrap_or(false)
    }

    /// Step `k` is shown (within the lesson), its view opened or why not.
    pub fn show_step(&mut self, k: usize, view_error: Option<String>) {
        self.step = k.min(self.lesson.steps.len().saturating_sub(1));
        self.view_error = view_error;
        self.scroll_to_top = true;
        self.armed = false;
        self.measurements_before = None;
    }

    /// A step of the lab's view, `view`, after the shown one (which it becomes), with the
    /// title and text written (or a placeholder title); or why not, the lesson unchanged.
    pub fn add_step(&mut self, view: StepView, panels: Vec<PanelId>) -> Result<(), String> {
        if !self.lesson.has_room() {
            return Err("the lesson is full".into());
        }
        let title = match self.writing.title.trim() {
            "" => format!("Step {}", self.step + 2),
            t => t.to_string(),
        };
        let step = Step::captured(&title, &self.writing.text, panels, view)?;
        self.lesson.steps.insert(self.step + 1, step);
        self.done.insert(self.step + 1, false);
        self.show_step(self.step + 1, None);
        self.writing.title.clear();
        self.writing.text.clear();
        Ok(())
    }

    /// The lesson's file was written under the field's name: the next save replaces it.
    pub fn saved(&mut self) {
        self.writing.named = true;
    }

    /// The shown step removed (a lesson keeps one); the step before it shown.
    pub fn remove_step(&mut self) -> bool {
        if self.lesson.steps.len() < 2 {
            return false;
        }
        self.lesson.steps.remove(self.step);
        self.done.remove(self.step);
        self.step = self.step.saturating_sub(1);
        true
    }

    /// Ticks the step's *try this* once its condition holds, having not held on this step
    /// (measurements counted from the step's opening).
    pub fn check(&mut self, now: &Now<'_>) {
        let step = self.step;
        let before = *self.measurements_before.get_or_insert(now.measurements);
        let now = Now {
            measurements: now.measurements.saturating_sub(before),
            ..*now
        };
        let Some(t) = &self.lesson.steps[step].try_this else {
            return;
        };
        if !t.when.holds(&now) {
            self.armed = true;
        } else if self.armed {
            self.done[step] = true;
        }
    }

    /// The step: navigation on top (fixed), then its words; what the user asked for.
    pub fn show(&mut self, ui: &mut egui::Ui, now: &Now<'_>) -> Option<Action> {
        let mut action = None;
        let n = self.lesson.steps.len();
        ui.add_space(4.0);
        ui.horizontal(|ui| {
            let big = |t: &str| egui::RichText::new(t).size(SMALL_SIZE);
            if ui
                .add_enabled(self.step > 0, egui::Button::new(big("back")))
                .on_hover_text("The step before (← or Page Up)")
                .clicked()
            {
                action = Some(Action::Go(self.step - 1));
            }
            if ui
                .add_enabled(self.step + 1 < n, egui::Button::new(big("next")))
                .on_hover_text("The next step (→ or Page Down)")
                .clicked()
            {
                action = Some(Action::Go(self.step + 1));
            }
            // The step's number opens the list of steps: one row for the navigation leaves
            // the step's words the height a projector needs.
            let mut chosen = self.step;
            egui::ComboBox::from_id_salt("lesson steps")
                .selected_text(big(&format!("{} / {n}", self.step + 1)))
                .height(f32::INFINITY)
                .show_ui(ui, |ui| {
                    for (k, s) in self.lesson.steps.iter().enumerate() {
                        let tick = if self.done(k) { " (done)" } else { "" };
                        let line = format!("{}. {}{tick}", k + 1, s.title);
                        ui.selectable_value(&mut chosen, k, line);
                    }
                })
                .response
                .on_hover_text(format!(
                    "{}: its steps ({})",
                    truncate(&self.lesson.title, 60),
                    self.source
                ));
            if chosen != self.step {
                action = Some(Action::Go(chosen));
            }
            ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
                if ui
                    .button("close lesson")
                    .on_hover_text("Leave the lesson; the lab keeps this step's view")
                    .clicked()
                {
                    action = Some(Action::Close);
                }
            });
        });
        ui.separator();
        // A new step's words start at their top, whatever the last step was scrolled to.
        let mut area = egui::ScrollArea::vertical().auto_shrink([false, false]);
        if std::mem::take(&mut self.scroll_to_top) {
            area = area.vertical_scroll_offset(0.0);
        }
        area.show(ui, |ui| {
            self.words(ui, now);
            ui.add_space(16.0);
            if let Some(a) = self.writing(ui) {
                action = Some(a);
            }
        });
        action
    }

    /// The step's title, text, equations, panel and control, and *try this*.
    fn words(&mut self, ui: &mut egui::Ui, now: &Now<'_>) {
        let step = &self.lesson.steps[self.step];
        ui.label(
            egui::RichText::new(format!("{}. {}", self.step + 1, step.title))
                .size(TITLE_SIZE)
                .strong(),
        );
        ui.add_space(6.0);
        let work = &mut self.work;
        let pinned = now
            .pinned
            .map(|p| (p.terms.len(), p.relative_error().to_bits()));
        let measured = now.measurement.map(|m| {
            let times: Vec<u64> = m.points.iter().map(|p| p.ms.to_bits()).collect();
            (m.device.clone(), times)
        });
        let lab = now.lab;
        let text = self.text.get(
            (
                Own((self.step, step.text.clone())),
                lab.material(),
                lab.lobe_view(),
                lab.tables(),
                lab.lights(),
                Own((pinned, measured)),
            ),
            |_| {
                let work = work.get_or_insert_with(work_per_light);
                read(&step.text, now, work)
            },
        );
        ui.label(egui::RichText::new(text.as_str()).size(TEXT_SIZE));
        if let Some(e) = &self.view_error {
            ui.add_space(6.0);
            ui.colored_label(
                egui::Color32::from_rgb(230, 90, 80),
                egui::RichText::new(format!("This step's view could not be opened: {e}"))
                    .size(SMALL_SIZE),
            );
        }
        if !step.equations.is_empty() {
            ui.add_space(8.0);
            egui::Frame::group(ui.style()).show(ui, |ui| {
                for e in &step.equations {
                    ui.label(egui::RichText::new(e).size(SMALL_SIZE));
                }
            });
        }
        ui.add_space(8.0);
        let panels: Vec<String> = step.panels.iter().map(|p| p.title(lab)).collect();
        ui.label(
            egui::RichText::new(format!("Look at: {}", panels.join(" and "))).size(SMALL_SIZE),
        );
        if !step.control.is_empty() {
            ui.label(egui::RichText::new(format!("Move: {}", step.control)).size(SMALL_SIZE));
        }
        if let Some(t) = &step.try_this {
            ui.add_space(8.0);
            let (mark, colour) = if self.done(self.step) {
                ("Done", egui::Color32::from_rgb(90, 190, 110))
            } else {
                ("Try this", ui.visuals().strong_text_color())
            };
            ui.label(
                egui::RichText::new(format!("{mark}: {}", t.task))
                    .size(TEXT_SIZE)
                    .color(colour),
            );
        }
    }

    /// A teacher's tools: a step of the current view, and the lesson's file.
    fn writing(&mut self, ui: &mut egui::Ui) -> Option<Action> {
        let mut action = None;
        egui::CollapsingHeader::new("write a lesson")
            .default_open(false)
            .show(ui, |ui| {
                let w = &mut self.writing;
                let title = ui.add(
                    egui::TextEdit::singleline(&mut w.title)
                        .hint_text("the new step's title")
                        .desired_width(f32::INFINITY),
                );
                name(ui, &title, "new step's title");
                let text = ui.add(
                    egui::TextEdit::multiline(&mut w.text)
                        .hint_text("what it says (2–6 sentences; {fit_error} and the like are read from the lab)")
                        .desired_rows(3)
                        .desired_width(f32::INFINITY),
                );
                name(ui, &text, "new step's text");
                ui.horizontal(|ui| {
                    if ui
                        .button("add step")
                        .on_hover_text("A step after this one, of the lab as it is now (its view, as share view writes it), \
                            showing the panel shown alone or this step's panels")
                        .clicked()
                    {
                        action = Some(Action::AddStep);
                    }
                    if ui
                        .button("remove step")
                        .on_hover_text("Remove this step from the lesson (a lesson keeps one)")
                        .clicked()
                    {
                        action = Some(Action::RemoveStep);
                    }
                });
                ui.horizontal(|ui| {
                    let field = ui.add(egui::TextEdit::singleline(&mut w.path).desired_width(160.0))
                        .on_hover_text("The lesson's file (a name ending in .lesson.toml): saved to, or loaded from; only the file named here is written");
                    name(ui, &field, "lesson file");
                    w.named |= field.changed();
                    if ui.button("save lesson").on_hover_text("Write the lesson to the file named on the left (a download in a browser)").clicked() {
                        action = Some(Action::Save(PathBuf::from(w.path.trim()), w.named));
                    }
                    if ui.button("load lesson").on_hover_text("Open the lesson in the file named on the left, or a shipped lesson by its name (paper, \
                        polygon); a browser picks a file; or drop a .lesson.toml on the window").clicked() {
                        action = Some(Action::Load(w.path.trim().to_string()));
                    }
                });
            });
        action
    }
}

/// `text` cut to `n` characters, with an ellipsis where it was cut.
fn truncate(text: &str, n: usize) -> String {
    match text.char_indices().nth(n) {
        Some((at, _)) => format!("{}…", &text[..at]),
        None => text.to_string(),
    }
}
