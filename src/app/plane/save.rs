//! The plane's finished image saved as EXR, linear, to the path the user named and no other.

use super::PlanePanel;
use crate::render::Frame;

impl PlanePanel {
    /// Writes the finished image's linear values as EXR (only the path the user named), once
    /// it is read back: `None` until then.
    pub fn save_exr(
        &mut self,
        path: &std::path::Path,
        exposure: f64,
    ) -> Option<Result<String, String>> {
        if self.shading.in_flight() {
            return Some(Err(
                "the image is still being rendered: try again when it is done".into(),
            ));
        }
        match self.shading.read() {
            Some(frame) => Some(encode_exr(&frame, path, exposure)),
            None if self.shading.read_pending() => None,
            None => Some(Err("there is no image to save yet".into())),
        }
    }
}

/// `frame` saved as the EXR the user named.
pub(super) fn encode_exr(
    frame: &Frame,
    path: &std::path::Path,
    exposure: f64,
) -> Result<String, String> {
    let format = crate::output::ImageFormat::of(path).map_err(|e| e.to_string())?;
    let bytes = crate::output::frame_bytes(frame, format, exposure);
    crate::app::files::save(path, &bytes, "image/x-exr")
}
