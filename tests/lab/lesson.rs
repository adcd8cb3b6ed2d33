//! The lesson (docs/design.md §5.11), walked as a student walks it: *lesson* pressed, *next*
//! pressed by its label through every step, each step's view, outlined panels and *try this*
//! checked, and each task done with the control the step names; snapshots of every step at a
//! projector's two sizes; a teacher's step added, saved and loaded; a broken lesson refused.

use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ltc_lab::app::lesson::bar::LessonBar;
use ltc_lab::app::lesson::{Lesson, StepView};
use ltc_lab::app::{LabApp, LabState, link};

use crate::harness::{
    click_at, drag_along, drop_file, lab, notice, press, settle, shows, slide, type_into,
};

/// A step's snapshot of `pixels`: 1% of them may differ. A step shows its panels large, and
/// at 1920×1080 the matrix step's fifteen heat maps span ~200 px for their 64 texels, whose
/// edges GL's and Vulkan's samplers round differently (0.27% of the window differed between
/// llvmpipe GL and lavapipe, over harness::options' 0.2%); a blank, garbled or re-laid-out
/// panel changes tens of percent.
fn options(pixels: usize) -> egui_kittest::SnapshotOptions {
    egui_kittest::SnapshotOptions::new().max_failed_pixels(pixels / 100)
}

fn paper() -> Lesson {
    Lesson::shipped("paper").expect("the shipped lesson")
}

/// The state a step's view opens, as the lab's own state compares (the parts a view
/// carries).
fn opened(view: &StepView) -> LabState {
    view.open(&LabState::default()).expect("a view")
}

/// The lab's view now, as a share-view string holds it.
fn view_now(h: &Harness<'static, LabApp>) -> StepView {
    StepView::Link(link::encode(&h.state().state()))
}

/// Where the lesson is: (step from 1, its *try this* done).
fn at(h: &Harness<'static, LabApp>) -> (usize, bool) {
    let r = h.state().report().lesson.expect("a lesson is open");
    (r.step, r.done)
}

/// The step's view is the lab's, its panels are the ones drawn (with the side panel where the
/// view shows it), and its task is not yet done.
fn check_arrival(h: &Harness<'static, LabApp>, lesson: &Lesson, k: usize) {
    let step = &lesson.steps[k];
    assert_eq!(at(h), (k + 1, false), "step {}: {}", k + 1, step.title);
    let now = opened(&view_now(h));
    let want = opened(&step.view);
    assert_eq!(now.lab, want.lab, "step {}: the lab's parts", k + 1);
    assert_eq!(
        (&now.lobe, &now.plane, &now.clipping, &now.window),
        (&want.lobe, &want.plane, &want.clipping, &want.window),
        "step {}: the panels' settings",
        k + 1
    );
    let mut drawn: Vec<&str> = h.state().report().panels;
    drawn.retain(|p| *p != "controls");
    let panels: Vec<&str> = step.panels.iter().map(|p| p.name()).collect();
    assert_eq!(drawn, panels, "step {}: the panels shown", k + 1);
    assert!(shows(h, &step.title), "step {}: its title", k + 1);
    words_fit(h, step, k);
}

/// The step's words are all in view without scrolling: its title at the top of the bar (the
/// bar scrolled back up on every step) and the last of its words — the *try this*, or the
/// control to move where it asks nothing — inside the window.
fn words_fit(h: &Harness<'static, LabApp>, step: &ltc_lab::app::lesson::Step, k: usize) {
    let window = h.ctx.content_rect();
    let title = h.get_by_label(&format!("{}. {}", k + 1, step.title)).rect();
    let last = match &step.try_this {
        Some(t) => format!("Try this: {}", t.task),
        None if !step.control.is_empty() => format!("Move: {}", step.control),
        None => "Look at: ".to_string(),
    };
    let last = h
        .query_all_by_label_contains(&last)
        .map(|n| n.rect())
        .next()
        .unwrap_or_else(|| panic!("step {}: '{last}' is not shown", k + 1));
    assert!(
        title.top() >= window.top() && title.top() < window.top() + 120.0,
        "step {}: the title is scrolled to {title:?}",
        k + 1
    );
    assert!(
        last.bottom() <= window.bottom(),
        "step {}: its last words end at {} below the window's {}",
        k + 1,
        last.bottom(),
        window.bottom()
    );
}

/// Does step `k`'s task with the control it names, as a student would.
fn do_task(h: &mut Harness<'static, LabApp>, k: usize) {
    let click = |h: &mut Harness<'static, LabApp>, label: &str| {
        h.get_by_role_and_label(Role::CheckBox, label).click();
        h.run_steps(2);
    };
    match k + 1 {
        1 => slide(h, "α", 0.6),
        2 => slide(h, "M: I -> fitted", 0.0),
        3 => slide(h, "θo (°)", 82.0),
        4 => click_a_low_light(h),
        5 => click(h, "paper-literal normalization"),
        6 => slide(h, "lights", 1000.0),
        7 => click(h, "case 1 rule (n·l ≤ 0 -> 0)"),
        8 => {
            click(h, "case 1 rule (n·l ≤ 0 -> 0)");
            click(h, "case 2 rule ((M^-1 l).z ≤ 0 -> 0)");
        }
        9 => slide(h, "θo (°)", 86.0),
        11 => slide(h, "φo (°)", 65.0),
        k => unreachable!("step {k} asks nothing the walk does"),
    }
    h.run_steps(2);
}

/// In the pinned pixel's table, the number of a light less than 15° above the surface: the
/// table sorted by ω's elevation, lowest first (its header pressed), and its top row's number
/// clicked.
fn click_a_low_light(h: &mut Harness<'static, LabApp>) {
    // The step's view sorts by elevation, highest first ("v"); once more, lowest first.
    h.get_by_role_and_label(Role::Button, "ω elev, az v")
        .click();
    h.run_steps(2);
    let header = h.get_by_label("#").rect();
    // Each row's angles, "elevation°, azimuth°": ω's first, then ω''s; the top row's.
    let top = h
        .query_all_by_label_contains("°, ")
        .filter_map(|n| {
            // A label's text is its node's value.
            let text = n.value()?;
            let elevation: f64 = text.split('°').next()?.trim().parse().ok()?;
            Some((n.rect().center().y, n.rect().left(), elevation))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)))
        .expect("the pinned pixel's table has rows");
    assert!(
        top.2 < 15.0,
        "no light under 15° at the pinned pixel: {top:?}"
    );
    crate::harness::click_at(h, egui::pos2(header.center().x, top.0));
}

#[test]
fn the_paper_lesson_walks_from_the_first_step_to_the_last() {
    let Some(mut h) = lab((1280.0, 720.0), LabState::default()) else {
        return;
    };
    let lesson = paper();
    press(&mut h, "lesson");
    h.run_steps(2);
    h.get_by_label(&lesson.title).click();
    h.run_steps(2);
    let mut snapshots = egui_kittest::SnapshotResults::new();
    for k in 0..lesson.steps.len() {
        settle(&mut h);
        check_arrival(&h, &lesson, k);
        snapshots.add(h.try_snapshot_options(
            format!("lesson_1280x720_step{:02}", k + 1),
            &options(1280 * 720),
        ));
        let last = k + 1 == lesson.steps.len();
        match &lesson.steps[k].try_this {
            // The last step's task is a measurement, left to the chart's own tests.
            Some(_) if !last => {
                do_task(&mut h, k);
                assert_eq!(at(&h), (k + 1, true), "step {}: its task was done", k + 1);
            }
            // The speed step quotes the shipped studies' ratios, read from their files here;
            // the chart plots the H100's on request.
            Some(_) => {
                for study in ltc_lab::app::chart::studies::ShippedStudy::ALL {
                    let path = study.path();
                    let rows =
                        ltc_lab::measure::study::parse_csv(study.text(), path).expect("a study");
                    let ms = |v: &str| {
                        let r = rows.iter().find(|r| r.variant == v && r.lights == 1000);
                        r.expect("1000 lights").ms_median
                    };
                    let said = format!("{:.2}× at 1000", ms("brdf") / ms("ltc-fast"));
                    assert!(shows(&h, &said), "{path}: '{said}' not shown");
                }
                press(&mut h, "H100 study");
                h.run_steps(2);
                let shown = h.query_all_by_label_contains("H100 study (NVIDIA H100");
                assert!(shown.count() >= 1, "the H100 study is not plotted");
            }
            // The step that only shows: each method's work per light, read from the shaders.
            None => {
                let work = ltc_lab::gpu::work::work_per_light().expect("counted");
                let shown = ["brdf", "ltc-fast"];
                for (m, w) in work.iter().filter(|(m, _)| shown.contains(&m.name())) {
                    let said = format!("{} arithmetic operations", w.arithmetic);
                    assert!(
                        shows(&h, &said),
                        "{}'s work per light: '{said}' not shown",
                        m.name()
                    );
                }
            }
        }
        if !last {
            press(&mut h, "next");
        }
    }
    // Leaving the lesson keeps the view: the last step's, laid out as its view says.
    let last = opened(&lesson.steps.last().unwrap().view);
    press(&mut h, "close lesson");
    h.run_steps(2);
    assert!(h.state().lesson().is_none());
    assert_eq!(opened(&view_now(&h)).lab, last.lab);
    settle(&mut h);
}

/// At 1920×1080, stepped by a presenter's clicker (Page Down, →) and back (Page Up, ←).
#[test]
fn the_paper_lesson_at_1920x1080_steps_by_the_keyboard() {
    let lesson = paper();
    let n = lesson.steps.len();
    let mut state = LabState::default();
    state.plane.show_gpu_times = false;
    let Some(mut h) = lab((1920.0, 1080.0), state) else {
        return;
    };
    h.state_mut().open_lesson(lesson.clone(), "paper", 0);
    let mut snapshots = egui_kittest::SnapshotResults::new();
    let mut buttons = Vec::new();
    for k in 0..n {
        settle(&mut h);
        check_arrival(&h, &lesson, k);
        buttons.push(["back", "next"].map(|b| h.get_by_label(b).rect()));
        snapshots.add(h.try_snapshot_options(
            format!("lesson_1920x1080_step{:02}", k + 1),
            &options(1920 * 1080),
        ));
        let key = if k % 2 == 0 {
            egui::Key::PageDown
        } else {
            egui::Key::ArrowRight
        };
        h.key_press(key);
        h.run_steps(2);
    }
    // The bar moves no control: back and next are where they were at every step, whatever
    // its text.
    assert!(buttons.iter().all(|b| *b == buttons[0]), "{buttons:?}");
    // Past the last step, the keys stay; back goes back.
    assert_eq!(at(&h).0, n);
    h.key_press(egui::Key::PageUp);
    h.run_steps(2);
    h.key_press(egui::Key::ArrowLeft);
    h.run_steps(2);
    assert_eq!(at(&h).0, n - 2);
    settle(&mut h);
}

/// A teacher adds a step of the current view, saves the lesson, and opens it again by a drop;
/// a broken lesson dropped is refused naming its step and field, and nothing else changes; a
/// step whose view is broken shows its text with why.
#[test]
fn a_teacher_writes_a_lesson_and_a_broken_one_is_refused() {
    let Some(mut h) = lab((1280.0, 720.0), LabState::default()) else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    h.state_mut().open_lesson(paper(), "paper", 0);
    settle(&mut h);
    press(&mut h, "write a lesson");
    h.run_steps(10);
    type_into(&mut h, "new step's title", "My own step");
    type_into(&mut h, "new step's text", "Look here. Then there.");
    let view = view_now(&h);
    press(&mut h, "add step");
    h.run_steps(2);
    let written = h.state().lesson().unwrap().lesson().clone();
    assert_eq!(written.steps.len(), paper().steps.len() + 1);
    assert_eq!(at(&h).0, 2);
    let added = &written.steps[1];
    assert_eq!(
        (added.title.as_str(), added.text.as_str()),
        ("My own step", "Look here. Then there.")
    );
    assert_eq!(opened(&added.view), opened(&view));
    // *add step* writes the view a person reads: a table of what differs from the defaults.
    assert!(
        matches!(&added.view, StepView::Fields(_)),
        "{:?}",
        added.view
    );

    // A name without .lesson.toml is refused (a drop would read it as a scene).
    let file = dir.path().join("mine.lesson.toml");
    type_into(
        &mut h,
        "lesson file",
        &dir.path().join("mine.toml").display().to_string(),
    );
    press(&mut h, "save lesson");
    h.run_steps(2);
    let said = notice(&h).unwrap();
    assert!(said.is_error && said.text.contains("mine.toml"), "{said:?}");
    assert!(!dir.path().join("mine.toml").exists());
    type_into(&mut h, "lesson file", &file.display().to_string());
    press(&mut h, "save lesson");
    h.run_steps(2);
    let saved = Lesson::from_toml(&std::fs::read_to_string(&file).unwrap(), "saved").unwrap();
    assert_eq!(saved, written);

    press(&mut h, "close lesson");
    h.run_steps(2);
    drop_file(&mut h, &file);
    assert_eq!(h.state().lesson().map(LessonBar::lesson), Some(&written));
    assert_eq!(at(&h).0, 1);

    // Broken: step 1's panel is not one; refused by step and field, the lab unchanged.
    let before = h.state().state();
    let broken_file = dir.path().join("broken.lesson.toml");
    let text =
        written
            .to_toml()
            .unwrap()
            .replacen("panels = [\"lobe\"]", "panels = [\"teapot\"]", 1);
    // Refused at the field's own line.
    let line = 1 + text[..text.find("panels = [\"teapot\"]").unwrap()]
        .matches('\n')
        .count();
    std::fs::write(&broken_file, text).unwrap();
    drop_file(&mut h, &broken_file);
    let said = notice(&h).unwrap();
    assert!(
        said.is_error
            && said.text.contains(&format!(
                "broken.lesson.toml: line {line}, step 1: field `panels`"
            )),
        "{said:?}"
    );
    assert_eq!(h.state().state(), before);
    assert_eq!(h.state().lesson().map(LessonBar::lesson), Some(&written));

    // A step whose view does not open shows its text, and why.
    let mut lesson = written.clone();
    lesson.steps[1].view = StepView::Link("v1.cut-short".into());
    h.state_mut().open_lesson(lesson, "cut.lesson.toml", 1);
    h.run_steps(2);
    assert!(shows(&h, "Look here. Then there."));
    assert!(shows(&h, "This step's view could not be opened"));
    settle(&mut h);
}

/// A *try this* ticks for what the student did on the step, not for a view that already
/// satisfies it: the condition must first be seen not to hold.
#[test]
fn a_try_this_ticks_only_for_what_the_student_did() {
    let Some(mut h) = lab((1280.0, 720.0), LabState::default()) else {
        return;
    };
    let mut rough = LabState::default();
    let material = ltc_lab::scene::Material {
        alpha: 0.6,
        ..*rough.lab.material
    };
    rough.lab.material = ltc_lab::app::lab::Part::new(material);
    let mut lesson = paper();
    lesson.steps.truncate(1);
    lesson.steps[0].view = StepView::of(&rough).expect("a view");
    h.state_mut().open_lesson(lesson, "rough.lesson.toml", 0);
    settle(&mut h);
    // α = 0.6 ≥ 0.5 from the view: nothing done yet.
    assert_eq!(at(&h), (1, false));
    slide(&mut h, "α", 0.3);
    h.run_steps(2);
    assert_eq!(at(&h), (1, false));
    slide(&mut h, "α", 0.7);
    h.run_steps(2);
    assert_eq!(at(&h), (1, true));
    settle(&mut h);
}

/// A step's words start at their top whatever the step before was scrolled to: the bar kept
/// its scroll position between steps, and steps opened with their titles scrolled away.
#[test]
fn every_step_opens_with_its_words_at_the_top() {
    let Some(mut h) = lab((1280.0, 720.0), LabState::default()) else {
        return;
    };
    let lesson = paper();
    h.state_mut().open_lesson(lesson.clone(), "paper", 0);
    settle(&mut h);
    let title = |h: &Harness<'static, LabApp>, k: usize| {
        h.get_by_label(&format!("{}. {}", k + 1, lesson.steps[k].title))
            .rect()
    };
    let top = title(&h, 0).top();
    // Scrolled down over the bar's words (open the teacher's tools so there is room to).
    press(&mut h, "write a lesson");
    h.run_steps(4);
    let over_words = title(&h, 0).center() + egui::vec2(0.0, 200.0);
    for _ in 0..10 {
        h.hover_at(over_words);
        h.event(egui::Event::MouseWheel {
            unit: egui::MouseWheelUnit::Point,
            delta: egui::vec2(0.0, -120.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Unknown,
            modifiers: egui::Modifiers::NONE,
        });
        h.run_steps(2);
    }
    assert!(
        title(&h, 0).top() < top - 50.0,
        "the bar did not scroll: {:?}",
        title(&h, 0)
    );
    press(&mut h, "next");
    settle(&mut h);
    assert_eq!(title(&h, 1).top(), top, "step 2 opened scrolled");
}

/// The polygon lesson (`#lesson=polygon`) walked by a student at 1280×720: every step arrives
/// with its view, panels and words in view, and its tasks from the fourth tick as the student
/// does them — the leak shown by unticking clip case 1, a proxy picked for the rects, a glossy
/// surface under the disks and under the tubes.
#[test]
fn the_polygon_lesson_walks_to_the_leak_and_the_proxy() {
    let lesson = Lesson::shipped("polygon").expect("the shipped lesson");
    let mut state = LabState::default();
    state.plane.show_gpu_times = false;
    let Some(mut h) = lab((1280.0, 720.0), state) else {
        return;
    };
    h.state_mut().open_lesson(lesson.clone(), "polygon", 0);
    for k in 0..lesson.steps.len() {
        settle(&mut h);
        check_arrival(&h, &lesson, k);
        // Every step's light is a rect, shaded by the paper's polygon against the exact one;
        // the sixth step's are disks, the seventh's tubes (a line given a width).
        let lab_ = h.state().lab();
        let shape = match k {
            5 => ltc_lab::light::ShapeKind::Disk,
            6 => ltc_lab::light::ShapeKind::Tube,
            _ => ltc_lab::light::ShapeKind::Rect,
        };
        assert!(
            lab_.lights().list.iter().all(|l| l.shape.kind() == shape),
            "step {}",
            k + 1
        );
        // Steps 1 and 3 ask for nothing in the side panel, which they fold away: the plane's
        // image takes the width left of the bar (794 points less the panel's margins),
        // not the 480 it had beside the side panel.
        let image = h.get_by_label("plane image").rect();
        if k == 0 || k == 2 {
            assert!(h.state().state().window.controls_hidden, "step {}", k + 1);
            assert!(image.width() >= 740.0, "step {}: image {image:?}", k + 1);
        }
        if k == 0 {
            click_at(&mut h, image.center());
            settle(&mut h);
            assert_eq!(at(&h), (k + 1, true), "a pixel pinned");
        }
        if k == 2 {
            // The step's move is the divider, as its task: dragged to the left.
            assert!(lesson.steps[k].control.contains("divider"));
            let start = egui::pos2(image.center().x, image.max.y - 0.2 * image.height());
            drag_along(
                &mut h,
                start,
                egui::pos2(image.min.x + 0.1 * image.width(), start.y),
            );
            h.run_steps(2);
            assert_eq!(at(&h), (k + 1, true), "the divider slid");
        }
        if k == 3 {
            // The side panel's last row is reachable: scrolled to with the wheel, it lies in
            // the window and its button works.
            press(&mut h, "share view");
            h.run_steps(2);
            let share = h.get_by_label("share view").rect();
            let window = h.ctx.input(egui::InputState::viewport_rect);
            assert!(window.contains_rect(share), "{share:?} in {window:?}");
            assert!(
                notice(&h).is_some_and(|m| m.text.contains("--view")),
                "{:?}",
                notice(&h)
            );
            h.get_by_label("clip case 1 (n·l ≤ 0)").click();
            h.run_steps(2);
            assert_eq!(at(&h), (k + 1, true), "the leak shown");
        }
        if k == 4 {
            h.get_by_label("lights with a size").click();
            h.run_steps(2);
            h.get_by_label("rect LTC side").click();
            h.run_steps(2);
            h.get_by_label("ltc-proxy-fast").click();
            h.run_steps(2);
            assert_eq!(at(&h), (k + 1, true), "a proxy picked");
        }
        if k == 5 || k == 6 {
            slide(&mut h, "α", 0.05);
            h.run_steps(2);
            assert_eq!(at(&h), (k + 1, true), "the surface made glossy");
        }
        h.key_press(egui::Key::ArrowRight);
        h.run_steps(2);
    }
}
