//! How the chart draws each series (docs/design.md §4.6): one colour per method, a marker
//! shape per variant and light shape, the paper's reference greys, and the legend under
//! each plot.

use egui::Color32;

use crate::light::ShapeKind;
use crate::render::{Method, ShapeMethod};

/// A legend entry: the series' name, colour and marker (`None`: a dashed line).
pub(super) type Entry = (String, Color32, Option<egui_plot::MarkerShape>);

/// The series' names with their markers, under the plot: egui_plot's legend sits inside
/// the plot, over the points.
pub(super) fn legend(ui: &mut egui::Ui, entries: &[Entry]) {
    ui.horizontal_wrapped(|ui| {
        ui.spacing_mut().item_spacing = egui::vec2(4.0, 0.0);
        let font = egui::TextStyle::Small.resolve(ui.style());
        let ink = ui.visuals().text_color();
        for (name, colour, shape) in entries {
            // Marker and name as one widget, so that a row never ends with a lone marker.
            let text = ui.fonts_mut(|f| f.layout_no_wrap(name.clone(), font.clone(), ink));
            let size = egui::vec2(14.0 + text.size().x, text.size().y.max(10.0));
            let (rect, response) = ui.allocate_exact_size(size, egui::Sense::hover());
            response.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Label, true, name));
            let dot = egui::Rect::from_center_size(
                egui::pos2(rect.left() + 5.0, rect.center().y),
                egui::vec2(10.0, 10.0),
            );
            marker(ui.painter(), dot, *colour, *shape);
            ui.painter()
                .galley(rect.left_top() + egui::vec2(14.0, 0.0), text, ink);
            ui.add_space(8.0);
        }
    });
}

/// A legend's marker: the plot's marker shape, or a dash for a dashed line.
pub(super) fn marker(
    painter: &egui::Painter,
    rect: egui::Rect,
    colour: Color32,
    shape: Option<egui_plot::MarkerShape>,
) {
    use egui_plot::MarkerShape as M;
    let (c, r) = (rect.center(), rect.width() * 0.45);
    let stroke = egui::Stroke::new(1.5, colour);
    let polygon =
        |points: Vec<egui::Pos2>| egui::Shape::convex_polygon(points, colour, egui::Stroke::NONE);
    let at = |dx: f32, dy: f32| c + egui::vec2(dx * r, dy * r);
    let shape = match shape {
        None => egui::Shape::line_segment([at(-1.0, 0.0), at(1.0, 0.0)], stroke),
        Some(M::Circle) => egui::Shape::circle_filled(c, r, colour),
        Some(M::Square) => egui::Shape::rect_filled(
            egui::Rect::from_center_size(c, egui::vec2(1.6 * r, 1.6 * r)),
            0.0,
            colour,
        ),
        Some(M::Diamond) => polygon(vec![
            at(0.0, -1.0),
            at(1.0, 0.0),
            at(0.0, 1.0),
            at(-1.0, 0.0),
        ]),
        Some(M::Up) => polygon(vec![at(0.0, -1.0), at(1.0, 0.8), at(-1.0, 0.8)]),
        Some(M::Down) => polygon(vec![at(0.0, 1.0), at(-1.0, -0.8), at(1.0, -0.8)]),
        Some(M::Left) => polygon(vec![at(-1.0, 0.0), at(0.8, -1.0), at(0.8, 1.0)]),
        Some(M::Right) => polygon(vec![at(1.0, 0.0), at(-0.8, 1.0), at(-0.8, -1.0)]),
        Some(M::Plus) => egui::Shape::Vec(vec![
            egui::Shape::line_segment([at(-1.0, 0.0), at(1.0, 0.0)], stroke),
            egui::Shape::line_segment([at(0.0, -1.0), at(0.0, 1.0)], stroke),
        ]),
        Some(M::Cross | M::Asterisk) => egui::Shape::Vec(vec![
            egui::Shape::line_segment([at(-0.8, -0.8), at(0.8, 0.8)], stroke),
            egui::Shape::line_segment([at(-0.8, 0.8), at(0.8, -0.8)], stroke),
        ]),
    };
    painter.add(shape);
}

/// The paper's reference lines' colours (greys, so that no measured method shares them).
pub(super) const PAPER_BRDF_COLOUR: Color32 = Color32::from_gray(210);

pub(super) const PAPER_LTC_COLOUR: Color32 = Color32::from_gray(140);

/// One colour per method in every plot (grey for a point of no known method): egui_plot's
/// automatic colours follow the drawing order and differ between the two plots.
pub fn method_colour(method: Option<Method>) -> Color32 {
    const PALETTE: [Color32; 6] = [
        Color32::from_rgb(240, 150, 60),
        Color32::from_rgb(230, 90, 90),
        Color32::from_rgb(70, 140, 255),
        Color32::from_rgb(90, 210, 120),
        Color32::from_rgb(200, 110, 230),
        Color32::from_rgb(60, 210, 210),
    ];
    // The method file in white: the one point that is not the lab's.
    if method == Some(Method::File) {
        return Color32::WHITE;
    }
    let index = method.map(Method::index);
    index.map_or(Color32::from_gray(180), |k| PALETTE[k % PALETTE.len()])
}

/// A point's colour and marker: a shape's method ("rect ltc-proxy", a study's
/// "rect-ltc-proxy") in its shape's colour with a marker of its own among that shape's methods;
/// any other by its point method's colour and its variant's marker.
pub(super) fn point_marker(
    label: &str,
    method: Option<Method>,
) -> (Color32, egui_plot::MarkerShape) {
    sized_marker(label).unwrap_or((method_colour(method), variant_shape(label, method)))
}

/// The colours of the shapes with a size' methods, in `ShapeKind::sized`'s order (light blue,
/// amber, pink, green, then again), apart from each other and from the point methods'
/// `PALETTE`.
const SHAPE_COLOURS: [Color32; 4] = [
    Color32::from_rgb(150, 200, 255),
    Color32::from_rgb(250, 210, 80),
    Color32::from_rgb(255, 120, 180),
    Color32::from_rgb(140, 230, 140),
];

/// The colour of a light shape's methods and each method's marker, by its place among the
/// shape's methods; `None` for a label that names no shape's method.
pub(super) fn sized_marker(label: &str) -> Option<(Color32, egui_plot::MarkerShape)> {
    use egui_plot::MarkerShape::*;
    const SHAPES: [egui_plot::MarkerShape; 5] = [Circle, Diamond, Square, Cross, Up];
    let (family, method) = label.split_once([' ', '-'])?;
    let kind = ShapeKind::from_name(family).filter(|&k| k != ShapeKind::Point)?;
    let names: Vec<&str> = ShapeMethod::all(kind)
        .into_iter()
        .map(ShapeMethod::name)
        .collect();
    let colour = SHAPE_COLOURS[(kind.index() - 1) % SHAPE_COLOURS.len()];
    let k = names.iter().position(|n| *n == method)?;
    Some((colour, SHAPES[k % SHAPES.len()]))
}

/// The marker of a method's variant ("ltc-lut16" of ltc): a circle for the method itself,
/// another shape for each variant (by what its name adds to the method's), so that variants
/// of one colour stay apart.
pub(super) fn variant_shape(label: &str, method: Option<Method>) -> egui_plot::MarkerShape {
    let variant = method
        .and_then(|m| label.strip_prefix(m.name()))
        .unwrap_or(label);
    if variant.is_empty() {
        return egui_plot::MarkerShape::Circle;
    }
    // Any variant name maps to one of the nine other shapes, the same one every run.
    let k = variant
        .bytes()
        .fold(0usize, |h, b| h.wrapping_mul(31).wrapping_add(b.into()));
    egui_plot::MarkerShape::all()
        .nth(1 + k % 9)
        .unwrap_or(egui_plot::MarkerShape::Square)
}
