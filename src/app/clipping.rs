//! The clipping panel: the paper's Figure 2 — one light at (0, 0, 1) and at (0, 0, −0.158731),
//! α = 0.5, LTC against BRDF — recomputed live with each clipping rule on or off, so that the
//! glow of case 1 and the negative light of case 2 appear and vanish; a map of which pixels
//! see the light in which case; and a radiance profile through the image's centre.

use egui::{Color32, Vec2};
use glam::DVec3;

use crate::app::state::{ClipScene, LabState};
use crate::cpu::{ClipCounts, clip_counts, render};
use crate::ltc::lut::Lut;
use crate::ltc::{Clipping, Normalization};
use crate::metrics::luminance;
use crate::output::tone_map;
use crate::render::{Frame, Method, RenderSettings};
use crate::scene::preset;

/// Size of each small picture: the CPU reference renders all of them (one light each).
pub const PICTURE: (usize, usize) = (192, 108);

#[derive(Clone, Debug, PartialEq)]
struct Key {
    clip: Clipping,
    scene: ClipScene,
    normalization: Normalization,
}

#[derive(Default)]
pub struct ClippingPanel {
    key: Option<Key>,
    /// (a) normal LTC, (b) normal BRDF, (c) case-1 LTC, (d) case-1 BRDF.
    pub pictures: Vec<Frame>,
    pub case_map: Vec<ClipCounts>,
    textures: Vec<egui::TextureHandle>,
    /// Luminance along the centre row: BRDF, LTC with both rules (eq. 30), LTC with the rules
    /// as toggled, LTC with none.
    profiles: [Vec<[f64; 2]>; 4],
}

const CAPTIONS: [&str; 4] = [
    "(a) LTC, light at (0, 0, 1)",
    "(b) BRDF, light at (0, 0, 1)",
    "(c) LTC, light at (0, 0, −0.158731)",
    "(d) BRDF, light at (0, 0, −0.158731)",
];

impl ClippingPanel {
    pub fn show(&mut self, ui: &mut egui::Ui, s: &mut LabState, lut: &Lut) {
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut s.clip_panel.horizon, "case 1 rule (n·l ≤ 0 -> 0)")
                .on_hover_text("Off: the light below the plane is lifted above the horizon by M^-1 and the LTC glows (c), while the BRDF (d) stays black");
            ui.checkbox(&mut s.clip_panel.transformed, "case 2 rule ((M^-1l).z ≤ 0 -> 0)")
                .on_hover_text("Off: a light above the horizon that M^-1 pushes below contributes negative light (see the case-2 map and profile)");
            ui.label("map and profile of:");
            for (c, name) in [(ClipScene::Normal, "normal"), (ClipScene::Case1, "case 1"), (ClipScene::Case2, "case 2")] {
                ui.selectable_value(&mut s.clip_scene, c, name)
                    .on_hover_text(format!("The {} preset", c.preset()));
            }
        });
        self.ensure(ui.ctx(), s, lut);
        let avail = ui.available_width();
        let w = ((avail - 20.0) / 5.0).max(40.0);
        let h = w * PICTURE.1 as f32 / PICTURE.0 as f32;
        ui.horizontal(|ui| {
            for (k, t) in self.textures.iter().enumerate() {
                ui.vertical(|ui| {
                    ui.add(egui::Image::new(t).fit_to_exact_size(Vec2::new(w, h)))
                        .on_hover_text(CAPTIONS.get(k).copied().unwrap_or("clipping cases: green visible, red case 1 (below the horizon), blue case 2 (pushed below by M^-1)"));
                    ui.small(CAPTIONS.get(k).copied().unwrap_or("case map"));
                });
            }
        });
        let [brdf, clipped, toggled, unclipped] = self.profiles.clone();
        egui_plot::Plot::new("clip profile")
            .legend(egui_plot::Legend::default())
            .x_axis_label("x along the centre row (pixels)")
            .y_axis_label("luminance")
            .allow_scroll(false)
            .show(ui, |p| {
                p.line(egui_plot::Line::new("BRDF", brdf).color(Color32::from_rgb(240, 150, 60)));
                p.line(
                    egui_plot::Line::new("LTC clipped (eq. 30)", clipped)
                        .color(Color32::from_rgb(70, 140, 255)),
                );
                p.line(
                    egui_plot::Line::new("LTC, rules as toggled", toggled)
                        .color(Color32::from_rgb(90, 210, 120)),
                );
                p.line(
                    egui_plot::Line::new("LTC unclipped (click to hide)", unclipped)
                        .color(Color32::from_rgb(220, 80, 200)),
                );
            });
    }

    fn ensure(&mut self, ctx: &egui::Context, s: &LabState, lut: &Lut) {
        let key = Key {
            clip: s.clip_panel,
            scene: s.clip_scene,
            normalization: s.normalization,
        };
        if self.key.as_ref() == Some(&key) {
            return;
        }
        let (w, h) = PICTURE;
        let shot = |scene: &str, method: Method, clip: Clipping| {
            let mut r = RenderSettings::single(w, h, method);
            r.clipping = clip;
            r.normalization = s.normalization;
            render(&preset(scene), lut, &r)
        };
        self.pictures = vec![
            shot("figure2-normal", Method::Ltc, key.clip),
            shot("figure2-normal", Method::Brdf, key.clip),
            shot("figure2-case1", Method::Ltc, key.clip),
            shot("figure2-case1", Method::Brdf, key.clip),
        ];
        let scene = preset(key.scene.preset());
        self.case_map = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .map(|(x, y)| {
                scene
                    .surface_point(x, y, w, h)
                    .map_or(ClipCounts::default(), |p| {
                        clip_counts(&scene, lut, &p, &scene.lights)
                    })
            })
            .collect();
        let row = |f: &Frame| -> Vec<[f64; 2]> {
            (0..w)
                .map(|x| [x as f64, luminance(f.pixels[(h / 2) * w + x])])
                .collect()
        };
        self.profiles = [
            row(&shot(key.scene.preset(), Method::Brdf, Clipping::BOTH)),
            row(&shot(key.scene.preset(), Method::Ltc, Clipping::BOTH)),
            row(&shot(key.scene.preset(), Method::Ltc, key.clip)),
            row(&shot(key.scene.preset(), Method::Ltc, Clipping::NONE)),
        ];
        // Each picture's own exposure: Figure 2 is about where light is, not how much.
        let mut images: Vec<egui::ColorImage> = self
            .pictures
            .iter()
            .map(|f| {
                let pixels = f.pixels.iter().zip(&f.on_plane).map(|(p, &on)| {
                    if !on {
                        return Color32::from_gray(24);
                    }
                    let [r, g, b] = tone_map(*p, 4.0);
                    Color32::from_rgb(r, g, b)
                });
                egui::ColorImage::new([w, h], pixels.collect())
            })
            .collect();
        images.push(egui::ColorImage::new(
            [w, h],
            self.case_map
                .iter()
                .zip(&self.pictures[0].on_plane)
                .map(
                    |(c, &on)| match (on, c.below_horizon > 0, c.pushed_below > 0) {
                        (false, _, _) => Color32::from_gray(24),
                        (true, true, _) => Color32::from_rgb(200, 60, 50),
                        (true, _, true) => Color32::from_rgb(60, 90, 220),
                        (true, false, false) => Color32::from_rgb(60, 170, 80),
                    },
                )
                .collect(),
        ));
        self.textures = images
            .into_iter()
            .enumerate()
            .map(|(k, img)| ctx.load_texture(format!("clip{k}"), img, egui::TextureOptions::LINEAR))
            .collect();
        self.key = Some(key);
    }

    /// Total luminance of a picture (tests: the glow of case 1 appears and vanishes).
    pub fn picture_energy(&self, k: usize) -> f64 {
        self.pictures.get(k).map_or(0.0, |f| {
            f.pixels
                .iter()
                .map(|&p| luminance(p.max(DVec3::ZERO)))
                .sum()
        })
    }
}
