//! RuledSurface construction, invariants, isometries and every strip scheme on fuzzed data.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ruledlab::RuledSurface;
use ruledlab::{recut, subdivide_lines, subdivide_polygon, subdivide_strip, Scheme, Variant};
use ruledlab::{Development, HingeChain};

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let Some((&choice, rest)) = data.split_first() else { return };
    let values = common::numbers(rest);
    let n = values.len() / 6 * 6;
    let Ok(s) = RuledSurface::from_flat(&values[..n.min(6 * 64)]) else { return };
    let _ = s.invariants();
    let chain = HingeChain::new(&s);
    let _ = chain.conoidal();
    let _ = chain.bend((choice as f64) / 255.0);
    let angles: Vec<f64> = values.iter().cycle().take(s.len() - 2).copied().collect();
    let _ = chain.deform(&angles);
    let _ = Development::of(&s).non_developability();
    let _ = recut(&s, values.first().copied());
    let scheme = match choice % 6 {
        0 => Scheme::Chaikin,
        1 => Scheme::BSpline { degree: 1 + (choice as usize / 6) % 7 },
        2 => Scheme::Bezier,
        3 => Scheme::FourPoint { w: values.get(1).copied().unwrap_or(0.0625) },
        4 => Scheme::Variational { n: 3 + (choice as usize) % 9, variant: Variant::Coupled },
        _ => Scheme::Variational { n: 3, variant: Variant::Averaged },
    };
    let steps = (choice as usize / 64) % 3;
    let closed = choice & 0x80 != 0;
    let _ = subdivide_strip(&s, scheme, closed, steps);
    let _ = subdivide_lines(&s, scheme, closed, steps, None);
    let _ = subdivide_polygon(s.points(), scheme, closed, steps);
});
