//! A view of the lab as one string (docs/design.md §5.9): the scene, the shared settings,
//! the panels' settings and the open panel, for a link's fragment (`index.html#view=…`) and
//! for `ltc-lab lab --view`, so that a teacher can move a view between a browser and the
//! desktop both ways. What belongs to one machine stays out: file paths, a refit's result,
//! a measured chart.

use base64::Engine;
use base64::engine::general_purpose::URL_SAFE_NO_PAD;
use serde::{Deserialize, Serialize};

use crate::app::clipping::setup::ClippingState;
use crate::app::lab::{LastRefit, Lights, Part, Shared, Tables};
use crate::app::lobe::LobeState;
use crate::app::plane::PlaneState;
use crate::app::state::{LabState, WindowState};

/// What a link's string starts with: the format's version, so that a later format can read
/// (or refuse by name) an older link.
const VERSION: &str = "v1.";

/// The fragment's key in a page's URL: `#view=v1.…`.
pub const FRAGMENT_KEY: &str = "view=";

/// The longest string `decode` reads: a generated scene of any size fits in under 1 kB; a
/// scene of dragged lights takes ~40 bytes a light. More is not a link a person sent.
pub const MAX_LEN: usize = 1 << 20;

/// The parts of the lab's state a link carries.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
struct Link {
    /// The scene's lights are the lab's generator's `count` (from the lights' seed), and
    /// the lights' list is left empty: a link of 20 000 lights stays short.
    generated: Option<usize>,
    lab: Shared,
    lobe: LobeState,
    plane: PlaneState,
    clipping: ClippingState,
    window: WindowState,
}

/// The view of `state` as a link's string: RON, raw deflate, URL-safe base64.
pub fn encode(state: &LabState) -> String {
    let link = link_of(state);
    let text = ron::to_string(&link).expect("the lab's state always serializes");
    let packed = miniz_oxide::deflate::compress_to_vec(text.as_bytes(), 9);
    format!("{VERSION}{}", URL_SAFE_NO_PAD.encode(packed))
}

/// What a link carries of `state`.
fn link_of(state: &LabState) -> Link {
    let mut lab = state.lab.clone();
    lab.tables = Part::new(Tables::shipped(lab.tables.shipped));
    lab.refit = Part::new(LastRefit(None));
    let generated = generated_count(&lab);
    let lights = match generated {
        Some(_) => Vec::new(),
        None => rounded_lights(&lab.lights.list),
    };
    lab.lights = Part::new(Lights {
        list: lights,
        seed: lab.lights.seed,
    });
    Link {
        generated,
        lab,
        lobe: state.lobe.clone(),
        plane: state.plane.clone(),
        clipping: state.clipping.clone(),
        window: state.window.clone(),
    }
}

/// `state` with the view of `text` in place of its own (its chart and the side panel's file
/// names kept); why not where `text` is not a view. `text` may be the string alone, a fragment
/// (`#view=…`) or a whole URL. What the view holds is checked where it enters the lab
/// (`LabState::check`), as any state is.
pub fn decode(text: &str, state: &LabState) -> Result<LabState, String> {
    let text = text.trim();
    let text = text
        .rsplit_once(FRAGMENT_KEY)
        .map_or(text, |(_, view)| view);
    if text.len() > MAX_LEN {
        return Err(format!("the view is {} bytes long: not a link", text.len()));
    }
    let body = text.strip_prefix(VERSION).ok_or_else(|| {
        let shown: String = text.chars().take(12).collect();
        format!("a view starts with {VERSION}, this one with '{shown}'")
    })?;
    let packed = URL_SAFE_NO_PAD
        .decode(body)
        .map_err(|e| format!("the view is not base64 ({e}): cut short when copied?"))?;
    let bytes =
        miniz_oxide::inflate::decompress_to_vec_with_limit(&packed, MAX_LEN).map_err(|e| {
            format!(
                "the view does not unpack ({:?}): cut short when copied?",
                e.status
            )
        })?;
    let text = String::from_utf8(bytes).map_err(|_| "the view's text is not UTF-8".to_string())?;
    let link: Link = ron::from_str(&text).map_err(|e| format!("the view does not read: {e}"))?;
    state_with(link, state)
}

/// `state` with the view `link` in place of its own.
fn state_with(mut link: Link, state: &LabState) -> Result<LabState, String> {
    if let Some(count) = link.generated {
        // Refused before they are made: a count beyond the limit is not a view of the lab.
        if count > crate::scene::MAX_LIGHTS {
            return Err(format!(
                "the view asks for {count} lights, over the {} a scene may have",
                crate::scene::MAX_LIGHTS
            ));
        }
        let list = link.lab.generated_lights(count);
        let seed = link.lab.lights.seed;
        link.lab.lights = Part::new(Lights { list, seed });
    }
    let mut out = state.clone();
    link.lab.tables = Part::new(Tables::shipped(link.lab.tables.shipped));
    out.lab = link.lab;
    out.lobe = link.lobe;
    out.plane = link.plane;
    out.clipping = link.clipping;
    out.window = link.window;
    Ok(out)
}

/// How many lights the lab's generator made, where the scene's lights are exactly those it
/// makes from the lights' seed (the lights slider's, and paper-100's).
fn generated_count(lab: &Shared) -> Option<usize> {
    let lights = &lab.lights.list;
    (lab.generated_lights(lights.len()) == *lights).then_some(lights.len())
}

/// The lights as a saved scene rounds them: a link of moved lights stays short.
fn rounded_lights(lights: &[crate::scene::Light]) -> Vec<crate::scene::Light> {
    let scene = crate::scene::Scene {
        lights: lights.to_vec(),
        ..crate::scene::preset("paper-100")
    };
    scene.rounded_for_saving().lights
}

/// The view of `state` as a table a person reads and edits (a lesson's `[step.view]`): only
/// what differs from the lab's defaults, by the names the lab's state has (`lobe.theta_o_deg
/// = 60`, `lab.material.alpha = 0.1`). `table` reads it back.
pub fn to_table(state: &LabState) -> Result<toml::Table, String> {
    let value = |state: &LabState| {
        toml::Table::try_from(link_of(state)).map_err(|e| format!("the view does not write: {e}"))
    };
    Ok(difference(&value(state)?, &value(&LabState::default())?))
}

/// The entries of `a` that differ from `b`'s, nested tables by their own differing entries.
fn difference(a: &toml::Table, b: &toml::Table) -> toml::Table {
    a.iter()
        .filter_map(|(key, value)| match (value, b.get(key)) {
            (_, Some(other)) if other == value => None,
            (toml::Value::Table(t), Some(toml::Value::Table(u))) => {
                Some((key.clone(), toml::Value::Table(difference(t, u))))
            }
            _ => Some((key.clone(), value.clone())),
        })
        .collect()
}

/// `state` with the view a table written by `to_table` describes (what it does not name
/// stays at the lab's defaults); why not, naming the entry, where an entry is not one of the
/// view's or its value does not read.
pub fn table(view: &toml::Table, state: &LabState) -> Result<LabState, String> {
    let defaults = toml::Table::try_from(link_of(&LabState::default()))
        .map_err(|e| format!("the view does not write: {e}"))?;
    let mut merged = defaults;
    // A view that names its lights names them all: not the defaults' generated count.
    let names_lights = view
        .get("lab")
        .and_then(|lab| lab.get("lights"))
        .and_then(|lights| lights.get("list"))
        .is_some();
    if names_lights {
        merged.remove("generated");
    }
    merge(&mut merged, view);
    let link: Link = merged.try_into().map_err(|e: toml::de::Error| {
        let message = e.message().trim();
        format!(
            "the view does not read: {message}{}",
            nearest_expected(message)
        )
    })?;
    // Every entry written must be read: serde passes over a name the state does not have.
    let read = toml::Table::try_from(&link).map_err(|e| format!("the view does not write: {e}"))?;
    if let Some(path) = unread(view, &read, "") {
        let near = nearest(&path, &paths(&read, "", true))
            .map_or_else(String::new, |n| format!("; the nearest is `{n}`"));
        return Err(format!("`{path}` is not a setting of the view{near}"));
    }
    state_with(link, state)
}

/// `view`'s entries laid over `into`, nested tables entry by entry.
fn merge(into: &mut toml::Table, view: &toml::Table) {
    for (key, value) in view {
        match (into.get_mut(key), value) {
            (Some(toml::Value::Table(t)), toml::Value::Table(v)) => merge(t, v),
            _ => {
                into.insert(key.clone(), value.clone());
            }
        }
    }
}

/// Every setting a view can hold, by its dotted path (`lab.material.alpha`), as the lab's
/// defaults write them: the list the README's "Writing a lesson" gives (tests/inputs/lesson.rs keeps
/// the two the same).
pub fn setting_paths() -> Vec<String> {
    toml::Table::try_from(link_of(&LabState::default()))
        .map(|t| paths(&t, "", false))
        .unwrap_or_default()
}

/// The dotted paths of `table`'s entries under `at`: its leaves, and with `tables` its
/// tables too.
fn paths(table: &toml::Table, at: &str, tables: bool) -> Vec<String> {
    let mut out = Vec::new();
    for (key, value) in table {
        let path = if at.is_empty() {
            key.clone()
        } else {
            format!("{at}.{key}")
        };
        match value {
            toml::Value::Table(t) => {
                if tables {
                    out.push(path.clone());
                }
                out.extend(paths(t, &path, tables));
            }
            _ => out.push(path),
        }
    }
    out
}

/// The path of `candidates` nearest `path` by edit distance, where one is within half its
/// length (a misspelling, not another name).
fn nearest<'a>(path: &str, candidates: &'a [String]) -> Option<&'a str> {
    candidates
        .iter()
        .map(|c| (edit_distance(path, c), c))
        .min_by_key(|(d, _)| *d)
        .filter(|(d, _)| *d <= path.len().div_ceil(2))
        .map(|(_, c)| c.as_str())
}

/// For serde's "unknown field `x`, expected one of `a`, `b`": the nearest of those to `x`, in
/// words ("; the nearest is `a`"), or nothing.
fn nearest_expected(message: &str) -> String {
    let Some(rest) = message.strip_prefix("unknown field `") else {
        return String::new();
    };
    let mut quoted = rest.split('`').step_by(2);
    let Some(unknown) = quoted.next() else {
        return String::new();
    };
    let expected: Vec<String> = quoted
        .map(str::to_string)
        .filter(|n| !n.is_empty())
        .collect();
    nearest(unknown, &expected).map_or_else(String::new, |n| format!("; the nearest is `{n}`"))
}

/// Levenshtein's distance between `a` and `b`, by characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = (diagonal + usize::from(ca != cb))
                .min(row[j] + 1)
                .min(above + 1);
            diagonal = above;
        }
    }
    row[b.len()]
}

/// The first entry of `written` (its dotted path under `at`) that `read` lacks.
fn unread(written: &toml::Table, read: &toml::Table, at: &str) -> Option<String> {
    written.iter().find_map(|(key, value)| {
        let path = if at.is_empty() {
            key.clone()
        } else {
            format!("{at}.{key}")
        };
        match (value, read.get(key)) {
            (_, None) => Some(path),
            (toml::Value::Table(w), Some(toml::Value::Table(r))) => unread(w, r, &path),
            _ => None,
        }
    })
}
