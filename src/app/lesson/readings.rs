//! The numbers a step's text quotes, read from the lab at the step's view when it is shown
//! (docs/design.md §5.11), never typed into the text: `{fit_error}` in a step's text becomes
//! the pointwise error of table A's lobe at the lab's (θo, α). `{{` is a brace.

use glam::DVec3;

use crate::app::chart::fps_ratios;
use crate::app::chart::studies::{SHIPPED_STUDIES, shipped_study, study_device};
use crate::app::lesson::Now;
use crate::gpu::work::Work;
use crate::ltc::fit::pointwise_error;
use crate::ltc::lobe::Lobe;
use crate::ltc::{Clipping, Normalization};
use crate::pixel::elevation_azimuth;
use crate::render::Method;

/// Every reading: its name in a text, and what it is (for the lesson's authors).
pub const READINGS: [(&str, &str); 21] = [
    ("alpha", "the material's GGX α"),
    ("theta_o", "θo, degrees"),
    ("f0", "Schlick's F0"),
    ("lights", "the scene's light count"),
    ("m_inv", "table A's specular M^-1 at (θo, α)"),
    (
        "magnitude",
        "the specular lobe's magnitude F0·n + (1 − F0)·f at (θo, α)",
    ),
    (
        "fit_error",
        "table A's pointwise error of the specular lobe at (θo, α), %",
    ),
    (
        "paper_factor",
        "how much brighter the printed eq. 25 shades than the corrected one",
    ),
    (
        "light_elevation",
        "the lobe panel's light's elevation, degrees",
    ),
    ("light_image", "its image M^-1ω's elevation, degrees"),
    (
        "jacobian",
        "eq. 18's |M^-1| / ‖M^-1ω‖³ at the lobe panel's light",
    ),
    (
        "glow",
        "the lobe panel's light's unclipped D over D along the lobe's axis, %",
    ),
    (
        "pinned_error",
        "the pinned pixel's relative error LTC vs BRDF, %",
    ),
    ("pinned_lights", "the pinned pixel's light count"),
    ("speedup", "the chart's brdf time over its ltc-fast time"),
    ("measured_on", "where the chart's times come from"),
    (
        "gpu_study",
        "brdf's time over ltc-fast's per light count, in the H100 study the lab ships",
    ),
    ("cpu_study", "the same in the lavapipe study the lab ships"),
    (
        "work_brdf",
        "brdf's work per light, counted from its shader",
    ),
    ("work_ltc", "ltc's work per light, counted from its shader"),
    (
        "work_ltc_fast",
        "ltc-fast's work per light, counted from its shader",
    ),
];

/// Strata per side of the pointwise error (the shipped tables' `err` channel's, and the
/// refit's).
const ERROR_SAMPLES: usize = 64;

/// Whether every `{name}` in `text` is a reading (and every brace closed).
pub fn check_placeholders(text: &str) -> Result<(), String> {
    fill(text, |name| {
        READINGS
            .iter()
            .any(|(n, _)| *n == name)
            .then(String::new)
            .ok_or_else(|| {
                let names: Vec<&str> = READINGS.iter().map(|(n, _)| *n).collect();
                format!("{{{name}}} is not a reading ({})", names.join(", "))
            })
    })
    .map(drop)
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
    fill(text, |name| Ok(reading(name, now, work))).unwrap_or_else(|e| e)
}

/// One reading, in words; "—" where the lab has no value for it yet.
fn reading(name: &str, now: &Now<'_>, work: &Result<Vec<(Method, Work)>, String>) -> String {
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
    let ms = |label: &str| now.measurement.and_then(|m| m.ms_of(label));
    match name {
        "alpha" => format!("{:.3}", lab.alpha()),
        "theta_o" => format!("{:.0}°", lab.lobe_view().theta_o_deg),
        "f0" => format!("{:.2}", lab.material().f0),
        "lights" => lab.lights().list.len().to_string(),
        "m_inv" => {
            let m = spec.cos_from_brdf / spec.cos_from_brdf.y_axis.y;
            format!(
                "[[{:.3}, 0, {:.3}], [0, 1, 0], [{:.3}, 0, {:.3}]]",
                m.x_axis.x, m.z_axis.x, m.x_axis.z, m.z_axis.z
            )
        }
        "magnitude" => format!("{:.3}", pair.spec_magnitude(lab.material().f0)),
        "fit_error" => format!(
            "{:.1}%",
            100.0 * pointwise_error(Lobe::Specular, v, lab.alpha(), spec, ERROR_SAMPLES)
        ),
        // Eq. 25 as printed: D without its 1/π, times nothing (docs/design.md §1.6).
        "paper_factor" => format!(
            "{:.1}×",
            std::f64::consts::PI / pair.spec_magnitude(lab.material().f0)
        ),
        "light_elevation" => light.map_or_else(none, |l| format!("{:.1}°", elevation_azimuth(l).0)),
        "light_image" => light.map_or_else(none, |l| {
            format!(
                "{:.1}°",
                elevation_azimuth((spec.cos_from_brdf * l).normalize()).0
            )
        }),
        "jacobian" => light.map_or_else(none, |l| {
            let w = spec.cos_from_brdf * l;
            format!("{:.3}", spec.det_cos_from_brdf / w.length().powi(3))
        }),
        "glow" => light.map_or_else(none, |l| {
            let d = |l: DVec3| spec.ltc_eval(l, Clipping::NONE, Normalization::Corrected);
            let axis = (spec.brdf_from_cos * DVec3::Z).normalize();
            format!("{:.2}%", 100.0 * d(l) / d(axis))
        }),
        "pinned_error" => now
            .pinned
            .map_or_else(none, |p| format!("{:+.1}%", 100.0 * p.relative_error())),
        "pinned_lights" => now.pinned.map_or_else(none, |p| p.terms.len().to_string()),
        "speedup" => match (ms("brdf"), ms("ltc-fast")) {
            (Some(b), Some(f)) => format!("{:.2}×", b / f),
            _ => none(),
        },
        // The reference study's name without its invitation to measure.
        "measured_on" => now.measurement.map_or_else(none, |m| {
            let device = m.device.as_str();
            device.split(" — ").next().unwrap_or(device).to_string()
        }),
        "gpu_study" => shipped_speedups("H100"),
        "cpu_study" => shipped_speedups("lavapipe"),
        "work_brdf" => work_of(Method::Brdf),
        "work_ltc" => work_of(Method::Ltc),
        "work_ltc_fast" => work_of(Method::LtcFast),
        other => format!("{{{other}}}"),
    }
}

/// brdf's time over ltc-fast's at each light count of the shipped study `name`, with its
/// device: "1.43× at 100 lights, 3.13× at 1000, … on NVIDIA H100 80GB HBM3".
fn shipped_speedups(name: &str) -> String {
    let study = SHIPPED_STUDIES.iter().find(|(n, ..)| *n == name);
    let ratios = shipped_study(name).and_then(|m| fps_ratios(&m, Method::LtcFast, Method::Brdf));
    let (Some((_, _, text)), Some((_, _, ratios))) = (study, ratios) else {
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
    let device = study_device(text);
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
