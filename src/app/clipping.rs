//! The clipping panel: the paper's Figure 2 for both clipping cases — per case, (a) LTC and
//! (b) BRDF with the light above the plane, (c) LTC and (d) BRDF with the case's light —
//! each picture exposed to its own content with its factor printed, negative light in the
//! diverging map; each case's four-class case map with a legend and counts; and a profile
//! along a line dragged on any picture (by default through the case's strongest artifact) on
//! a symmetric log axis. The rules are the lab's own; α, the light and the table are edited
//! here.

use egui::{Color32, Pos2, Vec2};
use glam::DVec3;

use crate::app::axes::symlog_y;
use crate::app::display::rgb;
use crate::app::other::OtherTable;
use crate::app::state::{ClipScene, ClipSetup, LabState};
use crate::colormap::{diverging, round_sig, short_number};
use crate::cpu::{ClipCounts, clip_counts_map, render};
use crate::ltc::lut::Lut;
use crate::ltc::{ClipCase, Clipping, Normalization};
use crate::metrics::{LuminanceRange, luminance, luminance_range};
use crate::output::srgb_encode;
use crate::render::{Frame, Method, RenderSettings};

/// Size of each picture: the CPU reference renders all of them (one light each, ~2 ms).
pub const PICTURE: (usize, usize) = (192, 108);

/// The two rows: case 1 and case 2.
const ROWS: [ClipScene; 2] = [ClipScene::Case1, ClipScene::Case2];

#[derive(Clone, Debug, PartialEq)]
struct Key {
    clip: Clipping,
    normalization: Normalization,
    setup: ClipSetup,
}

/// One picture: its render, the image shown, and how it was exposed.
pub struct Thumb {
    pub frame: Frame,
    pub image: egui::ColorImage,
    texture: egui::TextureHandle,
    /// The exposure factors of the positive and (if any) negative parts.
    pub factor: f64,
    pub negative_factor: Option<f64>,
    pub caption: String,
}

/// A case row: its four pictures, its case map and the profile's renders.
pub struct CaseRow {
    pub thumbs: Vec<Thumb>,
    pub case_map: Vec<Option<ClipCounts>>,
    map_texture: egui::TextureHandle,
    /// Pixels per class, in `ClipCase::ALL`'s order.
    pub class_counts: [usize; 4],
    /// BRDF, LTC with both rules, LTC as toggled, LTC without this case's rule.
    pub profile_frames: [Frame; 4],
    /// The line through the case's strongest artifact, in picture coordinates (0–1).
    pub default_line: [Pos2; 2],
}

#[derive(Default)]
pub struct ClippingPanel {
    key: Option<Key>,
    pub rows: Vec<CaseRow>,
    /// The user's profile line (picture coordinates, 0–1), while one is drawn.
    pub line: Option<[Pos2; 2]>,
    drag_from: Option<Pos2>,
}

/// The case map's class colours, in `ClipCase::ALL`'s order: grey for visible, the glow's
/// orange for case 1, the negative light's blue for case 2 (as in the diverging map), and a
/// dark violet for the harmless "stays below".
pub const CLASS_COLOURS: [Color32; 4] = [
    Color32::from_rgb(120, 120, 128),
    Color32::from_rgb(245, 150, 40),
    Color32::from_rgb(60, 140, 255),
    Color32::from_rgb(70, 45, 85),
];

const BACKGROUND: Color32 = Color32::from_rgb(24, 24, 28);

/// The rule that case `row` is about, off: what the profile's last line shows.
fn without_case_rule(row: ClipScene) -> Clipping {
    match row {
        ClipScene::Case2 => Clipping::HORIZON,
        _ => Clipping::TRANSFORMED,
    }
}

impl ClippingPanel {
    pub fn show(&mut self, ui: &mut egui::Ui, s: &mut LabState, lut: &Lut, other: &OtherTable) {
        ui.horizontal_wrapped(|ui| {
            ui.checkbox(&mut s.clipping.horizon, "case 1 rule (n·l ≤ 0 -> 0)")
                .on_hover_text("The lab's rule (the side panel's \"clip case 1\"). Off: the light below the plane is lifted above the horizon by M^-1 and the LTC glows (c), while the BRDF (d) stays black");
            ui.checkbox(&mut s.clipping.transformed, "case 2 rule ((M^-1 l).z ≤ 0 -> 0)")
                .on_hover_text("The lab's rule (the side panel's \"clip case 2\"). Off: a light above the horizon that M^-1 pushes below contributes negative light (blue)");
            ui.separator();
            ui.label("table");
            ui.selectable_value(&mut s.clip_setup.table_b, false, "A")
                .on_hover_text("Table A, the one the lab shades with");
            ui.selectable_value(&mut s.clip_setup.table_b, true, format!("B ({})", other.name))
                .on_hover_text("Table B, the other fit");
            if ui.small_button("reset").on_hover_text("The presets' α and lights").clicked() {
                s.clip_setup = ClipSetup::default();
                self.line = None;
            }
        });
        let table = if s.clip_setup.table_b {
            &other.lut
        } else {
            lut
        };
        self.ensure(ui.ctx(), s, table);
        let size = picture_size(ui);
        egui::ScrollArea::vertical()
            .auto_shrink([false; 2])
            .show(ui, |ui| {
                for (r, &row) in ROWS.iter().enumerate() {
                    self.row_controls(ui, s, row);
                    self.row_pictures(ui, s, r, row, size);
                }
                self.legend(ui, s);
                self.profile(ui, s);
            });
    }

    /// The row's title, α and light position.
    fn row_controls(&mut self, ui: &mut egui::Ui, s: &mut LabState, row: ClipScene) {
        let k = row.index();
        ui.horizontal_wrapped(|ui| {
            let selected = s.clip_scene == row;
            let title = match row {
                ClipScene::Case2 => "case 2: light above, pushed below by M^-1",
                _ => "case 1: light below, lifted by M^-1",
            };
            if ui
                .selectable_label(selected, egui::RichText::new(title).strong())
                .on_hover_text("Show this case's legend and profile")
                .clicked()
            {
                s.clip_scene = row;
                self.line = None;
            }
            ui.add(
                egui::DragValue::new(&mut s.clip_setup.alpha[k])
                    .range(crate::ltc::lut::ALPHA_MIN..=1.0)
                    .speed(0.005)
                    .prefix("α "),
            )
            .on_hover_text("This case's roughness (all four pictures of the row)");
            ui.label("light");
            for (c, axis) in ["x ", "y ", "z "].into_iter().enumerate() {
                ui.add(
                    egui::DragValue::new(&mut s.clip_setup.light[k][c])
                        .range(-3.0..=3.0)
                        .speed(0.005)
                        .max_decimals(4)
                        .prefix(axis),
                )
                .on_hover_text("The case light's position, scene units (the plane spans ±2)");
            }
        });
    }

    /// A row's four pictures and its case map; drag on any to draw the profile's line.
    fn row_pictures(
        &mut self,
        ui: &mut egui::Ui,
        s: &mut LabState,
        r: usize,
        row: ClipScene,
        size: Vec2,
    ) {
        let line = self.line_or_default(s);
        let show_line = s.clip_scene == row;
        let Some(case_row) = self.rows.get(r) else {
            return;
        };
        let mut drawn: Option<(Pos2, Pos2, bool)> = None;
        ui.horizontal(|ui| {
            let count = case_row.thumbs.len() + 1;
            for k in 0..count {
                ui.vertical(|ui| {
                    ui.set_width(size.x);
                    let (texture, caption, hover) = match case_row.thumbs.get(k) {
                        Some(t) => (t.texture.id(), t.caption.clone(), Some(&t.frame)),
                        None => (case_row.map_texture.id(), "case map".to_string(), None),
                    };
                    let (rect, response) =
                        ui.allocate_exact_size(size, egui::Sense::click_and_drag());
                    let name = format!("{} picture {k}", row.preset());
                    response
                        .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &name));
                    let painter = ui.painter_at(rect);
                    painter.image(
                        texture,
                        rect,
                        egui::Rect::from_min_max(Pos2::ZERO, egui::pos2(1.0, 1.0)),
                        Color32::WHITE,
                    );
                    let to_unit = |p: Pos2| {
                        let u = (p - rect.min) / rect.size();
                        egui::pos2(u.x.clamp(0.0, 1.0), u.y.clamp(0.0, 1.0))
                    };
                    if show_line {
                        let a = rect.min + line[0].to_vec2() * rect.size();
                        let b = rect.min + line[1].to_vec2() * rect.size();
                        let stroke = egui::Stroke::new(1.5, Color32::from_rgb(255, 240, 80));
                        painter.line_segment([a, b], stroke);
                        painter.circle_filled(a, 2.5, stroke.color);
                    }
                    if response.drag_started()
                        && let Some(p) = response.ctx.input(|i| i.pointer.press_origin())
                    {
                        drawn = Some((to_unit(p), to_unit(p), true));
                    } else if response.dragged()
                        && let Some(p) = response.interact_pointer_pos()
                    {
                        drawn = Some((Pos2::ZERO, to_unit(p), false));
                    }
                    ui.small(caption);
                    // The reading on its own line, under the caption, so that neither hides
                    // the other; blank (but kept) when the pointer is elsewhere.
                    let reading = response.hover_pos().map(|p| {
                        let u = to_unit(p);
                        match hover {
                            Some(frame) => format!(
                                "luminance {} (linear, scene units)",
                                short_number(sample(frame, u).unwrap_or(0.0))
                            ),
                            None => class_at(&case_row.case_map, u)
                                .map_or("off the plane".into(), |c| c.name().to_string()),
                        }
                    });
                    ui.small(reading.unwrap_or_default());
                });
            }
        });
        match drawn {
            Some((from, to, true)) => {
                self.drag_from = Some(from);
                s.clip_scene = row;
                self.line = Some([from, to]);
            }
            Some((_, to, false)) => {
                if let Some(from) = self.drag_from {
                    s.clip_scene = row;
                    self.line = Some([from, to]);
                }
            }
            None => {}
        }
    }

    /// The four classes' colours, names and pixel counts for both cases.
    fn legend(&self, ui: &mut egui::Ui, s: &LabState) {
        for (name, counts) in ["case 1", "case 2"]
            .into_iter()
            .zip(self.rows.iter().map(|r| r.class_counts))
        {
            ui.horizontal_wrapped(|ui| {
                ui.small(format!(
                    "case map of {name} (pixels of {}×{}; the rest is off the plane):",
                    PICTURE.0, PICTURE.1
                ));
                for (k, case) in ClipCase::ALL.into_iter().enumerate() {
                    let (rect, _) = ui.allocate_exact_size(Vec2::splat(10.0), egui::Sense::hover());
                    ui.painter().rect_filled(rect, 2.0, CLASS_COLOURS[k]);
                    ui.small(format!("{} {}", case.name(), counts[k]))
                        .on_hover_text(class_hover(case));
                }
            });
        }
        let Some(row) = self.selected_row(s) else {
            return;
        };
        if let Some(t) = row.thumbs.get(2) {
            let text = match t.negative_factor {
                Some(n) => format!(
                    "(c): orange positive ×{}, blue negative light ×{} (each part exposed to its own peak)",
                    short_number(round_sig(t.factor)),
                    short_number(round_sig(n))
                ),
                None => "each picture is exposed so that its brightest pixel is white; its factor is printed under it".into(),
            };
            ui.small(text);
            ui.small("(a), (b): the same light moved above the plane, for reference; (c), (d): this case's light; hover a picture to read it");
        }
    }

    /// Luminance along the line on a symmetric log axis: the BRDF, LTC with both rules, as
    /// toggled, and without the case's rule.
    fn profile(&mut self, ui: &mut egui::Ui, s: &LabState) {
        let line = self.line_or_default(s);
        let Some(row) = self.selected_row(s) else {
            return;
        };
        let curves: Vec<Vec<[f64; 2]>> = row
            .profile_frames
            .iter()
            .map(|f| profile_along(f, line))
            .collect();
        let peak = curves
            .iter()
            .flatten()
            .fold(0.0f64, |m, p| m.max(p[1].abs()))
            .max(1e-30);
        // Five decades under the peak: case 1's glow is ~1e-3 of the dip beside it.
        let c = peak * 1e-5;
        let names = [
            ("BRDF", Color32::from_rgb(240, 150, 60)),
            ("LTC, both rules (eq. 30)", Color32::from_rgb(70, 140, 255)),
            ("LTC, rules as toggled", Color32::from_rgb(90, 210, 120)),
            (
                if s.clip_scene == ClipScene::Case2 {
                    "LTC without the case-2 rule"
                } else {
                    "LTC without the case-1 rule"
                },
                Color32::from_rgb(220, 80, 200),
            ),
        ];
        if ui
            .small_button("line through the strongest artifact")
            .on_hover_text("Drag on any picture to draw another line")
            .clicked()
        {
            self.line = None;
        }
        let plot = egui_plot::Plot::new("clip profile")
            .legend(egui_plot::Legend::default())
            .x_axis_label("distance along the line (pixels of the pictures)")
            // Ticks every 10, 50 and 100 pixels (the default's 10s and 100s label one tick).
            .x_grid_spacer(egui_plot::uniform_grid_spacer(|_| [10.0, 50.0, 100.0]))
            .y_axis_label("luminance (symlog)")
            .min_size(Vec2::new(80.0, 140.0))
            .allow_scroll(false);
        symlog_y(plot, c).show(ui, |p| {
            for (k, (points, (name, colour))) in curves.into_iter().zip(names).enumerate() {
                let points: Vec<[f64; 2]> = points
                    .into_iter()
                    .map(|[x, y]| [x, crate::colormap::symlog(y, c)])
                    .collect();
                let mut line = egui_plot::Line::new(name, points).color(colour);
                if k == 3 {
                    line = line.style(egui_plot::LineStyle::dashed_loose());
                }
                p.line(line);
            }
        });
    }

    fn selected_row(&self, s: &LabState) -> Option<&CaseRow> {
        let r = if s.clip_scene == ClipScene::Case2 {
            1
        } else {
            0
        };
        self.rows.get(r)
    }

    /// The user's line, or the selected case's default.
    fn line_or_default(&self, s: &LabState) -> [Pos2; 2] {
        self.line.unwrap_or_else(|| {
            self.selected_row(s)
                .map_or([egui::pos2(0.0, 0.5), egui::pos2(1.0, 0.5)], |r| {
                    r.default_line
                })
        })
    }

    /// Renders both rows again when the rules, α, a light or the table changed.
    fn ensure(&mut self, ctx: &egui::Context, s: &LabState, lut: &Lut) {
        let key = Key {
            clip: s.clipping,
            normalization: s.normalization,
            setup: s.clip_setup.clone(),
        };
        if self.key.as_ref() == Some(&key) {
            return;
        }
        self.rows = ROWS
            .iter()
            .map(|&row| case_row(ctx, &key, row, lut))
            .collect();
        self.key = Some(key);
    }
}

/// One case's pictures, case map and profile renders.
fn case_row(ctx: &egui::Context, key: &Key, row: ClipScene, lut: &Lut) -> CaseRow {
    let (w, h) = PICTURE;
    let shot = |which: ClipScene, method: Method, clip: Clipping| {
        let mut r = RenderSettings::single(w, h, method);
        r.clipping = clip;
        r.normalization = key.normalization;
        render(&key.setup.scene(which, row), lut, &r)
    };
    let rules = if key.clip == Clipping::BOTH {
        "both rules".to_string()
    } else {
        format!("rules: {}", key.clip.name())
    };
    let pictures = [
        (
            "(a) LTC ref.",
            shot(ClipScene::Normal, Method::Ltc, key.clip),
        ),
        (
            "(b) BRDF ref.",
            shot(ClipScene::Normal, Method::Brdf, key.clip),
        ),
        ("(c) LTC", shot(row, Method::Ltc, key.clip)),
        ("(d) BRDF", shot(row, Method::Brdf, key.clip)),
    ];
    let thumbs: Vec<Thumb> = pictures
        .into_iter()
        .enumerate()
        .map(|(k, (name, frame))| {
            let mut t = thumb(ctx, &format!("clip {} {k}", row.preset()), frame);
            let factor = |f: f64| format!("×{}", short_number(round_sig(f)));
            // `factor` is 1/max: finite and positive only where some light is positive.
            let positive = (t.factor.is_finite() && t.factor > 0.0).then(|| factor(t.factor));
            let exposure = match (positive, t.negative_factor) {
                (Some(p), Some(n)) => format!("+{p} −{}", factor(n)),
                (Some(p), None) => p,
                (None, Some(n)) => format!("−{} (all negative)", factor(n)),
                (None, None) => "black".into(),
            };
            let rules = if k == 2 {
                format!(", {rules}")
            } else {
                String::new()
            };
            t.caption = format!("{name}{rules} {exposure}");
            t
        })
        .collect();
    let scene = key.setup.scene(row, row);
    let case_map = clip_counts_map(&scene, lut, w, h);
    let mut class_counts = [0; 4];
    for c in case_map.iter().flatten().filter_map(ClipCounts::class) {
        class_counts[c.index()] += 1;
    }
    let map_image = egui::ColorImage::new(
        [w, h],
        case_map
            .iter()
            .map(|c| {
                c.and_then(|c| c.class())
                    .map_or(BACKGROUND, |class| CLASS_COLOURS[class.index()])
            })
            .collect(),
    );
    let both = shot(row, Method::Ltc, Clipping::BOTH);
    let without = shot(row, Method::Ltc, without_case_rule(row));
    let default_line = strongest_artifact_line(&without, &both);
    CaseRow {
        profile_frames: [
            shot(row, Method::Brdf, key.clip),
            both,
            thumbs[2].frame.clone(),
            without,
        ],
        thumbs,
        case_map,
        map_texture: ctx.load_texture(
            format!("clip map {}", row.preset()),
            map_image,
            egui::TextureOptions::NEAREST,
        ),
        class_counts,
        default_line,
    }
}

/// The pictures' size: five abreast within the panel's width (its scroll bar and the gaps
/// between them included), and small enough in a short panel that both rows, the legend and
/// the profile's plot fit its height.
fn picture_size(ui: &egui::Ui) -> Vec2 {
    let spacing = ui.spacing();
    let across =
        ui.available_width() - 4.0 * spacing.item_spacing.x - spacing.scroll.bar_width - 8.0;
    // Per row: its controls and the two caption lines (about 70 points); then the legend's
    // lines and the profile's 140-point plot with its buttons (about 230).
    let down = (ui.available_height() - 2.0 * 70.0 - 230.0) / 2.0;
    let aspect = PICTURE.1 as f32 / PICTURE.0 as f32;
    // Not below 110 points, where the glow and the case map stop being readable: a short
    // panel scrolls to the profile instead.
    let w = (across / 5.0)
        .min((down / aspect).max(110.0))
        .clamp(40.0, 320.0);
    Vec2::new(w, w * aspect)
}

/// A picture exposed to its own content: a positive one so that its brightest pixel is
/// white; a signed one in the diverging map, each sign scaled to its own peak.
pub fn thumb(ctx: &egui::Context, name: &str, frame: Frame) -> Thumb {
    let LuminanceRange { min, max, .. } = luminance_range(&frame);
    let factor = 1.0 / max;
    let negative_factor = (min < 0.0).then(|| -1.0 / min);
    let pixels = frame
        .pixels
        .iter()
        .zip(&frame.on_plane)
        .map(|(p, &on)| {
            if !on {
                return BACKGROUND;
            }
            let l = luminance(*p);
            match negative_factor {
                // Each sign to its own peak, encoded like the positive pictures (sRGB), so
                // that the dim tail of the negative light reads as it would as light.
                Some(n) => {
                    let x = if l < 0.0 {
                        l * n
                    } else {
                        l * factor.min(1e300)
                    };
                    rgb(diverging(x.signum() * srgb_encode(x.abs().min(1.0))))
                }
                None if max > 0.0 => {
                    let c = (*p * factor).clamp(DVec3::ZERO, DVec3::ONE);
                    let e = |x: f64| (srgb_encode(x) * 255.0).round() as u8;
                    Color32::from_rgb(e(c.x), e(c.y), e(c.z))
                }
                None => Color32::BLACK,
            }
        })
        .collect();
    let image = egui::ColorImage::new([frame.width, frame.height], pixels);
    Thumb {
        texture: ctx.load_texture(name, image.clone(), egui::TextureOptions::LINEAR),
        image,
        frame,
        factor,
        negative_factor,
        caption: String::new(),
    }
}

/// A horizontal line through the pixel where the case's artifact (LTC without the case's rule
/// minus LTC with both) is largest; the centre row where there is none.
fn strongest_artifact_line(without: &Frame, both: &Frame) -> [Pos2; 2] {
    let (k, size) = without
        .pixels
        .iter()
        .zip(&both.pixels)
        .map(|(a, b)| (luminance(*a) - luminance(*b)).abs())
        .enumerate()
        .fold(
            (without.width * (without.height / 2), 0.0),
            |best, (k, d)| {
                if d > best.1 { (k, d) } else { best }
            },
        );
    let y = if size > 0.0 {
        ((k / without.width) as f32 + 0.5) / without.height as f32
    } else {
        0.5
    };
    [egui::pos2(0.0, y), egui::pos2(1.0, y)]
}

/// Luminance at picture coordinates `u` (0–1), nearest pixel; `None` off the plane.
fn sample(frame: &Frame, u: Pos2) -> Option<f64> {
    let x = ((u.x * frame.width as f32) as usize).min(frame.width - 1);
    let y = ((u.y * frame.height as f32) as usize).min(frame.height - 1);
    let k = y * frame.width + x;
    frame.on_plane[k].then(|| luminance(frame.pixels[k]))
}

/// The class of the case map at picture coordinates `u`.
fn class_at(map: &[Option<ClipCounts>], u: Pos2) -> Option<ClipCase> {
    let (w, h) = PICTURE;
    let x = ((u.x * w as f32) as usize).min(w - 1);
    let y = ((u.y * h as f32) as usize).min(h - 1);
    map.get(y * w + x)
        .copied()
        .flatten()
        .and_then(|c| c.class())
}

/// Luminance along `line` (picture coordinates), x in picture pixels from its start.
pub fn profile_along(frame: &Frame, line: [Pos2; 2]) -> Vec<[f64; 2]> {
    let px = Vec2::new(frame.width as f32, frame.height as f32);
    let length = ((line[1] - line[0]) * px).length();
    let steps = (length.ceil() as usize).max(2);
    (0..=steps)
        .filter_map(|k| {
            let t = k as f32 / steps as f32;
            let u = line[0] + (line[1] - line[0]) * t;
            sample(frame, u).map(|l| [f64::from(t * length), l])
        })
        .collect()
}

fn class_hover(case: ClipCase) -> &'static str {
    match case {
        ClipCase::Visible => "Above the horizon before and after M^-1: shaded as fitted",
        ClipCase::Lifted => {
            "Below the horizon but lifted above it by M^-1 (of either lobe, specular or diffuse): glows unless the case-1 rule clips it. The other lobe may stay below: with both rules off, that part is negative"
        }
        ClipCase::PushedBelow => {
            "Above the horizon but pushed below by M^-1 (of either lobe): negative light unless the case-2 rule clips it"
        }
        ClipCase::StaysBelow => {
            "Below the horizon and still below after M^-1: either rule removes it; with both rules off it is negative light"
        }
    }
}
