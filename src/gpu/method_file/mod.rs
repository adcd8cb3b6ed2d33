//! `shaders/method_file.wgsl` and a method loaded from a WGSL file (docs/design.md §5.13):
//! one function per light shape it shades, under the interface that file declares, checked
//! by naga against that interface alone (its errors at the file's own line and column), then
//! composed after the lab's plane shader — its module-scope names renamed (`file_…`) but for the
//! functions the lab calls, so none meets the lab's or shadows a WGSL builtin the lab calls, a
//! step guard at the top of each of its loops — as the method `file`.

pub mod bounds;
pub mod device_check;
pub mod wgsl_text;

use wgpu::naga;
use wgpu::naga::valid::Capabilities;

use crate::error::{Error, Result};
use crate::light::ShapeKind;
use wgsl_text::{first_directive, line_column, module_names, rewrite, tokens};

/// The shader text (composed after `plane::SOURCE`).
pub const SOURCE: &str = include_str!("../../../shaders/method_file.wgsl");

/// The most bytes a method file may hold: a file is read up to this and refused past it
/// (the lab's own shaders are 120 KiB together).
pub const MAX_BYTES: usize = 256 * 1024;

/// Whether a file shades each shape, in `ShapeKind::ALL`'s order.
pub type Shades = [bool; ShapeKind::ALL.len()];

/// A file's function for `kind` and the light's struct it takes: `method_<shape>` and
/// `Method<Shape>`, as method_file.wgsl declares them for every shape.
pub fn entry(kind: ShapeKind) -> (String, String) {
    let name = kind.name();
    let mut chars = name.chars();
    let capital: String = chars
        .next()
        .map(|c| c.to_ascii_uppercase())
        .into_iter()
        .collect();
    (
        format!("method_{name}"),
        format!("Method{capital}{}", chars.as_str()),
    )
}

/// The constant of method_file.wgsl that says whether the file shades `kind`.
fn shades_constant(kind: ShapeKind) -> String {
    format!("METHOD_FILE_{}", kind.name().to_ascii_uppercase())
}

/// METHOD_FILE_STEPS of method_file.wgsl: the steps a file's loops may take for one light
/// (tests/shaders/main.rs checks the two agree).
pub const STEPS: u32 = 16384;

/// The statement at the top of every loop body of a file (method_file.wgsl).
const LOOP_GUARD: &str = "if method_file_over() { break; }";

/// A method read from a file and checked: its name, its text as written, and the shapes it
/// has a function for. Never stored, linked or put in a lesson: only its name travels.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MethodFile {
    /// The file's name, as messages, charts and tables show it.
    pub name: String,
    source: String,
    /// Whether it shades each shape (`ShapeKind::ALL`'s order).
    pub shades: Shades,
}

impl MethodFile {
    /// The file at `path`, read up to `MAX_BYTES` (`files::read_bytes`: a FIFO or a device is
    /// refused at once) and checked (`from_source`) against the interface alone; the device's
    /// capabilities are `for_device`'s.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn read(path: &std::path::Path) -> Result<Self> {
        let shown = path.display().to_string();
        let bytes = crate::files::read_bytes(path, MAX_BYTES as u64)?;
        let name = path
            .file_name()
            .map_or(shown.clone(), |n| n.to_string_lossy().into_owned());
        Self::from_bytes(&name, &bytes).map_err(|e| Error { input: shown, ..e })
    }

    /// A method from a file's bytes (a dropped or picked file): UTF-8 and at most
    /// `MAX_BYTES`, then checked (`from_source`).
    pub fn from_bytes(name: &str, bytes: &[u8]) -> Result<Self> {
        if bytes.len() > MAX_BYTES {
            return Err(Error::input(
                name,
                format!("a method file holds at most {} KiB", MAX_BYTES / 1024),
            ));
        }
        let text = std::str::from_utf8(bytes)
            .map_err(|e| Error::input(name, format!("not UTF-8 text: {e}")))?;
        Self::from_source(name, text)
    }

    /// Checks `source` as a method: WGSL that, beside the interface structs alone, parses and
    /// validates; defines at least one shape's `entry` and each with its signature; holds no
    /// directive, entry point, binding, workgroup memory or override; and composes with the
    /// lab's shader. Each refusal names the line and column of the file.
    pub fn from_source(name: &str, source: &str) -> Result<Self> {
        if source.len() > MAX_BYTES {
            return Err(Error::input(
                name,
                format!("a method file holds at most {} KiB", MAX_BYTES / 1024),
            ));
        }
        let at = |offset: usize, message: String| {
            let (line, column) = line_column(source, offset);
            Error::input(name, format!("line {line}, column {column}: {message}"))
        };
        let toks = tokens(source);
        if let Some((directive, offset)) = first_directive(&toks) {
            return Err(at(
                offset,
                format!(
                    "`{directive}` directives are not taken: the file is composed after the lab's shader"
                ),
            ));
        }
        let beside = format!("{source}\n{}", interface());
        // Every capability naga knows: what the device running it lacks is its check
        // (`check_for`), with the feature named.
        let module = check(name, source, &beside, Capabilities::all())?;
        bounds::check(&module, source, &|offset, message| {
            place(name, source, offset, message)
        })?;
        // A name's first place in the file (its declaration, where it is declared first).
        let at_name = |wanted: &str, message: String| {
            let offset = toks
                .iter()
                .find(|t| t.text == wanted)
                .map_or(0, |t| t.start);
            at(offset, message)
        };
        if let Some(ep) = module.entry_points.first() {
            let message = "a method file holds functions, not entry points".to_string();
            return Err(at_name(&ep.name, message));
        }
        for (_, var) in module.global_variables.iter() {
            if var.space != naga::AddressSpace::Private {
                let var_name = var.name.as_deref().unwrap_or("");
                return Err(at_name(
                    var_name,
                    format!(
                        "`{var_name}`: only var<private> is taken (no bindings, no workgroup memory)"
                    ),
                ));
            }
        }
        if let Some((_, o)) = module.overrides.iter().next() {
            let o_name = o.name.as_deref().unwrap_or("");
            let message = format!("`{o_name}`: overrides are the lab's; use a const");
            return Err(at_name(o_name, message));
        }
        let defined = |f: &str| {
            module
                .functions
                .iter()
                .any(|(_, g)| g.name.as_deref() == Some(f))
        };
        let shades = ShapeKind::ALL.map(|k| defined(&entry(k).0));
        if !shades.contains(&true) {
            let functions = ShapeKind::ALL.map(|k| entry(k).0).join(", ");
            return Err(Error::input(
                name,
                format!(
                    "defines none of {functions}: a method file shades at least one light shape (docs/design.md §5.13)"
                ),
            ));
        }
        if let Some((f, light)) = wrong_signature(name, &beside, shades) {
            // At the function's own declaration (`fn` then its name).
            let offset = toks
                .windows(2)
                .find(|w| w[0].text == "fn" && w[1].text == f.as_str())
                .map_or(0, |w| w[1].start);
            return Err(at(
                offset,
                format!("{f} must be fn(pixel: MethodPixel, light: {light}) -> MethodRadiance"),
            ));
        }
        let file = Self {
            name: name.to_string(),
            source: source.to_string(),
            shades,
        };
        let composed = crate::gpu::plane_module_source_with(false, Some(&file));
        check(name, "", &composed, Capabilities::all()).map_err(|e| Error {
            message: format!(
                "the lab could not compose it with its shader: {}",
                e.message
            ),
            ..e
        })?;
        Ok(file)
    }

    /// Its identity: a hash of its name and text (a file loaded again with other text is
    /// another method, and renders again).
    pub fn id(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        (&self.name, &self.source).hash(&mut h);
        h.finish()
    }

    /// Whether it has a function for `kind`.
    pub fn shades(&self, kind: ShapeKind) -> bool {
        self.shades[kind.index()]
    }

    /// The text as the file holds it.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The shapes it shades, by name ("point, rect").
    pub fn shapes(&self) -> String {
        ShapeKind::ALL
            .into_iter()
            .filter(|&k| self.shades(k))
            .map(ShapeKind::name)
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// What follows `lab` (the plane shader's text) in the module: the constants of the
    /// shapes it shades, its text with every module-scope name but its entries renamed
    /// and a step guard in each loop, and a stub for each shape it does not shade.
    pub fn composed(&self, lab: &str) -> String {
        let lab_names: std::collections::HashSet<&str> = module_names(&tokens(lab))
            .into_iter()
            .map(|n| n.0)
            .collect();
        let own = module_names(&tokens(&self.source));
        let taken = |n: &str| lab_names.contains(n) || own.iter().any(|o| o.0 == n);
        // Every name but the functions the lab calls: a name that meets one of the lab's, and
        // one that shadows a WGSL builtin (`fn normalize`, `alias vec3f`), which would
        // otherwise take the lab's own calls to it, since WGSL's module scope is one.
        let renames: Vec<(String, String)> = own
            .iter()
            .filter(|(n, _)| !ShapeKind::ALL.iter().any(|&k| entry(k).0 == *n))
            .map(|(n, _)| {
                let mut new = format!("file_{n}");
                while taken(&new) {
                    new.insert(0, 'x');
                }
                (n.to_string(), new)
            })
            .collect();
        let body = rewrite(&self.source, &renames, LOOP_GUARD);
        format!(
            "// The method file {:?} (renamed: {}).\n{}\n{body}\n{}",
            self.name,
            if renames.is_empty() {
                "nothing".to_string()
            } else {
                renames
                    .iter()
                    .map(|(a, b)| format!("{a} as {b}"))
                    .collect::<Vec<_>>()
                    .join(", ")
            },
            shade_constants(self.shades),
            stubs(self.shades),
        )
    }
}

/// The text after the lab's where no file is loaded: no shape shaded, every function a stub.
pub fn no_file() -> String {
    let none = ShapeKind::ALL.map(|_| false);
    format!("{}\n{}", shade_constants(none), stubs(none))
}

fn shade_constants(shades: Shades) -> String {
    ShapeKind::ALL
        .iter()
        .zip(shades)
        .map(|(&k, s)| format!("const {}: bool = {s};\n", shades_constant(k)))
        .collect()
}

/// A function returning nothing for each shape not shaded (never called: the loop takes the
/// lab's method there).
fn stubs(shades: Shades) -> String {
    ShapeKind::ALL
        .iter()
        .zip(shades)
        .filter(|(_, s)| !*s)
        .map(|(&k, _)| {
            let (f, light) = entry(k);
            format!(
                "fn {f}(pixel: MethodPixel, light: {light}) -> MethodRadiance {{\n    return MethodRadiance(vec3<f32>(0.0), vec3<f32>(0.0));\n}}\n"
            )
        })
        .collect()
}

/// The structs of method_file.wgsl, all a file sees.
pub fn interface() -> &'static str {
    let end = SOURCE
        .find("// The steps a file's loops")
        .unwrap_or(SOURCE.len());
    &SOURCE[..end]
}

/// An error of the file `name` at `offset` of its text `source` (its line and column there), or
/// of the file as a whole where the offset falls outside it.
fn place(name: &str, source: &str, offset: Option<usize>, message: String) -> Error {
    match offset {
        Some(o) if o < source.len() => {
            let (line, column) = line_column(source, o);
            Error::input(name, format!("line {line}, column {column}: {message}"))
        }
        _ => Error::input(name, message),
    }
}

/// `text` parsed and validated by naga with `capabilities`; an error in its first
/// `source.len()` bytes (the file's own text) at its line and column there.
fn check(name: &str, source: &str, text: &str, capabilities: Capabilities) -> Result<naga::Module> {
    let place = |offset, message| place(name, source, offset, message);
    let module = naga::front::wgsl::parse_str(text).map_err(|e| {
        place(
            e.location(text).map(|l| l.offset as usize),
            e.message().to_string(),
        )
    })?;
    naga::valid::Validator::new(naga::valid::ValidationFlags::all(), capabilities)
        .validate(&module)
        .map_err(|e| {
            if let Some((offset, message)) = wrong_return(&module, e.as_inner()) {
                return place(Some(offset), message);
            }
            let mut message = e.as_inner().to_string();
            let mut source_err = std::error::Error::source(e.as_inner());
            while let Some(s) = source_err {
                message.push_str(&format!(": {s}"));
                source_err = s.source();
            }
            place(e.location(text).map(|l| l.offset as usize), message)
        })?;
    Ok(module)
}

/// naga's "The `return` expression Some([0]) does not match the declared return type
/// Some([0])", placed at the `fn`, in WGSL's types at the returned expression: "`helper`
/// returns vec3<f32>, but it is declared to return f32". `None` for any other error.
fn wrong_return(
    module: &naga::Module,
    error: &naga::valid::ValidationError,
) -> Option<(usize, String)> {
    use naga::common::wgsl::TypeContext;
    let naga::valid::ValidationError::Function {
        handle,
        name,
        source:
            naga::valid::FunctionError::InvalidReturnType {
                expression: Some(expression),
                expected_ty,
            },
    } = error
    else {
        return None;
    };
    let function = module.functions.try_get(*handle).ok()?;
    let context = naga::proc::ResolveContext::with_locals(
        module,
        &function.local_variables,
        &function.arguments,
    );
    let mut types = naga::front::Typifier::new();
    types
        .grow(*expression, &function.expressions, &context)
        .ok()?;
    let found = module.types.type_resolution_to_string(&types[*expression]);
    let declared = expected_ty.map_or("nothing".to_string(), |t| module.types.type_to_string(t));
    let offset = function.expressions.get_span(*expression).to_range()?.start;
    Some((
        offset,
        format!("`{name}` returns {found}, but it is declared to return {declared}"),
    ))
}

/// The first function the file defines whose signature is not the interface's (its name and
/// light struct): each is called as the light loop calls it.
fn wrong_signature(name: &str, beside: &str, shades: Shades) -> Option<(String, String)> {
    ShapeKind::ALL
        .iter()
        .zip(shades)
        .filter(|(_, s)| *s)
        .map(|(&k, _)| entry(k))
        .find(|(f, light)| {
            let call = format!(
                "{beside}\nfn method_file_call(p: MethodPixel, l: {light}) -> MethodRadiance {{ return {f}(p, l); }}\n"
            );
            check(name, "", &call, Capabilities::all()).is_err()
        })
}
