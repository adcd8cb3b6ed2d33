//! What the panels share, and the one way they say that it changed. Each edit names the
//! aspect it touches (`Lab::edit`); each aspect counts its edits; a panel that keeps work made
//! from the lab (a render, heat maps, a pixel's lights) keeps the `Stamp` of the aspects it
//! read, and makes it again when the stamp moves. A panel's own settings are its own.

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use crate::app::refit::RefitResult;
use crate::gpu::GpuContext;
use crate::ltc::lobe::Lobe;
use crate::ltc::lut::{Lut, THETA_MAX, Table};
use crate::ltc::remedy::{Horizon, HorizonRule};
use crate::ltc::{Clipping, Ltc, LtcPair, Normalization};
use crate::render::{LtcRules, LutFilter, Method};
use crate::scene::{Scene, preset};
use crate::tables::{NamedTable, NamedTables};

/// paper-100's light count (assets/scenes/paper-100.toml), whose intensities the light-count
/// slider's lights share.
const PAPER_LIGHT_COUNT: f64 = 100.0;

/// Every panel: it draws itself into `ui`, reads and edits the lab, and keeps its own state.
pub trait Panel {
    fn show(&mut self, ui: &mut egui::Ui, lab: &mut Lab);
}

/// What the plane's side B is: the exact BRDF, or LTC with table B (two tables compared).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Compare {
    #[default]
    Brdf,
    TableB,
}

/// The parts of the lab an edit may change, each with its own count of edits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Aspect {
    /// The scene: material, lights, plane, camera (not its exposure).
    Scene,
    /// The scene's exposure: how the plane is shown, not what it sums.
    Exposure,
    /// How the plane shades its lights: the methods, the global intensity and range, culling,
    /// and what side B is.
    Shading,
    /// Eq. 30's clipping rules and the normalization: what the clipping panel and the
    /// elevation view read too (the plane's intensity did not need to redraw them).
    Rules,
    /// The lobe and matrix panels' view: θo and which lobe.
    LobeView,
    /// The selected light and the light shown on the lobe panel.
    Selection,
    /// Tables A and B.
    Tables,
    /// The matrix panel's last refit.
    Refit,
}

impl Aspect {
    const COUNT: usize = 8;
}

/// The sum of some aspects' edit counts: counts only grow, so any edit of one of them moves
/// it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stamp(u64);

/// What an edit's closure returns, saying whether it changed anything: a widget's response,
/// a flag, or nothing (an edit that always changes).
pub trait Edited {
    fn changed(&self) -> bool;
}

impl Edited for bool {
    fn changed(&self) -> bool {
        *self
    }
}

impl Edited for () {
    fn changed(&self) -> bool {
        true
    }
}

impl Edited for egui::Response {
    fn changed(&self) -> bool {
        egui::Response::changed(self)
    }
}

/// A line in the notices bar: a notice, or an error (shown in red).
#[derive(Clone, Debug, PartialEq)]
pub struct Message {
    pub is_error: bool,
    pub text: String,
}

impl Message {
    pub fn note(text: impl Into<String>) -> Self {
        Self {
            is_error: false,
            text: text.into(),
        }
    }

    pub fn error(text: impl Into<String>) -> Self {
        Self {
            is_error: true,
            text: text.into(),
        }
    }
}

/// A file the user named, to be written by the app (which holds the window and the render).
#[derive(Clone, Debug, PartialEq)]
pub enum Request {
    /// The plane's linear radiance, as EXR.
    SaveExr(PathBuf),
    /// The window, as PNG.
    Screenshot(PathBuf),
    /// The view as a link (the page's address in a browser; `ltc-lab lab --view` on the
    /// desktop), copied to the clipboard.
    Share,
    /// The browser's file picker, for a file of this purpose (where a desktop reads a path).
    Pick(crate::app::file_io::Purpose),
}

/// What more than one panel reads; persisted by eframe between runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Shared {
    pub scene: Scene,
    /// θo of the lobe and matrix panels, degrees.
    pub theta_o_deg: f64,
    /// The lobe the lobe and matrix panels show.
    pub lobe: Lobe,
    /// The LTC and BRDF forms compared in the plane panel (and timed by the chart).
    pub method_ltc: Method,
    pub method_brdf: Method,
    pub clipping: Clipping,
    pub normalization: Normalization,
    /// What the LTC methods do for lights near the horizon (the `nl-fit` and `exact-band`
    /// remedies; the fitted ones are tables).
    pub horizon: HorizonRule,
    /// Multiplies every light's intensity when shading.
    pub intensity_scale: f64,
    /// Replaces every light's range when > 0.
    pub range_override: f64,
    /// Tiled culling of ranged lights in the plane's render (the same image, faster).
    pub cull: bool,
    /// The plane's side B.
    pub compare: Compare,
    /// The light generator's seed.
    pub seed: u64,
    pub selected_light: Option<usize>,
    /// A light of the pinned pixel shown on the lobe panel: ω in the shading frame.
    pub lobe_light: Option<[f64; 3]>,
    /// Which shipped table shades (classic or the point-light fit), unless `table_file`.
    pub table: Table,
    /// The file table A was loaded from; read again at the next start.
    pub table_file: Option<String>,
    /// The file table B was loaded from (*as B*); read again at the next start.
    pub table_b_file: Option<String>,
    /// The matrix panel's last refit, which the lobe panel draws while its cell is chosen.
    pub refit: Option<RefitResult>,
}

impl Default for Shared {
    fn default() -> Self {
        Self {
            scene: preset("paper-100"),
            theta_o_deg: 45.0,
            lobe: Lobe::Specular,
            method_ltc: Method::LtcFast,
            method_brdf: Method::Brdf,
            clipping: Clipping::BOTH,
            normalization: Normalization::Corrected,
            horizon: HorizonRule::Eq30,
            intensity_scale: 1.0,
            range_override: 0.0,
            cull: true,
            compare: Compare::Brdf,
            seed: 27,
            selected_light: None,
            lobe_light: None,
            table: Table::Classic,
            table_file: None,
            table_b_file: None,
            refit: None,
        }
    }
}

impl Shared {
    pub fn alpha(&self) -> f64 {
        self.scene.material.alpha
    }

    /// The scene as shaded: global intensity and range applied.
    pub fn shaded_scene(&self) -> Scene {
        let mut s = self.scene.clone();
        for l in &mut s.lights {
            l.intensity *= self.intensity_scale;
            if self.range_override > 0.0 {
                l.range = Some(self.range_override);
            }
        }
        s
    }

    /// The horizon remedy in use: the rule's, or the remedy whose table shades.
    pub fn horizon_remedy(&self) -> Horizon {
        let by_table = Horizon::ALL
            .into_iter()
            .find(|h| self.table_file.is_none() && h.table() == Some(self.table));
        match self.horizon {
            HorizonRule::Eq30 => by_table.unwrap_or(Horizon::Eq30),
            HorizonRule::NlFit => Horizon::NlFit,
            HorizonRule::ExactBand => Horizon::ExactBand,
        }
    }

    /// What the plane's LTC shades by, as the lab sets it (the table read bilinearly).
    pub fn ltc_rules(&self) -> LtcRules {
        LtcRules {
            clipping: self.clipping,
            normalization: self.normalization,
            filter: LutFilter::Bilinear,
            horizon: self.horizon,
        }
    }

    /// θo in radians, within the tables' rows.
    pub fn theta_o(&self) -> f64 {
        self.theta_o_deg.to_radians().min(THETA_MAX)
    }

    /// The LTC pair of the lobe and matrix panels' (θo, α).
    pub fn ltc_pair(&self, lut: &Lut) -> LtcPair {
        lut.sample(self.alpha(), self.theta_o().cos()).ltc_pair()
    }

    /// `count` lights from the seeded generator (heights 0.05–0.6, paper-100's intensities
    /// and range) in place of the scene's.
    pub fn set_light_count(&mut self, count: usize) {
        // paper-100's intensities, scaled down past 100 lights so that the total power stays
        // paper-100's: 20 000 lights at those intensities only show a white plane.
        let dim = (PAPER_LIGHT_COUNT / count.max(1) as f64).min(1.0);
        self.scene.lights = crate::scene::generate_lights(
            &crate::scene::RandomLights {
                count,
                seed: self.seed,
                height: [0.05, 0.6],
                intensity: [0.02 * dim, 0.08 * dim],
                range: Some(crate::bench::DEFAULT_RANGE),
            },
            self.scene.plane.half_size,
        );
    }

    /// The cell of `lut` nearest (θo, α): (column of α, row of θo).
    pub fn nearest_cell(&self, lut: &Lut) -> (usize, usize) {
        let n = lut.size;
        let (u, v) = (
            self.alpha().sqrt(),
            (1.0 - self.theta_o().cos()).max(0.0).sqrt(),
        );
        let at = |x: f64| ((x * (n - 1) as f64).round() as usize).min(n - 1);
        (at(u), at(v))
    }
}

/// The lab the panels share: its settings, its tables, its device, and its notices.
pub struct Lab {
    shared: Shared,
    tables: NamedTables,
    revisions: [u64; Aspect::COUNT],
    /// The device the plane is shaded and the chart measured on; `None`: the CPU.
    pub gpu: Option<GpuContext>,
    /// Why there is no GPU, for the window.
    pub gpu_error: Option<String>,
    /// The last error or notice, for the notices bar.
    pub message: Option<Message>,
    /// A file to write, for the app.
    pub request: Option<Request>,
}

impl Lab {
    pub fn new(shared: Shared, tables: NamedTables, gpu: Result<GpuContext, String>) -> Self {
        let (gpu, gpu_error) = match gpu {
            Ok(g) => (Some(g), None),
            Err(e) => (None, Some(e)),
        };
        Self {
            shared,
            tables,
            revisions: [0; Aspect::COUNT],
            gpu,
            gpu_error,
            message: None,
            request: None,
        }
    }

    pub fn shared(&self) -> &Shared {
        &self.shared
    }

    pub fn tables(&self) -> &NamedTables {
        &self.tables
    }

    /// Edits the shared settings through `f`, counting an edit of `aspect` where what `f`
    /// returns says that it changed something.
    pub fn edit<R: Edited>(&mut self, aspect: Aspect, f: impl FnOnce(&mut Shared) -> R) -> R {
        let r = f(&mut self.shared);
        if r.changed() {
            self.touch(aspect);
        }
        r
    }

    /// The stamp of `aspects`: equal to an earlier one only if none of them was edited since.
    pub fn stamp(&self, aspects: &[Aspect]) -> Stamp {
        Stamp(aspects.iter().map(|&a| self.revisions[a as usize]).sum())
    }

    fn touch(&mut self, aspect: Aspect) {
        self.revisions[aspect as usize] += 1;
    }

    /// The device in words, or why there is none.
    pub fn describe_device(&self) -> String {
        match (&self.gpu, &self.gpu_error) {
            (Some(g), _) => g.describe(),
            (None, Some(e)) => format!("no GPU: {e}"),
            (None, None) => "no GPU".into(),
        }
    }

    /// The most lights the plane shades at once: the GPU's limit, or the scene's on the CPU.
    pub fn max_lights(&self) -> usize {
        self.gpu.as_ref().map_or(crate::scene::MAX_LIGHTS, |g| {
            crate::gpu::renderer::PlaneRenderer::max_lights(g)
        })
    }

    /// Shows `scene` (a preset, a loaded file, the one the lab started with), its lights cut
    /// to what this adapter shades, which it then says; the light selection is cleared, as it
    /// may name a light the new scene lacks.
    pub fn use_scene(&mut self, scene: Scene) -> Option<String> {
        self.edit(Aspect::Scene, |s| s.scene = scene);
        self.edit(Aspect::Selection, |s| s.selected_light = None);
        self.keep_lights()
    }

    /// Cuts the scene's lights to what this adapter shades, and says so.
    pub fn keep_lights(&mut self) -> Option<String> {
        let max = self.max_lights();
        let held = self.shared.scene.lights.len();
        if held <= max {
            return None;
        }
        self.edit(Aspect::Scene, |s| s.scene.lights.truncate(max));
        self.edit(Aspect::Selection, |s| {
            s.selected_light = s.selected_light.filter(|&k| k < max);
        });
        Some(format!(
            "the scene holds {held} lights, more than the {max} this adapter shades at once: the first {max} are kept"
        ))
    }

    /// `count` lights from the seeded generator, as the lights slider makes them; they
    /// replace the current ones (and the selection goes).
    pub fn set_light_count(&mut self, count: usize) {
        self.edit(Aspect::Scene, |s| s.set_light_count(count));
        self.edit(Aspect::Selection, |s| s.selected_light = None);
    }

    /// Shades with the shipped table `t` from now on (table B follows, unless chosen).
    pub fn use_shipped(&mut self, t: Table) {
        self.edit(Aspect::Tables, |s| {
            s.table = t;
            s.table_file = None;
        });
        self.use_table_a(NamedTable::shipped(t));
    }

    /// Shades with a horizon remedy from now on: its table where it is one (a remedy's
    /// table leaves for the classic one under another remedy), else its rule on table A.
    pub fn use_horizon(&mut self, remedy: Horizon) {
        let own = |t: Table| Horizon::ALL.iter().any(|h| h.table() == Some(t));
        let table = match remedy.table() {
            Some(t) => Some(t),
            None if self.shared.table_file.is_none() && own(self.shared.table) => {
                Some(Table::Classic)
            }
            None => None,
        };
        if let Some(t) =
            table.filter(|&t| t != self.shared.table || self.shared.table_file.is_some())
        {
            self.use_shipped(t);
        }
        self.edit(Aspect::Rules, |s| s.horizon = remedy.rule());
    }

    /// Shades with the table read from `file` from now on; read again at the next start
    /// (`None`: bytes a browser's picker or a drop gave, which no later start can read).
    pub fn use_file(&mut self, table: NamedTable, file: Option<String>) {
        self.edit(Aspect::Tables, |s| s.table_file = file);
        self.use_table_a(table);
    }

    fn use_table_a(&mut self, a: NamedTable) {
        // A chosen table B stays; else it follows A to A's other.
        let chosen = self.tables.b_chosen.then(|| self.tables.b.clone());
        self.tables = NamedTables::with_a(a, self.shared.table);
        if let Some(b) = chosen {
            self.tables.b = b;
            self.tables.b_chosen = true;
        }
        self.touch(Aspect::Tables);
    }

    /// Compares with the table read from `file` as table B from now on; read again at the
    /// next start.
    pub fn use_file_b(&mut self, table: NamedTable, file: Option<String>) {
        self.edit(Aspect::Tables, |s| s.table_b_file = file);
        self.tables.b = table;
        self.tables.b_chosen = true;
        self.touch(Aspect::Tables);
    }

    /// Table B back to the other shipped table.
    pub fn reset_table_b(&mut self) {
        self.edit(Aspect::Tables, |s| s.table_b_file = None);
        self.tables.b = NamedTable::shipped(self.shared.table.default_b());
        self.tables.b_chosen = false;
        self.touch(Aspect::Tables);
    }

    /// The refitted lobe, while the chosen cell of table A is the one refitted.
    pub fn refit_ltc(&self) -> Option<(Lobe, Ltc)> {
        let r = self.shared.refit.as_ref()?;
        (r.cell == self.shared.nearest_cell(&self.tables.a.lut)).then(|| (r.lobe, r.ltc()))
    }

    /// Says `message` in the notices bar.
    pub fn say(&mut self, message: Message) {
        self.message = Some(message);
    }
}
