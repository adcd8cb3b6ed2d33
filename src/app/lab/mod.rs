//! What the panels share, and the only doors it changes through. Each shared thing is a part
//! of its own type (`parts`): a panel reads a part (`lab.material()`), and writes one only by
//! naming its type in `Lab::edit` or `Lab::set`, which check what enters and stamp the part.
//! Work made from parts keys on the parts it reads (`app::work::cache`). A panel's own settings are
//! its own.

mod light_check;
pub mod part;
pub mod parts;
pub mod refit_result;
pub mod tables;

use glam::DVec3;
use serde::{Deserialize, Serialize};

pub use part::{Checked, Part, Stamp};
pub use parts::{
    DiskForms, Exposure, Forms, LastRefit, Lights, LobeView, Overrides, RectForms, Selection,
    SideB, SphereForms, Stage,
};
pub use tables::{TableId, TableSources, Tables};

use crate::gpu::GpuContext;
use crate::gpu::method_file::MethodFile;
use crate::ltc::lut::{THETA_MAX, Table};
use crate::ltc::remedy::{Horizon, HorizonRule};
use crate::ltc::{Ltc, LtcPair};
use crate::render::{LtcRules, Method};
use crate::scene::{Light, Material, Scene};
use crate::tables::NamedTable;

/// paper-100's light count (assets/scenes/paper-100.toml), whose intensities the light-count
/// slider's lights share.
const PAPER_LIGHT_COUNT: f64 = 100.0;

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

/// Something a panel asks the app to do: what reaches beyond the lab (files, the clipboard,
/// the window).
#[derive(Clone, Debug, PartialEq)]
pub enum Request {
    /// The plane's linear radiance, as EXR, to the file the user named.
    SaveExr(std::path::PathBuf),
    /// The window, as PNG, to the file the user named.
    Screenshot(std::path::PathBuf),
    /// The scene, as TOML, to the file the user named (the view becomes what the file
    /// holds: its numbers rounded as a person writes them).
    SaveScene(std::path::PathBuf),
    /// The view as a link (the page's address in a browser; `ltc-lab lab --view` on the
    /// desktop), copied to the clipboard.
    Share,
    /// A file for `Purpose`: the path named on the desktop, the browser's picker on the web.
    Open(crate::app::files::Purpose, String),
}

impl Shared {
    /// The lights of `count` from the seeded generator (heights 0.05–0.6, paper-100's
    /// intensities and range), as the lights slider makes them.
    pub fn generated_lights(&self, count: usize) -> Vec<Light> {
        // paper-100's intensities, scaled down past 100 lights so that the total power stays
        // paper-100's: 20 000 lights at those intensities only show a white plane.
        let dim = (PAPER_LIGHT_COUNT / count.max(1) as f64).min(1.0);
        crate::scene::generate_lights(
            &crate::scene::RandomLights {
                count,
                seed: self.lights.seed,
                height: [0.05, 0.6],
                intensity: [0.02 * dim, 0.08 * dim],
                range: Some(crate::scene::PAPER_RANGE),
                radius: 0.0,
            },
            self.stage.plane.half_size,
        )
    }
}

/// A part of the lab, found by its type: how `Lab::edit` and `Lab::set` name what they write.
/// Its writing takes a `Key`, which only this module makes.
pub trait HasPart<T> {
    fn part(&self) -> &Part<T>;
    fn part_mut(&mut self, key: Key) -> &mut Part<T>;
}

/// The key to a part's writing: made only here, by the lab's doors.
pub struct Key(());

/// The parts, named once: `Shared` (as eframe keeps them between runs and a link carries
/// them), its check, and the lab's doors to each, all from this one list.
macro_rules! parts {
    ($($name:ident: $t:ty;)*) => {
        /// The parts, as eframe keeps them between runs and a link carries them.
        #[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
        #[serde(default, deny_unknown_fields)]
        pub struct Shared {
            $(pub $name: Part<$t>,)*
        }

        impl Shared {
            /// Every part brought within its range (against its default: what came in had no
            /// value before it); what was refused or clamped, named.
            pub fn check(&mut self) -> Vec<String> {
                fn one<T: Checked + Default>(part: &mut Part<T>, notes: &mut Vec<String>) {
                    notes.extend(part.value_mut().check(&T::default()));
                }
                let mut notes = Vec::new();
                $(one(&mut self.$name, &mut notes);)*
                notes
            }
        }

        $(
            impl HasPart<$t> for Lab {
                fn part(&self) -> &Part<$t> {
                    &self.shared.$name
                }
                fn part_mut(&mut self, _: Key) -> &mut Part<$t> {
                    &mut self.shared.$name
                }
            }
        )*
        impl Lab {
            $(
                pub fn $name(&self) -> &Part<$t> {
                    &self.shared.$name
                }
            )*

            /// The parts of `shared` in place of the lab's (a view opened: a lesson's step),
            /// each checked where it enters; the lights cut to what the device shades. The
            /// pattern names every part: a part added to `Shared` and not here does not
            /// compile.
            pub fn use_shared(&mut self, shared: Shared) {
                let Shared { $($name,)* } = shared;
                $(self.replace($name.into_value());)*
                self.keep_lights();
            }
        }
    };
}

parts! {
    lights: Lights;
    material: Material;
    stage: Stage;
    exposure: Exposure;
    lobe_view: LobeView;
    forms: Forms;
    spheres: SphereForms;
    rects: RectForms;
    disks: DiskForms;
    side_b: SideB;
    overrides: Overrides;
    rules: LtcRules;
    tables: Tables;
    selection: Selection;
    refit: LastRefit;
}

/// The device the plane is shaded and the chart measured on, or why there is none (the
/// plane is then drawn by the CPU reference).
pub type Device = Result<GpuContext, String>;

/// The lab the panels share: its parts, its device, its notices and what it asks of the app.
pub struct Lab {
    shared: Shared,
    device: Device,
    /// The most lights the plane shades at once (the app asks the plane's renderer).
    max_lights: usize,
    message: Option<Message>,
    requests: Vec<Request>,
    /// The method file the user loaded (docs/design.md §5.13): never a part, so never stored,
    /// linked or in a lesson; a side names it as the method `file`.
    method_file: Option<MethodFile>,
}

impl Lab {
    /// A lab of `shared`'s parts, each checked (what was refused or clamped is said), its
    /// lights cut to the `max_lights` the plane shades on `device`.
    pub fn new(mut shared: Shared, device: Device, max_lights: usize) -> Self {
        let notes = shared.check();
        let mut lab = Self {
            shared,
            device,
            max_lights,
            message: None,
            requests: Vec::new(),
            method_file: None,
        };
        lab.say_notes(&notes);
        lab.keep_method_file();
        lab.keep_lights();
        lab
    }

    /// The parts as eframe keeps them and a link carries them.
    pub fn shared(&self) -> &Shared {
        &self.shared
    }

    /// Edits the part of type `T` through `f`, which sees that part alone; what it leaves
    /// is checked (a refused or clamped value is said), and the part is stamped if it
    /// changed. What `f` returns (a widget's response) is returned.
    pub fn edit<T, R>(&mut self, f: impl FnOnce(&mut T) -> R) -> R
    where
        Self: HasPart<T>,
        T: Checked + Clone + PartialEq,
    {
        let part = self.part_mut(Key(()));
        let before = (**part).clone();
        let r = f(part.value_mut());
        if **part != before {
            let notes = part.value_mut().check(&before);
            part.touch();
            self.said_after_edit(&notes);
        }
        r
    }

    /// Replaces the part of type `T` with `value`, checked against what it replaces; the part
    /// is stamped even where the value is the same (a file read again may differ in what
    /// the value does not show).
    pub fn set<T>(&mut self, mut value: T)
    where
        Self: HasPart<T>,
        T: Checked,
    {
        let part = self.part_mut(Key(()));
        let notes = value.check(part);
        *part.value_mut() = value;
        part.touch();
        self.said_after_edit(&notes);
    }

    /// Replaces the part of type `T` with `value` where it differs (checked as `set` checks):
    /// the parts a view leaves as they were keep their stamps, so their work is not made again.
    fn replace<T>(&mut self, value: T)
    where
        Self: HasPart<T>,
        T: Checked + PartialEq,
    {
        if **self.part() != value {
            self.set(value);
        }
    }

    /// Edits light `k` through `f` (without copying the others: a drag edits one light a
    /// frame among up to 100 000); `None` where there is no light `k`.
    pub fn edit_light<R>(&mut self, k: usize, f: impl FnOnce(&mut Light) -> R) -> Option<R> {
        let part = &mut self.shared.lights;
        let before = *part.list.get(k)?;
        let light = &mut part.value_mut().list[k];
        let r = f(light);
        if *light != before {
            let mut single = Lights {
                list: vec![*light],
                seed: 0,
            };
            let was = Lights {
                list: vec![before],
                seed: 0,
            };
            let notes = single.check(&was);
            part.value_mut().list[k] = single.list.first().copied().unwrap_or(before);
            part.touch();
            self.said_after_edit(&notes);
        }
        Some(r)
    }

    /// After an edit: the selection still names a light the scene has, and the notes are
    /// said.
    fn said_after_edit(&mut self, notes: &[String]) {
        self.keep_method_file();
        let count = self.shared.lights.list.len();
        if self.shared.selection.light.is_some_and(|k| k >= count) {
            let part = &mut self.shared.selection;
            part.value_mut().light = None;
            part.touch();
        }
        self.say_notes(notes);
    }

    fn say_notes(&mut self, notes: &[String]) {
        if !notes.is_empty() {
            self.say(Message::error(notes.join("; ")));
        }
    }

    /// The method file loaded, if any.
    pub fn method_file(&self) -> Option<&MethodFile> {
        self.method_file.as_ref()
    }

    /// Shades with `file` from now on: side A takes it unless a side has it already (the
    /// render begins again, with the new file, either way). Refused where the plane shades
    /// on the CPU, which runs no WGSL. What was done, in words.
    pub fn use_method_file(&mut self, file: MethodFile) -> Message {
        if self.device().is_none() {
            return Message::error(format!(
                "{}: a method file runs on the GPU, and this lab shades on the CPU ({})",
                file.name,
                self.device_error().unwrap_or("no device")
            ));
        }
        let text = format!(
            "method file {} (shades {}; the lab's methods the rest) loaded",
            file.name,
            file.shapes()
        );
        self.method_file = Some(file);
        let mut forms = **HasPart::<Forms>::part(self);
        if forms.ltc != Method::File && forms.brdf != Method::File {
            forms.ltc = Method::File;
        }
        // A new file with the same forms renders again by its identity (`MethodFile::id` is
        // in the plane's render key).
        self.set(forms);
        Message::note(format!(
            "{text}: {} | {}",
            forms.ltc.name(),
            forms.brdf.name()
        ))
    }

    /// The method file's render was stopped (`why`): the sides that shade with it go back to
    /// the lab's forms, the file stays loaded (pick `file` again to retry), and why is said.
    pub fn stop_method_file(&mut self, why: &str) {
        let kept = without_file(**HasPart::<Forms>::part(self));
        self.set(kept);
        self.say(Message::error(format!(
            "{why} — the sides are back to {} | {}",
            kept.ltc.name(),
            kept.brdf.name()
        )));
    }

    /// A side that names the method file without one loaded (from a link, a lesson or
    /// stored state, which never carry shader code) goes back to the lab's form, and says
    /// why.
    fn keep_method_file(&mut self) {
        if self.method_file.is_some() {
            return;
        }
        let forms = **HasPart::<Forms>::part(self);
        let kept = without_file(forms);
        if kept != forms {
            let part = HasPart::<Forms>::part_mut(self, Key(()));
            *part.value_mut() = kept;
            part.touch();
            self.say(Message::error(
                "a side named the method file `file`, which is not loaded: a link, a lesson or the stored \
                    state never carries shader code. Load it with load method (or drop the .wgsl) to shade \
                    with it".to_string(),
            ));
        }
    }

    /// The device, if there is one.
    pub fn device(&self) -> Option<&GpuContext> {
        self.device.as_ref().ok()
    }

    /// Why there is no device, if there is none.
    pub fn device_error(&self) -> Option<&str> {
        self.device.as_ref().err().map(String::as_str)
    }

    /// The device in words, or why there is none.
    pub fn describe_device(&self) -> String {
        match &self.device {
            Ok(g) => g.describe(),
            Err(e) => format!("no GPU: {e}"),
        }
    }

    /// The most lights the plane shades at once: the GPU's limit, or the scene's on the CPU.
    pub fn max_lights(&self) -> usize {
        self.max_lights
    }

    /// The scene the parts make.
    pub fn scene(&self) -> Scene {
        parts::scene(
            self.stage(),
            self.material(),
            self.lights(),
            self.exposure(),
        )
    }

    /// The scene as shaded: every light's intensity multiplied, its range replaced where the
    /// overrides say.
    pub fn shaded_scene(&self) -> Scene {
        parts::shaded(self.scene(), self.overrides())
    }

    /// The scene without its lights: what camera rays and projections need (a drag reads it
    /// every frame, among up to 100 000 lights).
    pub fn stage_scene(&self) -> Scene {
        let no_lights = Lights {
            list: Vec::new(),
            seed: 0,
        };
        parts::scene(self.stage(), self.material(), &no_lights, self.exposure())
    }

    /// The camera's ray through pixel `(x, y)` of an image of `size`: eye and direction.
    pub fn scene_camera_ray(&self, x: f64, y: f64, size: (usize, usize)) -> (DVec3, DVec3) {
        self.stage_scene().camera_ray(x, y, size.0, size.1)
    }

    pub fn alpha(&self) -> f64 {
        self.material().alpha
    }

    /// θo in radians, within the tables' rows.
    pub fn theta_o(&self) -> f64 {
        self.lobe_view().theta_o_deg.to_radians().min(THETA_MAX)
    }

    /// The LTC pair of `lut` at the lobe and matrix panels' (θo, α), in the view's frame (x
    /// toward the view's azimuth): an anisotropic material's lobes come from the 4D table at
    /// (θo, φo) in its tangent frame, turned into the view's (`tangent_from_view`).
    pub fn ltc_pair(&self, lut: &crate::ltc::lut::Lut) -> LtcPair {
        let m = self.material();
        if !m.is_anisotropic() {
            return lut.sample(self.alpha(), self.theta_o().cos()).ltc_pair();
        }
        let turn = self.tangent_from_view();
        let v = turn * DVec3::new(self.theta_o().sin(), 0.0, self.theta_o().cos());
        let pair = lut.aniso_pair(m.roughness(), v);
        let turned = |l: &Ltc| Ltc::from_cos_from_brdf(l.cos_from_brdf * turn, l.norm, l.fresnel);
        LtcPair {
            spec: turned(&pair.spec),
            diff: turned(&pair.diff),
        }
    }

    /// The turn from the lobe view's frame (x toward the view's azimuth) to the material's
    /// tangent frame: by φo while the material is anisotropic, none while it is not.
    pub fn tangent_from_view(&self) -> glam::DMat3 {
        match self.material().is_anisotropic() {
            true => glam::DMat3::from_rotation_z(self.lobe_view().phi_o_deg.to_radians()),
            false => glam::DMat3::IDENTITY,
        }
    }

    /// The cell of table A nearest (θo, α): (column of α, row of θo).
    pub fn nearest_cell(&self) -> (usize, usize) {
        let lut = &self.tables().a().lut;
        lut.nearest_cell(self.alpha(), self.theta_o().cos())
    }

    /// The horizon remedy in use: the rule's, or the remedy whose table shades.
    pub fn horizon_remedy(&self) -> Horizon {
        let t = self.tables();
        let shipped = t.a().source == crate::tables::Source::Shipped(t.shipped);
        let by_table = Horizon::ALL
            .into_iter()
            .find(|h| shipped && h.table() == Some(t.shipped));
        match self.rules().horizon {
            HorizonRule::Eq30 => by_table.unwrap_or(Horizon::Eq30),
            HorizonRule::NlFit => Horizon::NlFit,
            HorizonRule::ExactBand => Horizon::ExactBand,
        }
    }

    /// Shows `scene` (a preset, a loaded file, the one the lab started with), its lights cut
    /// to what this adapter shades (which it then says); the light selection is cleared, as
    /// it may name a light the new scene lacks.
    pub fn use_scene(&mut self, scene: Scene) {
        let seed = self.lights().seed;
        self.set(Stage {
            plane: scene.plane,
            camera: scene.camera,
        });
        self.set(scene.material);
        self.set(Exposure(scene.exposure));
        self.set(Lights {
            list: scene.lights,
            seed,
        });
        self.edit(|s: &mut Selection| *s = Selection::default());
        self.keep_lights();
    }

    /// `count` lights from the seeded generator, as the lights slider makes them; they
    /// replace the current ones (and the selection goes).
    pub fn set_light_count(&mut self, count: usize) {
        let list = self.shared.generated_lights(count);
        let seed = self.lights().seed;
        self.set(Lights { list, seed });
        self.edit(|s: &mut Selection| *s = Selection::default());
        self.keep_lights();
    }

    /// Cuts the scene's lights to what this adapter shades, and says so.
    fn keep_lights(&mut self) {
        let max = self.max_lights();
        let held = self.lights().list.len();
        if held > max {
            self.edit(|l: &mut Lights| l.list.truncate(max));
            self.say(Message::error(format!(
                "the scene holds {held} lights, more than the {max} this adapter shades at once: the first {max} are kept"
            )));
        }
    }

    /// Shades with the shipped table `t` from now on (table B follows, unless the user named
    /// it).
    pub fn use_shipped(&mut self, t: Table) {
        let tables = self.tables().with_a(NamedTable::shipped(t), t);
        self.set(tables);
    }

    /// Shades with a horizon remedy from now on: its table where it is one (a remedy's
    /// table leaves for the classic one under another remedy), else its rule on table A.
    pub fn use_horizon(&mut self, remedy: Horizon) {
        let t = self.tables();
        let shipped = t.a().source == crate::tables::Source::Shipped(t.shipped);
        let own = Horizon::ALL.iter().any(|h| h.table() == Some(t.shipped));
        let table = match remedy.table() {
            Some(table) => Some(table),
            None if shipped && own => Some(Table::Classic),
            None => None,
        };
        if let Some(table) = table.filter(|&table| table != t.shipped || !shipped) {
            self.use_shipped(table);
        }
        self.edit(|r: &mut LtcRules| r.horizon = remedy.rule());
    }

    /// Shades with `table` (read from a file, or given) from now on.
    pub fn use_table_a(&mut self, table: NamedTable) {
        let shipped = self.tables().shipped;
        let tables = self.tables().with_a(table, shipped);
        self.set(tables);
    }

    /// Compares with `table` as table B from now on; `None`: back to A's default B.
    pub fn use_table_b(&mut self, table: Option<NamedTable>) {
        let tables = self.tables().with_b(table);
        self.set(tables);
    }

    /// Shades anisotropic materials on side `id` with the 4D table `source` from now on; one
    /// that cannot be read is said, and the current one stays.
    pub fn use_aniso(&mut self, id: TableId, source: crate::ltc::aniso::source::AnisoSource) {
        match self.tables().with_aniso(id, source) {
            Ok(tables) => self.set(tables),
            Err(e) => self.say(Message::error(e.to_string())),
        }
    }

    /// The refitted lobe, while the chosen cell of table A is the one refitted.
    pub fn refit_ltc(&self) -> Option<(crate::ltc::lobe::Lobe, Ltc)> {
        let r = self.refit().0.as_ref()?;
        (r.cell == self.nearest_cell()).then(|| (r.lobe, r.ltc()))
    }

    /// Says `message` in the notices bar.
    pub fn say(&mut self, message: Message) {
        self.message = Some(message);
    }

    /// The notices bar's line.
    pub fn message(&self) -> Option<&Message> {
        self.message.as_ref()
    }

    /// The notice read and dismissed.
    pub fn dismiss(&mut self) {
        self.message = None;
    }

    /// Asks the app for what reaches beyond the lab.
    pub fn request(&mut self, request: Request) {
        self.requests.push(request);
    }

    /// What the panels asked of the app this frame (the app's to carry out).
    pub(super) fn take_requests(&mut self) -> Vec<Request> {
        std::mem::take(&mut self.requests)
    }
}

/// `forms` with a side that shades with the method file back to the lab's default form.
fn without_file(forms: Forms) -> Forms {
    let defaults = Forms::default();
    let back = |form: Method, default: Method| {
        if form == Method::File { default } else { form }
    };
    Forms {
        ltc: back(forms.ltc, defaults.ltc),
        brdf: back(forms.brdf, defaults.brdf),
        ..forms
    }
}
