//! The side panel's lights: how many, where, how bright, each sized shape's methods and
//! fields, and the presets.

use crate::app::lab::parts::{RADIUS_RANGE, RANGE_RANGE};
use crate::app::lab::{Forms, Lab, Overrides, ShapeForms};
use crate::app::ui::widgets::explain;
use crate::light::ShapeKind;
use crate::render::ShapeMethod;
use crate::scene::{Light, preset, shape_presets};

use super::MAX_LIGHT_SLIDER;

pub(super) fn lights(ui: &mut egui::Ui, lab: &mut Lab) {
    let max = lab.max_lights().min(MAX_LIGHT_SLIDER);
    ui.strong("Lights");
    lab.edit(|o: &mut Overrides| {
        ui.add(
            egui::Slider::new(&mut o.intensity_scale, 0.01..=100.0)
                .logarithmic(true)
                .text("intensity ×"),
        )
        .on_hover_text("Multiplies every light's I in E = I/d² · w(d)");
        explain(ui, "× every light's I (not saved to the scene)");
        let range = ui
            .add(egui::Slider::new(&mut o.range, 0.0..=RANGE_RANGE[1]).text("range R"))
            .on_hover_text("The window w(d) = clamp(1 − (d/R)⁴, 0, 1)²; 0 keeps each light's own range (absent = ∞)");
        // In steps of the smallest range it shows (0.01): a range between 0 (each light's
        // own) and that showed as "0.00" beside a black plane.
        if range.changed() {
            o.range = (o.range / RANGE_RANGE[0]).round() * RANGE_RANGE[0];
        }
        explain(
            ui,
            if o.range > 0.0 {
                "every light fades to 0 at distance R"
            } else {
                "0: each light's own range from the scene"
            },
        );
    });
    if let Some(k) = lab.selection().light {
        let half_size = lab.stage().plane.half_size;
        lab.edit_light(k, |l| light_position(ui, k, l, half_size));
    }
    let mut count = lab.lights().list.len();
    ui.horizontal(|ui| {
        if ui
            .add(egui::Slider::new(&mut count, 0..=max).logarithmic(true).text("lights"))
            .on_hover_text(format!("Regenerates the lights with the seeded generator (replaces the current ones): N point \
                lights over the plane, heights 0.05–0.6, range 2, paper-100's intensities (past 100 \
                lights scaled down so that the total power stays paper-100's). At most {max} here: {}",
                if max < MAX_LIGHT_SLIDER { "this adapter's limit" } else { "the slider's" }))
            .changed()
        {
            lab.set_light_count(count);
        }
    });
    // The slider clamps a typed count without a word: say it where it was typed.
    if max < MAX_LIGHT_SLIDER && lab.lights().list.len() >= max {
        ui.small(format!("at most {max} lights: this adapter's limit"));
    }
    lab.edit(|f: &mut Forms| {
        ui.checkbox(&mut f.cull, "cull by range")
            .on_hover_text("Tiled culling: each 16×16 tile of the plane sums only the lights whose range reaches it. \
                The image is the same to the bit; with short ranges it is much faster")
    });
    egui::CollapsingHeader::new("lights with a size")
        .id_salt("sized lights")
        .show(ui, |ui| sized_lights(ui, lab));
}

/// How each side shades lights of `kind`, picked from the shape's methods (each described on
/// hover); a sphere's combos are named for the lights with a size, the others' by their shape.
fn shape_methods(ui: &mut egui::Ui, lab: &mut Lab, kind: ShapeKind) {
    let prefix = match kind {
        ShapeKind::Sphere => String::new(),
        _ => format!("{} ", kind.name()),
    };
    let noun = kind.light_noun();
    lab.edit(|f: &mut ShapeForms| {
        for (side, methods, hover) in [
            (
                "LTC side",
                &mut f.ltc,
                "How the LTC side (and table B) shades",
            ),
            ("reference side", &mut f.brdf, "How the BRDF side shades"),
        ] {
            let mut method = methods.of(kind);
            egui::ComboBox::from_label(format!("{prefix}{side}"))
                .selected_text(method.name())
                .show_ui(ui, |ui| {
                    for m in ShapeMethod::all(kind) {
                        ui.selectable_value(&mut method, m, m.name())
                            .on_hover_text(m.describe());
                    }
                })
                .response
                .on_hover_text(format!("{hover} {noun}"));
            methods.set(method);
        }
    });
    if let Some(emits) = kind.emits() {
        explain(ui, emits);
    }
    preset_buttons(
        ui,
        lab,
        shape_presets(kind),
        &format!("Load this failure case of {}", kind.lights_title()),
    );
}

/// Every light's radius, then how each side shades each shape with a size and its failure
/// presets (docs/design.md §1.10–§1.12).
fn sized_lights(ui: &mut egui::Ui, lab: &mut Lab) {
    lab.edit(|o: &mut Overrides| {
        ui.add(
            egui::Slider::new(&mut o.radius, 0.0..=RADIUS_RANGE[1])
                .logarithmic(true)
                .smallest_positive(RADIUS_RANGE[0])
                .text("radius r"),
        )
        .on_hover_text(
            "Every light a sphere of radius r, lighting a distant point as its point light does \
            (radiance I/(π r²)); 0 keeps each light's own radius (absent = a point)",
        );
        explain(
            ui,
            if o.radius > 0.0 {
                "every light a sphere of radius r"
            } else {
                "0: each light's own radius from the scene"
            },
        );
    });
    for (k, kind) in ShapeKind::sized().enumerate() {
        if k > 0 {
            ui.separator();
        }
        shape_methods(ui, lab, kind);
    }
}

/// Light `k`'s x, y (over the plane) and z, typed or dragged.
fn light_position(ui: &mut egui::Ui, k: usize, light: &mut Light, half_size: f64) {
    ui.horizontal(|ui| {
        ui.label(format!("light {k}"));
        for (i, (axis, range, hover)) in [
            ("x", -half_size..=half_size, "Across the plane"),
            ("y", -half_size..=half_size, "Along the plane, away from the camera"),
            ("z", -1.0..=3.0, "Height: below 0 the light is under the plane (clipping case 1). Shift-drag its marker for the same"),
        ]
        .into_iter()
        .enumerate()
        {
            let label = ui.label(axis);
            ui.add(egui::DragValue::new(&mut light.position[i]).speed(0.01).range(range).max_decimals(4))
                .labelled_by(label.id)
                .on_hover_text(hover);
        }
        // The shape's own sizes (`Shape::sizes`), each written back where it is dragged.
        for size in light.shape.sizes() {
            let label = ui.label(size.label);
            let was = (size.get)(light.shape);
            let mut value = was;
            ui.add(
                egui::DragValue::new(&mut value)
                    .speed(size.speed)
                    .range(size.range[0]..=size.range[1])
                    .max_decimals(4),
            )
            .labelled_by(label.id)
            .on_hover_text(size.hover);
            if value != was {
                light.shape = (size.set)(light.shape, value);
            }
        }
    });
}

/// A button per preset of `presets`, each loading its scene, in a row of their own.
pub(super) fn preset_buttons(
    ui: &mut egui::Ui,
    lab: &mut Lab,
    presets: &[(&str, &str)],
    hover: &str,
) {
    ui.horizontal_wrapped(|ui| preset_row(ui, lab, presets, hover));
}

/// The same buttons in the row being laid out.
pub(super) fn preset_row(ui: &mut egui::Ui, lab: &mut Lab, presets: &[(&str, &str)], hover: &str) {
    for (name, _) in presets {
        if ui.small_button(*name).on_hover_text(hover).clicked() {
            lab.use_scene(preset(name));
        }
    }
}
