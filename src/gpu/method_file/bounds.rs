//! The memory a method file may declare (docs/design.md §5.13): every value it can hold — a
//! variable, a `let`, a constant, an argument — at most `MAX_VALUE_BYTES`, and its private
//! variables and every function's local variables together at most `MAX_INVOCATION_BYTES`, each
//! refused at the line that declares it. A file's text is bounded (`MAX_BYTES`) and its loops
//! by their steps (`STEPS`); these bound what a short text can still ask for: one line
//! declaring `array<f32, 100000000>` was compiled until the process was killed for memory.

use wgpu::naga;

use crate::error::{Error, Result};

/// The most bytes one value of a method file may take: 1,024 f32, room for a polygon clipped
/// to hundreds of vertices or a 32×32 table of its own.
pub const MAX_VALUE_BYTES: u32 = 4096;

/// The most bytes of private and local variables a method file may declare in all, which is
/// what one invocation may hold at once (WGSL has no recursion). A GPU keeps an invocation's
/// private memory for every invocation in flight — an H100 or H200 holds 132 × 2,048 of them
/// (NVIDIA's Hopper tuning guide: 2,048 resident threads per SM) — so 16 KiB each is already
/// 4 GiB of scratch memory.
pub const MAX_INVOCATION_BYTES: u32 = 16384;

/// Refuses the first declaration of `module` past a bound, at its line and column in `source`
/// (the file's text, which `module`'s text begins with). `place` turns an offset into the
/// file and a message into the refusal.
pub fn check(
    module: &naga::Module,
    source: &str,
    place: &dyn Fn(Option<usize>, String) -> Error,
) -> Result<()> {
    let mut layouter = naga::proc::Layouter::default();
    layouter
        .update(module.to_ctx())
        .map_err(|e| place(None, format!("its types cannot be laid out: {e}")))?;
    let size = |ty: naga::Handle<naga::Type>| layouter[ty].size;
    let in_file = |span: naga::Span| {
        span.to_range()
            .map(|r| r.start)
            .filter(|&start| start < source.len())
    };
    let privates = module
        .global_variables
        .iter()
        .map(|(h, v)| (module.global_variables.get_span(h), v.ty));
    let locals = module.functions.iter().flat_map(|(_, f)| {
        f.local_variables
            .iter()
            .map(|(h, v)| (f.local_variables.get_span(h), v.ty))
    });
    let mut total = 0u32;
    for (span, ty) in privates.chain(locals) {
        let Some(at) = in_file(span) else { continue };
        if size(ty) > MAX_VALUE_BYTES {
            return Err(place(
                Some(at),
                format!(
                    "this variable takes {} bytes; a value of a method file holds at most {MAX_VALUE_BYTES}",
                    size(ty)
                ),
            ));
        }
        total = total.saturating_add(size(ty));
        if total > MAX_INVOCATION_BYTES {
            return Err(place(
                Some(at),
                format!(
                    "with this variable the file's private and local variables take {total} bytes; a method file declares at most {MAX_INVOCATION_BYTES} in all"
                ),
            ));
        }
    }
    // Any other value (a `let`, a constant, an argument) of a type past the bound: at the type
    // where naga kept its place, else at the file's first array of that length.
    for (ty, t) in module.types.iter() {
        if size(ty) <= MAX_VALUE_BYTES {
            continue;
        }
        let at = in_file(module.types.get_span(ty)).or_else(|| first_array_of(t, source));
        return Err(place(
            at,
            format!(
                "a value of this type takes {} bytes; a value of a method file holds at most {MAX_VALUE_BYTES}",
                size(ty)
            ),
        ));
    }
    Ok(())
}

/// The offset of the file's first `array<…, N>` whose length is `t`'s (an array type), read
/// from its tokens: the place naga did not keep.
fn first_array_of(t: &naga::Type, source: &str) -> Option<usize> {
    use super::wgsl_text::{TokenKind, tokens};
    let naga::TypeInner::Array {
        size: naga::ArraySize::Constant(n),
        ..
    } = t.inner
    else {
        return None;
    };
    let toks = tokens(source);
    let wanted = n.get().to_string();
    toks.iter().enumerate().find_map(|(k, tok)| {
        let number =
            tok.kind == TokenKind::Number && tok.text.trim_end_matches(['u', 'i']) == wanted;
        let arrays = toks[..k].iter().rev().take(8).any(|p| p.text == "array");
        (number && arrays).then(|| {
            toks[..k]
                .iter()
                .rev()
                .find(|p| p.text == "array")
                .map_or(tok.start, |p| p.start)
        })
    })
}
