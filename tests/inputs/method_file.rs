//! A method loaded from a WGSL file (docs/design.md §5.13), checked without a GPU: the shipped
//! examples load and compose; every kind of bad file is refused by name, with the line and
//! column of the fault in the file itself.

use ltc_lab::error::ErrorKind;
use ltc_lab::gpu::method_file::{MAX_BYTES, MethodFile};
use ltc_lab::gpu::plane_module_source_with;
use wgpu::naga;

const POINT_SIGNATURE: &str =
    "fn method_point(pixel: MethodPixel, light: MethodPoint) -> MethodRadiance";

fn shipped(name: &str) -> MethodFile {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("assets/methods")
        .join(name);
    MethodFile::read(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// The whole plane module with `file` composed in, validated by naga (f32 and f16 forms).
fn composes(file: &MethodFile) {
    for f16 in [false, true] {
        let source = plane_module_source_with(f16, Some(file));
        let module = naga::front::wgsl::parse_str(&source)
            .unwrap_or_else(|e| panic!("{}: {}", file.name, e.emit_to_string(&source)));
        naga::valid::Validator::new(
            naga::valid::ValidationFlags::all(),
            naga::valid::Capabilities::all(),
        )
        .validate(&module)
        .unwrap_or_else(|e| panic!("{}: {e:?}", file.name));
    }
}

/// The message of the refusal of `source`, which must be an input error naming the file.
fn refusal(source: &str) -> String {
    let e = MethodFile::from_source("mine.wgsl", source).expect_err("refused");
    assert_eq!(e.kind, ErrorKind::Input, "{e}");
    assert_eq!(e.input, "mine.wgsl");
    e.message
}

#[test]
fn the_shipped_examples_load_and_compose() {
    for (name, shapes) in [
        ("ltc.wgsl", "point"),
        ("no-case2.wgsl", "point"),
        ("ltc-disk-points.wgsl", "point"),
        ("threejs-rect.wgsl", "rect"),
    ] {
        let file = shipped(name);
        assert_eq!(file.name, name);
        assert_eq!(file.shapes(), shapes, "{name}");
        composes(&file);
    }
}

#[test]
fn a_name_the_lab_has_is_renamed_in_the_file_alone() {
    // ltc.wgsl declares PI, as the lab's brdf.wgsl does: two declarations would not compose.
    let file = shipped("ltc.wgsl");
    let lab = plane_module_source_with(false, None);
    assert!(lab.contains("const PI"));
    let composed = plane_module_source_with(false, Some(&file));
    assert!(composed.contains("const file_PI"), "the file's PI renamed");
    assert_eq!(
        composed.matches("const PI").count(),
        lab.matches("const PI").count(),
        "the lab's own PI untouched"
    );
}

#[test]
fn a_syntax_error_is_refused_at_its_line_and_column() {
    let m = refusal(&format!("{POINT_SIGNATURE} {{\n    let x = ;\n}}\n"));
    assert!(m.starts_with("line 2, column 13:"), "{m}");
}

#[test]
fn a_type_error_is_refused_at_its_line_and_column() {
    let src = format!(
        "// a comment\n{POINT_SIGNATURE} {{\n    let x: f32 = vec3<f32>(1.0);\n    return MethodRadiance(vec3<f32>(x), vec3<f32>(0.0));\n}}\n"
    );
    let m = refusal(&src);
    assert!(m.starts_with("line 3, column"), "{m}");
}

#[test]
fn a_return_of_the_wrong_type_is_said_in_wgsl_types_at_the_return() {
    // naga's own text is "The `return` expression Some([0]) does not match the declared
    // return type Some([0])", placed at the `fn`: the refusal names both types as WGSL
    // writes them, at the line of the `return`.
    let src = format!(
        "fn helper(x: f32) -> f32 {{\n    let y = x * 2.0;\n    return vec3<f32>(y);\n}}\n{POINT_SIGNATURE} {{\n    return MethodRadiance(vec3<f32>(helper(1.0)), vec3<f32>(0.0));\n}}\n"
    );
    let m = refusal(&src);
    assert!(m.starts_with("line 3, column 12:"), "{m}");
    assert!(
        m.contains("`helper` returns vec3<f32>, but it is declared to return f32"),
        "{m}"
    );
    assert!(!m.contains("Some(["), "naga's handles left in: {m}");
    // A value returned from a function declared to return nothing.
    let src = format!(
        "fn nothing() {{\n    return f32(1.0);\n}}\n{POINT_SIGNATURE} {{\n    nothing();\n    return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));\n}}\n"
    );
    let m = refusal(&src);
    assert!(
        m.starts_with("line 2, column 12:")
            && m.contains("returns f32, but it is declared to return nothing"),
        "{m}"
    );
}

#[test]
fn a_call_to_the_labs_own_functions_is_refused() {
    // A method sees the interface alone: d_ggx is the lab's, not the file's.
    let src = format!(
        "{POINT_SIGNATURE} {{\n    return MethodRadiance(vec3<f32>(d_ggx(1.0, 0.5)), vec3<f32>(0.0));\n}}\n"
    );
    let m = refusal(&src);
    assert!(m.starts_with("line 2, column"), "{m}");
}

#[test]
fn a_wrong_signature_is_refused_at_its_function() {
    let m = refusal(
        "\n\nfn method_point(pixel: MethodPixel, light: MethodRect) -> MethodRadiance {\n    return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));\n}\n",
    );
    assert!(m.starts_with("line 3, column 4:"), "{m}");
    assert!(
        m.contains("method_point must be fn(pixel: MethodPixel, light: MethodPoint)"),
        "{m}"
    );
}

#[test]
fn a_file_that_shades_nothing_or_reaches_outside_is_refused() {
    let m = refusal("fn helper() -> f32 { return 1.0; }\n");
    assert!(m.contains("defines none of method_point"), "{m}");
    let body = "{\n    return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));\n}\n";
    for (extra, says) in [
        (
            "@group(0) @binding(0) var<storage, read> leak: array<f32>;\n",
            "only var<private>",
        ),
        ("var<workgroup> shared_sum: f32;\n", "only var<private>"),
        ("override SPEED: f32 = 1.0;\n", "overrides are the lab's"),
        (
            "@compute @workgroup_size(1) fn main() {}\n",
            "not entry points",
        ),
    ] {
        let m = refusal(&format!("{POINT_SIGNATURE} {body}{extra}"));
        assert!(m.starts_with("line 4, column"), "{extra}: {m}");
        assert!(m.contains(says), "{extra}: {m}");
    }
    let m = refusal(&format!("enable f16;\n{POINT_SIGNATURE} {body}"));
    assert!(
        m.starts_with("line 1, column 1:") && m.contains("`enable`"),
        "{m}"
    );
}

#[test]
fn a_file_is_read_up_to_its_limit_and_must_be_text() {
    let big = format!("// {}\n", "x".repeat(MAX_BYTES));
    assert!(refusal(&big).contains("at most 256 KiB"));
    let e = MethodFile::from_bytes("bin.wgsl", &[0xff, 0xfe, 0x00]).expect_err("not text");
    assert!(e.message.contains("not UTF-8"), "{e}");
    let e = MethodFile::read(std::path::Path::new("no/such/method.wgsl")).expect_err("missing");
    assert_eq!(
        (e.kind, e.input.as_str()),
        (ErrorKind::Input, "no/such/method.wgsl")
    );
}

#[test]
fn every_loop_of_a_file_is_guarded() {
    // A loop that never ends: accepted (WGSL cannot tell), and stopped at run time.
    let src = format!(
        "{POINT_SIGNATURE} {{\n    var x = 0.0;\n    loop {{ x += 1.0; }}\n    for (var i = 0; i < 4; i++) {{ while (x > 0.0) {{ x -= 1.0; }} }}\n    return MethodRadiance(vec3<f32>(x), vec3<f32>(0.0));\n}}\n"
    );
    let file = MethodFile::from_source("forever.wgsl", &src).expect("a loop is valid WGSL");
    composes(&file);
    let composed = plane_module_source_with(false, Some(&file));
    let tail = &composed[composed.find("The method file \"forever.wgsl\"").unwrap()..];
    assert_eq!(tail.matches("if method_file_over() { break; }").count(), 3);
}

/// A method of `body` for points: `body` then a zero radiance.
fn point_file(before: &str, body: &str) -> String {
    format!(
        "{before}\n{POINT_SIGNATURE} {{\n{body}\n    return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));\n}}\n"
    )
}

/// Arrays past the stated sizes are refused at the line declaring them (a function's local,
/// a private variable, a constant, the total), and one within them is taken. Without the
/// bound, one line of `array<f32, 100000000>` had the process killed for memory.
#[test]
fn arrays_past_their_bounds_are_refused_at_their_line() {
    use ltc_lab::gpu::method_file::bounds::{MAX_INVOCATION_BYTES, MAX_VALUE_BYTES};
    let n = MAX_VALUE_BYTES / 4;
    // Within: one array at the bound.
    MethodFile::from_source(
        "mine.wgsl",
        &point_file("", &format!("    var a: array<f32, {n}>;\n    a[0] = 1.0;")),
    )
    .unwrap();
    for (before, body, line) in [
        (
            "",
            "    var a: array<f32, 100000000>;\n    a[0] = 1.0;".to_string(),
            3,
        ),
        (
            "var<private> big: array<vec4<f32>, 65536>;",
            String::new(),
            1,
        ),
        ("", format!("    let a = array<f32, {}>();", n + 1), 3),
    ] {
        let m = refusal(&point_file(before, &body));
        assert!(m.contains(&format!("line {line}")), "{m}");
        assert!(m.contains(&MAX_VALUE_BYTES.to_string()), "{m}");
    }
    // Many arrays each within the bound, past the total together.
    let count = MAX_INVOCATION_BYTES / MAX_VALUE_BYTES + 1;
    let vars: String = (0..count)
        .map(|k| format!("    var a{k}: array<f32, {n}>;\n    a{k}[0] = 1.0;\n"))
        .collect();
    let m = refusal(&point_file("", &vars));
    assert!(m.contains(&MAX_INVOCATION_BYTES.to_string()), "{m}");
    assert!(m.contains("line"), "{m}");
}
