//! `ltc-lab lab` (and `ltc-lab` alone): the window; with `--screenshot`, a few frames saved to
//! a PNG, then exit.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use ltc_lab::app::lesson::Lesson;
use ltc_lab::app::link;
use ltc_lab::app::screenshot::frame_log_csv;
use ltc_lab::app::{LabApp, LabState, PanelId, ScreenshotApp, Startup};
use ltc_lab::error::{Error, Result};
use ltc_lab::gpu::driver_output;
use ltc_lab::scene::Scene;

use super::parse_size;

/// The window's size unless `--size` says otherwise.
const DEFAULT_SIZE: (usize, usize) = (1600, 900);

/// `--panel`: one panel maximised, or all of them (`None`).
#[derive(Clone, Copy, Debug)]
pub struct Panels(Option<PanelId>);

fn parse_panel(s: &str) -> std::result::Result<Panels, String> {
    if s == "all" {
        return Ok(Panels(None));
    }
    PanelId::of_name(s).map(|p| Panels(Some(p))).ok_or_else(|| {
        let names: Vec<&str> = PanelId::GRID.iter().map(|p| p.name()).collect();
        format!("'{s}' is not a panel: {} or all", names.join(", "))
    })
}

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Render a few frames, save the window's pixels to this PNG and exit.
    #[arg(long)]
    screenshot: Option<PathBuf>,
    /// Show one panel maximised: lobe, matrix, plane, clipping, chart, or all five.
    #[arg(long, value_parser = parse_panel, default_value = "all")]
    panel: Panels,
    /// Window size, WxH [default: the last session's, or 1600x900].
    #[arg(long, value_parser = parse_size)]
    size: Option<(usize, usize)>,
    /// Start with this scene instead of the saved state.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// Fill the speed-vs-accuracy chart (as its "measure" button does; the screenshot waits
    /// for it).
    #[arg(long)]
    measure: bool,
    /// Start with this many lights from the seeded generator (as the lights slider makes
    /// them).
    #[arg(long)]
    lights: Option<usize>,
    /// Open this view: a string the lab's *share view* copied, or a browser link (or its
    /// `#view=…` part).
    #[arg(long)]
    view: Option<String>,
    /// Walk a lesson: a shipped one's name (paper, polygon) or a lesson file (.lesson.toml).
    #[arg(long, conflicts_with_all = ["view", "scene", "lights", "panel"])]
    lesson: Option<String>,
    /// A method of your own to shade with: a WGSL file under the interface of
    /// docs/design.md §5.13, on the plane's left side (the method `file`).
    #[arg(long)]
    method_file: Option<PathBuf>,
    /// With --lesson: the step to open it at, from 1.
    #[arg(long, requires = "lesson")]
    step: Option<usize>,
    /// With --screenshot: write one row per UI frame to this CSV
    /// (frame,ms,render_in_flight,lights_done,lights_total).
    #[arg(long, requires = "screenshot")]
    frame_log: Option<PathBuf>,
}

impl Default for Args {
    /// `ltc-lab` with no subcommand: the lab as `lab` with every default.
    fn default() -> Self {
        Self {
            screenshot: None,
            panel: Panels(None),
            size: None,
            scene: None,
            measure: false,
            lights: None,
            view: None,
            lesson: None,
            method_file: None,
            step: None,
            frame_log: None,
        }
    }
}

pub fn run(a: &Args) -> Result<()> {
    let Checked {
        startup,
        broken_view,
    } = check(a)?;
    let options = window_options(a);
    // eframe restores the last session's window size even where `persist_window` is off: a
    // size asked for (or a screenshot's) is set again once the window is open.
    let asked = (a.size.is_some() || a.screenshot.is_some())
        .then_some(options.viewport.inner_size)
        .flatten();
    // Drivers print while eframe opens the window's adapter (gpu::driver_output says what):
    // held back until the app is made, then dropped; handed to the error if the window
    // cannot open, or closes before the app is made.
    driver_output::hold();
    match &a.screenshot {
        Some(path) => {
            screenshot(
                path.clone(),
                a.frame_log.as_deref(),
                a.view.clone(),
                options,
                (startup, asked),
            )?;
            broken_view.map_or(Ok(()), Err)
        }
        None => {
            let view = a.view.clone();
            eframe::run_native(
                "LTC Lab",
                options,
                Box::new(move |cc| {
                    window_opened();
                    keep_driver_loaded(cc);
                    keep_asked_size(cc, asked);
                    let mut app = LabApp::from_creation_context(cc, view.as_deref());
                    app.start_with(startup);
                    Ok(Box::new(app))
                }),
            )
            .map_err(|e| window_error(&format!("cannot open the window: {e}")))
        }
    }
}

/// What the command line asks of the window, checked before it opens.
struct Checked {
    startup: Startup,
    /// A lesson's step whose view does not open: the window shows it with why; a screenshot
    /// of it is taken, then refused with this.
    broken_view: Option<Error>,
}

/// Every argument checked before a window opens: files that must be read or written, the
/// light count, the view, the lesson and its step.
fn check(a: &Args) -> Result<Checked> {
    let scene = a.scene.as_deref().map(Scene::load).transpose()?;
    if let Some(p) = &a.screenshot {
        check_screenshot_path(p)?;
    }
    if let Some(p) = &a.frame_log {
        ltc_lab::files::check_writable(p)?;
    }
    if let (Some(shot), Some(log)) = (&a.screenshot, &a.frame_log) {
        ltc_lab::files::check_distinct(&[("--screenshot", shot), ("--frame-log", log)])?;
    }
    if let Some(n) = a.lights.filter(|&n| n > ltc_lab::scene::MAX_LIGHTS) {
        return Err(Error::input(
            "--lights",
            format!(
                "{n} is more than the {} a scene may hold",
                ltc_lab::scene::MAX_LIGHTS
            ),
        ));
    }
    // A string that is not a view is refused before any window opens; what a view holds is
    // checked where it enters the lab, and what was refused or clamped is said there.
    if let Some(v) = &a.view {
        link::decode(v, &LabState::default()).map_err(|why| Error::input("--view", why))?;
    }
    let lesson = a
        .lesson
        .as_deref()
        .map(|l| open_lesson(l, a.step))
        .transpose()?;
    let broken_view = lesson.as_ref().and_then(|(lesson, name, k)| {
        let why = lesson.steps[*k].view.open(&LabState::default()).err()?;
        Some(Error::input(
            "--lesson",
            format!(
                "{name}: step {}'s view does not open ({why}); the screenshot shows the step without it",
                k + 1
            ),
        ))
    });
    // What the command line asked for, over the kept state (or the defaults).
    let startup = Startup {
        scene,
        lights: a.lights,
        panel: a.panel.0,
        measure: a.measure,
        lesson,
        method_file: a
            .method_file
            .as_deref()
            .map(ltc_lab::gpu::method_file::MethodFile::read)
            .transpose()?,
    };
    Ok(Checked {
        startup,
        broken_view,
    })
}

/// The window eframe opens: its title and size, on wgpu with the lab's device set-up.
fn window_options(a: &Args) -> eframe::NativeOptions {
    let (w, h) = a.size.unwrap_or(DEFAULT_SIZE);
    eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("LTC Lab")
            // Names eframe's store too; the lab keeps no egui memory there
            // (`LabApp::persist_egui_memory`), so a kept zoom cannot size a window.
            .with_app_id("ltc-lab")
            .with_inner_size([w as f32, h as f32]),
        renderer: eframe::Renderer::Wgpu,
        wgpu_options: egui_wgpu::WgpuConfiguration {
            wgpu_setup: ltc_lab::app::device::wgpu_setup(),
            ..Default::default()
        },
        // A screenshot shows the defaults, not whatever the last session left; a size asked
        // for wins over the last session's.
        persist_window: a.screenshot.is_none() && a.size.is_none(),
        ..Default::default()
    }
}

/// The window at the size asked for: eframe 0.37 applies the last session's stored size
/// whatever `persist_window` says, so the size is asked again once the window exists.
fn keep_asked_size(cc: &eframe::CreationContext<'_>, asked: Option<egui::Vec2>) {
    if let Some(size) = asked {
        cc.egui_ctx
            .send_viewport_cmd(egui::ViewportCommand::InnerSize(size));
    }
}

/// The window opened: what the drivers said while it did is dropped.
fn window_opened() {
    drop(driver_output::give_back());
}

/// The window failed: `why`, with what the drivers said while it opened.
fn window_error(why: &str) -> Error {
    let said = driver_output::as_note(&driver_output::give_back());
    Error::machine("lab", format!("{why}{said}"))
}

/// The window's pixels, once its work is done, to `path` (and its frames to `frame_log`).
fn screenshot(
    path: PathBuf,
    frame_log: Option<&Path>,
    view: Option<String>,
    options: eframe::NativeOptions,
    (startup, asked): (Startup, Option<egui::Vec2>),
) -> Result<()> {
    let result = Arc::new(Mutex::new(None));
    let frames = Arc::new(Mutex::new(Vec::new()));
    let (slot, log) = (result.clone(), frames.clone());
    let run = eframe::run_native(
        "LTC Lab (screenshot)",
        options,
        Box::new(move |cc| {
            window_opened();
            keep_driver_loaded(cc);
            keep_asked_size(cc, asked);
            // A screenshot shows the defaults (or the view, checked above), not whatever the
            // last session kept.
            let defaults = LabState::default();
            let state = match &view {
                Some(v) => link::decode(v, &defaults).unwrap_or(defaults),
                None => defaults,
            };
            let mut app = LabApp::new(state, cc.wgpu_render_state.as_ref());
            app.start_with(startup);
            let mut shot = ScreenshotApp::new(app, path);
            shot.result = slot;
            shot.frames = log;
            Ok(Box::new(shot))
        }),
    );
    if let Some(p) = frame_log {
        let records = frames.lock().expect("not poisoned");
        ltc_lab::files::write_atomically(p, frame_log_csv(&records).as_bytes())?;
    }
    let taken = result.lock().expect("not poisoned").take();
    // The screenshot's own error keeps its kind: a path that cannot be written is the user's
    // to fix (exit 2), as in every command.
    match (run, taken) {
        (Ok(()), Some(outcome)) => outcome,
        (Ok(()), None) => Err(window_error("the window closed before the screenshot")),
        (Err(e), _) => Err(window_error(&format!("cannot open the window: {e}"))),
    }
}

/// The window's driver is not unloaded before the process exits (gpu::keep_driver says why).
fn keep_driver_loaded(cc: &eframe::CreationContext<'_>) {
    if let Some(rs) = &cc.wgpu_render_state {
        ltc_lab::gpu::keep_driver::keep_driver_loaded(&rs.device);
    }
}

/// The lesson `--lesson` names, and the step `--step` asks for (from 1), as the lab opens
/// them: a lesson that does not read, or a step it lacks, is refused before a window opens.
fn open_lesson(name: &str, step: Option<usize>) -> Result<(Lesson, String, usize)> {
    let lesson = Lesson::open(name).map_err(|why| Error::input("--lesson", why))?;
    let step = match step {
        None => 0,
        Some(k) => lesson
            .step_index(k)
            .map_err(|why| Error::input("--step", why))?,
    };
    Ok((lesson, name.to_string(), step))
}

/// A screenshot is a PNG in an existing directory.
fn check_screenshot_path(p: &Path) -> Result<()> {
    if !p.extension().is_some_and(|e| e.eq_ignore_ascii_case("png")) {
        return Err(Error::input(
            p.display().to_string(),
            "the screenshot must be a .png",
        ));
    }
    ltc_lab::files::check_writable(p)
}
