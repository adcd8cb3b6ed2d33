//! The lab's method file (docs/design.md §5.13): the one loaded, taken on by side A where the
//! plane shades on a GPU; the sides back to the lab's forms, with why, when its render is
//! stopped; and a side naming it without one loaded (a link, a lesson, stored state) put back.

use super::{Forms, HasPart, Key, Lab, Message, without_file};
use crate::gpu::method_file::MethodFile;
use crate::render::Method;

impl Lab {
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
    pub(super) fn keep_method_file(&mut self) {
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
}
