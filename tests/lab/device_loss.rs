//! The window's device lost under the lab (docs/design.md §5.14), by injection
//! (`Device::destroy`): no panic, a notice saying so, the plane shaded on the CPU from then on,
//! every setting kept.

use crate::harness::{lab, notice, plane_image, plane_state, settle, slide};

#[test]
fn a_lost_device_moves_the_plane_to_the_cpu_and_says_so() {
    let Some(mut h) = lab((1280.0, 720.0), plane_state(5)) else {
        return;
    };
    h.state().lab().device().expect("a device").device.destroy();
    // A change restarts the render, on the lost device first.
    slide(&mut h, "α", 0.4);
    settle(&mut h);
    let said = notice(&h).expect("a notice");
    assert!(said.is_error, "{}", said.text);
    assert!(said.text.contains("lost"), "{}", said.text);
    assert!(said.text.contains("CPU"), "{}", said.text);
    // The setting stands, and the plane is shaded (on the CPU).
    assert!((h.state().lab().material().alpha - 0.4).abs() < 1e-3);
    let image = plane_image(&mut h);
    assert!(image.pixels.iter().all(|p| p.is_finite()));
    assert!(image.pixels.iter().any(|p| p.length() > 0.0));
}
