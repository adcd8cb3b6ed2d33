//! The clipping panel's pictures, made on a worker thread: per case row, (a) LTC and (b)
//! BRDF with the light above the plane, (c) LTC and (d) BRDF with the case's light, each
//! exposed to its own content; the case map; and the renders its profile reads. Sixteen CPU
//! renders of 192×108 take longer than a frame, and the UI thread never waits.

use std::sync::mpsc;

use egui::{Color32, Pos2};
use glam::DVec3;

use crate::app::clipping::setup::{ClipScene, ClipSetup};
use crate::app::ui::display::rgb;
use crate::colormap::{diverging, round_sig, short_number};
use crate::cpu::cases::{ClipCounts, clip_counts_map};
use crate::cpu::render;
use crate::ltc::lut::Lut;
use crate::ltc::{ClipCase, Clipping};
use crate::metrics::{LuminanceRange, luminance, luminance_range};
use crate::output::srgb_encode;
use crate::render::{Frame, LtcRules, Method, RenderSettings};

/// Size of each picture: the CPU reference renders all of them (one light each, ~2 ms).
pub const PICTURE: (usize, usize) = (192, 108);

/// The two rows: case 1 and case 2.
pub const ROWS: [ClipScene; 2] = [ClipScene::Case1, ClipScene::Case2];

/// The case map's class colours: grey for visible, the glow's orange for case 1, the
/// negative light's blue for case 2 (as in the diverging map), and a dark violet for the
/// harmless "stays below".
pub fn class_colour(class: ClipCase) -> Color32 {
    match class {
        ClipCase::Visible => Color32::from_rgb(120, 120, 128),
        ClipCase::Lifted => Color32::from_rgb(245, 150, 40),
        ClipCase::PushedBelow => Color32::from_rgb(60, 140, 255),
        ClipCase::StaysBelow => Color32::from_rgb(70, 45, 85),
    }
}

const BACKGROUND: Color32 = {
    let [r, g, b] = crate::output::BACKGROUND;
    Color32::from_rgb(r, g, b)
};

/// What the rows are rendered with: the lab's rules, the panel's α and lights, a table.
#[derive(Clone)]
pub struct RowsInput {
    pub rules: LtcRules,
    pub setup: ClipSetup,
    pub lut: Lut,
}

/// A picture exposed to its own content, and how.
pub struct Exposed {
    pub image: egui::ColorImage,
    /// The exposure factors of the positive and (if any) negative parts.
    pub factor: f64,
    pub negative_factor: Option<f64>,
}

/// One picture on the screen: its render, its texture, and how it was exposed.
pub struct Thumb {
    pub frame: Frame,
    pub texture: egui::TextureHandle,
    pub factor: f64,
    pub negative_factor: Option<f64>,
    pub caption: String,
}

/// A case row on the screen: its four pictures, its case map and the profile's renders.
pub struct CaseRow {
    pub thumbs: Vec<Thumb>,
    pub case_map: Vec<Option<ClipCounts>>,
    pub map_texture: egui::TextureHandle,
    /// Pixels per class, in `ClipCase::ALL`'s order.
    pub class_counts: [usize; 4],
    /// BRDF, LTC with both rules, LTC as toggled, LTC without this case's rule.
    pub profile_frames: [Frame; 4],
    /// The line through the case's strongest artifact, in picture coordinates (0–1).
    pub default_line: [Pos2; 2],
}

/// A case row as the worker makes it (images, not yet textures).
struct RowRenders {
    row: ClipScene,
    pictures: Vec<(Frame, Exposed, String)>,
    case_map: Vec<Option<ClipCounts>>,
    map_image: egui::ColorImage,
    class_counts: [usize; 4],
    profile_frames: [Frame; 4],
    default_line: [Pos2; 2],
}

/// The rows being made on a worker thread; a newer start drops an older one's result.
#[derive(Default)]
pub struct RowsWorker {
    rx: Option<mpsc::Receiver<Vec<RowRenders>>>,
}

impl RowsWorker {
    /// Starts making both rows from `input`, a row a step (the browser runs one per frame).
    pub fn start(&mut self, ctx: &egui::Context, input: RowsInput) {
        let (tx, rx) = mpsc::channel();
        let repaint = ctx.clone();
        let mut rows = Vec::new();
        crate::app::work::background::spawn_steps(
            "clipping rows",
            Box::new(move || {
                rows.push(render_row(&input, ROWS[rows.len()]));
                if rows.len() < ROWS.len() {
                    return false;
                }
                let _ = tx.send(std::mem::take(&mut rows));
                repaint.request_repaint();
                true
            }),
        );
        self.rx = Some(rx);
    }

    /// The rows, once made (their textures loaded into `ctx`).
    pub fn poll(&mut self, ctx: &egui::Context) -> Option<Vec<CaseRow>> {
        let rows = self.rx.as_ref()?.try_recv();
        match rows {
            Ok(rows) => {
                self.rx = None;
                Some(rows.into_iter().map(|r| upload(ctx, r)).collect())
            }
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => {
                self.rx = None;
                None
            }
        }
    }

    pub fn busy(&self) -> bool {
        self.rx.is_some()
    }
}

/// The rule that case `row` is about, off: what the profile's last line shows.
pub fn without_case_rule(row: ClipScene) -> Clipping {
    match row {
        ClipScene::Case2 => Clipping::CASE1,
        _ => Clipping::CASE2,
    }
}

/// One case's pictures, case map and profile renders, on the CPU.
fn render_row(input: &RowsInput, row: ClipScene) -> RowRenders {
    let (w, h) = PICTURE;
    let shot = |which: ClipScene, method: Method, clip: Clipping| {
        let mut r = RenderSettings::single(w, h, method);
        r.rules = LtcRules {
            clipping: clip,
            ..input.rules
        };
        render(&input.setup.scene(which, row), &input.lut, &r)
    };
    let clip = input.rules.clipping;
    let pictures = [
        ("(a) LTC ref.", shot(ClipScene::Normal, Method::Ltc, clip)),
        ("(b) BRDF ref.", shot(ClipScene::Normal, Method::Brdf, clip)),
        ("(c) LTC", shot(row, Method::Ltc, clip)),
        ("(d) BRDF", shot(row, Method::Brdf, clip)),
    ];
    let pictures: Vec<(Frame, Exposed, String)> = pictures
        .into_iter()
        .enumerate()
        .map(|(k, (name, frame))| {
            let exposed = expose(&frame);
            let caption = caption(name, k, clip, &exposed);
            (frame, exposed, caption)
        })
        .collect();
    let case_map = clip_counts_map(&input.setup.scene(row, row), &input.lut, w, h);
    let mut class_counts = [0; 4];
    for c in case_map.iter().flatten().filter_map(ClipCounts::class) {
        class_counts[c.index()] += 1;
    }
    let map_image = egui::ColorImage::new(
        [w, h],
        case_map
            .iter()
            .map(|c| c.and_then(|c| c.class()).map_or(BACKGROUND, class_colour))
            .collect(),
    );
    let both = shot(row, Method::Ltc, Clipping::BOTH);
    let without = shot(row, Method::Ltc, without_case_rule(row));
    let default_line = strongest_artifact_line(&without, &both);
    RowRenders {
        row,
        profile_frames: [
            shot(row, Method::Brdf, clip),
            both,
            pictures[2].0.clone(),
            without,
        ],
        pictures,
        case_map,
        map_image,
        class_counts,
        default_line,
    }
}

/// "(c) LTC, both rules +×12 −×3.4": the picture's name, the rules for (c), its exposure.
fn caption(name: &str, k: usize, clip: Clipping, e: &Exposed) -> String {
    let factor = |f: f64| format!("×{}", short_number(round_sig(f)));
    // `factor` is 1/max: finite and positive only where some light is positive.
    let positive = (e.factor.is_finite() && e.factor > 0.0).then(|| factor(e.factor));
    let exposure = match (positive, e.negative_factor) {
        (Some(p), Some(n)) => format!("+{p} −{}", factor(n)),
        (Some(p), None) => p,
        (None, Some(n)) => format!("−{} (all negative)", factor(n)),
        (None, None) => "black".into(),
    };
    let rules = match (k, clip == Clipping::BOTH) {
        (2, true) => ", both rules".to_string(),
        (2, false) => format!(", rules: {}", clip.name()),
        _ => String::new(),
    };
    format!("{name}{rules} {exposure}")
}

/// The worker's row with its images made textures.
fn upload(ctx: &egui::Context, r: RowRenders) -> CaseRow {
    let preset = r.row.preset();
    let thumbs = r
        .pictures
        .into_iter()
        .enumerate()
        .map(|(k, (frame, exposed, caption))| Thumb {
            texture: ctx.load_texture(
                format!("clip {preset} {k}"),
                exposed.image,
                egui::TextureOptions::LINEAR,
            ),
            frame,
            factor: exposed.factor,
            negative_factor: exposed.negative_factor,
            caption,
        })
        .collect();
    CaseRow {
        thumbs,
        case_map: r.case_map,
        map_texture: ctx.load_texture(
            format!("clip map {preset}"),
            r.map_image,
            egui::TextureOptions::NEAREST,
        ),
        class_counts: r.class_counts,
        profile_frames: r.profile_frames,
        default_line: r.default_line,
    }
}

/// A picture exposed to its own content: a positive one so that its brightest pixel is
/// white; a signed one in the diverging map, each sign scaled to its own peak.
pub fn expose(frame: &Frame) -> Exposed {
    let LuminanceRange { min, max, .. } = luminance_range(frame);
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
    Exposed {
        image: egui::ColorImage::new([frame.width, frame.height], pixels),
        factor,
        negative_factor,
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
pub fn sample(frame: &Frame, u: Pos2) -> Option<f64> {
    let x = ((u.x * frame.width as f32) as usize).min(frame.width - 1);
    let y = ((u.y * frame.height as f32) as usize).min(frame.height - 1);
    let k = y * frame.width + x;
    frame.on_plane[k].then(|| luminance(frame.pixels[k]))
}
