//! A lesson (docs/design.md §5.11): the paper's derivation as steps a student walks in the
//! lab. A lesson is a TOML file: a title and its steps, each with a title, a short text, the
//! equations it is about, the panels it shows and the control it names, a view in the format
//! settings as a table (or a string *share view* wrote), and an optional *try this* whose
//! condition the lab checks. A file is input from anyone: read through serde (an unknown field
//! refused by name), then checked in one step, and refused naming its line, step and field.

pub mod bar;
pub mod window;

pub mod condition;
pub mod readings;

use serde::{Deserialize, Serialize};

use crate::app::link;
use crate::app::panel::PanelId;
pub use condition::{Condition, Now};

/// The lessons that ship with the lab, by the name `--lesson` and `#lesson=` take.
pub const SHIPPED: [(&str, &str); 2] = [
    (
        "paper",
        include_str!("../../../assets/lessons/paper.lesson.toml"),
    ),
    (
        "polygon",
        include_str!("../../../assets/lessons/polygon.lesson.toml"),
    ),
];

/// What a lesson's link starts with: `#lesson=paper&step=5`.
pub const LINK_KEY: &str = "lesson=";

pub use crate::app::files::LESSON_EXTENSION as EXTENSION;

/// The most steps a lesson has: a lecture is a dozen; more is not a lesson a person wrote.
const MAX_STEPS: usize = 200;

pub use crate::app::files::LESSON_MAX_BYTES as MAX_FILE_BYTES;

/// The longest text a field holds, in characters (a step's text is 2–6 sentences; a view of
/// moved lights is longer, up to the link's own limit, `link::MAX_LEN`).
const MAX_TEXT: usize = 4000;

/// The most panels a step shows at once: beyond two, each is too small to read on a
/// projector.
pub const MAX_PANELS: usize = 2;

/// A lesson: its title and its steps.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Lesson {
    pub title: String,
    #[serde(rename = "step")]
    pub steps: Vec<Step>,
}

/// One step: what it says, what it shows, and what it asks.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Step {
    pub title: String,
    /// 2–6 sentences, Unicode math; `{name}` is a reading of the lab (`readings`).
    pub text: String,
    /// The equations it is about, as the paper numbers them, in their corrected forms.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub equations: Vec<String>,
    /// The panels it is about, outlined and shown large (one or two).
    #[serde(serialize_with = "panel_names")]
    pub panels: Vec<PanelId>,
    /// The control it is about, named as the lab labels it.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub control: String,
    #[serde(rename = "try", skip_serializing_if = "Option::is_none")]
    pub try_this: Option<TryThis>,
    /// The lab's view at this step (last, so that its table follows the step's plain fields).
    pub view: StepView,
}

/// A step's view: the settings that differ from the lab's defaults, as a table a person
/// reads and edits (what *add step* writes), or a string *share view* wrote (what a teacher
/// pastes). Opened when the step is shown, not when the file is read: a view that does not
/// open leaves its step's text readable, with why.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum StepView {
    Fields(toml::Table),
    Link(String),
}

impl StepView {
    /// The view of the lab `state` as a step writes it: its table of settings.
    pub fn of(state: &crate::app::state::LabState) -> Result<Self, String> {
        link::to_table(state).map(Self::Fields)
    }

    /// `state` with this view in place of its own, or why it does not open.
    pub fn open(
        &self,
        state: &crate::app::state::LabState,
    ) -> Result<crate::app::state::LabState, String> {
        match self {
            Self::Fields(table) => link::table(table, state),
            Self::Link(text) => link::decode(text, state),
        }
    }
}

/// Something the student does, and the condition that says it is done.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TryThis {
    pub task: String,
    #[serde(serialize_with = "condition_text")]
    pub when: Condition,
}

fn panel_names<S: serde::Serializer>(panels: &[PanelId], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(panels.iter().map(|p| p.name()))
}

fn condition_text<S: serde::Serializer>(c: &Condition, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(&c.to_string())
}

/// A lesson's file as serde reads it, before its one check (`RawLesson::check`).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLesson {
    title: String,
    #[serde(rename = "step")]
    steps: Vec<RawStep>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawStep {
    title: String,
    text: String,
    #[serde(default)]
    equations: Vec<String>,
    panels: Vec<String>,
    #[serde(default)]
    control: String,
    view: toml::Value,
    #[serde(rename = "try")]
    try_this: Option<RawTry>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTry {
    task: String,
    when: String,
}

impl Lesson {
    /// The shipped lesson `name`.
    pub fn shipped(name: &str) -> Option<Self> {
        let (_, text) = SHIPPED.iter().find(|(n, _)| *n == name)?;
        Self::from_toml(text, name).ok()
    }

    /// The lesson in `text` (read from `source`, for the messages), or why not: the step (from
    /// 1) and the field named.
    pub fn from_toml(text: &str, source: &str) -> Result<Self, String> {
        let raw: RawLesson = toml::from_str(text).map_err(|e| {
            let at = e
                .span()
                .map_or_else(String::new, |s| where_in(text, s.start));
            format!("{source}: {at}{}", e.message().trim())
        })?;
        raw.check(text).map_err(|e| format!("{source}: {e}"))
    }

    /// Step `k` counted from 1, as links and `--step` name it, counted from 0; or why it is
    /// not one of the lesson's.
    pub fn step_index(&self, k: usize) -> Result<usize, String> {
        let n = self.steps.len();
        if (1..=n).contains(&k) {
            Ok(k - 1)
        } else {
            Err(format!(
                "{k} is not a step of the lesson: it has steps 1 to {n}"
            ))
        }
    }

    /// The shipped lesson and step (from 0) a link's fragment names, `lesson=paper&step=5`
    /// (no step: the first); `None` where the fragment is not a lesson's.
    pub fn of_link(fragment: &str) -> Option<Result<(Self, String, usize), String>> {
        let rest = fragment.trim_start_matches('#').strip_prefix(LINK_KEY)?;
        let (name, step) = match rest.split_once('&') {
            None => (rest, None),
            Some((name, query)) => (name, Some(query)),
        };
        Some((|| {
            let lesson = Self::shipped(name).ok_or_else(|| {
                let names: Vec<&str> = SHIPPED.iter().map(|(n, _)| *n).collect();
                format!(
                    "'{name}' is not a lesson the lab ships ({})",
                    names.join(", ")
                )
            })?;
            let step = match step {
                None => 0,
                Some(q) => {
                    let k = q
                        .strip_prefix("step=")
                        .and_then(|k| k.parse::<usize>().ok())
                        .ok_or_else(|| format!("'{q}' is not step=K with K a step's number"))?;
                    lesson.step_index(k)?
                }
            };
            Ok((lesson, name.to_string(), step))
        })())
    }

    /// The lesson as its file holds it, read back as any lesson is: what the lab writes, it
    /// opens again (a step it cannot, named).
    pub fn to_toml(&self) -> Result<String, String> {
        let body =
            toml::to_string_pretty(self).map_err(|e| format!("the lesson does not write: {e}"))?;
        let text = format!(
            "# An LTC Lab lesson (docs/design.md §5.11): `ltc-lab lab --lesson FILE`.\n{body}"
        );
        Self::from_toml(&text, "the lesson").map(|_| text)
    }

    /// Whether a step can be added (a lesson holds at most `MAX_STEPS`).
    pub fn has_room(&self) -> bool {
        self.steps.len() < MAX_STEPS
    }

    /// The lesson `arg` names: a shipped one's name, or a file.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn open(arg: &str) -> Result<Self, String> {
        if let Some(lesson) = Self::shipped(arg) {
            return Ok(lesson);
        }
        let text =
            crate::files::read_text(std::path::Path::new(arg), MAX_FILE_BYTES).map_err(|e| {
                let names: Vec<&str> = SHIPPED.iter().map(|(n, _)| *n).collect();
                format!("not a shipped lesson ({}), and {e}", names.join(", "))
            })?;
        Self::from_toml(&text, arg)
    }
}

/// "line L, step K: " for the byte `at` of a lesson's `text` (no step before its first).
fn where_in(text: &str, at: usize) -> String {
    let before = &text[..at.min(text.len())];
    let line = before.matches('\n').count() + 1;
    match step_headers(text).iter().filter(|&&h| h <= at).count() {
        0 => format!("line {line}: "),
        k => format!("line {line}, step {k}: "),
    }
}

/// The start of the first line of `text` within `range` that writes `key`: a key or table
/// header naming it as one of its dotted parts (`text = …`, `view.lab.rules.clip.case1 = …`,
/// `[step.try]`), never a value that mentions it.
fn key_line(text: &str, range: std::ops::Range<usize>, key: &str) -> Option<usize> {
    let mut at = range.start;
    for line in text[range.start..range.end.min(text.len())].split_inclusive('\n') {
        let trimmed = line.trim_start();
        let head = if trimmed.starts_with('[') {
            trimmed
        } else {
            trimmed.split('=').next().unwrap_or("")
        };
        let parts = head.split(|c: char| c == '.' || c == '[' || c == ']' || c.is_whitespace());
        if (head.len() < trimmed.len() || trimmed.starts_with('['))
            && parts.into_iter().any(|p| p.trim_matches('"') == key)
        {
            return Some(at);
        }
        at += line.len();
    }
    None
}

/// Where each `[[step]]` header starts in `text`.
fn step_headers(text: &str) -> Vec<usize> {
    let mut at = 0;
    let mut headers = Vec::new();
    for line in text.split_inclusive('\n') {
        if line.trim_start().starts_with("[[step]]") {
            headers.push(at);
        }
        at += line.len();
    }
    headers
}

impl RawLesson {
    /// The lesson, every field checked; or the first that is wrong, with its step's line.
    fn check(self, text: &str) -> Result<Lesson, String> {
        let title = text_field(&self.title, true).map_err(|e| format!("the title: {e}"))?;
        if self.steps.is_empty() || self.steps.len() > MAX_STEPS {
            return Err(format!(
                "it has {} steps: a lesson has 1 to {MAX_STEPS}",
                self.steps.len()
            ));
        }
        let headers = step_headers(text);
        let steps = self
            .steps
            .into_iter()
            .enumerate()
            .map(|(k, s)| {
                s.check().map_err(|e| match headers.get(k) {
                    Some(&start) => {
                        // At the field's own line within its step, where it is written there.
                        let end = headers.get(k + 1).copied().unwrap_or(text.len());
                        // The key's own line, else its parent's (`try = { when = … }`).
                        let at = e
                            .key
                            .rsplit('.')
                            .find_map(|k| key_line(text, start..end, k))
                            .unwrap_or(start);
                        format!("{}{}", where_in(text, at), e.message)
                    }
                    None => format!("step {}: {}", k + 1, e.message),
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Lesson { title, steps })
    }
}

/// What is wrong with a step: the dotted key it is written under (a field's name, a view's
/// unknown setting), to find its line, and the message.
struct StepError {
    key: String,
    message: String,
}

impl StepError {
    /// The field `name`'s error `e`.
    fn field(name: &str, e: impl std::fmt::Display) -> Self {
        Self {
            key: name.to_string(),
            message: format!("field `{name}`: {e}"),
        }
    }
}

impl RawStep {
    fn check(self) -> Result<Step, StepError> {
        let field = |name: &str, value: &str, required: bool| {
            text_field(value, required).map_err(|e| StepError::field(name, e))
        };
        let title = field("title", &self.title, true)?;
        let text = field("text", &self.text, true)?;
        readings::check_placeholders(&text).map_err(|e| StepError::field("text", e))?;
        let control = field("control", &self.control, false)?;
        for (k, e) in self.equations.iter().enumerate() {
            field("equations", e, false).map_err(|why| StepError {
                message: format!("{} (item {})", why.message, k + 1),
                ..why
            })?;
        }
        let panels = read_panels(&self.panels).map_err(|e| StepError::field("panels", e))?;
        let view = match self.view {
            toml::Value::String(s) if s.len() > link::MAX_LEN => {
                let e = format!("{} bytes, not a view", s.len());
                return Err(StepError::field("view", e));
            }
            toml::Value::String(s) => StepView::Link(s.trim().to_string()),
            toml::Value::Table(t) => StepView::Fields(t),
            other => {
                let e = format!(
                    "a table of settings or a share-view string, not {}",
                    other.type_str()
                );
                return Err(StepError::field("view", e));
            }
        };
        // A table's settings checked as the file is read (a misspelled one dropped the whole
        // view when the step opened), at the unknown setting's own line.
        if let StepView::Fields(t) = &view {
            link::table(t, &crate::app::state::LabState::default()).map_err(|e| StepError {
                key: format!("view.{}", e.split('`').nth(1).unwrap_or("")),
                message: format!("field `view`: {e}"),
            })?;
        }
        let try_this = self
            .try_this
            .map(|t| {
                let task = field("try.task", &t.task, true)?;
                let when = field("try.when", &t.when, true)?;
                let when = when.parse().map_err(|e| StepError::field("try.when", e))?;
                Ok::<_, StepError>(TryThis { task, when })
            })
            .transpose()?;
        Ok(Step {
            title,
            text,
            equations: self.equations,
            panels,
            control,
            try_this,
            view,
        })
    }
}

/// A text field's value, trimmed; or what is wrong with it: empty where `required`, or over
/// `MAX_TEXT` characters.
fn text_field(value: &str, required: bool) -> Result<String, String> {
    let n = value.chars().count();
    if required && value.trim().is_empty() {
        Err("empty".into())
    } else if n > MAX_TEXT {
        Err(format!("{n} characters, over the {MAX_TEXT} a field holds"))
    } else {
        Ok(value.trim().to_string())
    }
}

fn read_panels(names: &[String]) -> Result<Vec<PanelId>, String> {
    if names.is_empty() || names.len() > MAX_PANELS {
        return Err(format!(
            "{} panels: a step shows 1 or {MAX_PANELS}",
            names.len()
        ));
    }
    names
        .iter()
        .map(|n| {
            PanelId::of_name(n).ok_or_else(|| {
                let all: Vec<&str> = PanelId::GRID.iter().map(|p| p.name()).collect();
                format!("'{n}' is not a panel ({})", all.join(", "))
            })
        })
        .collect()
}

impl Step {
    /// A step of the lab's `view` as it is now, for a teacher's *add step*; or why its title
    /// or text would not read back (the same rules as a file's).
    pub fn captured(
        title: &str,
        text: &str,
        panels: Vec<PanelId>,
        view: StepView,
    ) -> Result<Self, String> {
        let field = |name: &str, value: &str| {
            text_field(value, true).map_err(|e| format!("its {name}: {e}"))
        };
        let (title, text) = (field("title", title)?, field("text", text)?);
        readings::check_placeholders(&text).map_err(|e| format!("its text: {e}"))?;
        Ok(Self {
            title,
            text,
            equations: Vec::new(),
            panels,
            control: String::new(),
            try_this: None,
            view,
        })
    }
}
