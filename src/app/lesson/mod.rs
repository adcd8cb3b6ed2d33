//! A lesson (docs/design.md §5.11): the paper's derivation as steps a student walks in the
//! lab. A lesson is a TOML file: a title and its steps, each with a title, a short text, the
//! equations it is about, the panels it shows and the control it names, a view in the format
//! *share view* writes, and an optional *try this* whose condition the lab checks. A file is
//! input from anyone: read field by field, and refused naming the step and the field.

pub mod bar;
pub mod window;

pub mod condition;
pub mod readings;

use serde::Serialize;

use crate::app::panel::PanelId;
pub use condition::{Condition, Now};

/// The lessons that ship with the lab, by the name `--lesson` and `#lesson=` take.
pub const SHIPPED: [(&str, &str); 1] = [(
    "paper",
    include_str!("../../../assets/lessons/paper.lesson.toml"),
)];

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
    /// The lab's view at this step: a string *share view* wrote.
    pub view: String,
    #[serde(rename = "try", skip_serializing_if = "Option::is_none")]
    pub try_this: Option<TryThis>,
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

impl Lesson {
    /// The shipped lesson `name`.
    pub fn shipped(name: &str) -> Option<Self> {
        let (_, text) = SHIPPED.iter().find(|(n, _)| *n == name)?;
        Self::from_toml(text, name).ok()
    }

    /// The lesson in `text` (read from `source`, for the messages), or why not: the step (from
    /// 1) and the field named.
    pub fn from_toml(text: &str, source: &str) -> Result<Self, String> {
        let table: toml::Table = toml::from_str(text)
            .map_err(|e| format!("{source}: not a lesson's TOML: {}", e.message()))?;
        read_lesson(&table).map_err(|e| format!("{source}: {e}"))
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

/// The fields a step may have, for the message that refuses another.
const STEP_FIELDS: [&str; 7] = [
    "title",
    "text",
    "equations",
    "panels",
    "control",
    "view",
    "try",
];

fn read_lesson(table: &toml::Table) -> Result<Lesson, String> {
    if let Some(key) = table
        .keys()
        .find(|k| !["title", "step"].contains(&k.as_str()))
    {
        return Err(format!(
            "unknown field `{key}` (a lesson has title and step)"
        ));
    }
    let title = text_field(table, "title", true).map_err(|e| format!("the title: {e}"))?;
    let steps = match table.get("step") {
        Some(toml::Value::Array(steps)) => steps,
        Some(_) => return Err("`step` is not a list of [[step]] tables".into()),
        None => return Err("it has no [[step]]".into()),
    };
    if steps.is_empty() || steps.len() > MAX_STEPS {
        return Err(format!(
            "it has {} steps: a lesson has 1 to {MAX_STEPS}",
            steps.len()
        ));
    }
    let steps = steps
        .iter()
        .enumerate()
        .map(|(k, s)| read_step(s).map_err(|e| format!("step {}: {e}", k + 1)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Lesson { title, steps })
}

fn read_step(value: &toml::Value) -> Result<Step, String> {
    let toml::Value::Table(t) = value else {
        return Err("not a table".into());
    };
    if let Some(key) = t.keys().find(|k| !STEP_FIELDS.contains(&k.as_str())) {
        return Err(format!(
            "unknown field `{key}` (a step has {})",
            STEP_FIELDS.join(", ")
        ));
    }
    let field = |name: &'static str, required: bool| {
        text_field(t, name, required).map_err(|e| format!("field `{name}`: {e}"))
    };
    let title = field("title", true)?;
    let text = field("text", true)?;
    readings::check_placeholders(&text).map_err(|e| format!("field `text`: {e}"))?;
    let control = field("control", false)?;
    let view = field("view", true)?;
    if view.len() > crate::app::link::MAX_LEN {
        return Err(format!("field `view`: {} bytes, not a view", view.len()));
    }
    let equations = match t.get("equations") {
        None => Vec::new(),
        Some(v) => strings(v).map_err(|e| format!("field `equations`: {e}"))?,
    };
    let panels = match t.get("panels") {
        None => return Err("field `panels`: missing (the panels the step is about)".into()),
        Some(v) => read_panels(v).map_err(|e| format!("field `panels`: {e}"))?,
    };
    let try_this = t
        .get("try")
        .map(|v| read_try(v).map_err(|e| format!("field `try.{e}")))
        .transpose()?;
    Ok(Step {
        title,
        text,
        equations,
        panels,
        control,
        view,
        try_this,
    })
}

/// Text field `name` of `t` (empty where it is missing and not `required`), or what is
/// wrong with it.
fn text_field(t: &toml::Table, name: &str, required: bool) -> Result<String, String> {
    match t.get(name) {
        None if required => Err("missing".into()),
        None => Ok(String::new()),
        Some(toml::Value::String(s)) if s.trim().is_empty() && required => Err("empty".into()),
        Some(toml::Value::String(s)) if name != "view" && s.chars().count() > MAX_TEXT => {
            Err(format!(
                "{} characters, over the {MAX_TEXT} a field holds",
                s.chars().count()
            ))
        }
        Some(toml::Value::String(s)) => Ok(s.trim().to_string()),
        Some(v) => Err(format!("expected text, found {}", v.type_str())),
    }
}

fn strings(v: &toml::Value) -> Result<Vec<String>, String> {
    let toml::Value::Array(items) = v else {
        return Err(format!("expected a list of texts, found {}", v.type_str()));
    };
    items
        .iter()
        .enumerate()
        .map(|(k, item)| match item {
            toml::Value::String(s) if s.chars().count() <= MAX_TEXT => Ok(s.clone()),
            toml::Value::String(_) => Err(format!("item {} is over {MAX_TEXT} characters", k + 1)),
            other => Err(format!(
                "item {}: expected text, found {}",
                k + 1,
                other.type_str()
            )),
        })
        .collect()
}

fn read_panels(v: &toml::Value) -> Result<Vec<PanelId>, String> {
    let names = strings(v)?;
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

/// A step's *try this*; an error starts with the field's name after `try.`.
fn read_try(v: &toml::Value) -> Result<TryThis, String> {
    let toml::Value::Table(t) = v else {
        return Err(format!(
            "`: expected a table of task and when, found {}",
            v.type_str()
        ));
    };
    if let Some(key) = t.keys().find(|k| !["task", "when"].contains(&k.as_str())) {
        return Err(format!("{key}`: unknown (try has task and when)"));
    }
    let task = text_field(t, "task", true).map_err(|e| format!("task`: {e}"))?;
    let when = text_field(t, "when", true).map_err(|e| format!("when`: {e}"))?;
    let when = when.parse().map_err(|e| format!("when`: {e}"))?;
    Ok(TryThis { task, when })
}

impl Step {
    /// A step of the lab's `view` as it is now, for a teacher's *add step*; or why its title
    /// or text would not read back (the same rules as a file's).
    pub fn captured(
        title: &str,
        text: &str,
        panels: Vec<PanelId>,
        view: String,
    ) -> Result<Self, String> {
        let mut t = toml::Table::new();
        t.insert("title".into(), toml::Value::String(title.into()));
        t.insert("text".into(), toml::Value::String(text.into()));
        let field = |name: &str| text_field(&t, name, true).map_err(|e| format!("its {name}: {e}"));
        let (title, text) = (field("title")?, field("text")?);
        readings::check_placeholders(&text).map_err(|e| format!("its text: {e}"))?;
        Ok(Self {
            title,
            text,
            equations: Vec::new(),
            panels,
            control: String::new(),
            view,
            try_this: None,
        })
    }
}
