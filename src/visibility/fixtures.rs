//! What the tests of the hidden lines share: the page's camera, a square, a refusal's name.

use super::{HiddenLineOptions, Run, View};
use crate::error::{Error, Result};
use glam::DVec3;

/// The page's camera: perspective (35°) looking from `eye` at `target`, z up unless looking
/// along z, on a 640 × 420 viewport.
pub(super) fn camera(eye: DVec3, target: DVec3) -> View {
    View::looking(eye, target, 35f64.to_radians(), 640.0, 420.0).unwrap()
}

/// The square [−1, 1]² in the plane z = 0, as two triangles.
pub(super) fn square() -> (Vec<DVec3>, Vec<u32>) {
    let p = vec![
        DVec3::new(-1.0, -1.0, 0.0),
        DVec3::new(1.0, -1.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(-1.0, 1.0, 0.0),
    ];
    (p, vec![0, 1, 2, 0, 2, 3])
}

/// The name of the refused parameter.
pub(super) fn refused<T: std::fmt::Debug>(r: Result<T>) -> &'static str {
    match r {
        Err(Error::InvalidParameter { name, .. }) => name,
        other => panic!("expected a refusal, got {other:?}"),
    }
}

/// The visibility of each run.
pub(super) fn seen(runs: &[Run]) -> Vec<bool> {
    runs.iter().map(|r| r.visible).collect()
}

/// Options that keep every piece, however short.
pub(super) fn exact() -> HiddenLineOptions {
    HiddenLineOptions { min_piece: 0.0, ..Default::default() }
}
