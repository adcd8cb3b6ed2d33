//! The studies the lab ships, for the chart to plot and the lesson to quote: each a
//! `study.csv` made by `ltc-lab study` on one machine, its device and set-up in its comment
//! lines.

use crate::app::chart::measure::Measurement;

/// The studies the lab ships, each made by `ltc-lab study` (its `# made with:` line says
/// how): on this project's CPU driver (lavapipe, the chart's default), and on a lent NVIDIA
/// H100, so that a machine without a GPU can still show what a GPU measures. Name, file,
/// text.
pub const SHIPPED_STUDIES: [(&str, &str, &str); 2] = [
    (
        "lavapipe",
        "assets/study/reference.csv",
        include_str!("../../../assets/study/reference.csv"),
    ),
    (
        "H100",
        "assets/study/h100.csv",
        include_str!("../../../assets/study/h100.csv"),
    ),
];

/// The device a shipped study's `# device:` line names.
pub fn study_device(text: &str) -> &str {
    text.lines()
        .find_map(|l| l.strip_prefix("# device: "))
        .unwrap_or("unknown device")
}

/// The shipped study `name`, as the chart plots it.
pub fn shipped_study(name: &str) -> Option<Measurement> {
    let (name, path, text) = SHIPPED_STUDIES.iter().find(|(n, ..)| *n == name)?;
    let rows = crate::measure::study::parse_csv(text, path).ok()?;
    let mut m = Measurement::from_study(&rows, path);
    let label = if *name == "lavapipe" {
        "reference"
    } else {
        name
    };
    m.device = format!(
        "{label} study ({}) — press measure for this machine",
        study_device(text)
    );
    Some(m)
}

/// The chart's default: the study on this project's CPU driver.
pub fn reference_study() -> Option<Measurement> {
    shipped_study("lavapipe")
}
