//! `lut`'s encodings (docs/design.md §2.10): each measured on every shape
//! (`--encodings`), each layout's cost (`--layouts`), and one written as a table
//! (`--encode`).

use ltc_lab::error::{Error, Result};
use ltc_lab::files::{check_distinct, check_writable, is_exr, write_atomically};
use ltc_lab::ltc::lut::Encoding;
use ltc_lab::ltc::lut::encoding::SIZES;
use ltc_lab::ltc::lut::layout::layout_csv;
use ltc_lab::measure::encodings::{Candidate, csv_rows, encoding_errors};

use super::Args;
use crate::cli::print;

/// `--encodings`: every encoding measured on every shape, as CSV.
pub fn measure_encodings(a: &Args) -> Result<()> {
    if !(1..=100_000).contains(&a.cases) {
        return Err(Error::input(
            "--cases",
            format!("must be in 1..=100000, got {}", a.cases),
        ));
    }
    let lut = a.lut.load()?;
    let mut candidates: Vec<Candidate> = Encoding::tables(lut.size)
        .into_iter()
        .map(|e| Candidate::encoded(&lut, e))
        .collect();
    for &n in &a.fitted {
        if !SIZES[1..].contains(&n) {
            return Err(Error::input(
                "--fitted",
                format!("each size is one of {:?}, got {n}", &SIZES[1..]),
            ));
        }
        eprintln!("fitting the classic table at {n}×{n}…");
        candidates.push(Candidate::fitted(n));
    }
    for e in formulas(a)? {
        eprintln!("fitting {} to the table…", e.name());
        candidates.push(Candidate::encoded(&lut, e));
    }
    let rows = encoding_errors(&lut, &candidates, a.cases, 1);
    print(&format!(
        "encoding,bytes,shape,alpha,theta_o,cases,added_spec,added_diff,total_spec,total_diff\n{}",
        csv_rows(&rows)
    ))
}

/// `--layouts`: what a lookup costs for every encoding (and `--formulas`) in every layout.
pub fn layouts(a: &Args) -> Result<()> {
    let lut = a.lut.load()?;
    let mut encodings = Encoding::tables(lut.size);
    encodings.extend(formulas(a)?);
    print(&layout_csv(&encodings, lut.size))
}

/// `--formulas`, each checked to be one.
fn formulas(a: &Args) -> Result<Vec<Encoding>> {
    a.formulas
        .iter()
        .map(|e| match e.formula {
            Some(_) => Ok(*e),
            None => Err(Error::input(
                "--formulas",
                format!(
                    "each is a formula, chebD or rationalD (-STORAGE), not `{}`",
                    e.name()
                ),
            )),
        })
        .collect()
}

/// `--encode NAME --out FILE`: the table as the encoding gives it back (its f32 cells, which
/// `--encoding NAME` shades with too), as an .exr, written to the file the user named.
pub fn write_encoded(a: &Args, encoding: Encoding, out: &std::path::Path) -> Result<()> {
    if !is_exr(out) {
        return Err(Error::input(
            out.display().to_string(),
            "an encoded table is written as OpenEXR: the output must end in .exr",
        ));
    }
    if let Some(input) = &a.lut.lut {
        check_distinct(&[("--lut", input), ("--out", out)])?;
    }
    check_writable(out)?;
    let lut = a.lut.load()?;
    let (encoded, note) = encoding.decoded_saying(&lut);
    // A table every reader refuses is not written: its cells are not a fit's.
    if let Err(why) = encoded.validate() {
        return Err(Error::input(
            "--encode",
            format!(
                "{} gives a table that --lut would refuse ({why}): measure it with \
                 --encoding {} instead",
                encoding.name(),
                encoding.name()
            ),
        ));
    }
    if let Some(note) = note {
        eprintln!("ltc-lab: note: {note}");
    }
    write_atomically(out, &encoded.to_exr_bytes())?;
    eprintln!(
        "wrote {}: {} as {} ({}×{} cells, {} bytes in an engine)",
        out.display(),
        a.lut.describe(),
        encoding.name(),
        encoded.size,
        encoded.size,
        encoding.bytes(lut.size)
    );
    Ok(())
}
