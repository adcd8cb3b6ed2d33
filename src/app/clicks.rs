//! A click is a click however slow the frames are (docs/design.md §5.15).

/// How long a press may last and still be a click, in seconds. egui times a press from the
/// start of the frame that saw it to the one that sees the release, so a frame longer than its
/// default (0.8 s) turns a quick click into a long press that does nothing. On a software-GL
/// browser on two busy cores (SwiftShader, the browser test's machine) frames were measured at
/// up to 2.0 s and a click's pointerdown and pointerup reached the page 1.0–1.4 s apart: every
/// click on "load" was lost. The lab has no long-press action, so a long limit costs nothing.
pub const MAX_CLICK_SECONDS: f64 = 5.0;

/// Clicks survive slow frames (`MAX_CLICK_SECONDS`).
pub fn keep_slow_clicks(ctx: &egui::Context) {
    ctx.options_mut(|o| o.input_options.max_click_duration = MAX_CLICK_SECONDS);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether a button pressed at 0 s and released at `release_s` (each in a frame of its
    /// own, as on a slow page) was clicked, in a new context with slow clicks kept or not.
    fn clicked_after(keep: bool, release_s: f64) -> bool {
        let ctx = egui::Context::default();
        if keep {
            keep_slow_clicks(&ctx);
        }
        let at = egui::pos2(20.0, 20.0);
        let mut clicked = false;
        let events = [
            (0.0, vec![egui::Event::PointerMoved(at)]),
            (0.0, vec![press(at, true)]),
            (release_s, vec![press(at, false)]),
        ];
        for (time, events) in events {
            let input = egui::RawInput {
                time: Some(time),
                events,
                ..Default::default()
            };
            let mut output = ctx.run_ui(input, |ui| {
                clicked |= ui.button("load").clicked();
            });
            // No renderer takes the font atlas here (epaint checks that one did).
            output.textures_delta.clear();
        }
        clicked
    }

    fn press(pos: egui::Pos2, pressed: bool) -> egui::Event {
        egui::Event::PointerButton {
            pos,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        }
    }

    #[test]
    fn a_click_whose_release_comes_two_seconds_late_is_a_click() {
        // Without the setting egui's default loses it: the check that the test can fail.
        assert!(!clicked_after(false, 2.0));
        assert!(clicked_after(true, 2.0));
        // A press held past the limit is still not a click.
        assert!(!clicked_after(true, MAX_CLICK_SECONDS + 1.0));
    }
}
