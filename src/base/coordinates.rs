//! The check every coordinate of an input passes: finite, and not so large that products
//! overflow (at most [`MAX_COORD`] in magnitude).

use crate::error::{Error, Record, Result};
use crate::tolerance::MAX_COORD;

/// Every coordinate finite and at most [`MAX_COORD`] in magnitude (`stride` numbers per
/// record, for the messages).
pub fn check_coordinates(coords: &[f64], stride: usize) -> Result<()> {
    for (index, &value) in coords.iter().enumerate() {
        if !value.is_finite() {
            return Err(Error::NonFinite { index, value, record: Record::of_stride(stride) });
        }
        if value.abs() > MAX_COORD {
            return Err(Error::OutOfRange { index, value, max: MAX_COORD, record: Record::of_stride(stride) });
        }
    }
    Ok(())
}
