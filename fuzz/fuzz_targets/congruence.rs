//! LineCongruence construction and every congruence scheme on fuzzed grids.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ruledlab::butterfly_lines;
use ruledlab::{butterfly_diagonal, subdivide_congruence, CongruenceScheme, LineCongruence};

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let Some((&shape, rest)) = data.split_first() else { return };
    let (rows, cols) = (2 + (shape as usize & 3), 2 + (shape as usize >> 2 & 3));
    let values = common::numbers(rest);
    if values.len() < 6 * rows * cols {
        return;
    }
    let Ok(c) = LineCongruence::from_flat(rows, cols, &values[..6 * rows * cols]) else { return };
    let w = values[0];
    for scheme in [
        CongruenceScheme::Butterfly { w },
        CongruenceScheme::TwoStage { k: 3 + (shape as usize >> 4) },
        CongruenceScheme::Coupled { k: 4 },
    ] {
        let _ = subdivide_congruence(&c, scheme, 1);
    }
    let _ = butterfly_diagonal(&c, w);
    let _ = butterfly_lines(&c, 1.0 / 16.0, 1, None);
    let _ = c.row(0).map(|r| r.invariants());
});
