//! WGSL as text, for composing a method file into the plane shader (docs/design.md §5.13):
//! its tokens, the names it declares at module scope, its directives, and two rewrites — a
//! name renamed where it meets the lab's, and a step guard at the top of every loop body.
//! WGSL has no namespaces and no recursion, so these two are all it takes for a user's
//! functions to sit beside the lab's and to end.

/// One token: an identifier, a number, or a single punctuation character, with its byte
/// range. Comments and white space are not tokens.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token<'a> {
    pub text: &'a str,
    pub start: usize,
    pub kind: TokenKind,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TokenKind {
    Ident,
    Number,
    Punct,
}

/// The tokens of `src`, comments (`//`, nested `/* */`) skipped. An unterminated block
/// comment ends the text (naga reports it where it is).
pub fn tokens(src: &str) -> Vec<Token<'_>> {
    let bytes = src.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let c = bytes[i];
        if c.is_ascii_whitespace() {
            i += 1;
        } else if src[i..].starts_with("//") {
            i = src[i..].find('\n').map_or(bytes.len(), |n| i + n);
        } else if src[i..].starts_with("/*") {
            i = block_comment_end(bytes, i);
        } else if c.is_ascii_digit()
            || (c == b'.' && bytes.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            let end = number_end(bytes, i);
            out.push(token(src, i, end, TokenKind::Number));
            i = end;
        } else if is_ident_char(src, i) {
            let mut end = i;
            while end < bytes.len() && is_ident_char(src, end) {
                end += src[end..].chars().next().map_or(1, char::len_utf8);
            }
            out.push(token(src, i, end, TokenKind::Ident));
            i = end;
        } else {
            let end = i + src[i..].chars().next().map_or(1, char::len_utf8);
            out.push(token(src, i, end, TokenKind::Punct));
            i = end;
        }
    }
    out
}

fn token(src: &str, start: usize, end: usize, kind: TokenKind) -> Token<'_> {
    Token {
        text: &src[start..end],
        start,
        kind,
    }
}

fn is_ident_char(src: &str, i: usize) -> bool {
    src[i..]
        .chars()
        .next()
        .is_some_and(|c| c == '_' || c.is_alphanumeric())
}

/// After a nested block comment that opens at `i`.
fn block_comment_end(bytes: &[u8], mut i: usize) -> usize {
    let mut depth = 0;
    while i < bytes.len() {
        if bytes[i..].starts_with(b"/*") {
            depth += 1;
            i += 2;
        } else if bytes[i..].starts_with(b"*/") {
            depth -= 1;
            i += 2;
            if depth == 0 {
                return i;
            }
        } else {
            i += 1;
        }
    }
    i
}

/// After a numeric literal at `i`: digits, letters (hex digits, suffixes), dots, and a sign
/// after a decimal `e` or a hexadecimal `p` exponent.
fn number_end(bytes: &[u8], start: usize) -> usize {
    let hex = bytes[start..].starts_with(b"0x") || bytes[start..].starts_with(b"0X");
    let mut i = start;
    while i < bytes.len() {
        let c = bytes[i];
        let exponent = if hex { b"pP" } else { b"eE" };
        let sign = (c == b'+' || c == b'-') && i > start && exponent.contains(&bytes[i - 1]);
        if !(c.is_ascii_alphanumeric() || c == b'.' || c == b'_' || sign) {
            break;
        }
        i += 1;
    }
    i
}

/// Keywords that declare a name at module scope.
const DECLARATIONS: [&str; 6] = ["fn", "struct", "const", "var", "override", "alias"];

/// The names declared at module scope (outside every brace and parenthesis), with the byte
/// offset of each, in order.
pub fn module_names<'a>(toks: &[Token<'a>]) -> Vec<(&'a str, usize)> {
    let mut names = Vec::new();
    let mut depth = 0i32;
    let mut k = 0;
    while k < toks.len() {
        let t = toks[k];
        match t.text {
            "{" | "(" | "[" => depth += 1,
            "}" | ")" | "]" => depth -= 1,
            word if depth == 0 && t.kind == TokenKind::Ident && DECLARATIONS.contains(&word) => {
                let mut n = k + 1;
                // `var<private> name`: the address space first.
                if word == "var" && toks.get(n).is_some_and(|t| t.text == "<") {
                    while n < toks.len() && toks[n].text != ">" {
                        n += 1;
                    }
                    n += 1;
                }
                if let Some(name) = toks.get(n).filter(|t| t.kind == TokenKind::Ident) {
                    names.push((name.text, name.start));
                }
                k = n;
            }
            _ => {}
        }
        k += 1;
    }
    names
}

/// The first directive (`enable`, `requires`, `diagnostic` at module scope, outside an
/// attribute), with its offset: a method file's text is composed after the lab's, where WGSL
/// allows none.
pub fn first_directive(toks: &[Token<'_>]) -> Option<(&'static str, usize)> {
    let mut depth = 0i32;
    for (k, t) in toks.iter().enumerate() {
        match t.text {
            "{" | "(" | "[" => depth += 1,
            "}" | ")" | "]" => depth -= 1,
            _ => {}
        }
        let after_at = k > 0 && toks[k - 1].text == "@";
        if depth == 0 && !after_at {
            for d in ["enable", "requires", "diagnostic"] {
                if t.text == d {
                    return Some((d, t.start));
                }
            }
        }
    }
    None
}

/// A piece of text put in or taken for another, at a byte range of the original.
struct Edit {
    start: usize,
    end: usize,
    text: String,
}

/// `src` with each identifier in `renames` (old → new) renamed — except a member after `.`
/// and a member declared in a struct's body, which are not module-scope names — and with
/// `guard` at the top of every loop body (`loop`, `for`, `while`).
pub fn rewrite(src: &str, renames: &[(String, String)], guard: &str) -> String {
    let toks = tokens(src);
    let mut edits = Vec::new();
    let mut struct_body: Option<i32> = None;
    let mut depth = 0i32;
    for (k, t) in toks.iter().enumerate() {
        match t.text {
            "{" => {
                depth += 1;
                if struct_body.is_none() && k >= 2 && toks[k - 2].text == "struct" {
                    struct_body = Some(depth);
                }
            }
            "}" => {
                if struct_body == Some(depth) {
                    struct_body = None;
                }
                depth -= 1;
            }
            _ => {}
        }
        if t.kind != TokenKind::Ident {
            continue;
        }
        let after_dot = k > 0 && toks[k - 1].text == ".";
        let member = struct_body.is_some() && toks.get(k + 1).is_some_and(|n| n.text == ":");
        if !after_dot && !member {
            if let Some((_, new)) = renames.iter().find(|(old, _)| old == t.text) {
                edits.push(Edit {
                    start: t.start,
                    end: t.start + t.text.len(),
                    text: new.clone(),
                });
            }
            if let Some(body) = loop_body(&toks, k) {
                edits.push(Edit {
                    start: body,
                    end: body,
                    text: format!(" {guard} "),
                });
            }
        }
    }
    edits.sort_by_key(|e| e.start);
    let mut out = String::with_capacity(src.len() + edits.len() * guard.len());
    let mut at = 0;
    for e in edits {
        out.push_str(&src[at..e.start]);
        out.push_str(&e.text);
        at = e.end;
    }
    out.push_str(&src[at..]);
    out
}

/// Where the body of a loop whose keyword is token `k` begins (just after its `{`), or
/// `None` where token `k` begins no loop.
fn loop_body(toks: &[Token<'_>], k: usize) -> Option<usize> {
    let mut n = match toks[k].text {
        "loop" | "while" => k + 1,
        "for" => {
            // Past the parenthesized header.
            let mut depth = 0;
            let mut n = k + 1;
            while n < toks.len() {
                match toks[n].text {
                    "(" => depth += 1,
                    ")" => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    _ => {}
                }
                n += 1;
            }
            n + 1
        }
        _ => return None,
    };
    // The first `{` outside parentheses: a `while` condition holds none, nor do attributes.
    let mut depth = 0;
    while n < toks.len() {
        match toks[n].text {
            "(" => depth += 1,
            ")" => depth -= 1,
            "{" if depth == 0 => return Some(toks[n].start + 1),
            ";" | "}" => return None,
            _ => {}
        }
        n += 1;
    }
    None
}

/// The 1-based line and column (in characters) of byte `offset` of `src`.
pub fn line_column(src: &str, offset: usize) -> (usize, usize) {
    let before = &src[..offset.min(src.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_at_module_scope_only() {
        let src = "const PI = 3.14; // fn not_this\nvar<private> seed: u32;\n\
                   struct S { x: f32 }\nfn f(a: f32) -> f32 { let PI2 = 1.0; return a; }\n\
                   /* fn nor /* this */ */ alias R = f32;";
        let names: Vec<&str> = module_names(&tokens(src))
            .into_iter()
            .map(|n| n.0)
            .collect();
        assert_eq!(names, ["PI", "seed", "S", "f", "R"]);
    }

    #[test]
    fn numbers_keep_their_exponents() {
        let t = tokens("1e-5 0x1p-3f 0x1e-5 .5");
        let texts: Vec<&str> = t.iter().map(|t| t.text).collect();
        // A hexadecimal 0x1e minus 5: `e` is a digit there, not an exponent.
        assert_eq!(texts, ["1e-5", "0x1p-3f", "0x1e", "-", "5", ".5"]);
    }

    #[test]
    fn renames_spare_members() {
        let src = "struct S { PI: f32 }\nconst PI = 3.0;\nfn f(s: S) -> f32 { return s.PI * PI; }";
        let out = rewrite(src, &[("PI".into(), "file_PI".into())], "");
        assert_eq!(
            out,
            "struct S { PI: f32 }\nconst file_PI = 3.0;\nfn f(s: S) -> f32 { return s.PI * file_PI; }"
        );
    }

    #[test]
    fn every_loop_body_is_guarded() {
        let src = "fn f() { for (var i = 0; i < 3; i++) { } while (g(1)) { } loop { break; } }";
        let out = rewrite(src, &[], "G;");
        assert_eq!(out.matches("G;").count(), 3);
        assert!(out.contains("i++) { G;  }"), "{out}");
        assert!(out.contains("loop { G;  break;"), "{out}");
    }

    #[test]
    fn directives_are_found() {
        let t = tokens("enable f16;\nfn f() {}");
        assert_eq!(first_directive(&t), Some(("enable", 0)));
        let t = tokens("@diagnostic(off, derivative_uniformity) fn f() {}");
        assert_eq!(first_directive(&t), None);
    }

    #[test]
    fn lines_and_columns_count_from_one() {
        assert_eq!(line_column("ab\ncd", 4), (2, 2));
        assert_eq!(line_column("ab", 0), (1, 1));
    }
}
