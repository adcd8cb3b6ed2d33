//! Enums whose variants are listed once, each with the name the command line, the files and
//! the lab use: `ALL` (the declaration's order), `name`, `from_name` and `index` come from
//! that one list, so that no second list can drift from the first (docs/design.md §5.1).

/// Declares a field-less enum as `Variant = "name"` pairs and derives from them:
/// - `ALL`: every variant in the declaration's order;
/// - `name(self)`: the variant's name;
/// - `from_name(&str)`: the variant of that name;
/// - `index(self)`: its place in `ALL`.
///
/// Attributes and doc comments on the enum and on each variant are kept.
macro_rules! named_enum {
    (
        $(#[$meta:meta])*
        $vis:vis enum $Name:ident {
            $( $(#[$vmeta:meta])* $Variant:ident = $name:literal ),+ $(,)?
        }
    ) => {
        $(#[$meta])*
        $vis enum $Name {
            $( $(#[$vmeta])* $Variant ),+
        }

        impl $Name {
            /// Every variant, in the declaration's order.
            pub const ALL: [Self; [$($name),+].len()] = [$(Self::$Variant),+];

            /// Its name on the command line, in files and in the lab.
            pub fn name(self) -> &'static str {
                match self {
                    $(Self::$Variant => $name),+
                }
            }

            /// The variant named `name`, if any.
            #[allow(dead_code)]
            pub fn from_name(name: &str) -> Option<Self> {
                Self::ALL.into_iter().find(|v| v.name() == name)
            }

            /// Its place in `ALL` (the declaration's order).
            #[allow(dead_code)]
            pub fn index(self) -> usize {
                self as usize
            }
        }
    };
}

pub(crate) use named_enum;
