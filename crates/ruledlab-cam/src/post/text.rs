//! The words every dialect writes alike: numbers with the program's decimals (rounded as
//! `format!` rounds, never "-0"), spindle speeds, and comments made safe for every controller and
//! wrapped to a width LinuxCNC's interpreter reads.

use crate::tolerance::GCODE_DECIMALS;

/// A number with [`GCODE_DECIMALS`] decimals ("-0.0000" written "0.0000"); `plus`: a sign always.
pub fn number(x: f64, plus: bool) -> String {
    decimals(x, GCODE_DECIMALS, plus)
}

/// A number with `places` decimals ("-0.000" written "0.000"); `plus`: a sign always. Rounded
/// as `format!` rounds (to the nearest, exactly): where x·10^places is not within 10⁻⁶ of a half
/// (so rounding it cannot fall the other way) from its integer, else by `format!` itself — a
/// program of a million blocks spends most of its time writing numbers.
pub fn decimals(x: f64, places: usize, plus: bool) -> String {
    let scale = 10f64.powi(places as i32);
    let y = x * scale;
    let s = if y.abs() < 1e9 && (y.fract().abs() - 0.5).abs() > 1e-6 {
        let r = y.round() as i64;
        let (whole, part) = (r.unsigned_abs() / scale as u64, r.unsigned_abs() % scale as u64);
        let sign = if r < 0 { "-" } else { "" };
        if places == 0 {
            format!("{sign}{whole}")
        } else {
            format!("{sign}{whole}.{part:0places$}")
        }
    } else {
        format!("{x:.places$}")
    };
    let s = if s.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
        s.trim_start_matches('-').to_string()
    } else {
        s
    };
    if plus && !s.starts_with('-') {
        format!("+{s}")
    } else {
        s
    }
}

/// A spindle speed: a whole number as one ("10000"), else with the program's decimals.
pub fn speed(x: f64) -> String {
    if x.fract() == 0.0 {
        format!("{x}")
    } else {
        number(x, false)
    }
}

/// A comment's text made safe for every dialect: printable ASCII without parentheses, braces
/// or `;` (square brackets stay: an INI section's name is written as LinuxCNC's INI file has it),
/// a degree sign written `deg`.
pub fn clean(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '(' | '{' => out.push('<'),
            ')' | '}' => out.push('>'),
            ';' => out.push(','),
            '°' => out.push_str(" deg"),
            c if c.is_ascii_graphic() || c == ' ' => out.push(c),
            _ => out.push(' '),
        }
    }
    out
}

/// The longest comment line a program writes (LinuxCNC's interpreter refuses lines of 256
/// characters and more: "Command too long").
pub const COMMENT_WIDTH: usize = 120;

/// A comment made safe ([`clean`]) and wrapped at spaces into lines of at most
/// [`COMMENT_WIDTH`] characters, the later ones indented by two spaces.
pub fn comment_lines(text: &str) -> Vec<String> {
    let text = clean(text);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        let room = COMMENT_WIDTH - if lines.is_empty() { 0 } else { 2 };
        if !line.is_empty() && line.len() + 1 + word.len() > room {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    lines.push(line);
    lines.into_iter().enumerate().map(|(k, l)| if k == 0 { l } else { format!("  {l}") }).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_and_comments() {
        assert_eq!(number(-0.00001, false), "0.0000");
        assert_eq!(number(1.5, true), "+1.5000");
        assert_eq!(number(-2.25, true), "-2.2500");
        assert_eq!(decimals(99_999.999_4, 3, false), "99999.999");
        // the fast way and format!'s agree, ties and near-ties included
        for x in [0.12345, -0.00005, 2.5e-5, 123456.78905, -7.0, 0.99995, 1e8 + 0.5, -3.24159265, 1.0000499999] {
            for places in [0, 3, 4] {
                let mut want = format!("{x:.places$}");
                if want.trim_start_matches('-').chars().all(|c| c == '0' || c == '.') {
                    want = want.trim_start_matches('-').to_string();
                }
                assert_eq!(decimals(x, places, false), want, "{x} to {places}");
            }
        }
        assert_eq!(decimals(-0.0004, 3, true), "+0.000");
        assert_eq!(clean("a (b); [c] {d} é"), "a <b>, [c] <d>  ");
        assert_eq!(clean("within 1° of the pole"), "within 1 deg of the pole");
        let long = "word ".repeat(60);
        let lines = comment_lines(&long);
        assert!(lines.len() == 3 && lines.iter().all(|l| l.len() <= COMMENT_WIDTH), "{lines:?}");
        assert!(lines[1].starts_with("  word") && lines.concat().matches("word").count() == 60);
        assert_eq!((speed(10000.0), speed(12.5)), ("10000".to_string(), number(12.5, false)));
    }

    #[test]
    fn numbers_beyond_the_fast_way_and_a_negative_zero_from_format() {
        // x·10^places of 1e9 and more: format! writes them (an i64 would not hold 1e20·10⁴)
        assert_eq!(decimals(1e20, 4, false), "100000000000000000000.0000");
        assert_eq!(decimals(-123_456.789, 4, true), "-123456.7890");
        assert_eq!(decimals(1e15 + 0.25, 0, true), "+1000000000000000");
        // a near-tie that rounds to zero goes to format!, which writes "-0.0000": written "0.0000"
        assert_eq!(format!("{:.4}", -0.000_049_999_95), "-0.0000");
        assert_eq!(decimals(-0.000_049_999_95, 4, false), "0.0000");
        assert_eq!(decimals(-0.000_049_999_95, 4, true), "+0.0000");
    }

    #[test]
    fn a_comment_line_may_be_exactly_as_wide_as_allowed() {
        let word = |c: &str, n: usize| c.repeat(n);
        // 59 + 1 + 60 = 120 characters: one line
        let exact = format!("{} {}", word("a", 59), word("b", 60));
        assert_eq!(comment_lines(&exact), std::slice::from_ref(&exact));
        // one more: the second word goes to the next line, indented
        let over = format!("{} {}", word("a", 59), word("b", 61));
        assert_eq!(comment_lines(&over), [word("a", 59), format!("  {}", word("b", 61))]);
        // a later line has two characters less room: 58 + 1 + 59 = 118, 120 with its indent
        let later = format!("{} {} {}", word("a", 120), word("c", 58), word("d", 59));
        assert_eq!(comment_lines(&later), [word("a", 120), format!("  {} {}", word("c", 58), word("d", 59))]);
    }
}
