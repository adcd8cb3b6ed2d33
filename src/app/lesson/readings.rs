//! The numbers a step's text quotes, read from the lab at the step's view when it is shown
//! (docs/design.md §5.11), never typed into the text: `{fit_error}` in a step's text becomes
//! the pointwise error of table A's lobe at the lab's (θo, α). `{{` is a brace.

use glam::DVec3;

use crate::app::chart::studies::ShippedStudy;
use crate::app::lesson::Now;
use crate::gpu::work::Work;
use crate::ltc::fit::pointwise_error;
use crate::ltc::lobe::Lobe;
use crate::ltc::{Clipping, Normalization};
use crate::named::named_enum;
use crate::pixel::elevation_azimuth;
use crate::render::Method;

named_enum! {
    /// A number a step's text quotes, written `{name}` there: read from the lab at the step's
    /// view each time it is shown.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub enum Reading {
        Alpha = "alpha",
        ThetaO = "theta_o",
        F0 = "f0",
        Lights = "lights",
        MInv = "m_inv",
        Magnitude = "magnitude",
        FitError = "fit_error",
        PaperFactor = "paper_factor",
        LightElevation = "light_elevation",
        LightImage = "light_image",
        Jacobian = "jacobian",
        Glow = "glow",
        PinnedError = "pinned_error",
        PinnedLights = "pinned_lights",
        Speedup = "speedup",
        MeasuredOn = "measured_on",
        GpuStudy = "gpu_study",
        CpuStudy = "cpu_study",
        WorkBrdf = "work_brdf",
        WorkLtc = "work_ltc",
        WorkLtcFast = "work_ltc_fast",
    }
}

impl Reading {
    /// What it is, for the lesson's authors (the README lists these).
    pub fn describe(self) -> &'static str {
        match self {
            Self::Alpha => "the material's GGX α",
            Self::ThetaO => "θo, degrees",
            Self::F0 => "Schlick's F0",
            Self::Lights => "the scene's light count",
            Self::MInv => {
                "table A's specular M^-1 at (θo, α), divided by its m11 as the table stores it"
            }
            Self::Magnitude => "the specular lobe's magnitude F0·n + (1 − F0)·f at (θo, α)",
            Self::FitError => "table A's pointwise error of the specular lobe at (θo, α), %",
            Self::PaperFactor => {
                "how much brighter the printed eq. 25 shades than the corrected one"
            }
            Self::LightElevation => "the lobe panel's light's elevation, degrees",
            Self::LightImage => "its image M^-1ω's elevation, degrees",
            Self::Jacobian => {
                "eq. 18's det M^-1 over the cube of M^-1ω's length, at the lobe panel's light"
            }
            Self::Glow => "the lobe panel's light's unclipped D over D along the lobe's axis, %",
            Self::PinnedError => "the pinned pixel's relative error LTC vs BRDF, %",
            Self::PinnedLights => "the pinned pixel's light count",
            Self::Speedup => "the chart's brdf time over its ltc-fast time",
            Self::MeasuredOn => {
                "where the chart's times come from: a study the lab ships, or this machine's device"
            }
            Self::GpuStudy => {
                "brdf's time over ltc-fast's per light count, in the H100 study the lab ships"
            }
            Self::CpuStudy => "the same in the lavapipe study the lab ships",
            Self::WorkBrdf => "brdf's work per light, counted from its shader",
            Self::WorkLtc => "ltc's work per light, counted from its shader",
            Self::WorkLtcFast => "ltc-fast's work per light, counted from its shader",
        }
    }
}

/// Strata per side of the pointwise error (the shipped tables' `err` channel's, and the
/// refit's).
const ERROR_SAMPLES: usize = 64;

/// Whether every `{name}` in `text` is a reading (and every brace closed).
pub fn check_placeholders(text: &str) -> Result<(), String> {
    fill(text, |name| reading_named(name).map(|_| String::new())).map(drop)
}

/// The reading `name` names, or why it is none.
fn reading_named(name: &str) -> Result<Reading, String> {
    Reading::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Reading::ALL.iter().map(|r| r.name()).collect();
        format!("{{{name}}} is not a reading ({})", names.join(", "))
    })
}

/// `text` with each `{name}` replaced by `value(name)`.
pub fn fill(
    text: &str,
    mut value: impl FnMut(&str) -> Result<String, String>,
) -> Result<String, String> {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(['{', '}']) {
        out.push_str(&rest[..at]);
        let tail = &rest[at..];
        if let Some(after) = tail.strip_prefix("{{").or_else(|| tail.strip_prefix("}}")) {
            out.push_str(&tail[..1]);
            rest = after;
            continue;
        }
        if tail.starts_with('}') {
            return Err("a '}' without its '{' (write }} for a brace)".into());
        }
        let end = tail
            .find('}')
            .ok_or("a '{' without its '}' (write {{ for a brace)")?;
        out.push_str(&value(&tail[1..end])?);
        rest = &tail[end + 1..];
    }
    out.push_str(rest);
    Ok(out)
}

/// The step's text with its readings, as the lab shows them now; `work` is each method's
/// work per light (counted once, by the caller).
pub fn read(text: &str, now: &Now<'_>, work: &Result<Vec<(Method, Work)>, String>) -> String {
    fill(text, |name| Ok(reading_named(name)?.value(now, work))).unwrap_or_else(|e| e)
}

impl Reading {
    /// Its value in words; "—" where the lab has no value for it yet (no light on the lobe, no
    /// pixel pinned, nothing measured).
    pub fn value(self, now: &Now<'_>, work: &Result<Vec<(Method, Work)>, String>) -> String {
        let lab = now.lab;
        let pair = lab.ltc_pair(&lab.tables().a().lut);
        let spec = pair.lobe(Lobe::Specular);
        let theta = lab.theta_o();
        let v = DVec3::new(theta.sin(), 0.0, theta.cos());
        let light = lab.lobe_view().light.map(DVec3::from);
        let none = || "—".to_string();
        let work_of = |m: Method| match work {
            Ok(w) => w
                .iter()
                .find(|(wm, _)| *wm == m)
                .map_or_else(none, |(_, w)| describe_work(w)),
            Err(e) => format!("(not counted: {e})"),
        };
        let ms = |m: Method| now.measurement.and_then(|x| x.ms_of(m.name()));
        match self {
            Self::Alpha => format!("{:.3}", lab.alpha()),
            Self::ThetaO => format!("{:.0}°", lab.lobe_view().theta_o_deg),
            Self::F0 => format!("{:.2}", lab.material().f0),
            Self::Lights => lab.lights().list.len().to_string(),
            Self::MInv => {
                let m = spec.cos_from_brdf / spec.cos_from_brdf.y_axis.y;
                format!(
                    "[[{:.3}, 0, {:.3}], [0, 1, 0], [{:.3}, 0, {:.3}]]",
                    m.x_axis.x, m.z_axis.x, m.x_axis.z, m.z_axis.z
                )
            }
            Self::Magnitude => format!("{:.3}", pair.spec_magnitude(lab.material().f0)),
            Self::FitError => format!(
                "{:.1}%",
                100.0 * pointwise_error(Lobe::Specular, v, lab.alpha(), spec, ERROR_SAMPLES)
            ),
            // Eq. 25 as printed: D without its 1/π, times nothing (docs/design.md §1.6).
            Self::PaperFactor => format!(
                "{:.1}×",
                std::f64::consts::PI / pair.spec_magnitude(lab.material().f0)
            ),
            Self::LightElevation => {
                light.map_or_else(none, |l| format!("{:.1}°", elevation_azimuth(l).0))
            }
            Self::LightImage => light.map_or_else(none, |l| {
                format!(
                    "{:.1}°",
                    elevation_azimuth((spec.cos_from_brdf * l).normalize()).0
                )
            }),
            Self::Jacobian => light.map_or_else(none, |l| {
                let w = spec.cos_from_brdf * l;
                format!("{:.3}", spec.det_cos_from_brdf / w.length().powi(3))
            }),
            Self::Glow => light.map_or_else(none, |l| {
                let d = |l: DVec3| spec.ltc_eval(l, Clipping::NONE, Normalization::Corrected);
                let axis = (spec.brdf_from_cos * DVec3::Z).normalize();
                format!("{:.2}%", 100.0 * d(l) / d(axis))
            }),
            Self::PinnedError => now
                .pinned
                .map_or_else(none, |p| format!("{:+.1}%", 100.0 * p.relative_error())),
            Self::PinnedLights => now.pinned.map_or_else(none, |p| p.terms.len().to_string()),
            Self::Speedup => match (ms(Method::Brdf), ms(Method::LtcFast)) {
                (Some(b), Some(f)) => format!("{:.2}×", b / f),
                _ => none(),
            },
            // A shipped study by its name; a measurement by its device's name alone (the
            // chart's label has its details).
            Self::MeasuredOn => now.measurement.map_or_else(none, |m| match &m.study {
                Some(name) => format!("the {name} study the lab ships"),
                None => {
                    let device = m.device.split(" (").next().unwrap_or(&m.device);
                    format!("this machine's {device}")
                }
            }),
            Self::GpuStudy => shipped_speedups(ShippedStudy::H100),
            Self::CpuStudy => shipped_speedups(ShippedStudy::Lavapipe),
            Self::WorkBrdf => work_of(Method::Brdf),
            Self::WorkLtc => work_of(Method::Ltc),
            Self::WorkLtcFast => work_of(Method::LtcFast),
        }
    }
}

/// brdf's time over ltc-fast's at each light count of the shipped study `name`, with its
/// device: "1.43× at 100 lights, 3.13× at 1000, … on NVIDIA H100 80GB HBM3".
fn shipped_speedups(study: ShippedStudy) -> String {
    let ratios = study
        .measurement()
        .and_then(|m| m.fps_ratios(Method::LtcFast, Method::Brdf));
    let Some((_, _, ratios)) = ratios else {
        return "—".into();
    };
    let ratios: Vec<String> = ratios
        .iter()
        .enumerate()
        .map(|(k, (n, r))| {
            let unit = if k == 0 { " lights" } else { "" };
            format!("{r:.2}× at {n}{unit}")
        })
        .collect();
    // The device's name without its details (the chart's label has them).
    let device = study.device();
    let device = device.split(" (").next().unwrap_or(device);
    format!("{} on {device}", ratios.join(", "))
}

/// A method's work per light in words.
fn describe_work(w: &Work) -> String {
    let of = |n: u32, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    format!(
        "{} arithmetic operations, {}, {}, {}",
        w.arithmetic,
        of(w.divisions, "division", "divisions"),
        of(
            w.special,
            "root or transcendental",
            "roots or transcendentals"
        ),
        of(w.reads, "read", "reads")
    )
}
