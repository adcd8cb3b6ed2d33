//! The table's encodings in the lab (docs/design.md §2.10): each side picks one by its name
//! and the bytes it ships, the A | B split shows one table in two encodings, the choice is
//! kept between runs, and a kept name that is not an encoding is said and dropped.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use ltc_lab::app::LabApp;
use ltc_lab::app::lab::part::Checked;
use ltc_lab::app::lab::{SideB, TableId, TableSources, Tables};
use ltc_lab::ltc::aniso::encoded::stored_in;
use ltc_lab::ltc::lut::{Encoding, Lut, Storage};
use ltc_lab::scene::preset;

use crate::harness::{lab, plane_image, plane_state, settle};

/// Picks `entry` from the combo box labelled `combo`, as a user does.
fn pick(h: &mut Harness<'static, LabApp>, combo: &str, entry: &str) {
    use egui::accesskit::Role;
    h.get_by_role_and_label(Role::ComboBox, combo).click();
    h.run_steps(2);
    h.query_all_by_label(entry)
        .find(|n| n.accesskit_node().role() != Role::Label)
        .unwrap_or_else(|| panic!("no entry {entry} in {combo}"))
        .click();
    settle(h);
}

/// With the default table B, an encoding for B makes side B table A's table in that
/// encoding: an 8² 8-bit table beside the f32 one, the left half of the split unchanged and
/// the right one not (an 8² table moves the light by several percent, docs/design.md §2.10),
/// named for both; "as read" gives the default table B back. The choice survives a restart.
#[test]
fn a_split_shows_one_table_in_two_encodings() {
    // Tall enough that the side panel's table rows are on screen, not scrolled away.
    let Some(mut h) = lab((1000.0, 900.0), plane_state(100)) else {
        return;
    };
    h.get_by_label("A | B tables").click();
    settle(&mut h);
    let before = plane_image(&mut h);
    pick(&mut h, "encoding B", "unorm8-8 · 0.8 KB");
    let tables = h.state().lab().tables();
    assert_eq!(tables.b().name, "classic as unorm8-8");
    // B's anisotropic materials keep B's 4D table (I3D 2022's), not A's, in B's encoding.
    assert_ne!(tables.b().lut.aniso(), tables.a().lut.aniso());
    let b_own = tables.aniso(TableId::B).load().unwrap();
    assert_eq!(
        *tables.b().lut.aniso(),
        stored_in(&b_own, Storage::Unorm8),
        "B's 4D table in 8 bits"
    );
    let expected = Encoding::parse("unorm8-8")
        .unwrap()
        .decoded(Lut::embedded());
    assert_eq!(tables.b().lut.cells, expected.cells);
    assert_eq!(tables.a().lut.cells, Lut::embedded().cells);
    let after = plane_image(&mut h);
    // The largest change of a pixel against the image before, among the columns `keep`
    // takes (well inside each half: the divider's column is its own).
    let w = before.width;
    let change = |keep: &dyn Fn(usize) -> bool| {
        let pixels = before.pixels.iter().zip(&after.pixels).enumerate();
        pixels
            .filter(|(k, _)| keep(k % w))
            .map(|(_, (a, b))| (*a - *b).abs().max_element())
            .fold(0.0f64, f64::max)
    };
    assert_eq!(
        change(&|x| x + 4 < w / 2),
        0.0,
        "side A changed with B's encoding"
    );
    assert!(change(&|x| x > w / 2 + 4) > 0.0, "side B did not change");
    let again = LabApp::new(h.state().state(), None);
    assert_eq!(again.lab().tables().b().name, "classic as unorm8-8");
    pick(&mut h, "encoding B", "as read");
    assert_eq!(h.state().lab().tables().b().name, "point");
}

/// An encoding that turns cells of `M⁻¹` inside out is said in the notices bar, as the
/// command line says it (8 bits at 64²: 153 cells near α → 0).
#[test]
fn an_encoding_that_breaks_cells_says_so() {
    let Some(mut h) = lab((1000.0, 900.0), plane_state(10)) else {
        return;
    };
    pick(&mut h, "encoding A", "unorm8 · 44.1 KB");
    let notice = h.state().lab().message().cloned().expect("no notice");
    assert!(
        !notice.is_error && notice.text.contains("153 cells"),
        "{}",
        notice.text
    );
    assert_eq!(h.state().lab().tables().a().name, "classic as unorm8");
}

/// Encoding B's first entries load where an encoding fails, as a user picks them: the
/// near-mirror preset with table A as read against table A in 8 bits on the plane's A | B
/// tables, and the notice counting what 8 bits break (the 2D table's cells and the 4D
/// table's nodes).
#[test]
fn a_failure_entry_loads_its_scene_with_the_failing_encoding() {
    let Some(mut h) = lab((1000.0, 900.0), plane_state(10)) else {
        return;
    };
    pick(&mut h, "encoding A", "f16 · 88.0 KB");
    pick(&mut h, "encoding B", "unorm8: table-mirror");
    let lab = h.state().lab();
    assert_eq!(lab.tables().b().name, "classic as unorm8");
    assert_eq!(lab.material().alpha, preset("table-mirror").material.alpha);
    assert_eq!(lab.lights().list.len(), preset("table-mirror").lights.len());
    assert_eq!(lab.tables().encoding(TableId::A), None, "A as read");
    assert_eq!(lab.tables().b().name, "classic as unorm8");
    assert_eq!(**lab.side_b(), SideB::TableB);
    let notice = lab.message().cloned().expect("no notice");
    assert!(
        notice.text.contains("153 cells") && notice.text.contains("nodes of its 4D table"),
        "{}",
        notice.text
    );
}

/// A kept state whose encoding is not one (hand-edited, or from a later version) is said
/// where the tables enter the lab, naming the value, and the table is shaded as read.
#[test]
fn a_kept_encoding_that_is_not_one_is_said_and_dropped() {
    let sources = TableSources {
        encoding_a: Some("f12".to_string()),
        encoding_b: Some("cheb16-f16".to_string()),
        ..TableSources::default()
    };
    let mut tables = Tables::from(sources);
    assert_eq!(tables.encoding(TableId::A), None);
    assert_eq!(tables.a().lut.cells, Lut::embedded().cells);
    assert_eq!(tables.b().name, "classic as cheb16-f16");
    let said = tables.check(&Tables::default());
    assert!(said.len() == 1 && said[0].contains("f12"), "{said:?}");
}
