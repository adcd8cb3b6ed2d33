//! The plane's image under the pointer: where the image is placed, and a press, a click and a
//! drag on it — a light's marker moved, a light selected, a pixel pinned, the divider dragged.

use egui::{Pos2, Vec2};

use super::{ASPECT, Drag, MAX_RENDER_WIDTH, PlanePanel};
use crate::app::lab::{Lab, LobeView, Selection};
use crate::app::plane::paint::Placed;
use crate::render::View;

impl PlanePanel {
    /// The divider's x in the image's rect, from its place (0–1) across the image.
    pub(super) fn divider_x(&self, rect: egui::Rect) -> f32 {
        rect.min.x + rect.width() * self.state.divider as f32
    }

    /// A press on a marker or the divider starts dragging it; a click selects a light or
    /// pins the pixel under it; a drag moves what it started on.
    pub(super) fn interact(
        &mut self,
        response: &egui::Response,
        lab: &mut Lab,
        placed: Placed,
        markers: &[(usize, Pos2)],
    ) {
        let near = |pos: Pos2| {
            markers
                .iter()
                .map(|(k, p)| (*k, p.distance(pos)))
                .filter(|(_, d)| *d < 8.0)
                .min_by(|a, b| a.1.total_cmp(&b.1))
                .map(|(k, _)| k)
        };
        // Where the press began: by the time egui calls it a drag, the pointer has moved.
        if response.drag_started()
            && let Some(pos) = response.ctx.input(|i| i.pointer.press_origin())
        {
            let on_divider =
                self.state.view == View::Split && (pos.x - self.divider_x(placed.rect)).abs() < 8.0;
            self.drag = match near(pos) {
                Some(k) => {
                    lab.edit(|s: &mut Selection| s.light = Some(k));
                    Some(Drag::Light(k))
                }
                None if on_divider => Some(Drag::Divider),
                None => None,
            };
        }
        if response.clicked()
            && let Some(pos) = response.interact_pointer_pos()
        {
            let hit = near(pos);
            lab.edit(|s: &mut Selection| s.light = hit);
            // A click beside the markers pins the pixel under it.
            if hit.is_none() {
                let u = (pos - placed.rect.min) / placed.rect.size();
                self.state.pinned = Some([
                    f64::from(u.x.clamp(0.0, 1.0)),
                    f64::from(u.y.clamp(0.0, 1.0)),
                ]);
                lab.edit(|v: &mut LobeView| v.light = None);
            }
        }
        if response.dragged()
            && let Some(pos) = response.interact_pointer_pos()
        {
            match self.drag {
                Some(Drag::Divider) => {
                    let u = (pos.x - placed.rect.min.x) / placed.rect.width();
                    self.state.divider = f64::from(u).clamp(0.0, 1.0);
                }
                Some(Drag::Light(k)) => drag_light(response, lab, placed, pos, k),
                None => {}
            }
        }
        if response.drag_stopped() {
            self.drag = None;
        }
    }
}

/// Moves light `k` with the pointer at `pos`: along the plane at its height, or (Shift) up
/// and down.
pub(super) fn drag_light(
    response: &egui::Response,
    lab: &mut Lab,
    placed: Placed,
    pos: Pos2,
    k: usize,
) {
    let shift = response.ctx.input(|i| i.modifiers.shift);
    let dy = f64::from(response.drag_delta().y);
    let (x, y) = placed.pixel(pos);
    let (width, height) = placed.size;
    // Keep the height; follow the pointer's ray to that height.
    let (eye, dir) = lab.scene_camera_ray(x, y, (width, height));
    let h = lab.stage().plane.half_size * 1.5;
    lab.edit_light(k, |light| {
        if shift {
            light.position[2] -= dy * 0.01;
            return;
        }
        let t = (light.position[2] - eye.z) / dir.z;
        if dir.z != 0.0 && t > 0.0 {
            let p = eye + t * dir;
            light.position[0] = p.x.clamp(-h, h);
            light.position[1] = p.y.clamp(-h, h);
        }
    });
}

/// The image's place: as large as fits `avail` at 16:9; the render's size in pixels: as
/// large as the image would be in `unpinned`, the area without the pinned pixel's table, so
/// that pinning a pixel shows the same render smaller instead of restarting it at a new size
/// (and the pinned pixel stays the pixel it was).
pub(super) fn image_area(
    ui: &mut egui::Ui,
    avail: Vec2,
    unpinned: Vec2,
) -> (Placed, egui::Response) {
    let fit = |avail: Vec2| {
        if avail.x / avail.y > ASPECT {
            Vec2::new(avail.y * ASPECT, avail.y)
        } else {
            Vec2::new(avail.x, avail.x / ASPECT)
        }
        .max(Vec2::new(32.0, 18.0))
    };
    let (rect, response) = ui.allocate_exact_size(fit(avail), egui::Sense::click_and_drag());
    response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, "plane image"));
    let ppp = ui.ctx().pixels_per_point();
    let width = (fit(unpinned).x * ppp)
        .min(MAX_RENDER_WIDTH)
        .round()
        .max(16.0) as usize;
    let height = ((width as f32) / ASPECT).round().max(9.0) as usize;
    let placed = Placed {
        rect,
        size: (width, height),
    };
    (placed, response)
}
