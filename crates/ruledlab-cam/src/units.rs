//! The units a file of tool poses or target points says it is in (`# units: inch`, JSON
//! `"units"`): millimetres or inches, each under the names CAM systems write; any other word is
//! refused with the list, never read as millimetres.

use ruledlab::{Error, Result};

/// The words read as millimetres.
pub const MM_WORDS: [&str; 5] = ["mm", "millimetre", "millimetres", "millimeter", "millimeters"];
/// The words read as inches.
pub const INCH_WORDS: [&str; 4] = ["in", "inch", "inches", "\""];

/// "mm" or "inch" for what a file (`source`: "csv" or "json") says of its units; `None` where
/// it says nothing, or says "model units" (ruledlab's own tool-path files); an error naming the
/// accepted words for anything else.
pub fn units_word(said: Option<String>, source: &'static str) -> Result<Option<String>> {
    let Some(said) = said else { return Ok(None) };
    let s = said.trim().to_ascii_lowercase();
    if MM_WORDS.contains(&s.as_str()) {
        Ok(Some("mm".into()))
    } else if INCH_WORDS.contains(&s.as_str()) {
        Ok(Some("inch".into()))
    } else if s.starts_with("model units") {
        Ok(None)
    } else {
        Err(Error::parse(source, None, None, crate::msg!("units-unknown", said = said.trim())))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn millimetres_and_inches_by_their_names_and_nothing_else() {
        for w in MM_WORDS {
            assert_eq!(units_word(Some(format!(" {} ", w.to_uppercase())), "csv").unwrap().as_deref(), Some("mm"));
        }
        for w in INCH_WORDS {
            assert_eq!(units_word(Some(w.into()), "csv").unwrap().as_deref(), Some("inch"));
        }
        assert_eq!(units_word(None, "csv").unwrap(), None);
        assert_eq!(units_word(Some("model units; axis is a unit vector".into()), "json").unwrap(), None);
        for bad in ["imperial", "furlong", "metric", ""] {
            let e = units_word(Some(bad.into()), "csv").unwrap_err();
            assert_eq!(e.details().reason, Some("units-unknown"), "{bad}");
            assert!(e.to_string().contains("mm or inch"), "{e}");
        }
    }
}
