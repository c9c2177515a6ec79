//! The triangles binned in a screen grid of about one triangle per cell (coarser where huge
//! triangles would fill too many cells), in a CSR layout; a segment visits only the cells its
//! image crosses.

use super::occluder::{bend, occluder, Occluder};
use super::view::View;
use crate::tolerance::{HIDDEN_LINE_BEND, HIDDEN_LINE_GRID_ENTRIES, MAX_HIDDEN_LINE_GRID};
use glam::{DVec2, DVec3};

/// The triangles and their screen grid.
pub(super) struct Scene {
    pub(super) occluders: Vec<Occluder>,
    origin: DVec2,
    cell: DVec2,
    pub(super) cols: usize,
    rows: usize,
    /// CSR layout: the triangles of cell c are `items[starts[c]..starts[c + 1]]`.
    starts: Vec<u32>,
    items: Vec<u32>,
}

impl Scene {
    pub(super) fn new(view: &View, meshes: &[(&[DVec3], &[u32])], tau: f64) -> Self {
        let mut occluders = Vec::new();
        for (positions, indices) in meshes {
            let bends = bend(positions, indices);
            for (t, bent) in indices.chunks_exact(3).zip(bends) {
                let Some(corners) = t.iter().map(|&i| positions.get(i as usize).copied()).collect::<Option<Vec<_>>>()
                else {
                    continue;
                };
                if let Some(o) = occluder(view, [corners[0], corners[1], corners[2]], tau.max(HIDDEN_LINE_BEND * bent))
                {
                    occluders.push(o);
                }
            }
        }
        // the grid: the viewport with a margin of one viewport around it (images beyond are
        // clamped into the border cells, queries likewise), about one triangle per cell — coarser
        // while the triangles would fill more than HIDDEN_LINE_GRID_ENTRIES cells each on
        // average (huge triangles, seen from close by)
        let n = occluders.len().max(1) as f64;
        let (w, h) = (view.width, view.height);
        let aspect = (w / h).clamp(0.1, 10.0);
        let mut side = (n.sqrt().ceil() as usize).clamp(1, MAX_HIDDEN_LINE_GRID);
        let mut scene = loop {
            let cols = ((side as f64 * aspect.sqrt()).round() as usize).clamp(1, MAX_HIDDEN_LINE_GRID);
            let rows = ((side as f64 / aspect.sqrt()).round() as usize).clamp(1, MAX_HIDDEN_LINE_GRID);
            let origin = DVec2::new(-w, -h);
            let cell = DVec2::new(3.0 * w / cols as f64, 3.0 * h / rows as f64);
            let scene =
                Scene { occluders: Vec::new(), origin, cell, cols, rows, starts: Vec::new(), items: Vec::new() };
            let entries: usize = occluders
                .iter()
                .map(|o| {
                    let ((c0, r0), (c1, r1)) = (scene.cell_of(o.min), scene.cell_of(o.max));
                    (c1 - c0 + 1) * (r1 - r0 + 1)
                })
                .sum();
            if side == 1 || entries <= HIDDEN_LINE_GRID_ENTRIES * occluders.len() + 4096 {
                break Scene { occluders, starts: vec![0; cols * rows + 1], ..scene };
            }
            side /= 2;
        };
        let (cols, rows) = (scene.cols, scene.rows);
        let mut counts = vec![0u32; cols * rows];
        for o in &scene.occluders {
            let (c0, r0) = scene.cell_of(o.min);
            let (c1, r1) = scene.cell_of(o.max);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    counts[r * cols + c] += 1;
                }
            }
        }
        for c in 0..cols * rows {
            scene.starts[c + 1] = scene.starts[c] + counts[c];
        }
        let mut fill: Vec<u32> = scene.starts[..cols * rows].to_vec();
        scene.items = vec![0; scene.starts[cols * rows] as usize];
        for (k, o) in scene.occluders.iter().enumerate() {
            let (c0, r0) = scene.cell_of(o.min);
            let (c1, r1) = scene.cell_of(o.max);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    let slot = &mut fill[r * cols + c];
                    scene.items[*slot as usize] = k as u32;
                    *slot += 1;
                }
            }
        }
        scene
    }

    fn cell_of(&self, p: DVec2) -> (usize, usize) {
        let f = (p - self.origin) / self.cell;
        let clamp = |x: f64, n: usize| if x.is_nan() { 0 } else { (x.floor().max(0.0) as usize).min(n - 1) };
        (clamp(f.x, self.cols), clamp(f.y, self.rows))
    }

    /// Calls `visit` with every triangle binned in a cell the image segment a → b crosses
    /// (each cell once; a triangle in several cells may come more than once).
    pub(super) fn cells_along(&self, a: DVec2, b: DVec2, mut visit: impl FnMut(u32)) {
        let (ca, _) = self.cell_of(a);
        let (cb, _) = self.cell_of(b);
        let (c0, c1) = (ca.min(cb), ca.max(cb));
        for c in c0..=c1 {
            // the part of the segment over column c (the border columns reach to infinity)
            let left = if c == 0 { f64::NEG_INFINITY } else { self.origin.x + c as f64 * self.cell.x };
            let right = if c + 1 == self.cols { f64::INFINITY } else { self.origin.x + (c + 1) as f64 * self.cell.x };
            let (y0, y1) = if (b.x - a.x).abs() <= f64::EPSILON * (a.x.abs() + b.x.abs()).max(1.0) {
                (a.y.min(b.y), a.y.max(b.y))
            } else {
                let at = |x: f64| {
                    let s = ((x - a.x) / (b.x - a.x)).clamp(0.0, 1.0);
                    a.y + s * (b.y - a.y)
                };
                let (ya, yb) = (at(left.max(a.x.min(b.x))), at(right.min(a.x.max(b.x))));
                (ya.min(yb), ya.max(yb))
            };
            let (_, r0) = self.cell_of(DVec2::new(a.x, y0));
            let (_, r1) = self.cell_of(DVec2::new(a.x, y1));
            for r in r0..=r1 {
                let cell = r * self.cols + c;
                for &k in &self.items[self.starts[cell] as usize..self.starts[cell + 1] as usize] {
                    visit(k);
                }
            }
        }
    }
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::tolerance::test::uniform;

    /// A screen grid of `cols` × `rows` cells from `origin`, each holding one item, its own
    /// number r·cols + c: what `cells_along` visits are then the cells themselves.
    fn numbered_grid(origin: DVec2, cell: DVec2, cols: usize, rows: usize) -> Scene {
        let n = (cols * rows) as u32;
        Scene { occluders: Vec::new(), origin, cell, cols, rows, starts: (0..=n).collect(), items: (0..n).collect() }
    }

    /// The cells `cells_along` visits, sorted; none twice.
    fn visited(scene: &Scene, a: DVec2, b: DVec2) -> Vec<u32> {
        let mut cells = Vec::new();
        scene.cells_along(a, b, |k| cells.push(k));
        let n = cells.len();
        cells.sort_unstable();
        cells.dedup();
        assert_eq!(cells.len(), n, "a cell visited twice along {a} → {b}");
        cells
    }

    /// The cells whose closed rectangle (the border cells reaching to infinity) the segment
    /// a → b meets, by clipping the segment to each rectangle (Liang–Barsky): the same answer
    /// found another way.
    fn crossed(scene: &Scene, a: DVec2, b: DVec2) -> Vec<u32> {
        let bounds = |k: usize, n: usize, origin: f64, size: f64| {
            let lo = if k == 0 { f64::NEG_INFINITY } else { origin + k as f64 * size };
            let hi = if k + 1 == n { f64::INFINITY } else { origin + (k + 1) as f64 * size };
            (lo, hi)
        };
        let mut out = Vec::new();
        for r in 0..scene.rows {
            for c in 0..scene.cols {
                let (x0, x1) = bounds(c, scene.cols, scene.origin.x, scene.cell.x);
                let (y0, y1) = bounds(r, scene.rows, scene.origin.y, scene.cell.y);
                let (mut t0, mut t1) = (0.0f64, 1.0f64);
                for (p, d, lo, hi) in [(a.x, b.x - a.x, x0, x1), (a.y, b.y - a.y, y0, y1)] {
                    if d == 0.0 {
                        if p < lo || p > hi {
                            t0 = 2.0;
                        }
                    } else {
                        let (ta, tb) = ((lo - p) / d, (hi - p) / d);
                        t0 = t0.max(ta.min(tb));
                        t1 = t1.min(ta.max(tb));
                    }
                }
                if t0 <= t1 {
                    out.push((r * scene.cols + c) as u32);
                }
            }
        }
        out
    }

    /// The screen grid: a point's cell (clamped into the border cells, NaN to the first), and
    /// the cells a segment visits — exactly those it crosses, for 2 000 random segments, as many
    /// vertical ones and as many single points, over the grid and beyond its borders.
    #[test]
    fn a_segment_visits_exactly_the_cells_it_crosses() {
        let scene = numbered_grid(DVec2::new(-300.0, -200.0), DVec2::new(100.0, 50.0), 9, 12);
        assert_eq!(scene.cell_of(DVec2::new(150.0, 60.0)), (4, 5));
        assert_eq!(scene.cell_of(DVec2::new(-300.0, -200.0)), (0, 0));
        assert_eq!(scene.cell_of(DVec2::new(599.999, 399.999)), (8, 11));
        assert_eq!(scene.cell_of(DVec2::new(-1e9, 1e9)), (0, 11));
        assert_eq!(scene.cell_of(DVec2::new(f64::NAN, 0.0)), (0, 4));
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..2000 {
            let mut point = || DVec2::new(-500.0 + 1300.0 * uniform(&mut seed), -400.0 + 1000.0 * uniform(&mut seed));
            let (a, b) = (point(), point());
            let vertical = DVec2::new(a.x, b.y);
            for (a, b) in [(a, b), (a, vertical), (b, b)] {
                assert_eq!(visited(&scene, a, b), crossed(&scene, a, b), "{a} → {b}");
            }
        }
        // a segment whose x extent is within rounding of zero (one unit in the last place at
        // x = 100, a column border) counts as vertical: its whole y range in both columns, a
        // harmless superset; ten units are a slope like any other
        let scene = numbered_grid(DVec2::new(0.0, -200.0), DVec2::new(100.0, 50.0), 9, 12);
        let below = |x: f64, units: u64| f64::from_bits(x.to_bits() - units);
        let (a, b) = (DVec2::new(below(100.0, 1), 30.0), DVec2::new(100.0, 380.0));
        let mut both: Vec<u32> = (4..=11).flat_map(|r| [r * 9, r * 9 + 1]).collect();
        both.sort_unstable();
        assert_eq!(visited(&scene, a, b), both);
        let a = DVec2::new(below(100.0, 10), 30.0);
        let exact = visited(&scene, a, b);
        assert_eq!(exact, crossed(&scene, a, b));
        assert_eq!(exact.iter().filter(|&&k| k % 9 == 1).collect::<Vec<_>>(), [&(11 * 9 + 1)]);
    }
}
