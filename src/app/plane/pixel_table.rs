//! The plane's pinned pixel opened into its lights: its two sides' radiance and their
//! difference, and a table of its lights — where each is before and after M^-1, its clipping
//! case, D, the Jacobian, the magnitudes and Fresnel, E, and its contribution to either side
//! with its share of their difference — sortable by any column. The sides are LTC and the
//! exact BRDF, or (two tables compared) LTC with table A and with table B. A row's click
//! shows that light on the lobe panel.

use glam::DVec3;

use serde::{Deserialize, Serialize};

use crate::app::lab::{Lab, LobeView, Selection, SideB, parts};
use crate::app::work::cache::{Cached, Own};
use crate::colormap::short_number;
use crate::light::ShapeKind;
use crate::ltc::ClipCase;
use crate::metrics::luminance;
use crate::pixel::{LightTerm, PixelTerms, elevation_azimuth, pixel_terms};
use crate::render::ShapeMethod;

/// At most this many rows (the largest contributions first when sorted so): a table of
/// 20 000 lights is unreadable, and the sums above it cover every light.
const MAX_ROWS: usize = 200;

/// The columns of the pinned pixel's lights table (sortable).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum LightColumn {
    Index,
    Elevation,
    ElevationCos,
    Case,
    DSpec,
    Jacobian,
    Fresnel,
    Irradiance,
    Ltc,
    Exact,
    ErrorShare,
}

/// The pinned pixel's lights, made again only when what they are made from changes: every
/// light in f64 takes 17 ms at 100 000 lights (release build, 2-core CPU), a whole frame, and
/// the lab repaints every frame while the plane is summed.
pub struct PinnedLights {
    terms: Cached<Option<PixelTerms>>,
    /// The method file's value of each light at the pinned pixel, on the GPU, and what it was
    /// made for (the terms' count, the file, the sides' forms).
    file: Option<(FileKey, FileValues)>,
}

/// What the file's values were made for: the terms made (their count), the file
/// (`MethodFile::id`), and the sides' point forms.
type FileKey = (u64, Option<u64>, [crate::render::Method; 2]);

/// The file's name and each light's radiance by it, or why there is none.
pub type FileValues = Result<Option<(String, Vec<DVec3>)>, String>;

impl Default for PinnedLights {
    fn default() -> Self {
        Self {
            terms: Cached::new("plane.pinned"),
            file: None,
        }
    }
}

impl PinnedLights {
    /// The terms of the pixel `pinned` (image coordinates 0–1) of a `size` image, with table
    /// A (and B, where two tables are compared), as the plane renders it; `None`: none
    /// pinned, or it is off the plane.
    pub fn update(&mut self, lab: &Lab, pinned: Option<[f64; 2]>, size: (usize, usize)) {
        let inputs = (
            lab.stage(),
            lab.material(),
            lab.lights(),
            lab.overrides(),
            lab.side_b(),
            lab.rules(),
            lab.tables(),
            lab.shape_forms(),
            Own((pinned, size)),
        );
        self.terms.get(
            inputs,
            |(
                stage,
                material,
                lights,
                overrides,
                side_b,
                rules,
                tables,
                shapes,
                Own((pinned, (width, height))),
            )| {
                let [u, v] = pinned?;
                let scene = parts::scene(stage, material, lights, &Default::default());
                let scene = parts::shaded(scene, overrides);
                let p =
                    scene.surface_point_at(u * width as f64, v * height as f64, width, height)?;
                let b = (**side_b == SideB::TableB).then_some(&tables.b().lut);
                let sides = (&shapes.ltc, &shapes.brdf);
                pixel_terms(&scene, (&tables.a().lut, b), &p, rules, sides)
            },
        );
    }

    /// The method file's values at the pinned pixel (`probe`: the plane's GPU probe), made
    /// again when the pixel's terms, the file or the sides change.
    pub fn update_file(
        &mut self,
        lab: &Lab,
        pinned: Option<[f64; 2]>,
        probe: impl FnOnce([f64; 2]) -> Option<Result<Option<Vec<DVec3>>, String>>,
    ) {
        let file = lab.method_file();
        let key: FileKey = (
            self.terms.count().1,
            file.map(crate::gpu::method_file::MethodFile::id),
            [lab.forms().ltc, lab.forms().brdf],
        );
        if self.file.as_ref().is_some_and(|(k, _)| *k == key) {
            return;
        }
        let values = match (pinned, file) {
            (Some(at), Some(f)) => match probe(at) {
                Some(Ok(v)) => Ok(v.map(|v| (f.name.clone(), v))),
                Some(Err(e)) => Err(e),
                None => Ok(None),
            },
            _ => Ok(None),
        };
        self.file = Some((key, values));
    }

    /// The method file's values at the pinned pixel, as last made.
    pub fn file(&self) -> Option<&FileValues> {
        self.file.as_ref().map(|(_, v)| v)
    }

    /// The pinned pixel's lights, as last made.
    pub fn terms(&self) -> Option<&PixelTerms> {
        self.terms.last()?.as_ref()
    }

    pub fn count(&self) -> (&'static str, u64) {
        self.terms.count()
    }
}

/// The columns both comparisons share: where the light is and the factors of table A's LTC.
const COLUMNS: [(LightColumn, &str, &str); 8] = [
    (
        LightColumn::Index,
        "#",
        "The light's index in the scene; click it to show the light on the lobe panel",
    ),
    (
        LightColumn::Elevation,
        "ω elev, az",
        "Toward the light in the shading frame: elevation above the plane and azimuth from the view's side, degrees",
    ),
    (
        LightColumn::ElevationCos,
        "ω' elev, az",
        "ω' = M^-1 ω (specular lobe, table A): where the clamped cosine sees the light",
    ),
    (
        LightColumn::Case,
        "case",
        "visible; case 1: below, lifted by M^-1; case 2: above, pushed below; below, stays below",
    ),
    (
        LightColumn::DSpec,
        "D_s, D_d",
        "The specular and diffuse D(ω) of table A with the rules in force (1/sr)",
    ),
    (
        LightColumn::Jacobian,
        "J",
        "|M^-1| / |M^-1 ω|³ (specular): how M^-1 stretches solid angle toward ω",
    ),
    (
        LightColumn::Fresnel,
        "F(v·h)",
        "The exact BRDF's Schlick Fresnel toward this light (the LTC's is folded into the pixel's specular magnitude, above)",
    ),
    (
        LightColumn::Irradiance,
        "E",
        "I·w(d)/d² on luminance (w: the range window)",
    ),
];

/// The columns of the two sides compared, LTC against the exact BRDF. The same three
/// `LightColumn`s (and their sort) stand for table A, table B and their share where two
/// tables are compared (`TABLE_COLUMNS`).
const BRDF_COLUMNS: [(LightColumn, &str, &str); 3] = [
    (
        LightColumn::Ltc,
        "LTC",
        "This light's LTC radiance (luminance)",
    ),
    (
        LightColumn::Exact,
        "exact",
        "This light's exact radiance (luminance)",
    ),
    (
        LightColumn::ErrorShare,
        "error share",
        "(L_LTC − L_exact) of this light over the pixel's; the shares sum to 100%",
    ),
];

const TABLE_COLUMNS: [(LightColumn, &str, &str); 3] = [
    (
        LightColumn::Ltc,
        "table A",
        "This light's LTC radiance with table A (luminance)",
    ),
    (
        LightColumn::Exact,
        "table B",
        "This light's LTC radiance with table B (luminance), the same LTC form and rules",
    ),
    (
        LightColumn::ErrorShare,
        "share of |A−B|",
        "|L_A − L_B| of this light over the sum of every light's |L_A − L_B|: which lights make the tables differ here; the shares sum to 100%",
    ),
];

/// Whether the terms compare two tables (else LTC against the exact BRDF).
fn tables_compared(t: &PixelTerms) -> bool {
    t.ltc_b.is_some()
}

fn sort_key(t: &PixelTerms, l: &LightTerm, c: LightColumn) -> f64 {
    match c {
        LightColumn::Index => l.index as f64,
        LightColumn::Elevation => elevation_azimuth(l.omega).0,
        LightColumn::ElevationCos => elevation_azimuth(l.omega_cos).0,
        LightColumn::Case => l.case.index() as f64,
        LightColumn::DSpec => l.d_spec,
        LightColumn::Jacobian => l.jacobian,
        LightColumn::Fresnel => l.fresnel,
        LightColumn::Irradiance => l.irradiance,
        LightColumn::Ltc => luminance(l.ltc),
        LightColumn::Exact => luminance(l.side_b()),
        LightColumn::ErrorShare if tables_compared(t) => t.difference_share(l),
        LightColumn::ErrorShare => t.error_share(l).abs(),
    }
}

/// The rows in the table's order.
pub fn sorted_rows(t: &PixelTerms, (column, descending): (LightColumn, bool)) -> Vec<&LightTerm> {
    let mut rows: Vec<&LightTerm> = t.terms.iter().collect();
    rows.sort_by(|a, b| {
        let o = sort_key(t, a, column).total_cmp(&sort_key(t, b, column));
        if descending { o.reverse() } else { o }
    });
    rows
}

/// The readout's sums under the sides' `names` (the split's, `plane::sized_side_names`),
/// then the lights table in `table_height` points: the method file's rows first, where a
/// side shades with one.
pub fn show(
    ui: &mut egui::Ui,
    (pinned, sort): (&mut Option<[f64; 2]>, &mut (LightColumn, bool)),
    lab: &mut Lab,
    (terms, file): (Option<&PixelTerms>, Option<&FileValues>),
    (names, table_height): ((&str, &str), f32),
) {
    let Some(t) = terms else {
        return;
    };
    let file_sum = match file {
        Some(Ok(Some((_, values)))) => Some(values.iter().sum::<DVec3>()),
        _ => None,
    };
    readout(ui, (pinned, lab), t, (names, file_sum));
    let rows = sorted_rows(t, *sort);
    let value_columns = if tables_compared(t) {
        TABLE_COLUMNS
    } else {
        BRDF_COLUMNS
    };
    egui::ScrollArea::both()
        .id_salt("pixel lights")
        .max_height(table_height)
        .auto_shrink([false, true])
        .show(ui, |ui| {
            file_rows(ui, &rows, file);
            egui::Grid::new("pixel lights grid")
                .striped(true)
                .spacing([10.0, 2.0])
                .show(ui, |ui| {
                    for (c, name, hover) in COLUMNS.into_iter().chain(value_columns) {
                        header(ui, sort, (c, name, hover));
                    }
                    ui.end_row();
                    for l in rows.iter().take(MAX_ROWS) {
                        row(ui, lab, t, l);
                        ui.end_row();
                    }
                });
            if rows.len() > MAX_ROWS {
                ui.small(format!(
                    "… {} more lights (their sums are above)",
                    rows.len() - MAX_ROWS
                ));
            }
            sized_rows(ui, &rows);
        });
}

/// The method file's value of each light (the table's first rows, above the lab's), evaluated on the GPU at
/// this pixel, beside the CPU's LTC and exact values of the same light.
fn file_rows(ui: &mut egui::Ui, rows: &[&LightTerm], file: Option<&FileValues>) {
    match file {
        Some(Ok(Some((name, values)))) => {
            let lights: Vec<(usize, Vec<DVec3>)> = rows
                .iter()
                .take(MAX_ROWS)
                .filter_map(|l| Some((l.index, vec![*values.get(l.index)?, l.ltc, l.exact])))
                .collect();
            let title = format!("each light by the method file {name} (on the GPU)");
            let methods = [
                (
                    name.as_str(),
                    "The method file's radiance of this light alone at this pixel, evaluated on the GPU by the plane shader's probe",
                ),
                ("ltc", "The lab's LTC (table A) in f64 on the CPU"),
                (
                    "exact",
                    "The exact BRDF (or the shape's exact integral) in f64 on the CPU",
                ),
            ];
            method_rows(ui, &title, (&methods, 2), &lights);
        }
        Some(Err(e)) => {
            ui.colored_label(
                egui::Color32::LIGHT_RED,
                format!("the method file's values: {e}"),
            );
        }
        _ => {}
    }
}

/// A side's name from the split's (`plane::sized_side_names`: the side, then a line per
/// shape with a size) on one line: "threejs-rect.wgsl (rect: file)".
fn one_line(name: &str) -> String {
    let mut lines = name.lines();
    let first = lines.next().unwrap_or_default();
    let rest: Vec<&str> = lines.collect();
    if rest.is_empty() {
        first.to_string()
    } else {
        format!("{first} ({})", rest.join(", "))
    }
}

/// The pixel's sides, each named by its method as the split names it, and their difference,
/// its magnitudes, and the unpin button. Side A is the method file's sum over the lights,
/// read on the GPU (`file_sum`), where a side shades with one; else table A's LTC on the CPU.
fn readout(
    ui: &mut egui::Ui,
    (pinned, lab): (&mut Option<[f64; 2]>, &mut Lab),
    t: &PixelTerms,
    ((a_name, b_name), file_sum): ((&str, &str), Option<DVec3>),
) {
    let [u, v] = pinned.unwrap_or_default();
    let file_shades = lab.method_file().is_some() && lab.forms().ltc == crate::render::Method::File;
    let (a_name, a) = match file_sum {
        Some(sum) => (one_line(a_name), luminance(sum)),
        // The file's values are read on the GPU after the pixel's terms: until then (or where
        // the probe failed, said under the table) side A is the lab's own LTC.
        None if file_shades => ("LTC (the lab's, f64)".to_string(), luminance(t.ltc)),
        None => (one_line(a_name), luminance(t.ltc)),
    };
    let b = luminance(t.side_b());
    let b_name = one_line(b_name);
    let (a_name, b_name) = if tables_compared(t) && file_sum.is_none() {
        (format!("table {a_name}"), format!("table {b_name}"))
    } else {
        (a_name, b_name)
    };
    let difference = 100.0 * (a - b) / b.abs().max(1e-300);
    let (sides, hover) = if tables_compared(t) {
        (
            format!(
                "{a_name} {} | {b_name} {} (luminance), difference {difference:+.2}%",
                short_number(a),
                short_number(b),
            ),
            "Side A against the same LTC form with table B, the rules in force, in f64 on the CPU (a \
                method file's values on the GPU); it updates with every change",
        )
    } else {
        (
            format!(
                "{a_name} {} | {b_name} {} (luminance), error {difference:+.2}%",
                short_number(a),
                short_number(b),
            ),
            "Side A (LTC with table A and the rules in force, in f64 on the CPU; a method file's sum \
                over the lights, on the GPU) against the exact BRDF in f64; it updates with every change",
        )
    };
    ui.horizontal_wrapped(|ui| {
        ui.label(format!(
            "pinned ({u:.3}, {v:.3}), θo {:.1}°: {sides}, {} lights",
            t.theta_o.to_degrees(),
            t.terms.len()
        ))
        .on_hover_text(hover);
        if let Some(l) = t.terms.first() {
            ui.small(format!(
                "magnitudes: specular F0·n_s + (1−F0)·f_s = {}, diffuse n_d = {}",
                short_number(l.spec_magnitude),
                short_number(l.diff_magnitude)
            ))
            .on_hover_text(
                "Table A's LTC lobes' magnitudes at this pixel's θo (the same for all its lights)",
            );
        }
        if !tables_compared(t) {
            ui.small("error share: a light's LTC − exact over the pixel's (the shares sum to 100%; lights that err both ways give shares beyond ±100%)");
        }
        if ui.small_button("unpin").clicked() {
            *pinned = None;
            lab.edit(|v: &mut LobeView| {
                v.light = None;
                v.polygon = None;
            });
        }
    });
}

/// Each light with a size by every method of its shape, against the exact integral (the
/// renders' rule), in the table's order: what each engine's choice gives at this pixel.
fn sized_rows(ui: &mut egui::Ui, rows: &[&LightTerm]) {
    for kind in ShapeKind::sized() {
        let lights: Vec<(usize, Vec<DVec3>)> = rows
            .iter()
            .filter(|l| l.by_method.first().is_some_and(|(m, _)| m.kind() == kind))
            .map(|l| (l.index, l.by_method.iter().map(|(_, v)| *v).collect()))
            .take(MAX_ROWS)
            .collect();
        let all = ShapeMethod::all(kind);
        let methods: Vec<(&str, &str)> = all.iter().map(|m| (m.name(), m.describe())).collect();
        let exact = ShapeMethod::reference(kind);
        let exact_at = all.iter().position(|&m| m == exact).unwrap_or(0);
        method_rows(ui, kind.lights_title(), (&methods, exact_at), &lights);
    }
}

/// One grid of `sized_rows`, titled `title`: a light a row, a method (name,
/// description) a column, each value's error against the column `exact_at`'s.
fn method_rows(
    ui: &mut egui::Ui,
    title: &str,
    (methods, exact_at): (&[(&str, &str)], usize),
    lights: &[(usize, Vec<DVec3>)],
) {
    if lights.is_empty() {
        return;
    }
    ui.small(format!(
        "{title}, by each method (luminance; error against exact):"
    ));
    egui::Grid::new(("pixel sized lights", title))
        .striped(true)
        .spacing([10.0, 2.0])
        .show(ui, |ui| {
            ui.small("light");
            for (name, describe) in methods {
                ui.small(*name).on_hover_text(*describe);
            }
            ui.end_row();
            for (index, values) in lights {
                ui.monospace(index.to_string());
                let exact = luminance(values[exact_at]);
                for (k, &v) in values.iter().enumerate() {
                    let l = luminance(v);
                    if k == exact_at {
                        ui.monospace(short_number(l));
                    } else {
                        let error = 100.0 * (l - exact) / exact.abs().max(1e-300);
                        ui.monospace(format!("{} ({error:+.1}%)", short_number(l)));
                    }
                }
                ui.end_row();
            }
        });
}

/// A column's header: a button that sorts by it (again: the other way round).
fn header(
    ui: &mut egui::Ui,
    sort: &mut (LightColumn, bool),
    (c, name, hover): (LightColumn, &str, &str),
) {
    let arrow = match *sort {
        (sorted, true) if sorted == c => " v",
        (sorted, false) if sorted == c => " ^",
        _ => "",
    };
    if ui
        .small_button(format!("{name}{arrow}"))
        .on_hover_text(hover)
        .clicked()
    {
        *sort = if sort.0 == c { (c, !sort.1) } else { (c, true) };
    }
}

fn row(ui: &mut egui::Ui, lab: &mut Lab, t: &PixelTerms, l: &LightTerm) {
    // Within 1e-3 (0.06°): a view saved from a render of another size pins the same place
    // on the image, whose ω differs in the last digits.
    let shown = lab
        .lobe_view()
        .light
        .is_some_and(|w| glam::DVec3::from(w).distance(l.omega) < 1e-3);
    if ui
        .selectable_label(shown, format!("{}", l.index))
        .on_hover_text("Show this light's ω and M^-1 ω on the lobe panel, at this pixel's θo")
        .clicked()
    {
        lab.set(Selection {
            light: Some(l.index),
        });
        lab.edit(|v: &mut LobeView| {
            v.light = (!shown).then_some(l.omega.to_array());
            v.polygon = l
                .corners
                .filter(|_| !shown)
                .map(|c| c.map(|w| w.to_array()));
            v.theta_o_deg = t.theta_o.to_degrees();
        });
    }
    let angles = |w| {
        let (e, a) = elevation_azimuth(w);
        format!("{e:.1}°, {a:.0}°")
    };
    ui.monospace(angles(l.omega));
    ui.monospace(angles(l.omega_cos));
    // ω' is the specular lobe's; where the case is the diffuse lobe's artifact, say so.
    if l.case == ClipCase::of(l.omega, l.omega_cos) {
        ui.small(l.case.name());
    } else {
        ui.small(format!("{} (diffuse lobe)", l.case.name()));
    }
    ui.monospace(format!(
        "{}, {}",
        short_number(l.d_spec),
        short_number(l.d_diff)
    ));
    ui.monospace(short_number(l.jacobian));
    ui.monospace(format!("{:.4}", l.fresnel));
    ui.monospace(short_number(l.irradiance));
    ui.monospace(short_number(luminance(l.ltc)));
    ui.monospace(short_number(luminance(l.side_b())));
    if tables_compared(t) {
        ui.monospace(format!("{:.1}%", 100.0 * t.difference_share(l)));
    } else {
        ui.monospace(format!("{:+.1}%", 100.0 * t.error_share(l)));
    }
}
