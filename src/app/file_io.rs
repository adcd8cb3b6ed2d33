//! Files into and out of the lab, all carried out by the app: read from the path a field
//! names (the desktop), picked in the browser's file picker, dropped on the window (both),
//! and saved — to the file the user named on the desktop, as a download of that name in the
//! browser (docs/design.md §5.8). What a given file is for comes from the button that asked
//! for it, or, for a drop, from its name.

use std::path::Path;

use crate::app::LabApp;
use crate::app::files::{Given, Purpose, group, save};
use crate::app::lab::{Lab, Message};
use crate::gpu::method_file::MethodFile;
use crate::scene::Scene;
use crate::tables::{NamedTable, Source};

impl LabApp {
    /// Reads the file at `path` for `purpose` (the desktop), or opens the browser's picker
    /// for it; says what was done, or why nothing was.
    pub(super) fn open(&mut self, purpose: Purpose, path: &str, ctx: &egui::Context) {
        #[cfg(target_arch = "wasm32")]
        {
            let _ = path;
            let picked =
                crate::app::browser::pick(purpose.accept(), purpose.multiple(), ctx.clone());
            match picked {
                Ok(p) => self.picking = Some((Some(purpose), p)),
                Err(e) => self.lab.say(Message::error(e)),
            }
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = ctx;
            let message = self.read(purpose, path.trim());
            self.lab.say(message);
        }
    }

    /// The file at `path` used for `purpose`.
    #[cfg(not(target_arch = "wasm32"))]
    fn read(&mut self, purpose: Purpose, path: &str) -> Message {
        match (purpose, path) {
            // The embedded table (an empty field) is the shipped classic one.
            (Purpose::Table, "") => {
                self.lab.use_shipped(crate::ltc::lut::Table::Classic);
                Message::note("shading with the embedded LUT (classic)")
            }
            (Purpose::TableB, "") => {
                Message::error("as B: name a table file in the field first — table B stays")
            }
            (Purpose::Scene, _) => use_scene(&mut self.lab, Scene::load(Path::new(path)), path),
            (Purpose::Table | Purpose::TableB, _) => {
                let b = purpose == Purpose::TableB;
                match NamedTable::from_file(path) {
                    Ok(loaded) => use_table(&mut self.lab, loaded, b),
                    Err(e) if b => Message::error(format!("{e} — table B stays")),
                    Err(e) => Message::error(format!("{e} — still using the previous table")),
                }
            }
            (Purpose::Study, "") => {
                Message::error("load study: name a study.csv in the field first")
            }
            (Purpose::Study, _) => {
                let rows = crate::measure::study::read_csv(Path::new(path));
                self.panels.use_study(rows, path)
            }
            (Purpose::Method, "") => {
                Message::error("load method: name a .wgsl file in the field first")
            }
            (Purpose::Method, _) => use_method(&mut self.lab, MethodFile::read(Path::new(path))),
            // A shipped lesson's name (where no file has it) opens that lesson.
            (Purpose::Lesson, name)
                if !Path::new(name).exists()
                    && crate::app::lesson::SHIPPED.iter().any(|(n, _)| *n == name) =>
            {
                let (_, text) = crate::app::lesson::SHIPPED
                    .iter()
                    .find(|(n, _)| *n == name)
                    .expect("matched above");
                self.take_lesson(text, name)
            }
            (Purpose::Lesson, _) => {
                match crate::files::read_text(Path::new(path), Purpose::Lesson.max_bytes()) {
                    Ok(text) => self.take_lesson(&text, path),
                    Err(e) => Message::error(format!("load lesson: {e}")),
                }
            }
        }
    }

    /// Writes the scene to the file the user named; the view becomes what the file holds
    /// (its numbers rounded as a person writes them).
    pub(super) fn save_scene(&mut self, path: &Path) {
        let rounded = self.lab.scene().rounded_for_saving();
        if rounded != self.lab.scene() {
            self.lab.use_scene(rounded);
        }
        let text = self.lab.scene().to_toml();
        self.lab
            .say(match save(path, text.as_bytes(), "application/toml") {
                Ok(done) => Message::note(done),
                Err(e) => Message::error(e),
            });
    }

    /// Takes the files dropped on the window this frame: read at once on the desktop; in a
    /// browser, which reads them asynchronously, once they have arrived (`take_picked`).
    pub(super) fn take_dropped(&mut self, ctx: &egui::Context) {
        let files = ctx.input(|i| i.raw.dropped_files.clone());
        if files.is_empty() {
            return;
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let mut given = Vec::new();
            let mut refused = Vec::new();
            for file in files {
                let name = file.path().display().to_string();
                match crate::files::read_bytes(file.path(), Purpose::largest_max_bytes()) {
                    Ok(bytes) => given.push((name, bytes)),
                    Err(e) => refused.push(e.to_string()),
                }
            }
            self.take_given(None, given, refused);
        }
        #[cfg(target_arch = "wasm32")]
        {
            let arrived = crate::app::browser::Picked::default();
            let into = arrived.clone();
            let repaint = ctx.clone();
            wasm_bindgen_futures::spawn_local(async move {
                let mut given = Vec::new();
                for file in files {
                    if let Ok(bytes) = file.bytes_async().await {
                        given.push((file.path().display().to_string(), bytes));
                    }
                }
                *into.borrow_mut() = Some(given);
                repaint.request_repaint();
            });
            self.picking = Some((None, arrived));
        }
    }

    /// Takes what the browser read (picked or dropped files), once it has.
    #[cfg(target_arch = "wasm32")]
    pub(super) fn take_picked(&mut self) {
        let Some((purpose, picked)) = &self.picking else {
            return;
        };
        let Some(files) = picked.borrow_mut().take() else {
            return;
        };
        let purpose = *purpose;
        self.picking = None;
        self.take_given(purpose, files, Vec::new());
    }

    /// Uses given files: all for `purpose`, or (`None`, dropped) each for what its name says;
    /// says what was `refused` before (files that could not be read) with what is refused here.
    fn take_given(
        &mut self,
        purpose: Option<Purpose>,
        files: Vec<Given>,
        mut refused: Vec<String>,
    ) {
        match purpose {
            Some(p) => self.take_in(p, &files),
            None => {
                let (groups, unread) = group(files);
                refused.extend(unread);
                for (p, files) in groups {
                    self.take_in(p, &files);
                }
            }
        }
        if !refused.is_empty() {
            self.lab.say(Message::error(refused.join("; ")));
        }
    }

    /// Uses given files as `purpose` says: the scene, table A or B, the chart's study. A file
    /// that cannot be used changes nothing and says why (its name first).
    fn take_in(&mut self, purpose: Purpose, files: &[Given]) {
        let Some((name, bytes)) = files.first() else {
            return;
        };
        if let Some(e) = files.iter().find_map(|(name, b)| {
            crate::files::check_length(name, b.len(), purpose.max_bytes()).err()
        }) {
            self.lab.say(Message::error(e.to_string()));
            return;
        }
        let text = || String::from_utf8_lossy(bytes).into_owned();
        let message = match purpose {
            Purpose::Scene => use_scene(&mut self.lab, Scene::from_toml(&text(), name), name),
            Purpose::Table | Purpose::TableB => match given_table(files) {
                Ok(loaded) => use_table(&mut self.lab, loaded, purpose == Purpose::TableB),
                Err(e) => Message::error(format!("{e} — the tables stay")),
            },
            Purpose::Study => self
                .panels
                .use_study(crate::measure::study::parse_csv(&text(), name), name),
            Purpose::Lesson => self.take_lesson(&text(), name),
            Purpose::Method => {
                // A dropped file comes with its path: the method is named by its file name.
                let short = Path::new(name)
                    .file_name()
                    .map_or(name.clone(), |n| n.to_string_lossy().into_owned());
                use_method(&mut self.lab, MethodFile::from_bytes(&short, bytes))
            }
        };
        self.lab.say(message);
    }
}

/// Shows `loaded` (the scene read from `name`) from now on; what was done, or why the scene
/// stays.
fn use_scene(lab: &mut Lab, loaded: crate::error::Result<Scene>, name: &str) -> Message {
    let scene = match loaded {
        Ok(scene) => scene,
        Err(e) => return Message::error(e.to_string()),
    };
    lab.dismiss();
    lab.use_scene(scene);
    // What entering the lab refused, clamped or cut is said with the file's name.
    match lab.message() {
        Some(m) if m.is_error => Message::error(format!("loaded {name}; {}", m.text)),
        _ => Message::note(format!("loaded {name}")),
    }
}

/// Shades with `loaded` from now on (on side A, unless a side already has the method file),
/// or says why not: its error names the file's line and column; nothing else changes.
pub(super) fn use_method(lab: &mut Lab, loaded: crate::error::Result<MethodFile>) -> Message {
    match loaded {
        Ok(file) => lab.use_method_file(file),
        Err(e) => Message::error(format!("{e} — the methods stay")),
    }
}

/// Makes `table` (with what its format could not hold, `note`) table A, or B; what was done.
fn use_table(lab: &mut Lab, (table, note): (NamedTable, String), as_b: bool) -> Message {
    let text = if as_b {
        format!("table B is {}{note}", table.name)
    } else {
        format!("shading with {}{note}", table.name)
    };
    if as_b {
        lab.use_table_b(Some(table));
    } else {
        lab.use_table_a(table);
    }
    Message::note(text)
}

/// The table in given files, named for labels, with what its format could not hold.
fn given_table(files: &[Given]) -> Result<(NamedTable, String), String> {
    let loaded = crate::ltc::formats::read_given(files).map_err(|e| e.to_string())?;
    let name = files
        .iter()
        .map(|(n, _)| n.as_str())
        .find(|n| !n.ends_with(crate::ltc::formats::DDS_HEADER_FILE))
        .unwrap_or_default();
    Ok(NamedTable::read(
        loaded,
        name,
        Source::Given(name.to_string()),
    ))
}
