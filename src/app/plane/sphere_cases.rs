//! The plane panel's map of sphere cases (docs/design.md §1.10): over the plane, each pixel
//! coloured by where its lights with a size are against its surface — above it, below it,
//! cut by its horizon, or around the point — with each case's share of the plane. Computed
//! on the CPU at a quarter of the render's size, made again when the scene changes.

use egui::Color32;

use crate::app::lab::{Exposure, Lab, parts};
use crate::app::work::cache::{Cached, Own};
use crate::cpu::cases::sphere_case_map;
use crate::light::sphere::cap::SphereCase;

/// The map's pixels per render pixel, each way: a quarter keeps it under a few milliseconds
/// for a hundred lights while its edges stay where the render's are to within 4 pixels.
pub const SCALE: usize = 4;

/// Each case's colour: grey above (as the case map's "visible"), dark violet below (its
/// "stays below"), the glow's orange for a cut cap, red for a point inside the sphere.
pub fn case_colour(case: SphereCase) -> Color32 {
    match case {
        SphereCase::Above => Color32::from_rgb(120, 120, 128),
        SphereCase::Below => Color32::from_rgb(70, 45, 85),
        SphereCase::Cut => Color32::from_rgb(245, 150, 40),
        SphereCase::Inside => Color32::from_rgb(220, 40, 60),
    }
}

/// How much of the render shows through the map.
const OPACITY: f32 = 0.6;

/// The map as last made: its texture and each case's count of pixels.
pub struct SphereCases {
    map: Cached<(egui::TextureHandle, [usize; 4])>,
}

impl Default for SphereCases {
    fn default() -> Self {
        Self {
            map: Cached::new("plane.sphere_cases"),
        }
    }
}

impl SphereCases {
    /// The map of the lab's scene for a render of `size`, made where its inputs changed.
    pub fn update(&mut self, ctx: &egui::Context, lab: &Lab, size: (usize, usize)) {
        let (w, h) = (size.0.div_ceil(SCALE), size.1.div_ceil(SCALE));
        let inputs = (
            lab.stage(),
            lab.material(),
            lab.lights(),
            lab.overrides(),
            Own((w, h)),
        );
        self.map.get(
            inputs,
            |(stage, material, lights, overrides, Own((w, h)))| {
                let scene = parts::scene(stage, material, lights, &Exposure(1.0));
                let scene = parts::shaded(scene, overrides);
                let cases = sphere_case_map(&scene, w, h);
                let mut counts = [0; 4];
                let pixels: Vec<Color32> = cases
                    .iter()
                    .map(|c| match c {
                        Some(c) => {
                            counts[c.index()] += 1;
                            case_colour(*c).gamma_multiply(OPACITY)
                        }
                        None => Color32::TRANSPARENT,
                    })
                    .collect();
                let image = egui::ColorImage::new([w, h], pixels);
                let texture =
                    ctx.load_texture("sphere cases", image, egui::TextureOptions::NEAREST);
                (texture, counts)
            },
        );
    }

    /// The map over the render's `rect`.
    pub fn paint(&self, painter: &egui::Painter, rect: egui::Rect) {
        if let Some((texture, _)) = self.map.last() {
            let uv = egui::Rect::from_min_max(egui::Pos2::ZERO, egui::pos2(1.0, 1.0));
            painter.image(texture.id(), rect, uv, Color32::WHITE);
        }
    }

    /// The legend: each case's colour and share of the plane's pixels with a sized light.
    pub fn legend(&self, ui: &mut egui::Ui) {
        let Some((_, counts)) = self.map.last() else {
            return;
        };
        let total = counts.iter().sum::<usize>().max(1);
        ui.horizontal_wrapped(|ui| {
            ui.small("sphere cases:");
            for (case, count) in SphereCase::ALL.into_iter().zip(counts) {
                let (swatch, _) =
                    ui.allocate_exact_size(egui::vec2(10.0, 10.0), egui::Sense::hover());
                ui.painter().rect_filled(swatch, 2.0, case_colour(case));
                ui.small(format!(
                    "{} {:.0}%",
                    case.name(),
                    100.0 * *count as f64 / total as f64
                ));
            }
        });
    }

    pub fn count(&self) -> (&'static str, u64) {
        self.map.count()
    }
}
