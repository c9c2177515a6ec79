//! JSON of segments. Accepted shapes:
//!
//! - `[[ax, ay, az, bx, by, bz], …]`: one array of six numbers per line;
//! - `[ax, ay, az, bx, by, bz, …]`: flat, a multiple of six numbers;
//! - `{ "segments": <either of the above>, "rows": r, "cols": c }`: rows and cols (both or
//!   neither) give a congruence's grid shape; other keys are ignored.
//!
//! A small recursive-descent parser (nesting limited to 16 levels, so hostile input cannot
//! exhaust the stack) reports the line and column of any problem.

use super::{classify, position, rust_number, Imported, NumberParser, Token};
use crate::error::{Error, Message, Result};
use crate::msg;
use crate::tolerance::{MAX_IMPORT_TEXT, MAX_JSON_DEPTH, MAX_JSON_NUMBERS, MAX_RULINGS};

/// A parsed JSON value; arrays and objects keep the byte offset of each item (so that a reader
/// built on it says where a value at fault is, by line and column).
#[derive(Debug, Clone, PartialEq)]
pub enum JsonValue {
    /// `null`.
    Null,
    /// `true` or `false` (which one is not kept: no reader needs it).
    Bool,
    /// A number, read by the parser given.
    Number(f64),
    /// A string, its escapes resolved.
    String(String),
    /// An array: each item with its byte offset.
    Array(Vec<(usize, JsonValue)>),
    /// An object: each field's name, its value's byte offset, its value.
    Object(Vec<(String, usize, JsonValue)>),
}

/// A parse error at byte offset `at` of `text`, said by line and column.
fn fail(text: &str, at: usize, message: Message) -> Error {
    let (line, column) = position(text, at);
    Error::parse("json", Some(line), Some(column), message)
}

struct Parser<'a> {
    text: &'a str,
    bytes: &'a [u8],
    at: usize,
    numbers: usize,
    /// The most numbers read ([`MAX_JSON_NUMBERS`]; a test's own below it).
    max_numbers: usize,
    number: NumberParser<'a>,
}

impl<'a> Parser<'a> {
    fn fail(&self, at: usize, message: Message) -> Error {
        fail(self.text, at, message)
    }

    fn skip_space(&mut self) {
        while self.at < self.bytes.len() && matches!(self.bytes[self.at], b' ' | b'\t' | b'\n' | b'\r') {
            self.at += 1;
        }
    }

    fn value(&mut self, depth: usize) -> Result<(usize, JsonValue)> {
        self.skip_space();
        let start = self.at;
        if depth > MAX_JSON_DEPTH {
            return Err(self.fail(start, msg!("json-too-deep", max = MAX_JSON_DEPTH)));
        }
        let Some(&c) = self.bytes.get(self.at) else { return Err(self.fail(start, msg!("json-end"))) };
        let v = match c {
            b'[' => {
                self.at += 1;
                let mut items = Vec::new();
                self.skip_space();
                if self.bytes.get(self.at) == Some(&b']') {
                    self.at += 1;
                } else {
                    loop {
                        items.push(self.value(depth + 1)?);
                        self.skip_space();
                        match self.bytes.get(self.at) {
                            Some(b',') => self.at += 1,
                            Some(b']') => {
                                self.at += 1;
                                break;
                            }
                            _ => return Err(self.fail(self.at, msg!("json-array-separator"))),
                        }
                    }
                }
                JsonValue::Array(items)
            }
            b'{' => {
                self.at += 1;
                let mut fields = Vec::new();
                self.skip_space();
                if self.bytes.get(self.at) == Some(&b'}') {
                    self.at += 1;
                } else {
                    loop {
                        self.skip_space();
                        let key_at = self.at;
                        let JsonValue::String(key) = self.value(depth + 1)?.1 else {
                            return Err(self.fail(key_at, msg!("json-string-key")));
                        };
                        self.skip_space();
                        if self.bytes.get(self.at) != Some(&b':') {
                            return Err(self.fail(self.at, msg!("json-colon")));
                        }
                        self.at += 1;
                        let (at, v) = self.value(depth + 1)?;
                        fields.push((key, at, v));
                        self.skip_space();
                        match self.bytes.get(self.at) {
                            Some(b',') => self.at += 1,
                            Some(b'}') => {
                                self.at += 1;
                                break;
                            }
                            _ => return Err(self.fail(self.at, msg!("json-object-separator"))),
                        }
                    }
                }
                JsonValue::Object(fields)
            }
            b'"' => {
                self.at += 1;
                let begin = self.at;
                while self.at < self.bytes.len() && self.bytes[self.at] != b'"' {
                    self.at += if self.bytes[self.at] == b'\\' { 2 } else { 1 };
                }
                if self.at >= self.bytes.len() {
                    return Err(self.fail(start, msg!("json-unterminated")));
                }
                let s = self.text.get(begin..self.at).unwrap_or("").to_string();
                self.at += 1;
                JsonValue::String(s)
            }
            b't' | b'f' | b'n' => {
                for word in ["true", "false", "null"] {
                    if self.text.get(self.at..self.at + word.len()) == Some(word) {
                        self.at += word.len();
                        return Ok((start, if word == "null" { JsonValue::Null } else { JsonValue::Bool }));
                    }
                }
                return Err(self.fail(start, msg!("json-word")));
            }
            b'-' | b'0'..=b'9' => {
                while self.at < self.bytes.len()
                    && matches!(self.bytes[self.at], b'-' | b'+' | b'.' | b'e' | b'E' | b'0'..=b'9')
                {
                    self.at += 1;
                }
                let token = &self.text[start..self.at];
                if classify(token) != Token::Number {
                    return Err(self.fail(start, msg!("not-a-number", text = token)));
                }
                let x = (self.number)(token);
                if !x.is_finite() {
                    return Err(self.fail(start, msg!("not-finite-number", text = token)));
                }
                self.numbers += 1;
                if self.numbers > self.max_numbers {
                    return Err(Error::TooMany {
                        what: "numbers in the JSON",
                        got: self.numbers,
                        max: self.max_numbers,
                    });
                }
                JsonValue::Number(x)
            }
            _ => {
                let c = self.text[start..].chars().next().unwrap_or(' ');
                return Err(self.fail(start, msg!("json-character", char = c)));
            }
        };
        Ok((start, v))
    }
}

/// Parses JSON text into a [`JsonValue`] with the size and nesting limits of [`read_json`]: the
/// root's byte offset and the value (the tool poses of ruledlab-cam are read with it).
pub fn read_json_value<'a>(text: &'a str, number: NumberParser<'a>) -> Result<(usize, JsonValue)> {
    value_at_most(text, number, MAX_JSON_NUMBERS)
}

/// [`value_with`] with at most `max_numbers` numbers (a parameter, so that a test reaches the
/// limit with a few numbers instead of 25 million).
fn value_at_most<'a>(text: &'a str, number: NumberParser<'a>, max_numbers: usize) -> Result<(usize, JsonValue)> {
    if text.len() > MAX_IMPORT_TEXT {
        return Err(Error::TooMany { what: "bytes of JSON", got: text.len(), max: MAX_IMPORT_TEXT });
    }
    let mut p = Parser { text, bytes: text.as_bytes(), at: 0, numbers: 0, max_numbers, number };
    let root = p.value(0)?;
    p.skip_space();
    if p.at < text.len() {
        return Err(p.fail(p.at, msg!("json-trailing")));
    }
    Ok(root)
}

/// Parses JSON text into flat coordinates (and a grid shape if given).
pub fn read_json(text: &str) -> Result<Imported> {
    read_json_with(text, &rust_number)
}

/// As [`read_json`], converting numbers with `number` (see [`NumberParser`]).
pub fn read_json_with<'a>(text: &'a str, number: NumberParser<'a>) -> Result<Imported> {
    let (at, root) = read_json_value(text, number)?;
    let (segments_at, segments, grid) = match root {
        JsonValue::Object(fields) => {
            let find = |k: &str| fields.iter().find(|f| f.0 == k);
            let Some((_, s_at, s)) = find("segments") else {
                return Err(fail(text, at, msg!("json-segments-missing")));
            };
            let dim = |k: &str| -> Result<Option<usize>> {
                match find(k) {
                    None => Ok(None),
                    Some((_, a, JsonValue::Number(x))) if x.fract() == 0.0 && *x >= 2.0 && *x <= MAX_RULINGS as f64 => {
                        Ok(Some(*x as usize))
                    }
                    Some((_, a, _)) => Err(fail(text, *a, msg!("json-grid-integer", key = k, max = MAX_RULINGS))),
                }
            };
            let grid = match (dim("rows")?, dim("cols")?) {
                (Some(r), Some(c)) => Some((r, c)),
                (None, None) => None,
                _ => return Err(fail(text, at, msg!("json-rows-and-cols"))),
            };
            (*s_at, s.clone(), grid)
        }
        other => (at, other, None),
    };
    let JsonValue::Array(items) = segments else {
        return Err(fail(text, segments_at, msg!("json-segments-array")));
    };
    let mut coords = Vec::with_capacity(items.len().min(MAX_JSON_NUMBERS));
    // where each record starts, for the messages of check_records
    let mut starts: Vec<usize> = Vec::new();
    let nested = matches!(items.first(), Some((_, JsonValue::Array(_))));
    for (item_at, item) in &items {
        if nested || coords.len() % 6 == 0 {
            starts.push(*item_at);
        }
        match (nested, item) {
            (false, JsonValue::Number(x)) => coords.push(*x),
            (true, JsonValue::Array(row)) => {
                if row.len() != 6 {
                    return Err(fail(text, *item_at, msg!("json-segment-six", found = row.len())));
                }
                for (a, v) in row {
                    match v {
                        JsonValue::Number(x) => coords.push(*x),
                        _ => return Err(fail(text, *a, msg!("json-number"))),
                    }
                }
            }
            (true, _) => return Err(fail(text, *item_at, msg!("json-segment"))),
            (false, _) => return Err(fail(text, *item_at, msg!("json-number"))),
        }
    }
    if coords.len() % 6 != 0 {
        return Err(fail(text, segments_at, msg!("json-whole-segments", count = coords.len())));
    }
    if let Some((r, c)) = grid {
        if r * c * 6 != coords.len() {
            return Err(fail(
                text,
                at,
                msg!("json-grid-count", rows = r, cols = c, need = r * c, found = coords.len() / 6),
            ));
        }
    }
    super::check_records("json", &coords, |k| match starts.get(k) {
        Some(&a) => {
            let (line, column) = position(text, a);
            (Some(line), Some(column))
        }
        None => (None, None),
    })?;
    Ok(Imported { coords, grid })
}

/// Writes segments as `{ "segments": [[…], …] }`, with the grid shape if given.
pub fn write_json(coords: &[f64], grid: Option<(usize, usize)>) -> String {
    let rows: Vec<String> = coords
        .chunks_exact(6)
        .map(|c| format!("[{}]", c.iter().map(|x| format!("{x:?}")).collect::<Vec<_>>().join(", ")))
        .collect();
    let shape = grid.map_or(String::new(), |(r, c)| format!("\"rows\": {r}, \"cols\": {c}, "));
    format!("{{ {shape}\"segments\": [\n  {}\n] }}\n", rows.join(",\n  "))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accepted_shapes_and_round_trip() {
        let flat = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5, -1e-300, 3.0, 0.25, 1.0, 1.0];
        assert_eq!(read_json("[0,0,0,1,0,0, 0.5,-1e-300,3,0.25,1,1]").unwrap().coords, flat);
        assert_eq!(read_json(&write_json(&flat, None)).unwrap().coords, flat);
        let g = read_json(&write_json(&[flat, flat].concat(), Some((2, 2)))).unwrap();
        assert_eq!(g.grid, Some((2, 2)));
        assert_eq!(
            read_json("{\"note\": \"x\", \"segments\": [[1,2,3,4,5,6], [0,0,0,1,1,1]], \"v\": [true, null]}")
                .unwrap()
                .coords
                .len(),
            12
        );
    }

    #[test]
    fn zero_length_records_are_named_by_their_place() {
        let e = read_json("[[0,0,0,1,0,0],\n [3,3,3,3,3,3]]").unwrap_err();
        assert_eq!(
            (e.details().reason, e.details().line, e.details().column),
            (Some("import-zero-length"), Some(2), Some(2))
        );
        let e = read_json("[0,0,0,1,0,0, 5,5,5,5,5,5]").unwrap_err();
        assert_eq!((e.details().line, e.details().column), (Some(1), Some(15)));
    }

    #[test]
    fn malformed_files_name_line_and_column() {
        let e = |t: &str| read_json(t).unwrap_err().to_string();
        assert_eq!(e("[[0,0,0,1,0,0],\n [0,0,0,1,0]]"), "json: line 2, column 2: a segment needs 6 numbers, found 5");
        assert_eq!(e("[0,0,0,1,0,\"x\"]"), "json: line 1, column 12: expected a number");
        assert_eq!(
            e("{\"segments\": [1,2,3]}"),
            "json: line 1, column 14: 3 numbers are not a whole number of segments (6 each)"
        );
        assert_eq!(e("[1,2,3,4,5,6"), "json: line 1, column 13: expected , or ] in an array");
        assert_eq!(
            e("{\"rows\": 2, \"segments\": []}"),
            "json: line 1, column 1: give both \"rows\" and \"cols\", or neither"
        );
        assert!(e(&"[".repeat(100_000)).contains("nested deeper than 16 levels"));
        assert!(e("[1e999]").contains("not a finite number"));
        assert!(e("[1,2] x").contains("unexpected text after"));
        assert!(e("\"abc").contains("unterminated string"));
        assert!(e("").contains("unexpected end"));
    }

    #[test]
    fn nesting_is_limited_by_level_through_arrays_objects_and_keys() {
        let read = |t: &str| read_json_value(t, &rust_number);
        let at = |t: &str| {
            let d = read(t).unwrap_err().details();
            (d.reason, d.column)
        };
        // the root is level 0: 17 arrays (the innermost at level 16) are read, 18 are not
        let arrays = |n: usize| format!("{}{}", "[".repeat(n), "]".repeat(n));
        assert!(read(&arrays(17)).is_ok());
        assert_eq!(at(&arrays(18)), (Some("json-too-deep"), Some(18)));
        // an object's keys and values are a level below it: in 16 nested objects the last key
        // and the 1 are at level 16; in 17 the last key is at 17 (column 16·6 + 2)
        let objects = |n: usize| format!("{}1{}", "{\"a\": ".repeat(n), "}".repeat(n));
        assert!(read(&objects(16)).is_ok());
        assert_eq!(at(&objects(17)), (Some("json-too-deep"), Some(16 * 6 + 2)));
        // and so are its keys: an object at level 16 fails at its key (column 18), not its value
        let deep = format!("{}{{\"a\": 1}}{}", "[".repeat(16), "]".repeat(16));
        assert_eq!(at(&deep), (Some("json-too-deep"), Some(18)));
    }

    #[test]
    fn words_objects_and_grids_are_read_as_written() {
        let read = |t: &str| read_json_value(t, &rust_number).unwrap().1;
        assert_eq!(read("null"), JsonValue::Null);
        assert_eq!(read(" true "), JsonValue::Bool);
        assert_eq!(read("{}"), JsonValue::Object(Vec::new()));
        assert_eq!(read("{ \"k\" : [ ] }"), JsonValue::Object(vec![("k".into(), 8, JsonValue::Array(Vec::new()))]));
        let reason = |t: &str| read_json(t).unwrap_err().details().reason;
        assert_eq!(reason("{}"), Some("json-segments-missing"));
        assert_eq!(reason("{\"segments\": {}}"), Some("json-segments-array"));
        assert_eq!(reason("[1,2] x"), Some("json-trailing"));
        // rows and cols: integers from 2 to MAX_RULINGS
        let two = "[[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1],[0,0,0,1,1,0]]";
        assert_eq!(
            read_json(&format!("{{\"rows\": 2, \"cols\": 2, \"segments\": {two}}}")).unwrap().grid,
            Some((2, 2))
        );
        for rows in ["2.5", "1", "0", "-2", "4194305", "\"2\""] {
            let e = read_json(&format!("{{\"rows\": {rows}, \"cols\": 2, \"segments\": {two}}}")).unwrap_err();
            assert_eq!((e.details().reason, e.details().column), (Some("json-grid-integer"), Some(10)), "rows {rows}");
        }
    }

    #[test]
    fn a_text_of_the_size_limit_is_read_and_a_byte_more_is_not() {
        let data = "[0,0,0,1,0,0, 0,0,1,0,1,1]";
        let mut text = format!("{data}{}", " ".repeat(MAX_IMPORT_TEXT - data.len()));
        assert_eq!(read_json(&text).unwrap().coords.len(), 12);
        text.push(' ');
        let e = read_json(&text).unwrap_err();
        assert_eq!((e.code(), e.details().limit), ("too-large", Some(MAX_IMPORT_TEXT as f64)));
    }

    #[test]
    fn numbers_beyond_the_limit_are_refused_at_the_first_one_over() {
        let text = "{\"rows\": 2, \"v\": [1, 2.5]}";
        assert!(value_at_most(text, &rust_number, 3).is_ok());
        let e = value_at_most(text, &rust_number, 2).unwrap_err();
        assert_eq!(e, Error::TooMany { what: "numbers in the JSON", got: 3, max: 2 });
    }
}
