//! The window in a lesson (docs/design.md §5.11): the lesson bar on the right, the step's
//! panels large and outlined in the centre, ←/→ and Page Up/Down (a presenter's clicker) to
//! step, and what the bar asks carried out — a step's view opened through the same doors as
//! a link's, a step written, a lesson saved or loaded.

use crate::app::files::{Purpose, save};
use crate::app::lab::{Message, Request};
use crate::app::lesson::bar::{Action, LessonBar, bar_width};
use crate::app::lesson::{Lesson, StepView};
use crate::app::panel::PanelId;
use crate::app::{LabApp, LabState};

/// The width over height above which a step's two panels sit side by side: from a little
/// taller than square, since a panel gets more of its own room beside the other than under it
/// (the plane's image keeps 16:9: under a pinned pixel's table the stacked plane was 145×80 at
/// 1280×720, side by side 365×205; at 1024×640, 70×40 against 300×170).
const SIDE_BY_SIDE: f32 = 0.9;

impl LabApp {
    /// Walks `lesson` (from `source`: a shipped name or a file) from step `step` (from 0).
    pub fn open_lesson(&mut self, lesson: Lesson, source: &str, step: usize) {
        if lesson.steps.is_empty() {
            self.lab
                .say(Message::error(format!("the lesson {source} has no step")));
            return;
        }
        self.lesson = Some(LessonBar::new(lesson, source));
        self.go_to(step);
    }

    /// The lesson a link's fragment names (`lesson=paper&step=5`), opened; a fragment that
    /// names no shipped lesson or step is said, and the lab stays as it was.
    pub fn open_lesson_link(&mut self, fragment: &str) {
        match Lesson::of_link(fragment) {
            Some(Ok((lesson, name, step))) => self.open_lesson(lesson, &name, step),
            Some(Err(why)) => self.lab.say(Message::error(format!(
                "the link's lesson could not be opened: {why}"
            ))),
            None => {}
        }
    }

    /// The lesson being walked, if any.
    pub fn lesson(&self) -> Option<&LessonBar> {
        self.lesson.as_ref()
    }

    /// Shows step `k`: its view opened (a broken one leaves the view and says why on the
    /// step).
    fn go_to(&mut self, k: usize) {
        let Some(bar) = &self.lesson else { return };
        let k = k.min(bar.lesson().steps.len() - 1);
        let view = bar.lesson().steps[k].view.clone();
        let opened = view.open(&self.state()).map(|state| self.use_view(state));
        if let Some(bar) = &mut self.lesson {
            bar.show_step(k, opened.err());
        }
    }

    /// The view of `state` in place of the lab's: its parts through the lab's doors, the
    /// panels' settings, the window's layout; what was refused or clamped is said.
    fn use_view(&mut self, mut state: LabState) {
        let notes = state.check();
        self.lab.dismiss();
        self.panels.use_view(&state);
        self.lab.use_shared(state.lab);
        self.window = state.window;
        if !notes.is_empty() {
            self.lab.say(Message::error(notes.join("; ")));
        }
    }

    /// ←/→ and Page Up/Down step through the lesson, unless a field or a slider has the
    /// keyboard (a focused slider takes the arrows).
    pub(in crate::app) fn lesson_keys(&mut self, ctx: &egui::Context) {
        let Some(bar) = &self.lesson else { return };
        if ctx.text_edit_focused() {
            return;
        }
        let focused = ctx.memory(|m| m.focused().is_some());
        let pressed = |key| ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, key));
        let step = bar.step();
        let next = pressed(egui::Key::PageDown) || (!focused && pressed(egui::Key::ArrowRight));
        let back = pressed(egui::Key::PageUp) || (!focused && pressed(egui::Key::ArrowLeft));
        if next && step + 1 < bar.lesson().steps.len() {
            self.go_to(step + 1);
        } else if back && step > 0 {
            self.go_to(step - 1);
        }
    }

    /// The lesson bar on the window's right, at a fixed width; what it asks, carried out.
    pub(in crate::app) fn lesson_panel(&mut self, ui: &mut egui::Ui) {
        let Some(mut bar) = self.lesson.take() else {
            return;
        };
        let now = self.panels.now(&self.lab);
        bar.check(&now);
        let width = bar_width(ui.ctx().content_rect().width());
        let action = egui::Panel::right("lesson")
            .resizable(false)
            .exact_size(width)
            .show(ui, |ui| bar.show(ui, &now))
            .inner;
        self.lesson = Some(bar);
        if let Some(a) = action {
            self.lesson_action(a);
        }
    }

    fn lesson_action(&mut self, action: Action) {
        match action {
            Action::Go(k) => self.go_to(k),
            Action::Close => {
                self.lesson = None;
                self.lab
                    .say(Message::note("left the lesson; the view stays"));
            }
            Action::AddStep => {
                let view = StepView::of(&self.state());
                let panels = match (self.window.maximised, &self.lesson) {
                    (Some(p), _) => vec![p],
                    (None, Some(bar)) => bar.current().panels.clone(),
                    (None, None) => vec![PanelId::Plane],
                };
                if let Some(bar) = &mut self.lesson {
                    let n = bar.lesson().steps.len() + 1;
                    self.lab
                        .say(match view.and_then(|view| bar.add_step(view, panels)) {
                            Ok(()) => Message::note(format!(
                                "added step {} of {n}, of this view",
                                bar.step() + 1
                            )),
                            Err(e) => Message::error(format!("add step: {e}: nothing added")),
                        });
                }
            }
            Action::RemoveStep => {
                let removed = self.lesson.as_mut().is_some_and(LessonBar::remove_step);
                if removed {
                    let k = self.lesson.as_ref().map_or(0, LessonBar::step);
                    self.go_to(k);
                } else {
                    self.lab
                        .say(Message::error("a lesson keeps at least one step"));
                }
            }
            Action::Save(path, named) => self.save_lesson(&path, named),
            Action::Load(path) => self.lab.request(Request::Open(Purpose::Lesson, path)),
        }
    }

    /// Writes the lesson to the file the user named, which must end in `.lesson.toml` (so
    /// that a drop opens it as a lesson, not a scene). The field's default name never replaces
    /// a file (on the desktop: a browser's download never replaces one).
    fn save_lesson(&mut self, path: &std::path::Path, typed: bool) {
        let Some(bar) = &self.lesson else { return };
        if !typed && !cfg!(target_arch = "wasm32") && path.exists() {
            self.lab.say(Message::error(format!(
                "save lesson: {} exists and is not a name you typed: name the file to write",
                path.display()
            )));
            return;
        }
        let named = path.to_string_lossy();
        if !named
            .to_ascii_lowercase()
            .ends_with(crate::app::lesson::EXTENSION)
        {
            self.lab.say(Message::error(format!(
                "save lesson: '{named}' does not end in {}: nothing written",
                crate::app::lesson::EXTENSION
            )));
            return;
        }
        let saved = bar
            .lesson()
            .to_toml()
            .and_then(|text| save(path, text.as_bytes(), "application/toml"));
        if saved.is_ok()
            && let Some(bar) = &mut self.lesson
        {
            bar.saved();
        }
        self.lab.say(match saved {
            Ok(done) => Message::note(done),
            Err(e) => Message::error(format!("save lesson: {e}: nothing written")),
        });
    }

    /// A lesson read from `name`'s text: opened at its first step, or refused with why (the
    /// lab unchanged).
    pub(in crate::app) fn take_lesson(&mut self, text: &str, name: &str) -> Message {
        match Lesson::from_toml(text, name) {
            Ok(lesson) => {
                let n = lesson.steps.len();
                self.lab.dismiss();
                self.open_lesson(lesson, name, 0);
                match self.lab.message() {
                    Some(m) if m.is_error => m.clone(),
                    _ => Message::note(format!("opened the lesson {name} ({n} steps)")),
                }
            }
            Err(e) => Message::error(format!("{e} — the lab is unchanged")),
        }
    }

    /// The step's panels, large, each outlined: side by side where the area is wide enough for
    /// two panels of the plane's 16:9 image with their controls, else one above the other.
    pub(in crate::app) fn lesson_panels(&mut self, ui: &mut egui::Ui) {
        let Some(panels) = self.lesson.as_ref().map(|b| b.current().panels.clone()) else {
            return;
        };
        let full = ui.available_rect_before_wrap();
        let n = panels.len() as f32;
        let gap = 6.0;
        for (k, id) in panels.into_iter().enumerate() {
            let k = k as f32;
            let rect = if full.width() > SIDE_BY_SIDE * full.height() {
                let w = (full.width() - gap * (n - 1.0)) / n;
                egui::Rect::from_min_size(
                    egui::pos2(full.min.x + k * (w + gap), full.min.y),
                    egui::vec2(w, full.height()),
                )
            } else {
                let h = (full.height() - gap * (n - 1.0)) / n;
                egui::Rect::from_min_size(
                    egui::pos2(full.min.x, full.min.y + k * (h + gap)),
                    egui::vec2(full.width(), h),
                )
            };
            let mut child = ui.new_child(egui::UiBuilder::new().max_rect(rect).id_salt(id));
            child.set_clip_rect(rect.expand(2.0));
            self.panel_frame(&mut child, id);
            child.painter().rect_stroke(
                rect.shrink(1.0),
                4.0,
                egui::Stroke::new(3.0, child.visuals().selection.bg_fill),
                egui::StrokeKind::Inside,
            );
        }
        ui.allocate_rect(full, egui::Sense::hover());
    }
}
