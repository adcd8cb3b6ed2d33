//! `--method-for [SIDE:]SHAPE=METHOD`: how a render's side shades one shape, keyed by the
//! shape (docs/design.md §5.12), and today's per-shape flags (`--rect-a`, `--disk-b`…) as
//! its aliases. A shape named twice for one side, by two flags that disagree, is refused.

use ltc_lab::error::{Error, Result};
use ltc_lab::light::ShapeKind;
use ltc_lab::render::ShapeMethod;

/// Which side of a render a choice is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The method alone, or left of a split (the numerator of a diff).
    A,
    /// Right of a split (the reference of a diff).
    B,
}

/// One `--method-for`: a side and a method of one shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MethodFor {
    pub side: Side,
    pub method: ShapeMethod,
}

/// `--method-for`'s help: what it takes, then each shape with its methods and the defaults
/// of side A and side B, in `ShapeKind::ALL`'s order (a point's methods are the side's own).
pub fn help() -> String {
    let shapes: Vec<String> = ShapeKind::ALL
        .into_iter()
        .map(|kind| {
            if kind == ShapeKind::Point {
                return "point (the side's method: --point-a and --point-b)".to_string();
            }
            let names: Vec<_> = ShapeMethod::all(kind).iter().map(|m| m.name()).collect();
            format!(
                "{} ({}; default {} | {})",
                kind.name(),
                names.join(", "),
                ShapeMethod::approximation(kind).name(),
                ShapeMethod::reference(kind).name()
            )
        })
        .collect();
    format!(
        "How a side shades one shape, `[a:|b:]SHAPE=METHOD` (side a, the method alone or left \
         of a split, unless b: the reference right of it), as often as there are shapes: \
         `rect=ltc-proxy`, `b:sphere=ltc-disk`. The shapes and their methods (docs/design.md \
         §1.10–§1.15): {}.",
        shapes.join(", ")
    )
}

/// `[a:|b:]SHAPE=METHOD`, e.g. `rect=ltc-proxy` or `b:disk=ltc-disk` (side A unless told).
pub fn parse(text: &str) -> std::result::Result<MethodFor, String> {
    let (side, rest) = match text.split_once(':') {
        Some(("a", rest)) => (Side::A, rest),
        Some(("b", rest)) => (Side::B, rest),
        Some((side, _)) => return Err(format!("the side is a or b, got `{side}`")),
        None => (Side::A, text),
    };
    let shapes = || ShapeKind::ALL.map(ShapeKind::name).join(", ");
    let Some((shape, method)) = rest.split_once('=') else {
        return Err(format!("write SHAPE=METHOD (SHAPE one of {})", shapes()));
    };
    let kind = ShapeKind::from_name(shape)
        .ok_or_else(|| format!("no shape `{shape}`: one of {}", shapes()))?;
    let method = ShapeMethod::parse(kind, method).ok_or_else(|| {
        let names: Vec<_> = ShapeMethod::all(kind).iter().map(|m| m.name()).collect();
        format!(
            "{shape} has no method `{method}`: one of {}",
            names.join(", ")
        )
    })?;
    Ok(MethodFor { side, method })
}

/// The choices of `given` (each with the flag it came by), one per side and shape: a
/// second choice for the same side and shape that differs from the first is refused,
/// naming both flags.
pub fn merged(given: &[(&'static str, MethodFor)]) -> Result<Vec<MethodFor>> {
    let mut kept: Vec<(&'static str, MethodFor)> = Vec::new();
    for &(flag, choice) in given {
        let same = |(_, c): &&(&str, MethodFor)| {
            c.side == choice.side && c.method.kind() == choice.method.kind()
        };
        match kept.iter().find(same) {
            Some((_, c)) if c.method == choice.method => {}
            Some((first, c)) => {
                return Err(Error::input(
                    flag,
                    format!(
                        "{} {} for {}, where {first} gave {}",
                        choice.method.kind().name(),
                        choice.method.name(),
                        side_name(choice.side),
                        c.method.name()
                    ),
                ));
            }
            None => kept.push((flag, choice)),
        }
    }
    Ok(kept.into_iter().map(|(_, c)| c).collect())
}

fn side_name(side: Side) -> &'static str {
    match side {
        Side::A => "side A",
        Side::B => "side B",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ltc_lab::light::rect::RectMethod;

    #[test]
    fn a_side_a_shape_and_a_method_of_that_shape() {
        let rect = ShapeMethod::Rect(RectMethod::LtcProxy);
        assert_eq!(
            parse("rect=ltc-proxy"),
            Ok(MethodFor {
                side: Side::A,
                method: rect
            })
        );
        assert_eq!(parse("b:rect=ltc-proxy").map(|m| m.side), Ok(Side::B));
        for bad in [
            "rect",
            "c:rect=exact",
            "cone=exact",
            "disk=ltc-polygon",
            "rect=",
        ] {
            assert!(parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn two_flags_that_disagree_are_refused() {
        let a = |m| MethodFor {
            side: Side::A,
            method: ShapeMethod::Rect(m),
        };
        let agree = [
            ("--rect-a", a(RectMethod::Exact)),
            ("--method-for", a(RectMethod::Exact)),
        ];
        assert_eq!(merged(&agree).map(|m| m.len()).ok(), Some(1));
        let differ = [
            ("--rect-a", a(RectMethod::Exact)),
            ("--method-for", a(RectMethod::LtcPoint)),
        ];
        let e = merged(&differ).unwrap_err().to_string();
        assert!(e.contains("--method-for") && e.contains("--rect-a"), "{e}");
    }
}
