//! Section 5 compared: error of the inserted lines against the exact congruence after one
//! step, for bilinear averaging, butterfly, two-stage and coupled variational subdivision.
//! `cargo run --release --example congruence`
use ruledlab::{subdivide_congruence, CongruenceScheme, LineCongruence};
use ruledlab::{AnalyticCongruence, SmoothCongruence};

/// Bilinear averaging: edge lines the average of their two ends, face lines of four corners.
fn bilinear(c: &LineCongruence) -> LineCongruence {
    let (r, cc) = (c.rows(), c.cols());
    let (rr, c2) = (2 * r - 1, 2 * cc - 1);
    let at = |g: &[glam::DVec3], i: usize, j: usize| {
        let (i0, j0, i1, j1) = (i / 2, j / 2, i.div_ceil(2), j.div_ceil(2));
        (g[i0 * cc + j0] + g[i0 * cc + j1] + g[i1 * cc + j0] + g[i1 * cc + j1]) / 4.0
    };
    let (p, q) = (c.p(), c.q());
    let pp: Vec<_> = (0..rr * c2).map(|k| at(&p, k / c2, k % c2)).collect();
    let qq: Vec<_> = (0..rr * c2).map(|k| at(&q, k / c2, k % c2)).collect();
    LineCongruence::from_points(rr, c2, &pp, &qq).expect("valid")
}

fn main() {
    for c in AnalyticCongruence::ALL {
        let (_, _, rows, cols) = c.domain();
        let grid = c.grid(rows, cols).expect("valid grid");
        println!("{} ({rows} × {cols}, one step): max |P − p|, max angle (rad) of new lines", c.title());
        let rows_out = [
            ("bilinear average", bilinear(&grid)),
            (
                "butterfly w = 1/16",
                subdivide_congruence(&grid, CongruenceScheme::Butterfly { w: 1.0 / 16.0 }, 1).unwrap(),
            ),
            ("two-stage variational K=6", subdivide_congruence(&grid, CongruenceScheme::TwoStage { k: 6 }, 1).unwrap()),
            ("coupled variational", subdivide_congruence(&grid, CongruenceScheme::Coupled { k: 6 }, 1).unwrap()),
        ];
        for (name, refined) in rows_out {
            let (d, a) = c.errors(&refined);
            println!("  {name:<28} {d:10.2e} {a:10.2e}");
        }
    }
}
