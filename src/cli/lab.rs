//! `ltc-lab lab` (and `ltc-lab` alone): the window; with `--screenshot`, a few frames saved to
//! a PNG, then exit.

use std::path::{Path, PathBuf};

use ltc_lab::app::{LabApp, LabState, PanelId, ScreenshotApp};
use ltc_lab::error::{Error, Result};
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
    PanelId::ALL
        .into_iter()
        .find(|p| p.name() == s)
        .map(|p| Panels(Some(p)))
        .ok_or_else(|| {
            let names: Vec<&str> = PanelId::ALL.iter().map(|p| p.name()).collect();
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
    /// Window size, WxH.
    #[arg(long, default_value = "1600x900", value_parser = parse_size)]
    size: (usize, usize),
    /// Start with this scene instead of the saved state.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// Fill the speed-vs-accuracy chart before showing (as its "measure" button does).
    #[arg(long)]
    measure: bool,
}

impl Default for Args {
    /// `ltc-lab` with no subcommand: the lab as `lab` with every default.
    fn default() -> Self {
        Self {
            screenshot: None,
            panel: Panels(None),
            size: DEFAULT_SIZE,
            scene: None,
            measure: false,
        }
    }
}

pub fn run(a: Args) -> Result<()> {
    let scene = a.scene.as_deref().map(Scene::load).transpose()?;
    if let Some(p) = &a.screenshot {
        check_screenshot_path(p)?;
    }
    let (w, h) = a.size;
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("LTC Lab")
            .with_inner_size([w as f32, h as f32]),
        renderer: eframe::Renderer::Wgpu,
        // A screenshot shows the defaults, not whatever the last session left.
        persist_window: a.screenshot.is_none(),
        ..Default::default()
    };
    let panel = a.panel.0;
    let measure = a.measure;
    let configure = move |mut state: LabState| {
        if let Some(sc) = &scene {
            state.light_count = sc.lights.len();
            state.scene = sc.clone();
        }
        if panel.is_some() {
            state.maximised = panel;
        }
        state
    };
    let prepare = move |mut app: LabApp| {
        if measure {
            app.chart.measure_now(&app.state.shaded_scene(), &app.lut);
        }
        app
    };
    let outcome = match a.screenshot {
        Some(path) => {
            let shot =
                ScreenshotApp::new(prepare(LabApp::new(configure(LabState::default()))), path);
            let result = shot.result.clone();
            let run = eframe::run_native(
                "LTC Lab (screenshot)",
                options,
                Box::new(move |_cc| Ok(Box::new(shot))),
            );
            let taken = result.lock().expect("not poisoned").take();
            match (run, taken) {
                (Ok(()), Some(outcome)) => outcome,
                (Ok(()), None) => Err("the window closed before the screenshot".into()),
                (Err(e), _) => Err(e.to_string()),
            }
        }
        None => eframe::run_native(
            "LTC Lab",
            options,
            Box::new(move |cc| {
                let mut app = LabApp::from_creation_context(cc);
                app.state = configure(app.state);
                Ok(Box::new(prepare(app)))
            }),
        )
        .map_err(|e| e.to_string()),
    };
    outcome.map_err(|e| Error::machine("lab", format!("cannot open the window: {e}")))
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
