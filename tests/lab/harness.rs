//! The lab as eframe makes it, in a kittest harness drawing with the wgpu device the lab
//! renders on (as eframe's window does), and what a user does to it.

use std::collections::HashMap;
use std::time::{Duration, Instant};

use egui_kittest::kittest::Queryable;
use egui_kittest::wgpu::WgpuTestRenderer;
use egui_kittest::{Harness, SnapshotOptions};
use ltc_lab::app::{LabApp, LabState, PanelId, STORAGE_KEY};
use ltc_lab::render::Frame;

use crate::gpu_common;

/// eframe's storage, in memory: what a previous run left.
#[derive(Default)]
pub struct Kept(HashMap<String, String>);

impl eframe::Storage for Kept {
    fn get_string(&self, key: &str) -> Option<String> {
        self.0.get(key).cloned()
    }

    fn set_string(&mut self, key: &str, value: String) {
        self.0.insert(key.to_string(), value);
    }

    fn remove_string(&mut self, key: &str) {
        self.0.remove(key);
    }

    fn flush(&mut self) {}
}

impl Kept {
    /// A storage holding `state`, as eframe keeps it.
    pub fn state(state: &LabState) -> Self {
        let mut kept = Self::default();
        eframe::set_value(&mut kept, STORAGE_KEY, state);
        kept
    }
}

/// A settled harness showing the lab at `size` started from `state` (with the live GPU
/// times hidden: they change run to run); `None` (loudly) without an adapter.
pub fn lab(size: (f32, f32), state: LabState) -> Option<Harness<'static, LabApp>> {
    gpu_common::gpu()?;
    let mut harness = unsettled(size, state);
    settle(&mut harness);
    Some(harness)
}

/// The same, its first frames run and its work not waited for (the caller has checked that
/// there is an adapter).
pub fn unsettled(size: (f32, f32), state: LabState) -> Harness<'static, LabApp> {
    opened(size, state, None)
}

/// The lab opened on `view` (a link's string) over `state`, not settled.
pub fn opened(
    size: (f32, f32),
    mut state: LabState,
    view: Option<&str>,
) -> Harness<'static, LabApp> {
    // The live GPU times change run to run: off, as a user would for a slide.
    state.plane.show_gpu_times = false;
    opened_from(size, &Kept::state(&state), view)
}

/// The lab eframe starts from the storage `kept` (what a previous run left), with the view
/// `view` over it.
pub fn opened_from(size: (f32, f32), kept: &Kept, view: Option<&str>) -> Harness<'static, LabApp> {
    let render_state = egui_kittest::wgpu::create_render_state(
        ltc_lab::app::device::wgpu_setup(),
        egui_wgpu::RendererOptions::PREDICTABLE,
    );
    let mut cc = eframe::CreationContext::_new_kittest(egui::Context::default());
    cc.wgpu_render_state = Some(render_state.clone());
    cc.storage = Some(kept);
    let app = LabApp::from_creation_context(&cc, view);
    assert!(
        app.lab().device().is_some(),
        "{}",
        app.lab().describe_device()
    );
    let mut frame = eframe::Frame::_new_kittest();
    frame.wgpu_render_state = Some(render_state.clone());
    Harness::builder()
        .with_size(egui::vec2(size.0, size.1))
        .renderer(WgpuTestRenderer::from_render_state(render_state))
        .build_ui_state(
            move |ui, app: &mut LabApp| eframe::App::ui(app, ui, &mut frame),
            app,
        )
}

/// Runs frames until nothing is in flight (the plane summed, a refit or measurement done).
/// Five minutes is far beyond any of these tests' renders on lavapipe (seconds): only a
/// render that never completes reaches it.
pub fn settle(h: &mut Harness<'static, LabApp>) {
    let start = Instant::now();
    h.run_steps(2);
    while h.state().busy() {
        assert!(
            start.elapsed() < Duration::from_secs(300),
            "the lab never settled: {:?}",
            h.state().report()
        );
        h.step();
        std::thread::sleep(Duration::from_millis(1));
    }
    h.run_steps(2);
}

/// A primary click at `at`, as a pointer would: move there, press, release.
pub fn click_at(h: &mut Harness<'static, LabApp>, at: egui::Pos2) {
    h.hover_at(at);
    h.run_steps(1);
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: at,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: Default::default(),
        });
        h.run_steps(1);
    }
}

/// A press at `start`, ten moves to `end` a frame each, and the release there.
pub fn drag_along(h: &mut Harness<'static, LabApp>, start: egui::Pos2, end: egui::Pos2) {
    h.drag_at(start);
    h.run_steps(1);
    for k in 1..=10 {
        h.hover_at(start + (end - start) * (k as f32 / 10.0));
        h.run_steps(1);
    }
    h.drop_at(end);
}

/// Presses the button labelled `label`, scrolled into view first with the mouse wheel over
/// it (the side panel scrolls in a small window).
pub fn press(h: &mut Harness<'static, LabApp>, label: &str) {
    let window = h.ctx.input(egui::InputState::viewport_rect);
    for _ in 0..50 {
        let rect = h.get_by_label(label).rect();
        if window.contains_rect(rect) {
            break;
        }
        h.hover_at(egui::pos2(rect.center().x, window.center().y));
        h.event(egui::Event::MouseWheel {
            unit: egui::MouseWheelUnit::Point,
            delta: egui::vec2(0.0, -60.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Unknown,
            modifiers: egui::Modifiers::NONE,
        });
        h.run_steps(2);
    }
    h.get_by_label(label).click();
}

/// Types `text` into the field named `name` (a screen reader's way: its value set).
pub fn type_into(h: &mut Harness<'static, LabApp>, name: &str, text: &str) {
    // Scrolled to first, as a user would: a field scrolled out of the side panel takes no
    // text.
    h.get_by_label(name).scroll_to_me();
    h.run_steps(2);
    h.get_by_label(name).set_text_value_accesskit(text);
    h.run_steps(1);
}

/// Sets the slider labelled `label` to `value` (a screen reader's way) and settles.
pub fn slide(h: &mut Harness<'static, LabApp>, label: &str, value: f64) {
    use egui::accesskit::Role;
    h.get_by_role_and_label(Role::Slider, label)
        .set_value_accesskit(value);
    h.run_steps(1);
}

/// The plane's finished image as the user saves it: `screenshot` with an `.exr` name writes
/// the plane's linear radiance there. Returned as a frame of its pixels (RGB, as f64 from
/// the file's f32, which are the GPU's own values); the plane off the image is 0.
pub fn plane_image(h: &mut Harness<'static, LabApp>) -> Frame {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("plane.exr");
    type_into(h, "screenshot file", &path.display().to_string());
    press(h, "screenshot");
    let start = Instant::now();
    while !path.exists() {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "the plane's image was never saved to {path:?}: {:?}",
            h.state().report()
        );
        h.step();
    }
    h.run_steps(1);
    read_exr(&path)
}

/// An RGB f32 EXR as a frame.
pub fn read_exr(path: &std::path::Path) -> Frame {
    use exr::prelude::*;
    let image = read_first_rgba_layer_from_file(
        path,
        |size, _| {
            (
                size.width(),
                vec![glam::DVec3::ZERO; size.width() * size.height()],
            )
        },
        |(w, pixels), pos, (r, g, b, _): (f32, f32, f32, f32)| {
            pixels[pos.y() * *w + pos.x()] =
                glam::DVec3::new(f64::from(r), f64::from(g), f64::from(b));
        },
    )
    .unwrap();
    let size = image.layer_data.size;
    let (_, pixels) = image.layer_data.channel_data.pixels;
    Frame {
        width: size.width(),
        height: size.height(),
        kind: ltc_lab::render::FrameKind::Radiance,
        on_plane: vec![true; pixels.len()],
        pixels,
        divider: None,
    }
}

/// lavapipe renders bit-identically run to run; the threshold (kittest's default colour
/// distance) and 0.2% of the pixels absorb antialiasing changes of another Mesa version,
/// while a blank, garbled or re-laid-out panel changes far more than that.
pub fn options(pixels: usize) -> SnapshotOptions {
    SnapshotOptions::new().max_failed_pixels(pixels / 500)
}

/// The default state with panel `id` shown alone.
pub fn maximised(id: PanelId) -> LabState {
    let mut state = LabState::default();
    state.window.maximised = Some(id);
    state
}

/// The plane's state for the render tests: maximised, split (both methods shaded), `lights`
/// from the lab's generator, so that the pacer, which starts at one light per chunk and at
/// most doubles, needs many frames.
pub fn plane_state(lights: usize) -> LabState {
    let mut state = maximised(PanelId::Plane);
    state.plane.view = ltc_lab::render::View::Split;
    with_lights(&mut state, lights);
    state
}

/// `state` with `count` lights from the lab's generator, as the lights slider makes them.
pub fn with_lights(state: &mut LabState, count: usize) {
    let list = state.lab.generated_lights(count);
    let seed = state.lab.lights.seed;
    state.lab.lights = ltc_lab::app::lab::Part::new(ltc_lab::app::lab::Lights { list, seed });
}

/// The notices bar's line, if any.
pub fn notice(h: &Harness<'static, LabApp>) -> Option<ltc_lab::app::Message> {
    h.state().lab().message().cloned()
}

/// Whether a text containing `text` is shown.
pub fn shows(h: &Harness<'static, LabApp>, text: &str) -> bool {
    h.query_by_label_contains(text).is_some()
}

/// A file from the disk, as eframe hands a dropped one to the app.
#[derive(Debug)]
struct DroppedFromDisk(std::path::PathBuf);

impl egui::DroppedFile for DroppedFromDisk {
    fn path(&self) -> &std::path::Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// `path` dropped on the window.
pub fn drop_file(h: &mut Harness<'static, LabApp>, path: &std::path::Path) {
    h.input_mut()
        .dropped_files
        .push(std::sync::Arc::new(DroppedFromDisk(path.to_path_buf())));
    h.run_steps(2);
}

/// The failure preset `name` of lights with a size, picked from the side panel's list.
pub fn load_sized_preset(h: &mut Harness<'static, LabApp>, name: &str) {
    h.get_by_label("lights with a size").click();
    h.run_steps(2);
    h.get_by_label(name).click();
    settle(h);
}
