// Hidden lines from arbitrary bytes: any camera matrix and viewport, meshes with any points and
// indices (naming no point, degenerate, behind the eye), lines of every kind with NaN and huge
// coordinates: an answer or an error, never a panic.
#![no_main]
use glam::DVec3;
use libfuzzer_sys::fuzz_target;
use ruledlab::{hidden_lines, HiddenLineOptions, LineKind, View};

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    if data.len() < 24 {
        return;
    }
    let (head, rest) = data.split_at(24);
    let shape = head[0];
    let numbers = common::numbers(rest);
    // a sensible camera (the page's) or one made of the bytes
    let view = if shape & 1 == 0 || numbers.len() < 18 {
        View::looking(DVec3::new(3.0, -4.0, 2.5), DVec3::ZERO, 0.6, 640.0, 420.0)
    } else {
        View::new(&numbers[..16], numbers[16].abs() * 100.0, numbers[17].abs() * 100.0)
    };
    let Ok(view) = view else { return };
    let points: Vec<DVec3> = numbers.chunks_exact(3).map(|c| DVec3::new(c[0], c[1], c[2])).collect();
    let n = points.len().max(1) as u32;
    let indices: Vec<u32> = head[1..]
        .iter()
        .chain(rest.iter())
        .take(3 * (points.len() + 4))
        .map(|&b| if b == 255 { u32::MAX } else { b as u32 % (n + 2) })
        .collect();
    let indices = &indices[..indices.len() / 3 * 3];
    let kind = match shape >> 1 & 3 {
        0 => LineKind::Segments,
        1 => LineKind::Polyline { closed: false },
        2 => LineKind::Polyline { closed: true },
        _ => LineKind::Points,
    };
    let half = &points[..points.len() / 2 * 2];
    let options = HiddenLineOptions { tolerance: (head[2] as f64) / 255.0 * 0.1, min_piece: (head[3] as f64) / 32.0 };
    let _ = hidden_lines(&view, &[(&points, indices)], &[(kind, half), (LineKind::Points, &points)], options);
});
