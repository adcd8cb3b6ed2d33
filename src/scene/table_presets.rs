//! The scenes where an encoding of the table fails (docs/design.md §2.10), and which encoding
//! fails in each: what the lab's *encoding B* offers as "where one fails", and what
//! tests/lut/encoding_failures.rs pins.

/// The scenes: a near-mirror floor (the table's α → 0 columns) and a glossy floor seen at
/// grazing angles (its last rows).
pub const TABLE_PRESETS: [(&str, &str); 2] = [
    (
        "table-mirror",
        include_str!("../../assets/scenes/table-mirror.toml"),
    ),
    (
        "table-grazing",
        include_str!("../../assets/scenes/table-grazing.toml"),
    ),
];

/// One failure: the preset that shows it, the encoding that fails there (a name
/// `Encoding::parse` reads), and what fails, in words.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EncodingFailure {
    pub preset: &'static str,
    pub encoding: &'static str,
    pub what: &'static str,
}

/// The failures the lab offers and the tests pin, each beside the f32 table it is compared
/// with (table A as read).
pub const ENCODING_FAILURES: [EncodingFailure; 3] = [
    EncodingFailure {
        preset: "table-mirror",
        encoding: "unorm8",
        what: "8 bits near α → 0: each channel's steps are its whole range over 255, coarser than M⁻¹'s small entries there, so the difference map bands",
    },
    EncodingFailure {
        preset: "table-mirror",
        encoding: "cheb8",
        what: "a Chebyshev series of degree 8 (three.js #34611's form, at half its degree) rings along the table's α → 0 column and grazing rows",
    },
    EncodingFailure {
        preset: "table-grazing",
        encoding: "f32-8",
        what: "an 8² table across the horizon band: three rows from θo 60° to 84°, where M⁻¹ turns fastest",
    },
];
