//! CSV of segments: one ruling (or line of a congruence) per line, six numbers a.x a.y a.z
//! b.x b.y b.z separated by commas, semicolons, tabs or spaces. An optional header line (the
//! first non-comment line, if it holds anything that is not a number) is skipped; blank lines
//! and lines starting with `#` are ignored.

use super::{classify, rust_number, Imported, NumberParser, Token};
use crate::error::{Error, Message, Result};
use crate::msg;
use crate::tolerance::{MAX_IMPORT_TEXT, MAX_RULINGS};

fn fail(line: usize, column: usize, message: Message) -> Error {
    Error::parse("csv", Some(line), Some(column), message)
}

/// Parses CSV text into flat coordinates.
pub fn read_csv(text: &str) -> Result<Imported> {
    read_csv_with(text, &rust_number)
}

/// As [`read_csv`], converting numbers with `number` (see [`NumberParser`]).
pub fn read_csv_with(text: &str, number: NumberParser<'_>) -> Result<Imported> {
    let (coords, lines) = rows_with(text, number)?;
    super::check_records("csv", &coords, |k| (lines.get(k).copied(), None))?;
    Ok(Imported { coords, grid: None })
}

/// The rows of six numbers (flat) and the 1-based line of each, checked for syntax only (the
/// tool poses of `io/toolpath.rs` read the same rows as tip and axis).
pub fn rows_with(text: &str, number: NumberParser<'_>) -> Result<(Vec<f64>, Vec<usize>)> {
    rows_at_most(text, number, MAX_RULINGS)
}

/// [`rows_with`] with at most `max_rows` rows (a parameter, so that a test reaches the limit
/// with three rows instead of four million).
fn rows_at_most(text: &str, number: NumberParser<'_>, max_rows: usize) -> Result<(Vec<f64>, Vec<usize>)> {
    if text.len() > MAX_IMPORT_TEXT {
        return Err(Error::TooMany { what: "bytes of CSV", got: text.len(), max: MAX_IMPORT_TEXT });
    }
    let mut coords = Vec::new();
    // the 1-based line of each record, for the messages of check_records
    let mut lines: Vec<usize> = Vec::new();
    let mut header_allowed = true;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let fields = super::table::fields(raw);
        let kinds: Vec<Token> = fields.iter().map(|(_, f)| classify(f)).collect();
        if header_allowed && kinds.contains(&Token::Invalid) {
            header_allowed = false;
            continue; // a header
        }
        header_allowed = false;
        for ((col, f), kind) in fields.iter().zip(&kinds) {
            let (col, f) = (*col, f.as_ref());
            match kind {
                Token::Invalid => return Err(fail(line, col, msg!("not-a-number", text = f))),
                Token::NonFinite => return Err(fail(line, col, msg!("not-finite-number", text = f))),
                Token::Number => {}
            }
        }
        if fields.len() != 6 {
            let col = fields.get(6).map_or(raw.chars().count() + 1, |f| f.0);
            return Err(fail(line, col, msg!("csv-six-numbers", found = fields.len())));
        }
        if coords.len() / 6 >= max_rows {
            return Err(Error::TooMany { what: "rulings in the CSV", got: coords.len() / 6 + 1, max: max_rows });
        }
        lines.push(line);
        for (col, f) in &fields {
            let (col, f) = (*col, f.as_ref());
            let x = number(f);
            if !x.is_finite() {
                return Err(fail(line, col, msg!("not-finite-number", text = f)));
            }
            coords.push(x);
        }
    }
    if coords.is_empty() {
        return Err(Error::parse("csv", None, None, msg!("csv-no-data")));
    }
    Ok((coords, lines))
}

/// Writes flat coordinates as CSV with a header (shortest round-trip number format).
pub fn write_csv(coords: &[f64]) -> String {
    let mut out = String::from("ax,ay,az,bx,by,bz\n");
    for c in coords.chunks_exact(6) {
        let row: Vec<String> = c.iter().map(|x| format!("{x:?}")).collect();
        out.push_str(&row.join(","));
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_with_and_without_header_and_round_trips() {
        let text = "# a comment\nax,ay,az,bx,by,bz\n0,0,0,1,0,0\n\n0 0 1 ; 0 1 1\n";
        let r = read_csv(text).unwrap();
        assert_eq!(r.coords, vec![0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]);
        assert_eq!(read_csv(&write_csv(&r.coords)).unwrap(), r);
        let odd = [0.1, -2.5e-300, 1.0 / 3.0, 7.0, 1e17, -0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        assert_eq!(read_csv(&write_csv(&odd)).unwrap().coords, odd);
    }

    /// A German spreadsheet: semicolons between the fields, decimal commas in the numbers.
    #[test]
    fn semicolon_lines_take_decimal_commas() {
        let r = read_csv("ax;ay;az;bx;by;bz\n1,5;0;0;0;1;0\n0; 0; 1,25; -0,5; 1; 1\n").unwrap();
        assert_eq!(r.coords, vec![1.5, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.25, -0.5, 1.0, 1.0]);
    }

    /// One record, or a record of zero length, is refused where it is, with its line.
    #[test]
    fn records_are_checked_where_they_are() {
        let e = read_csv("0,0,0,1,0,0\n").unwrap_err();
        assert_eq!(e.details().reason, Some("import-too-few"));
        let e = read_csv("# header\n0,0,0,1,0,0\n\n2,2,2,2,2,2\n").unwrap_err();
        assert_eq!((e.details().reason, e.details().line), (Some("import-zero-length"), Some(4)));
    }

    #[test]
    fn malformed_files_name_line_and_column() {
        let e = |t: &str| read_csv(t).unwrap_err().to_string();
        assert_eq!(
            e("x,y,z,a,b,c\n0,0,0,1,0\n"),
            "csv: line 2, column 10: expected 6 numbers (a.x a.y a.z b.x b.y b.z), found 5"
        );
        assert_eq!(e("0,0,0,1,0,0\n0,0,zero,1,0,0\n"), "csv: line 2, column 5: \"zero\" is not a number");
        assert_eq!(
            e("0,0,0,1,0,0,7\n"),
            "csv: line 1, column 13: expected 6 numbers (a.x a.y a.z b.x b.y b.z), found 7"
        );
        assert_eq!(e("0,0,NaN,1,0,0\n"), "csv: line 1, column 5: NaN is not a finite number");
        assert!(e("\n# nothing\n").contains("no data lines"));
        assert!(e("just a header\n").contains("no data lines"));
    }

    #[test]
    fn a_text_of_the_size_limit_is_read_and_a_byte_more_is_not() {
        let data = "0,0,0,1,0,0\n0,0,1,0,1,1\n#";
        let mut text = format!("{data}{}", "x".repeat(MAX_IMPORT_TEXT - data.len()));
        assert_eq!(read_csv(&text).unwrap().coords.len(), 12);
        text.push('x');
        let e = read_csv(&text).unwrap_err();
        assert_eq!((e.code(), e.details().limit), ("too-large", Some(MAX_IMPORT_TEXT as f64)));
    }

    #[test]
    fn rows_beyond_the_limit_are_refused_at_the_first_one_over() {
        let rows = "0,0,0,1,0,0\n# a comment\n0,0,1,0,1,1\n0,0,2,1,1,2\n";
        assert_eq!(rows_at_most(rows, &rust_number, 3).unwrap().1, [1, 3, 4]);
        let e = rows_at_most(rows, &rust_number, 2).unwrap_err();
        assert_eq!(e, Error::TooMany { what: "rulings in the CSV", got: 3, max: 2 });
    }
}
