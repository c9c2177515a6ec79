//! The runs of one visibility along a polyline or segment: the pieces between the hidden
//! intervals joined, and a run shorter than `min_piece` pixels between runs of the other kind —
//! a sliver where a line grazes an edge — given to its neighbours, the shortest first.

use glam::DVec2;

/// A run of one visibility along a line: its image as pixel positions (one for a dot).
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    /// Pixel positions (x right, y down) of the run's polyline: at least two, or one for a dot.
    pub points: Vec<DVec2>,
    /// Whether this run is seen (or hidden by a surface).
    pub visible: bool,
}

/// A chain of pieces along one polyline or segment, before runs are formed.
pub(super) struct Chain {
    /// (image point, visible) per piece: the pieces are the polylines between consecutive
    /// breakpoints; `visible[k]` is the visibility of the piece from point k to k + 1.
    pub(super) points: Vec<DVec2>,
    pub(super) visible: Vec<bool>,
}

impl Chain {
    pub(super) fn new() -> Self {
        Chain { points: Vec::new(), visible: Vec::new() }
    }

    /// Appends a segment's pieces (`parts`: its hidden intervals of s); the segment starts where
    /// the chain ends, or the chain is empty.
    pub(super) fn push_segment(&mut self, a: DVec2, b: DVec2, parts: &[(f64, f64)]) {
        let at = |s: f64| a + (b - a) * s;
        if self.points.is_empty() {
            self.points.push(a);
        }
        let mut s = 0.0;
        for &(lo, hi) in parts {
            if lo > s {
                self.points.push(at(lo));
                self.visible.push(true);
            }
            self.points.push(at(hi));
            self.visible.push(false);
            s = hi;
        }
        if s < 1.0 {
            self.points.push(b);
            self.visible.push(true);
        }
    }

    /// The runs of one visibility, slivers shorter than `min` pixels given to their neighbours.
    pub(super) fn runs(self, min: f64) -> Vec<Run> {
        // pieces → runs (start index, end index, visible, length)
        let mut runs: Vec<(usize, usize, bool, f64)> = Vec::new();
        for (k, &v) in self.visible.iter().enumerate() {
            let len = self.points[k].distance(self.points[k + 1]);
            match runs.last_mut() {
                Some(r) if r.2 == v => {
                    r.1 = k + 1;
                    r.3 += len;
                }
                _ => runs.push((k, k + 1, v, len)),
            }
        }
        // give the shortest sliver to its neighbours until none is left (or one run remains)
        while runs.len() > 1 {
            let Some((k, _)) =
                runs.iter().enumerate().filter(|(_, r)| r.3 < min).min_by(|x, y| x.1 .3.total_cmp(&y.1 .3))
            else {
                break;
            };
            let v = !runs[k].2;
            runs[k].2 = v;
            // join with neighbours of the same visibility
            if k + 1 < runs.len() && runs[k + 1].2 == v {
                let next = runs.remove(k + 1);
                runs[k].1 = next.1;
                runs[k].3 += next.3;
            }
            if k > 0 && runs[k - 1].2 == v {
                let this = runs.remove(k);
                runs[k - 1].1 = this.1;
                runs[k - 1].3 += this.3;
            }
        }
        runs.into_iter()
            .map(|(start, end, visible, _)| Run { points: drop_repeats(&self.points[start..=end]), visible })
            .collect()
    }
}

/// Consecutive equal points removed (a piece boundary at a vertex repeats it); at least two kept.
fn drop_repeats(points: &[DVec2]) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = Vec::with_capacity(points.len());
    for &p in points {
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    if out.len() == 1 {
        out.push(out[0]);
    }
    out
}
#[cfg(test)]
mod tests {
    use super::*;

    /// A chain along the x axis from 0: pieces of the given lengths and visibilities.
    fn chain(pieces: &[(f64, bool)]) -> Chain {
        let mut c = Chain::new();
        c.points.push(DVec2::ZERO);
        let mut x = 0.0;
        for &(length, visible) in pieces {
            x += length;
            c.points.push(DVec2::new(x, 0.0));
            c.visible.push(visible);
        }
        c
    }

    /// Runs as (visible, first x, last x, number of points).
    fn shape(runs: &[Run]) -> Vec<(bool, f64, f64, usize)> {
        runs.iter().map(|r| (r.visible, r.points[0].x, r.points[r.points.len() - 1].x, r.points.len())).collect()
    }

    /// Runs of pieces, and slivers (shorter than `min`, 1 here) given to their neighbours, the
    /// shortest first, with lengths that add up: a run exactly `min` long stays, so does a run
    /// made of two short pieces, or made long enough by the sliver it took in (first, last).
    #[test]
    fn runs_join_pieces_and_give_slivers_away() {
        const V: bool = true;
        const H: bool = false;
        let runs = |pieces: &[(f64, bool)]| shape(&chain(pieces).runs(1.0));
        assert_eq!(runs(&[(5.0, V), (5.0, H)]), [(V, 0.0, 5.0, 2), (H, 5.0, 10.0, 2)]);
        assert_eq!(runs(&[(0.625, V), (0.625, V), (5.0, H)]), [(V, 0.0, 1.25, 3), (H, 1.25, 6.25, 2)]);
        assert_eq!(runs(&[(0.5, V)]), [(V, 0.0, 0.5, 2)]);
        assert_eq!(runs(&[(5.0, V), (1.0, H), (5.0, V)]), [(V, 0.0, 5.0, 2), (H, 5.0, 6.0, 2), (V, 6.0, 11.0, 2)]);
        assert_eq!(runs(&[(5.0, V), (0.5, H), (5.0, V)]), [(V, 0.0, 10.5, 4)]);
        // the first run a sliver: it joins the next, 0.375 + 0.75 = 1.125, no longer a sliver
        assert_eq!(runs(&[(0.375, V), (0.75, H), (3.0, V)]), [(H, 0.0, 1.125, 3), (V, 1.125, 4.125, 2)]);
        // the last: it joins the one before
        assert_eq!(runs(&[(3.0, V), (0.75, H), (0.375, V)]), [(V, 0.0, 3.0, 2), (H, 3.0, 4.125, 3)]);
        // the shortest sliver goes first: 0.25 joins its neighbours (0.5 + 0.25 + 0.75 = 1.5)
        assert_eq!(
            runs(&[(4.0, V), (0.5, H), (0.25, V), (0.75, H), (4.0, V)]),
            [(V, 0.0, 4.0, 2), (H, 4.0, 5.5, 4), (V, 5.5, 9.5, 2)]
        );
        // min = 0 keeps everything, a zero-length piece too
        assert_eq!(shape(&chain(&[(0.0, H), (2.0, V)]).runs(0.0)), [(H, 0.0, 0.0, 2), (V, 0.0, 2.0, 2)]);
    }
}
