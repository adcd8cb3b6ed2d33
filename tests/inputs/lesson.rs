//! Lessons as files (docs/design.md §5.11): the shipped one reads, every view it holds opens,
//! every character it shows has a glyph; a lesson round-trips through its file; a broken one is
//! refused naming its step and field; conditions and readings read as documented.

use ltc_lab::app::lesson::readings::{Reading, check_placeholders, fill};
use ltc_lab::app::lesson::{Condition, Lesson, Step, StepView, TryThis};
use ltc_lab::app::{LabState, PanelId, link};

fn paper() -> Lesson {
    Lesson::shipped("paper").expect("the shipped lesson reads")
}

/// Every shipped lesson, by name.
fn shipped() -> Vec<(&'static str, Lesson)> {
    ltc_lab::app::lesson::SHIPPED
        .iter()
        .map(|(name, _)| {
            (
                *name,
                Lesson::shipped(name).expect("a shipped lesson reads"),
            )
        })
        .collect()
}

#[test]
fn the_shipped_lessons_read_and_every_view_opens() {
    for (name, lesson) in shipped() {
        // The paper's derivation in about 10–12 steps; the polygon's in four to seven (the
        // rect's five, the disk's and the line's).
        let steps = if name == "paper" { 10..=12 } else { 4..=7 };
        assert!(
            steps.contains(&lesson.steps.len()),
            "{name}: {} steps",
            lesson.steps.len()
        );
        check_steps(&lesson);
    }
}

fn check_steps(lesson: &Lesson) {
    for (k, step) in lesson.steps.iter().enumerate() {
        // Every view is the table a person reads, not a share-view string.
        assert!(
            matches!(step.view, StepView::Fields(_)),
            "step {}: a share-view string",
            k + 1
        );
        let state = step
            .view
            .open(&LabState::default())
            .unwrap_or_else(|e| panic!("step {}: its view does not open: {e}", k + 1));
        let mut checked = state.clone();
        assert!(
            checked.check().is_empty(),
            "step {}: its view holds values the lab refuses or clamps",
            k + 1
        );
        assert!(
            !step.panels.is_empty() && step.panels.len() <= 2,
            "step {}",
            k + 1
        );
        // 2–6 sentences: a step is read aloud in a lecture, not a page.
        let sentences = step.text.matches(". ").count() + 1;
        assert!(
            (2..=6).contains(&sentences),
            "step {}: {sentences} sentences",
            k + 1
        );
        assert!(!step.equations.is_empty(), "step {}: no equation", k + 1);
    }
    // A step may only show (the work per light); all others ask something of the student.
    let asks = lesson.steps.iter().filter(|s| s.try_this.is_some()).count();
    assert!(asks + 1 >= lesson.steps.len(), "{asks} steps ask something");
}

/// Every character the shipped lessons show has a glyph in egui's fonts (a missing one is drawn
/// as a box: `M⁻¹` and `‖ω‖` were, before the lesson wrote `M^-1` and `|ω|`).
#[test]
fn every_character_of_the_shipped_lesson_has_a_glyph() {
    // egui's fonts without the emoji ones, which a test harness (and a slim build) lacks.
    let ctx = egui::Context::default();
    let mut fonts = egui::FontDefinitions::default();
    for family in fonts.families.values_mut() {
        family.retain(|name| !name.to_ascii_lowercase().contains("emoji"));
    }
    ctx.set_fonts(fonts);
    let mut out = ctx.run_ui(egui::RawInput::default(), |_| {});
    out.textures_delta.clear();
    let font = egui::FontId::proportional(20.0);
    // The bar's own marks with the lessons' words.
    let mut shown = String::from("…");
    for (_, lesson) in shipped() {
        shown.push_str(&lesson.title);
        for s in &lesson.steps {
            shown.push_str(&s.title);
            shown.push_str(&s.text);
            shown.push_str(&s.control);
            shown.extend(s.equations.iter().map(String::as_str));
            if let Some(t) = &s.try_this {
                shown.push_str(&t.task);
            }
        }
    }
    let missing: std::collections::BTreeSet<char> = shown
        .chars()
        .filter(|c| !c.is_whitespace())
        .filter(|&c| !ctx.fonts_mut(|f| f.has_glyph(&font, c)))
        .collect();
    assert!(missing.is_empty(), "no glyph for {missing:?}");
}

#[test]
fn a_lesson_round_trips_through_its_file() {
    let mut lesson = paper();
    let view = StepView::of(&LabState::default()).expect("a view");
    lesson.steps.push(
        Step::captured(
            "A teacher's step",
            "Quoted \"text\", a brace {{ and a reading {alpha}.\nA second line.",
            vec![PanelId::Chart, PanelId::Plane],
            view.clone(),
        )
        .expect("a step"),
    );
    // What the file could not read back is refused when the step is written.
    for (title, text, says) in [
        ("t", "", "its text: empty"),
        ("", "Fine.", "its title: empty"),
        ("t", "a {teapot}", "{teapot} is not a reading"),
        ("t", "a } alone", "a '}' without its '{'"),
    ] {
        let e = Step::captured(title, text, vec![PanelId::Plane], view.clone()).expect_err(says);
        assert!(e.contains(says), "{e}");
    }
    lesson.steps[0].try_this = Some(TryThis {
        task: "two conditions".into(),
        when: "case1 == 0 and morph <= 0.25".parse().expect("a condition"),
    });
    let text = lesson.to_toml().expect("it writes");
    let back = Lesson::from_toml(&text, "saved.lesson.toml").expect("what it wrote reads");
    assert_eq!(back, lesson);
}

/// A step's TOML with `field` replaced by `value` (or removed, for `None`), in a lesson of
/// three steps whose third is the one broken.
fn broken(field: &str, value: Option<&str>) -> String {
    let view = link::encode(&LabState::default());
    let good = format!(
        "[[step]]\ntitle = \"ok\"\ntext = \"Fine. Fine.\"\npanels = [\"plane\"]\nview = \"{view}\"\n"
    );
    let mut third = String::from("[[step]]\n");
    for (k, v) in [
        ("title", "\"t\"".to_string()),
        ("text", "\"Fine. Fine.\"".to_string()),
        ("panels", "[\"lobe\"]".to_string()),
        ("view", format!("\"{view}\"")),
    ] {
        match (k == field, value) {
            (true, Some(v)) => third.push_str(&format!("{k} = {v}\n")),
            (true, None) => {}
            (false, _) => third.push_str(&format!("{k} = {v}\n")),
        }
    }
    if !["title", "text", "panels", "view"].contains(&field)
        && let Some(v) = value
    {
        third.push_str(&format!("{field} = {v}\n"));
    }
    format!("title = \"broken\"\n{good}{good}{third}")
}

#[test]
fn a_broken_lesson_is_refused_naming_its_line_step_and_field() {
    // The third step starts on line 12 (`broken` writes a title, then two steps of five lines);
    // its title, text, panels and view are on lines 13 to 16, a field it adds on line 17. A
    // field's error is at its own line; one serde refuses (a missing field) at the step's.
    for (field, value, says) in [
        ("title", None, "line 12, step 3: missing field `title`"),
        (
            "title",
            Some("5"),
            "step 3: invalid type: integer `5`, expected a string",
        ),
        (
            "text",
            Some("\"  \""),
            "line 14, step 3: field `text`: empty",
        ),
        (
            "text",
            Some("\"{nope}\""),
            "line 14, step 3: field `text`: {nope} is not a reading",
        ),
        (
            "text",
            Some("\"a } alone\""),
            "line 14, step 3: field `text`: a '}' without its '{'",
        ),
        (
            "panels",
            Some("[\"teapot\"]"),
            "line 15, step 3: field `panels`: 'teapot' is not a panel",
        ),
        (
            "panels",
            Some("[]"),
            "line 15, step 3: field `panels`: 0 panels",
        ),
        (
            "panels",
            Some("[\"lobe\", \"plane\", \"chart\"]"),
            "line 15, step 3: field `panels`: 3 panels",
        ),
        ("view", None, "step 3: missing field `view`"),
        (
            "view",
            Some("3"),
            "line 16, step 3: field `view`: a table of settings or a share-view string",
        ),
        (
            "titel",
            Some("\"x\""),
            "line 17, step 3: unknown field `titel`",
        ),
        (
            "try",
            Some("{ task = \"t\", when = \"morph < \" }"),
            "line 17, step 3: field `try.when`: '' is not a finite number",
        ),
        (
            "try",
            Some("{ task = \"t\", when = \"teapot > 1\" }"),
            "line 17, step 3: field `try.when`: 'teapot' is not a quantity",
        ),
        (
            "try",
            Some("{ task = \"t\", when = \"morph ~ 1\" }"),
            "line 17, step 3: field `try.when`: 'morph ~ 1' has no comparison",
        ),
        (
            "try",
            Some("{ when = \"morph < 1\" }"),
            "step 3: missing field `task`",
        ),
        (
            "equations",
            Some("[1]"),
            "line 17, step 3: invalid type: integer `1`, expected a string",
        ),
    ] {
        let text = broken(field, value);
        let e = Lesson::from_toml(&text, "t.lesson.toml").expect_err(says);
        assert!(e.starts_with("t.lesson.toml: "), "{e}");
        assert!(
            e.contains(says),
            "{field} = {value:?}: said '{e}', not '{says}'"
        );
    }
    for (text, says) in [
        ("title = \"x\"\n", "missing field `step`"),
        (
            "title = \"x\"\nstep = 3\n",
            "line 2: invalid type: integer `3`, expected a sequence",
        ),
        (
            "title = \"x\"\nauthor = \"me\"\n",
            "line 2: unknown field `author`",
        ),
        ("title = \"x\"\n\n[[step]\n", "line 3"),
        ("title = \"x\"\nstep = []\n", "it has 0 steps"),
    ] {
        let e = Lesson::from_toml(text, "t.lesson.toml").expect_err(says);
        assert!(e.contains(says), "said '{e}', not '{says}'");
    }
    // A share-view string that does not open is not refused with the lesson: its step shows
    // its text with why (the lab's test walks that).
    let text = broken("view", Some("\"v1.not-a-view\""));
    assert!(Lesson::from_toml(&text, "t.lesson.toml").is_ok());
    // A table's unknown setting is, as the file is read: at its line.
    let text = broken("view", Some("{ lobe.teapot = 1 }"));
    let e = Lesson::from_toml(&text, "t.lesson.toml").unwrap_err();
    assert!(
        e.contains("line 16, step 3: field `view`: `lobe.teapot` is not a setting of the view"),
        "{e}"
    );
}

/// A misspelled setting in a step's `[step.view]` table is refused as the file is read, at
/// its own line, with the nearest setting the view has (it dropped the whole view when the
/// step opened, and the step showed the default 100 lights under the lesson's text).
#[test]
fn a_misspelled_setting_is_refused_at_its_line_with_the_nearest_name() {
    let text = "title = \"t\"\n\n[[step]]\ntitle = \"s\"\ntext = \"Fine. Fine.\"\npanels = [\"plane\"]\n\n[step.view]\nlab.material.alpha = 0.3\nlab.material.alhpa = 0.4\n";
    let e = Lesson::from_toml(text, "t.lesson.toml").unwrap_err();
    assert!(e.contains("line 10, step 1: field `view`"), "{e}");
    assert!(e.contains("unknown field `alhpa`"), "{e}");
    assert!(e.contains("the nearest is `alpha`"), "{e}");
    // A misspelled table: the nearest path the view has.
    let text = text.replace("lab.material.alhpa = 0.4", "lab.rules.clip.case1 = false");
    let e = Lesson::from_toml(&text, "t.lesson.toml").unwrap_err();
    assert!(e.contains("line 10, step 1: field `view`"), "{e}");
    assert!(
        e.contains("`lab.rules.clip` is not a setting of the view"),
        "{e}"
    );
    assert!(e.contains("the nearest is `lab.rules.clipping`"), "{e}");
}

/// A step's view as a table: what it names is set, the rest stays at the lab's defaults; a
/// setting the view does not have, or a value of the wrong kind, is named when the step opens.
#[test]
fn a_view_table_sets_what_it_names_and_refuses_what_it_does_not_know() {
    let defaults = LabState::default();
    let view: toml::Table = toml::from_str(
        "lab.material.alpha = 0.35\nlobe.theta_o_deg = 1\nlab.lobe_view.theta_o_deg = 70.0",
    )
    .unwrap();
    let err = StepView::Fields(view)
        .open(&defaults)
        .expect_err("lobe.theta_o_deg");
    assert!(
        err.contains("`lobe.theta_o_deg` is not a setting of the view"),
        "{err}"
    );
    let view: toml::Table =
        toml::from_str("lab.material.alpha = 0.35\nlab.lobe_view.theta_o_deg = 70.0").unwrap();
    let state = StepView::Fields(view.clone())
        .open(&defaults)
        .expect("it opens");
    assert_eq!(state.lab.material.alpha, 0.35);
    assert_eq!(state.lab.lobe_view.theta_o_deg, 70.0);
    assert_eq!(state.lab.lights, defaults.lab.lights);
    // What `StepView::of` writes is exactly what differs, and opens to the same state.
    match StepView::of(&state).unwrap() {
        StepView::Fields(t) => assert_eq!(t, view),
        other => panic!("{other:?}"),
    }
    let wrong: toml::Table = toml::from_str("lab.material.alpha = \"rough\"").unwrap();
    let err = StepView::Fields(wrong)
        .open(&defaults)
        .expect_err("a text for α");
    assert!(err.contains("does not read"), "{err}");
}

#[test]
fn conditions_read_and_write_as_documented() {
    for text in [
        "morph <= 0.02",
        "case1 == 0 and case2 == 0",
        "theta_o >= 85",
        "lights > 999",
        "pinned != 0",
    ] {
        let c: Condition = text.parse().expect(text);
        assert_eq!(c.to_string(), text);
    }
    for bad in [
        "",
        "morph",
        "morph <= x",
        "morph <= inf",
        "morph <= NaN",
        "and",
    ] {
        assert!(bad.parse::<Condition>().is_err(), "'{bad}' was read");
    }
}

#[test]
fn readings_fill_braces_and_refuse_what_they_do_not_know() {
    let filled = fill("a {x} b {{c}} {y}", |n| Ok(n.to_uppercase())).expect("fills");
    assert_eq!(filled, "a X b {c} Y");
    assert!(fill("a {x", |_| Ok(String::new())).is_err());
    for reading in Reading::ALL {
        let name = reading.name();
        check_placeholders(&format!("the {{{name}}} reading")).expect(name);
        assert!(!reading.describe().is_empty(), "{name}");
    }
    assert!(check_placeholders("{teapot}").is_err());
}

#[test]
fn a_lesson_link_names_a_shipped_lesson_and_a_step() {
    let n = paper().steps.len();
    let (lesson, name, step) = Lesson::of_link("lesson=paper&step=7")
        .expect("a lesson's link")
        .expect("it opens");
    assert_eq!((name.as_str(), step, lesson.steps.len()), ("paper", 6, n));
    let (_, _, first) = Lesson::of_link("#lesson=paper")
        .expect("a link")
        .expect("opens");
    assert_eq!(first, 0);
    assert!(Lesson::of_link("view=v1.abc").is_none());
    for (bad, says) in [
        ("lesson=teapot", "'teapot' is not a lesson the lab ships"),
        ("lesson=paper&step=0", "0 is not a step of the lesson"),
        (
            &format!("lesson=paper&step={}", n + 1),
            "is not a step of the lesson",
        ),
        ("lesson=paper&step=x", "is not step=K"),
    ] {
        let e = Lesson::of_link(bad)
            .expect("a lesson's link")
            .expect_err(bad);
        assert!(e.contains(says), "{bad}: said '{e}'");
    }
}

/// The README's reference for lesson authors names every reading and every quantity with the
/// meaning the lab gives it, and every field a step has: a reading or quantity added to the
/// lab and not to the README fails here.
#[test]
fn the_readme_lists_every_reading_quantity_and_field() {
    use ltc_lab::app::lesson::condition::Quantity;
    let readme = include_str!("../../README.md");
    let section = readme
        .split("### Writing a lesson")
        .nth(1)
        .expect("the README has a section for lesson authors");
    for r in Reading::ALL {
        let row = format!("| `{{{}}}` | {} |", r.name(), r.describe());
        assert!(section.contains(&row), "the README lacks: {row}");
    }
    for q in Quantity::ALL {
        let row = format!("| `{}` | {} |", q.name(), q.describe());
        assert!(section.contains(&row), "the README lacks: {row}");
    }
    for field in [
        "title",
        "text",
        "equations",
        "panels",
        "control",
        "view",
        "try.task",
        "try.when",
    ] {
        assert!(section.contains(&format!("| `{field}` |")), "{field}");
    }
    // Every setting a view can hold, as the lab's defaults write them.
    let settings = section
        .split("Settings a view can hold")
        .nth(1)
        .expect("the README lists a view's settings");
    let missing: Vec<String> = ltc_lab::app::link::setting_paths()
        .into_iter()
        .filter(|p| !settings.contains(&format!("`{p}`")))
        .collect();
    assert!(
        missing.is_empty(),
        "the README lacks the settings: {missing:?}"
    );
}
