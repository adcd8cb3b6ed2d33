//! The side panel's material: α (or α_x, α_y and the tangent), the view angle the lobe and
//! matrix panels show, F0 and the base colour.

use crate::app::lab::{Lab, LobeView};
use crate::ltc::lut::ALPHA_MIN;
use crate::scene::{ANISO_PRESETS, Material};

pub(super) fn material(ui: &mut egui::Ui, lab: &mut Lab) {
    ui.strong("Material");
    ui.horizontal_wrapped(|ui| {
        lab.edit(|m: &mut Material| anisotropic_switch(ui, m));
        super::lights::preset_row(
            ui,
            lab,
            &ANISO_PRESETS,
            "Brushed metal (α_x ≫ α_y): the streak a rect light or spheres draw across it",
        );
    });
    lab.edit(|m: &mut Material| roughness(ui, m));
    let anisotropic = lab.material().is_anisotropic();
    lab.edit(|v: &mut LobeView| {
        ui.add(egui::Slider::new(&mut v.theta_o_deg, 0.0..=90.0).text("θo (°)"))
            .on_hover_text("View angle of the lobe and matrix panels: v = (sin θo cos φo, sin θo sin φo, cos θo); the LUT row is sqrt(1 − cos θo)");
        // An isotropic lobe is the same at every azimuth: the slider shows only where it
        // changes something.
        if anisotropic {
            ui.add(egui::Slider::new(&mut v.phi_o_deg, 0.0..=360.0).text("φo (°)"))
                .on_hover_text("The view's azimuth from the tangent, which only an anisotropic material sees: the 4D table's fourth axis");
        }
    });
    lab.edit(|m: &mut Material| {
        ui.add(egui::Slider::new(&mut m.f0, 0.0..=1.0).text("F0"))
            .on_hover_text("Schlick: F = F0 + (1 − F0)(1 − v·h)⁵; in the LTC, the specular magnitude F0·n_s + (1 − F0)·f_s");
        ui.horizontal(|ui| {
            let mut c = m.base_color.map(|x| x as f32);
            if ui
                .color_edit_button_rgb(&mut c)
                .on_hover_text("Base colour c: fd = c/π (…)(…); in the LTC, c · n_d · D_d")
                .changed()
            {
                m.base_color = c.map(f64::from);
            }
            ui.label("base colour");
        });
    });
}

/// The switch between one α and two.
fn anisotropic_switch(ui: &mut egui::Ui, m: &mut Material) {
    let mut anisotropic = m.alpha_y.is_some();
    if ui
        .checkbox(&mut anisotropic, "anisotropic")
        .on_hover_text("Brushed metal: α_x along the tangent, α_y along the bitangent, shaded with the 4D table \
            (table A's, and B's on side B); off, one α and the 2D table as before")
        .changed()
    {
        // Starts stretched along the tangent, so that the change is seen at once.
        m.alpha_y = anisotropic.then(|| (m.alpha * 0.25).max(ALPHA_MIN));
    }
}

/// One α while the material is isotropic; α_x, α_y and the tangent's angle once it is not.
fn roughness(ui: &mut egui::Ui, m: &mut Material) {
    let Some(alpha_y) = m.alpha_y.as_mut() else {
        ui.add(
            egui::Slider::new(&mut m.alpha, 1e-3..=1.0)
                .logarithmic(true)
                .text("α"),
        )
        .on_hover_text(
            "GGX α: D = α² / (π ((n·h)²(α²−1)+1)²), Λ = (−1+sqrt(1+α² tan²θ))/2; also the LUT \
                 column (r = sqrt α) the LTC comes from",
        );
        let mut r = m.alpha.sqrt();
        if ui
            .add(egui::Slider::new(&mut r, 0.0316..=1.0).text("roughness r = √α"))
            .on_hover_text("Perceptual roughness; α = r². Burley's FD = 0.5 + 2α(l·h)² uses the paper's α (ltc_code and Unity use √α)")
            .changed()
        {
            m.alpha = (r * r).max(ALPHA_MIN);
        }
        return;
    };
    ui.add(
        egui::Slider::new(&mut m.alpha, 1e-3..=1.0)
            .logarithmic(true)
            .text("α_x"),
    )
    .on_hover_text(
        "GGX α along the tangent: D = 1 / (π α_x α_y ((h_x/α_x)² + (h_y/α_y)² + h_z²)²)",
    );
    ui.add(
        egui::Slider::new(alpha_y, 1e-3..=1.0)
            .logarithmic(true)
            .text("α_y"),
    )
    .on_hover_text("GGX α along the bitangent; Burley's diffuse takes (α_x + α_y)/2");
    ui.add(egui::Slider::new(&mut m.tangent_degrees, -180.0..=180.0).text("tangent (°)"))
        .on_hover_text("The tangent's angle on the plane from the world's +x toward +y: the brushing's direction, along which α_x acts");
}
