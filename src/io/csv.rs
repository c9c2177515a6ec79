//! CSV of segments: one ruling (or line of a congruence) per line, six numbers a.x a.y a.z
//! b.x b.y b.z separated by commas, semicolons, tabs or spaces. An optional header line (the
//! first non-comment line, if it holds anything that is not a number) is skipped; blank lines
//! and lines starting with `#` are ignored.

use super::{classify, rust_number, Imported, NumberParser, Token, MAX_TEXT};
use crate::error::{Error, Message, Result};
use crate::msg;
use crate::tolerance::MAX_RULINGS;

fn fail(line: usize, column: usize, message: Message) -> Error {
    Error::parse("csv", Some(line), Some(column), message)
}

/// Parses CSV text into flat coordinates.
pub fn parse(text: &str) -> Result<Imported> {
    parse_with(text, &rust_number)
}

/// As [`parse`], converting numbers with `number` (see [`NumberParser`]).
pub fn parse_with(text: &str, number: NumberParser<'_>) -> Result<Imported> {
    if text.len() > MAX_TEXT {
        return Err(Error::TooMany { what: "bytes of CSV", got: text.len(), max: MAX_TEXT });
    }
    let mut coords = Vec::new();
    let mut header_allowed = true;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        // fields with their 1-based columns
        let mut fields: Vec<(usize, &str)> = Vec::with_capacity(6);
        let mut start = None;
        for (i, c) in raw.char_indices().chain(std::iter::once((raw.len(), ','))) {
            let separator = matches!(c, ',' | ';' | '\t' | ' ');
            match (separator, start) {
                (false, None) => start = Some(i),
                (true, Some(s)) => {
                    fields.push((raw[..s].chars().count() + 1, &raw[s..i]));
                    start = None;
                }
                _ => {}
            }
        }
        let kinds: Vec<Token> = fields.iter().map(|&(_, f)| classify(f)).collect();
        if header_allowed && kinds.contains(&Token::Invalid) {
            header_allowed = false;
            continue; // a header
        }
        header_allowed = false;
        for (&(col, f), kind) in fields.iter().zip(&kinds) {
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
        if coords.len() / 6 >= MAX_RULINGS {
            return Err(Error::TooMany { what: "rulings in the CSV", got: coords.len() / 6 + 1, max: MAX_RULINGS });
        }
        for &(col, f) in &fields {
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
    Ok(Imported { coords, grid: None })
}

/// Writes flat coordinates as CSV with a header (shortest round-trip number format).
pub fn write(coords: &[f64]) -> String {
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
        let r = parse(text).unwrap();
        assert_eq!(r.coords, vec![0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0]);
        assert_eq!(parse(&write(&r.coords)).unwrap(), r);
        let odd = [0.1, -2.5e-300, 1.0 / 3.0, 7.0, 1e17, -0.0];
        assert_eq!(parse(&write(&odd)).unwrap().coords, odd);
    }

    #[test]
    fn malformed_files_name_line_and_column() {
        let e = |t: &str| parse(t).unwrap_err().to_string();
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
}
