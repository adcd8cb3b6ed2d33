//! What the lab reads off its parts for the panels: the scene as given, as shaded and as a
//! stage; the material's α and the lobe view's θo; the LTC pair, the tangent frame and the
//! table's nearest cell there; the horizon remedy in force.

use glam::DVec3;

use super::{Lab, Lights, parts};
use crate::ltc::lut::THETA_MAX;
use crate::ltc::remedy::{Horizon, HorizonRule};
use crate::ltc::{Ltc, LtcPair};
use crate::scene::Scene;

impl Lab {
    /// The scene the parts make.
    pub fn scene(&self) -> Scene {
        parts::scene(
            self.stage(),
            self.material(),
            self.lights(),
            self.exposure(),
        )
    }

    /// The scene as shaded: every light's intensity multiplied, its range replaced where the
    /// overrides say.
    pub fn shaded_scene(&self) -> Scene {
        parts::shaded(self.scene(), self.overrides())
    }

    /// The scene without its lights: what camera rays and projections need (a drag reads it
    /// every frame, among up to 100 000 lights).
    pub fn stage_scene(&self) -> Scene {
        let no_lights = Lights {
            list: Vec::new(),
            seed: 0,
        };
        parts::scene(self.stage(), self.material(), &no_lights, self.exposure())
    }

    /// The camera's ray through pixel `(x, y)` of an image of `size`: eye and direction.
    pub fn scene_camera_ray(&self, x: f64, y: f64, size: (usize, usize)) -> (DVec3, DVec3) {
        self.stage_scene().camera_ray(x, y, size.0, size.1)
    }

    pub fn alpha(&self) -> f64 {
        self.material().alpha
    }

    /// θo in radians, within the tables' rows.
    pub fn theta_o(&self) -> f64 {
        self.lobe_view().theta_o_deg.to_radians().min(THETA_MAX)
    }

    /// The LTC pair of `lut` at the lobe and matrix panels' (θo, α), in the view's frame (x
    /// toward the view's azimuth): an anisotropic material's lobes come from the 4D table at
    /// (θo, φo) in its tangent frame, turned into the view's (`tangent_from_view`).
    pub fn ltc_pair(&self, lut: &crate::ltc::lut::Lut) -> LtcPair {
        let m = self.material();
        if !m.is_anisotropic() {
            return lut.sample(self.alpha(), self.theta_o().cos()).ltc_pair();
        }
        let turn = self.tangent_from_view();
        let v = turn * DVec3::new(self.theta_o().sin(), 0.0, self.theta_o().cos());
        let pair = lut.aniso_pair(m.roughness(), v);
        let turned = |l: &Ltc| Ltc::from_cos_from_brdf(l.cos_from_brdf * turn, l.norm, l.fresnel);
        LtcPair {
            spec: turned(&pair.spec),
            diff: turned(&pair.diff),
        }
    }

    /// The turn from the lobe view's frame (x toward the view's azimuth) to the material's
    /// tangent frame: by φo while the material is anisotropic, none while it is not.
    pub fn tangent_from_view(&self) -> glam::DMat3 {
        match self.material().is_anisotropic() {
            true => glam::DMat3::from_rotation_z(self.lobe_view().phi_o_deg.to_radians()),
            false => glam::DMat3::IDENTITY,
        }
    }

    /// The cell of table A nearest (θo, α): (column of α, row of θo).
    pub fn nearest_cell(&self) -> (usize, usize) {
        let lut = &self.tables().a().lut;
        lut.nearest_cell(self.alpha(), self.theta_o().cos())
    }

    /// The horizon remedy in use: the rule's, or the remedy whose table shades.
    pub fn horizon_remedy(&self) -> Horizon {
        let t = self.tables();
        let shipped = t.a().source == crate::tables::Source::Shipped(t.shipped);
        let by_table = Horizon::ALL
            .into_iter()
            .find(|h| shipped && h.table() == Some(t.shipped));
        match self.rules().horizon {
            HorizonRule::Eq30 => by_table.unwrap_or(Horizon::Eq30),
            HorizonRule::NlFit => Horizon::NlFit,
            HorizonRule::ExactBand => Horizon::ExactBand,
        }
    }
}
