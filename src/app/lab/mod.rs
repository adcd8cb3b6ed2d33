//! What the panels share, and the only doors it changes through. Each shared thing is a part
//! of its own type (`parts`): a panel reads a part (`lab.material()`), and writes one only by
//! naming its type in `Lab::edit` or `Lab::set`, which check what enters and stamp the part.
//! Work made from parts keys on the parts it reads (`app::work::cache`). A panel's own settings are
//! its own.

mod derived;
mod light_check;
mod method_file_door;
pub mod part;
pub mod parts;
pub mod refit_result;
pub mod tables;

use serde::{Deserialize, Serialize};

pub use part::{Checked, Part, Stamp};
pub use parts::{
    Exposure, Forms, LastRefit, Lights, LobeView, Overrides, Selection, ShapeForms, SideB, Stage,
};
pub use tables::{TableId, TableSources, Tables};

use crate::gpu::GpuContext;
use crate::gpu::method_file::MethodFile;
use crate::ltc::Ltc;
use crate::ltc::lut::Table;
use crate::ltc::remedy::Horizon;
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
    shape_forms: ShapeForms;
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
