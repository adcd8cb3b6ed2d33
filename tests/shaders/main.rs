//! The WGSL, without an adapter: naga parses and validates every file (in the order they are
//! composed), the Rust Pod types have the WGSL structs' layout, the functions mirrored
//! between Rust and WGSL carry the same names, and the constants and bindings Rust writes
//! for the shaders are the WGSL's.

use ltc_lab::gpu::{bin_module_source, brdf, brdf_aniso, light, ltc, plane_module_source};

mod aniso;
mod constants;
mod layout;
mod names;

/// brdf.wgsl and brdf_aniso.wgsl, which every later file builds on (the exact lobes of either
/// material: `exact_lobes`).
fn brdf_sources() -> String {
    [brdf::SOURCE, brdf_aniso::SOURCE].join("\n")
}

/// brdf, ltc and the lights' files (each shape's holding its method codes).
fn lights_source() -> String {
    [&brdf_sources(), ltc::SOURCE, &light::sources()].join("\n")
}

fn validate(name: &str, src: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(src)
        .unwrap_or_else(|e| panic!("{name} does not parse:\n{}", e.emit_to_string(src)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{name} does not validate:\n{}", e.emit_to_string(src)));
    module
}

#[test]
fn every_wgsl_file_validates() {
    validate("brdf.wgsl", brdf::SOURCE);
    validate("brdf.wgsl + brdf_aniso.wgsl", &brdf_sources());
    validate(
        "brdf.wgsl + brdf_aniso.wgsl + ltc.wgsl",
        &[&brdf_sources(), ltc::SOURCE].join("\n"),
    );
    for f16 in [false, true] {
        let module = validate(
            &format!("brdf.wgsl + ltc.wgsl + scene.wgsl + plane.wgsl (f16: {f16})"),
            &plane_module_source(f16),
        );
        for entry in ["shade", "reduce", "floor_of_means", "resolve"] {
            assert!(
                module.entry_points.iter().any(|e| e.name == entry),
                "{entry}"
            );
        }
    }
    validate(
        "brdf.wgsl + brdf_aniso.wgsl + ltc.wgsl + the lights' files",
        &lights_source(),
    );
    let module = validate("scene.wgsl + bin.wgsl", &bin_module_source());
    for entry in ["bin_count", "bin_scan", "bin_write"] {
        assert!(
            module.entry_points.iter().any(|e| e.name == entry),
            "{entry}"
        );
    }
}

/// The names of a module's functions.
fn function_names(module: &naga::Module) -> Vec<&str> {
    module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.as_deref())
        .collect()
}

/// Every repository path that a shader's, a source file's or a document's text names
/// (`src/…rs`, `shaders/…wgsl`, `tests/…rs`, `docs/…md`) exists: a file moved without its
/// mentions fails here instead of leaving a reader at a dead end.
#[test]
fn every_path_the_comments_name_exists() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut texts = vec![root.join("README.md")];
    let mut dirs = vec![
        root.join("src"),
        root.join("shaders"),
        root.join("docs"),
        root.join("tests"),
    ];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path
                .extension()
                .is_some_and(|e| e == "rs" || e == "wgsl" || e == "md")
            {
                texts.push(path);
            }
        }
    }
    let mut missing = Vec::new();
    for file in &texts {
        let text = std::fs::read_to_string(file).unwrap();
        for (at, _) in text.match_indices(['s', 't', 'd']) {
            let rest = &text[at..];
            let Some(prefix) = ["src/", "shaders/", "tests/", "docs/"]
                .into_iter()
                .find(|p| rest.starts_with(p))
            else {
                continue;
            };
            // Only a path that starts a word (not `gpu_tests/…`, not inside another path).
            if at > 0 {
                let before = text[..at].chars().next_back().unwrap();
                if before.is_alphanumeric() || "_/.-".contains(before) {
                    continue;
                }
            }
            let len = rest
                .find(|c: char| !(c.is_ascii_alphanumeric() || "_/.-".contains(c)))
                .unwrap_or(rest.len());
            let path = rest[..len].trim_end_matches('.');
            let named_file = [".rs", ".wgsl", ".md"].iter().any(|e| path.ends_with(e));
            if path.len() > prefix.len() && named_file && !root.join(path).exists() {
                missing.push(format!(
                    "{}: {path}",
                    file.strip_prefix(root).unwrap().display()
                ));
            }
        }
    }
    assert!(
        missing.is_empty(),
        "paths that do not exist:\n{}",
        missing.join("\n")
    );
}
