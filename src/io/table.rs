//! A table of numbers as spreadsheets and CAM systems write it: a record a line, its numbers
//! separated by commas, tabs or spaces — or by semicolons, and then with decimal commas
//! (German spreadsheets: `1,5;0;0`) —, an optional first line of column names, `#` comments
//! (kept: a comment may say the file's units or machine). Each number is said where it is
//! wrong: its line and column. Read for tool poses with named columns and for target curves.

use crate::error::{Error, Result};
use crate::io::{classify, NumberParser, Token};
use crate::tolerance::MAX_IMPORT_TEXT;
use std::borrow::Cow;

/// One record: its 1-based line, its numbers, and each one's 1-based column.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The line.
    pub line: usize,
    /// The numbers.
    pub values: Vec<f64>,
    /// Their columns.
    pub columns: Vec<usize>,
}

/// A table read.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The column names of a header line, lowercase and trimmed.
    pub header: Option<Vec<String>>,
    /// The records.
    pub rows: Vec<Row>,
    /// The comments' texts (after `#`, trimmed).
    pub comments: Vec<String>,
    /// The line of the last text line (for a message about the whole file).
    pub lines: usize,
}

impl Table {
    /// The value of a comment `# key: value` (the key compared without case), if one says it.
    pub fn said(&self, key: &str) -> Option<String> {
        self.comments.iter().find_map(|c| {
            let (k, v) = c.split_once(':')?;
            k.trim().eq_ignore_ascii_case(key).then(|| v.trim().to_string())
        })
    }
}

/// The fields of a line with their 1-based columns: separated by commas, semicolons, tabs or
/// spaces; a line separated by semicolons writes numbers with decimal commas (German
/// spreadsheets: "1,5;0;0;…"), read as points. Borrowed where nothing is replaced.
pub fn fields(raw: &str) -> Vec<(usize, Cow<'_, str>)> {
    let decimal_comma = raw.contains(';');
    let mut out = Vec::with_capacity(6);
    let mut start = None;
    for (i, c) in raw.char_indices().chain(std::iter::once((raw.len(), ' '))) {
        let separator = matches!(c, ';' | '\t' | ' ') || (c == ',' && !decimal_comma);
        match (separator, start) {
            (false, None) => start = Some(i),
            (true, Some(s)) => {
                let field = &raw[s..i];
                let field = if decimal_comma { field.replace(',', ".").into() } else { field.into() };
                out.push((raw[..s].chars().count() + 1, field));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// Reads a table from `text` (named `source` in messages), at most `max_rows` records.
pub fn read_table(text: &str, number: NumberParser<'_>, source: &str, max_rows: usize) -> Result<Table> {
    if text.len() > MAX_IMPORT_TEXT {
        return Err(Error::TooMany { what: "bytes of CSV", got: text.len(), max: MAX_IMPORT_TEXT });
    }
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut table = Table { header: None, rows: Vec::new(), comments: Vec::new(), lines: 0 };
    let mut header_allowed = true;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        table.lines = line;
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(comment) = trimmed.strip_prefix('#') {
            table.comments.push(comment.trim().to_string());
            continue;
        }
        let fields = fields(raw);
        let kinds: Vec<Token> = fields.iter().map(|(_, f)| classify(f)).collect();
        if header_allowed && kinds.contains(&Token::Invalid) {
            header_allowed = false;
            table.header = Some(fields.iter().map(|(_, f)| f.trim().to_ascii_lowercase()).collect());
            continue;
        }
        header_allowed = false;
        let mut row = Row { line, values: Vec::with_capacity(fields.len()), columns: Vec::with_capacity(fields.len()) };
        for ((col, f), kind) in fields.iter().zip(&kinds) {
            let x = match kind {
                Token::Invalid => {
                    return Err(Error::parse(
                        source,
                        Some(line),
                        Some(*col),
                        crate::msg!("not-a-number", text = f.as_ref()),
                    ))
                }
                Token::NonFinite => {
                    return Err(Error::parse(
                        source,
                        Some(line),
                        Some(*col),
                        crate::msg!("not-finite-number", text = f.as_ref()),
                    ))
                }
                Token::Number => number(f),
            };
            if !x.is_finite() {
                return Err(Error::parse(
                    source,
                    Some(line),
                    Some(*col),
                    crate::msg!("not-finite-number", text = f.as_ref()),
                ));
            }
            row.values.push(x);
            row.columns.push(*col);
        }
        if table.rows.len() >= max_rows {
            return Err(Error::TooMany { what: "records in the CSV", got: table.rows.len() + 1, max: max_rows });
        }
        table.rows.push(row);
    }
    Ok(table)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::rust_number;

    /// The limits are exact: a text of MAX_IMPORT_TEXT bytes is read and one byte more refused
    /// before anything is parsed; `max_rows` records are read and the next refused, counted as
    /// the record it would have been.
    #[test]
    fn the_size_and_record_limits_are_exact() {
        let blank = " ".repeat(MAX_IMPORT_TEXT);
        assert_eq!(read_table(&blank, &rust_number, "csv", 10).unwrap().rows.len(), 0);
        let over = " ".repeat(MAX_IMPORT_TEXT + 1);
        assert_eq!(
            read_table(&over, &rust_number, "csv", 10).unwrap_err(),
            Error::TooMany { what: "bytes of CSV", got: MAX_IMPORT_TEXT + 1, max: MAX_IMPORT_TEXT }
        );
        let three = "1 2 3\n4 5 6\n7 8 9\n";
        assert_eq!(read_table(three, &rust_number, "csv", 3).unwrap().rows.len(), 3);
        assert_eq!(
            read_table(three, &rust_number, "csv", 2).unwrap_err(),
            Error::TooMany { what: "records in the CSV", got: 3, max: 2 }
        );
    }

    #[test]
    fn a_table_with_a_header_comments_and_decimal_commas() {
        let t = read_table("\u{feff}# units: inch\nX;Y;Z\n1,5;0;-2\n\n3 4\t5\n", &rust_number, "csv", 10).unwrap();
        assert_eq!(t.header, Some(vec!["x".into(), "y".into(), "z".into()]));
        assert_eq!(t.said("UNITS").as_deref(), Some("inch"));
        assert_eq!(t.rows.len(), 2);
        assert_eq!((t.rows[0].line, &t.rows[0].values), (3, &vec![1.5, 0.0, -2.0]));
        assert_eq!((t.rows[1].line, &t.rows[1].columns), (5, &vec![1, 3, 5]));
        let e = read_table("1,2,x\n", &rust_number, "csv", 10);
        assert!(e.is_ok(), "a first line with a word is a header");
        let e = read_table("1,2,3\n1,2,x\n", &rust_number, "csv", 10).unwrap_err();
        assert_eq!((e.details().line, e.details().column), (Some(2), Some(5)));
        let e = read_table("1,2,3\n1,inf,3\n", &rust_number, "csv", 10).unwrap_err();
        assert_eq!(e.details().reason, Some("not-finite-number"));
        assert!(matches!(read_table("1\n2\n3\n", &rust_number, "csv", 2), Err(Error::TooMany { .. })));
    }
}
