//! `ltc-lab bench`'s table in Markdown (`measure::bench::run`'s rows): every row, then the
//! ratios of the same run — LTC over BRDF, culling, the horizon remedies, each shape's methods
//! and a method file's.

use crate::light::ShapeKind;
use crate::ltc::remedy::Horizon;
use crate::measure::bench::{
    BenchRow, PAPER_BRDF_FPS, PAPER_LIGHTS, PAPER_LTC_FPS, Sizing, range_text, sized_title,
};
use crate::render::{Method, ShapeMethod};

/// The table in Markdown: one row per method, light count and culling, then the speed-ups of
/// each LTC form over each BRDF form and of culling, and the paper's figures for reference.
pub fn markdown(rows: &[BenchRow], device: &str) -> String {
    let mut out = format!(
        "GPU: {device}\n\n| method | lights | size | cull | range | in range | ms (median) | ms (min–max) | bin ms | fps | G light-px/s |\n|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|\n"
    );
    for r in rows {
        let method = r.label();
        out.push_str(&format!(
            "| {method} | {} | {}×{} | {} | {} | {:.1}% | {:.3} | {:.3}–{:.3} | {} | {:.1} | {:.2} |\n",
            r.lights,
            r.width,
            r.height,
            if r.cull { "on" } else { "off" },
            range_text(r.range),
            100.0 * r.in_range_fraction,
            r.ms_median,
            r.ms_min,
            r.ms_max,
            r.bin_ms_median.map_or("–".into(), |b| format!("{b:.3}")),
            r.fps(),
            r.glightpx_per_s()
        ));
    }
    let ms_with = |n: usize, cull: bool, m: Method, h: Horizon| {
        rows.iter()
            .find(|r| {
                r.lights == n
                    && r.cull == cull
                    && r.method == m
                    && r.horizon == h
                    && r.sizing == Sizing::Point
                    && r.alpha_y.is_none()
            })
            .map(|r| r.ms_median)
    };
    let ms = |n: usize, cull: bool, m: Method| ms_with(n, cull, m, Horizon::Eq30);
    let ratio = |slow: Option<f64>, fast: Option<f64>| match (slow, fast) {
        (Some(s), Some(f)) => format!("{:.2}×", s / f),
        _ => "–".into(),
    };
    let mut keys: Vec<(usize, bool)> = rows.iter().map(|r| (r.lights, r.cull)).collect();
    keys.dedup();
    out.push_str("\nSpeed-up (ms of the slower / ms of the faster, same run):\n\n| lights | cull | ltc / brdf | ltc-fast / brdf | ltc / brdf-fast | ltc-fast / brdf-fast | ltc-f16-pairs / ltc-fast |\n|---:|---|---:|---:|---:|---:|---:|\n");
    for &(n, cull) in &keys {
        let m = |method| ms(n, cull, method);
        out.push_str(&format!(
            "| {n} | {} | {} | {} | {} | {} | {} |\n",
            if cull { "on" } else { "off" },
            ratio(m(Method::Brdf), m(Method::Ltc)),
            ratio(m(Method::Brdf), m(Method::LtcFast)),
            ratio(m(Method::BrdfFast), m(Method::Ltc)),
            ratio(m(Method::BrdfFast), m(Method::LtcFast)),
            ratio(m(Method::LtcFast), m(Method::LtcF16Pairs)),
        ));
    }
    let counts: Vec<usize> = keys.iter().map(|k| k.0).collect();
    if rows.iter().any(|r| r.cull) && rows.iter().any(|r| !r.cull) {
        out.push_str("\nCulling (unculled ms / culled ms, same run):\n\n| lights | brdf | ltc-fast | ltc-f16-pairs |\n|---:|---:|---:|---:|\n");
        let mut seen = counts.clone();
        seen.dedup();
        for n in seen {
            let r = |m| ratio(ms(n, false, m), ms(n, true, m));
            out.push_str(&format!(
                "| {n} | {} | {} | {} |\n",
                r(Method::Brdf),
                r(Method::LtcFast),
                r(Method::LtcF16Pairs)
            ));
        }
    }
    let mut remedies: Vec<Horizon> = Vec::new();
    for r in rows.iter().filter(|r| r.horizon != Horizon::Eq30) {
        if !remedies.contains(&r.horizon) {
            remedies.push(r.horizon);
        }
    }
    if !remedies.is_empty() {
        let names: Vec<&str> = remedies.iter().map(|h| h.name()).collect();
        out.push_str(&format!(
            "\nHorizon remedies (ms with the remedy / ms with eq30, same run):\n\n| lights | cull | method | {} |\n|---:|---|---|{}\n",
            names.join(" | "),
            "---:|".repeat(names.len())
        ));
        for &(n, cull) in &keys {
            for m in [Method::Ltc, Method::LtcFast] {
                let cells: Vec<String> = remedies
                    .iter()
                    .map(|&h| ratio(ms_with(n, cull, m, h), ms(n, cull, m)))
                    .collect();
                out.push_str(&format!(
                    "| {n} | {} | {} | {} |\n",
                    if cull { "on" } else { "off" },
                    m.name(),
                    cells.join(" | ")
                ));
            }
        }
    }
    if rows.iter().any(|r| r.method == Method::File) {
        out.push_str(&file_markdown(rows, &keys));
    }
    for kind in ShapeKind::sized() {
        let Some(r) = rows
            .iter()
            .find(|r| matches!(r.sizing, Sizing::Shape(m) if m.kind() == kind))
        else {
            continue;
        };
        let methods: Vec<Sizing> = ShapeMethod::all(kind)
            .into_iter()
            .map(Sizing::Shape)
            .collect();
        let title = sized_title(kind, r.size);
        let pair = (
            Sizing::Shape(ShapeMethod::approximation(kind)),
            Sizing::Shape(ShapeMethod::at_centre(kind)),
        );
        out.push_str(&sized_markdown(
            rows,
            (&keys, &title),
            (&methods, pair),
            &ms,
        ));
    }
    out.push_str(&aniso_markdown(rows));
    out.push_str("\nThe paper's Table 1 (GTX 1060, resolution not stated), for reference:\n\n| lights | BRDF fps | LTC fps | LTC / BRDF |\n|---:|---:|---:|---:|\n");
    for k in 0..PAPER_LIGHTS.len() {
        out.push_str(&format!(
            "| {} | {} | {} | {:.2}× |\n",
            PAPER_LIGHTS[k],
            PAPER_BRDF_FPS[k],
            PAPER_LTC_FPS[k],
            PAPER_LTC_FPS[k] / PAPER_BRDF_FPS[k]
        ));
    }
    out
}

/// Lights with a size: each method's ms per frame and its cost over the point formula's
/// (ltc and ltc-fast on points, same run, same lights), and one sized method's over another
/// (`pair`: the LTC disk's or polygon's over the centre's point formula on the same lights).
fn sized_markdown(
    rows: &[BenchRow],
    (keys, title): (&[(usize, bool)], &str),
    (methods, pair): (&[Sizing], (Sizing, Sizing)),
    point_ms: &dyn Fn(usize, bool, Method) -> Option<f64>,
) -> String {
    let names: Vec<&str> = methods.iter().map(|m| m.method_name()).collect();
    let pair_name = format!("{} / {}", pair.0.method_name(), pair.1.method_name());
    let mut out = format!(
        "\nLights with a size ({title}; ms, and × the point formula's ltc-fast / ltc, same run):\n\n| lights | cull | {} | {pair_name} |\n|---:|---|{}---:|\n",
        names.join(" | "),
        "---:|".repeat(names.len())
    );
    for &(n, cull) in keys {
        let sized_ms = |sizing| {
            rows.iter()
                .find(|r| r.lights == n && r.cull == cull && r.sizing == sizing)
                .map(|r| r.ms_median)
        };
        let point = |m| point_ms(n, cull, m);
        let (fast, paper) = (point(Method::LtcFast), point(Method::Ltc));
        let cells: Vec<String> = methods
            .iter()
            .map(|&m| match (sized_ms(m), fast, paper) {
                (Some(ms), Some(f), Some(p)) => {
                    format!("{ms:.3} ({:.2}× / {:.2}×)", ms / f, ms / p)
                }
                (Some(ms), _, _) => format!("{ms:.3}"),
                _ => "–".into(),
            })
            .collect();
        let ratio = match (sized_ms(pair.0), sized_ms(pair.1)) {
            (Some(a), Some(b)) => format!("{:.2}×", a / b),
            _ => "–".into(),
        };
        out.push_str(&format!(
            "| {n} | {} | {} | {ratio} |\n",
            if cull { "on" } else { "off" },
            cells.join(" | ")
        ));
    }
    out
}

/// The method file's ratios: its ms over ltc-fast's and ltc's (points), and over the shape's
/// LTC method and its `ltc-point` (lights with a size), at each light count and culling.
fn file_markdown(rows: &[BenchRow], keys: &[(usize, bool)]) -> String {
    let ms = |n: usize, cull: bool, m: Method, sizing: Sizing| {
        rows.iter()
            .find(|r| {
                (r.lights, r.cull, r.method, r.sizing, r.horizon)
                    == (n, cull, m, sizing, Horizon::Eq30)
            })
            .map(|r| r.ms_median)
    };
    let ratio = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}×", a / b),
        _ => "–".into(),
    };
    let mut out = String::from(
        "\nThe method file (ms of the file / ms of the lab's method, same run):\n\n| lights | cull | lights' shape | file / ltc-fast | file / ltc | file / the shape's LTC | file / the shape's ltc-point |\n|---:|---|---|---:|---:|---:|---:|\n",
    );
    for &(n, cull) in keys {
        for kind in ShapeKind::ALL {
            let sizing = match kind {
                ShapeKind::Point => Sizing::Point,
                _ => Sizing::File(kind),
            };
            let Some(file) = ms(n, cull, Method::File, sizing) else {
                continue;
            };
            let fast = Method::LtcFast;
            let (ltc, point) = match kind {
                ShapeKind::Point => (None, None),
                _ => (
                    ms(
                        n,
                        cull,
                        fast,
                        Sizing::Shape(ShapeMethod::approximation(kind)),
                    ),
                    ms(n, cull, fast, Sizing::Shape(ShapeMethod::at_centre(kind))),
                ),
            };
            let shape = kind.name();
            out.push_str(&format!(
                "| {n} | {} | {shape} | {} | {} | {} | {} |\n",
                if cull { "on" } else { "off" },
                ratio(Some(file), ms(n, cull, fast, Sizing::Point)),
                ratio(Some(file), ms(n, cull, Method::Ltc, Sizing::Point)),
                ratio(Some(file), ltc),
                ratio(Some(file), point),
            ));
        }
    }
    out
}

/// An anisotropic material's cost: each run's ms with the material anisotropic over the same
/// run's ms isotropic (the 4D table's lookup, once a pixel, against the 2D table's; the
/// BRDF forms' anisotropic D and Λ), same lights, same run; and their difference, which for
/// the LTC forms is the lookup's, the same at any light count.
fn aniso_markdown(rows: &[BenchRow]) -> String {
    let brushed: Vec<&BenchRow> = rows.iter().filter(|r| r.alpha_y.is_some()).collect();
    let Some(first) = brushed.first() else {
        return String::new();
    };
    let mut out = format!(
        "\nAnisotropic material (α_y = {}; ms anisotropic / ms isotropic, same run):\n\n| method | lights | cull | ms isotropic | ms anisotropic | anisotropic / isotropic | ms anisotropic − isotropic |\n|---|---:|---|---:|---:|---:|---:|\n",
        first.alpha_y.unwrap_or_default()
    );
    for b in brushed {
        let same = |r: &&BenchRow| {
            r.alpha_y.is_none()
                && (r.method, r.horizon, r.sizing, r.lights, r.cull)
                    == (b.method, b.horizon, b.sizing, b.lights, b.cull)
        };
        let Some(iso) = rows.iter().find(same) else {
            continue;
        };
        out.push_str(&format!(
            "| {} | {} | {} | {:.3} | {:.3} | {:.2}× | {:+.3} |\n",
            iso.label(),
            b.lights,
            if b.cull { "on" } else { "off" },
            iso.ms_median,
            b.ms_median,
            b.ms_median / iso.ms_median,
            b.ms_median - iso.ms_median
        ));
    }
    out
}
