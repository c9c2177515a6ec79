//! Data formats, the one home of every file the geometry reads or writes as data (drawings are
//! the page's: `www/export/`; tool paths, tool poses and target curves are ruledlab-cam's, built
//! on the JSON and table readers here): segments as CSV (6 numbers per line) and JSON, read and
//! written; OBJ of a strip; a flat pattern's sheet as SVG and DXF R12 for cutting; the invariants of Section 2 as CSV and JSON; what kind of data a text
//! holds (`sniff`).
//! Malformed input is rejected with the line and column of the problem; sizes are checked
//! before anything large is allocated ([`MAX_IMPORT_TEXT`](crate::tolerance::MAX_IMPORT_TEXT), and the ruling limit).

pub mod csv;
pub mod invariants;
pub mod json;
pub mod obj;
pub mod sheet_dxf;
pub mod sheet_svg;
pub mod sniff;
pub mod table;

use crate::error::{Error, Result};
use crate::tolerance::ZERO_LENGTH_REL;
use glam::DVec3;

/// Imported data: flat coordinates (6 per line) and, for a congruence, its grid shape.
#[derive(Debug, Clone, PartialEq)]
pub struct Imported {
    /// p/a then q/b per line.
    pub coords: Vec<f64>,
    /// (rows, cols) when the file gives a grid shape.
    pub grid: Option<(usize, usize)>,
}

/// Converts a token that [`classify`] found to be a decimal number into an `f64`. The core
/// uses Rust's `str::parse`; the wasm bindings pass the host's correctly rounded `parseFloat`
/// instead, which keeps Rust's large float-parsing tables out of the wasm file. Both round
/// correctly, so they agree to the last bit.
pub type NumberParser<'a> = &'a dyn Fn(&str) -> f64;

/// Rust's own conversion (for native use and the tests).
pub fn rust_number(token: &str) -> f64 {
    token.parse().unwrap_or(f64::NAN)
}

/// What a token is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Token {
    /// A decimal number: `[+-]? digits [. digits] [(e|E) [+-] digits]` (or `.digits`).
    Number,
    /// NaN or an infinity, spelled as Rust or JavaScript would.
    NonFinite,
    /// Anything else.
    Invalid,
}

/// Classifies a token without converting it.
pub fn classify(token: &str) -> Token {
    let t = token.strip_prefix(['+', '-']).unwrap_or(token);
    if ["nan", "inf", "infinity"].iter().any(|w| t.eq_ignore_ascii_case(w)) {
        return Token::NonFinite;
    }
    let (mantissa, exponent) = match t.find(['e', 'E']) {
        Some(i) => (&t[..i], Some(&t[i + 1..])),
        None => (t, None),
    };
    let (int, frac) = match mantissa.split_once('.') {
        Some((a, b)) => (a, Some(b)),
        None => (mantissa, None),
    };
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    let mantissa_ok = digits(int) && frac.is_none_or(digits) && !(int.is_empty() && frac.is_none_or(str::is_empty));
    let exponent_ok = exponent.is_none_or(|e| {
        let e = e.strip_prefix(['+', '-']).unwrap_or(e);
        !e.is_empty() && digits(e)
    });
    if mantissa_ok && exponent_ok {
        Token::Number
    } else {
        Token::Invalid
    }
}

/// The checks an imported file passes besides its syntax, each said where it fails: at least
/// two records (lines of six numbers), and no record whose endpoints coincide (the rule of
/// [`crate::tolerance::ZERO_LENGTH_REL`]: it would have no direction). `at(k)` is the line and
/// column where record k starts.
pub fn check_records(source: &str, coords: &[f64], at: impl Fn(usize) -> (Option<usize>, Option<usize>)) -> Result<()> {
    let n = coords.len() / 6;
    if n < 2 {
        return Err(Error::parse(source, None, None, crate::msg!("import-too-few", found = n)));
    }
    let rel2 = ZERO_LENGTH_REL * ZERO_LENGTH_REL;
    for (k, r) in coords.chunks_exact(6).enumerate() {
        let (a, b) = (DVec3::new(r[0], r[1], r[2]), DVec3::new(r[3], r[4], r[5]));
        if (b - a).length_squared() <= rel2 * a.length_squared().max(b.length_squared()) {
            let (line, column) = at(k);
            return Err(Error::parse(source, line, column, crate::msg!("import-zero-length", record = k)));
        }
    }
    Ok(())
}

/// 1-based line and column of byte offset `at` in `text`.
pub fn position(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..at.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn token_grammar() {
        for t in ["0", "-1", "+2.5", ".5", "5.", "1e3", "1E-300", "-0.0", "123456789012345678901234567890"] {
            assert_eq!(classify(t), Token::Number, "{t}");
        }
        for t in ["NaN", "inf", "-Infinity", "+INF"] {
            assert_eq!(classify(t), Token::NonFinite, "{t}");
        }
        for t in ["", ".", "-", "e5", "1e", "1e+", "0x10", "1,5", "1.2.3", "--1", "1e5.5", "١"] {
            assert_eq!(classify(t), Token::Invalid, "{t}");
        }
    }

    #[test]
    fn a_record_is_of_zero_length_relative_to_its_endpoints() {
        let at = |_| (None, None);
        // endpoints near 1000 apart by 1e-10: |b − a|² = 1e-20 ≤ (1e-12)²·1e6 = 1e-18, zero length
        let near = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1000.0, 0.0, 0.0, 1000.0, 1e-10, 0.0];
        let e = check_records("csv", &near, at).unwrap_err();
        assert_eq!(e.details().reason, Some("import-zero-length"));
        // endpoints near 1 apart by 1e-11: |b − a|² = 1e-22 > (1e-12)²·1 = 1e-24, a direction
        let short = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1e-11, 0.0];
        assert!(check_records("csv", &short, at).is_ok());
        assert_eq!(check_records("csv", &near[..6], at).unwrap_err().details().reason, Some("import-too-few"));
    }
}
