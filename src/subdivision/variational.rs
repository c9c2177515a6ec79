//! Variational interpolatory subdivision of a ruled strip (Section 4, Figs. 9–10).
//!
//! Between consecutive rulings a_i b_i and a_{i+1} b_{i+1} a new ruling A_i B_i is inserted.
//! Old and new segments are divided into n parts, z_{i,k} = ((n−k)/n) a_i + (k/n) b_i (9) and
//! Z_{i,k} likewise (10); the two triangulations of Fig. 9 give every interior vertex six
//! neighbours, (11) and (12), and the umbrella vectors U, Ũ (13), (14). The new endpoints
//! minimise F = Σ (U² + Ũ²) (15), old points fixed.
//!
//! **Literal variant** (umbrellas at the new vertices Z_{i,k}, 0 < k < n, only, as written):
//! since every point is linear in k, U + Ũ and U − Ũ separate and
//! U² + Ũ² = 2|⅓(z_{i,k} − 2Z_{i,k} + z_{i+1,k})|² + const, so the minimiser is exactly the
//! midpoint rule A_i = (a_i + a_{i+1})/2 (docs/src/conventions.md, Section 4; a test shows it).
//!
//! **Coupled variant** (default): umbrellas at every interior vertex of the refined strip,
//! old vertices included, whose neighbours are new points (Kobbelt's variational
//! subdivision). With P^k_j the refined polygon at level k (columns z_0, Z_0, z_1, …):
//!
//! F = (2/9) Σ_{k=1}^{n−1} Σ_j |Δ² P^k_j|² + ((n−1)/(18n²)) Σ_i |D_i − D_{i−1}|²,
//!
//! j over the interior columns, D_i = B_i − A_i, the second sum over the old interior
//! rulings. As P^k = (1 − k/n) P^0 + (k/n) P^n, the sum over k has closed weights
//! S₀ = Σ(1 − t_k)², S₁ = Σ t_k(1 − t_k), S₂ = Σ t_k², and F is a quadratic form in
//! (A_i, B_i) with 2×2-block tridiagonal, symmetric positive definite matrix (n ≥ 3): one
//! banded Cholesky solve, O(N) time for any n, three right-hand sides (x, y, z).
//!
//! **Measured** (docs/src/guide/subdivision.md, `cargo run --release --example subdivision`): the coupled scheme
//! beats the midpoint rule clearly, but the twist term ((n−1)/(18n²))|D_i − D_{i−1}|², which
//! comes from the sheared neighbours of the two triangulations, does not vanish for smooth
//! data and costs accuracy; [`Variant::Averaged`] omits it.

use crate::error::Result;
use crate::linalg::SymmetricBanded;
use crate::line::Segment;
use crate::ruled::RuledSurface;
use glam::DVec3;

/// Which energy the variational scheme minimises.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    /// Umbrellas at every interior vertex, old ones included (the scheme worth having).
    Coupled,
    /// Umbrellas at the new vertices only, as (13)–(15) literally read: the midpoint rule.
    Literal,
    /// The coupled energy with the averaged umbrella (U + Ũ)/2 of the two triangulations in
    /// place of U² + Ũ²: it drops the twist term |D_i − D_{i−1}|², which for smooth data
    /// is O(H) larger than the fairness terms and biases the rulings towards one direction.
    /// Each level is then faired independently, and cubic data are reproduced away from the
    /// ends.
    Averaged,
}

/// A linear form Σ c_m x_{u_m} + constant in the unknowns (A_0, B_0, A_1, B_1, …).
struct Form<'a> {
    terms: &'a [(usize, f64)],
    constant: DVec3,
}

/// Accumulates Σ_{p,q} M_pq F_p·F_q into the normal equations H x = r.
fn add_energy(h: &mut SymmetricBanded, r: &mut [[f64; 3]], forms: &[Form<'_>], metric: &[&[f64]]) {
    for (p, fp) in forms.iter().enumerate() {
        for (q, fq) in forms.iter().enumerate() {
            let m = metric[p][q];
            if m == 0.0 {
                continue;
            }
            for &(u, cu) in fp.terms {
                for &(v, cv) in fq.terms {
                    if u >= v {
                        // symmetric: add each unordered pair once, the diagonal once
                        h.add(u, v, m * cu * cv);
                    }
                }
                let k = m * cu * fq.constant;
                r[u][0] -= k.x;
                r[u][1] -= k.y;
                r[u][2] -= k.z;
            }
        }
    }
}

/// One step: N rulings → 2N − 1, old rulings at even indices, unchanged.
pub fn refine_variational(surface: &RuledSurface, n: usize, variant: Variant) -> Result<RuledSurface> {
    let segs: Vec<Segment> = surface.segments().collect();
    let count = segs.len() - 1; // new rulings
    let (a_idx, b_idx) = (|i: usize| 2 * i, |i: usize| 2 * i + 1);
    let (mut s0, mut s1, mut s2) = (0.0, 0.0, 0.0);
    for k in 1..n {
        let t = k as f64 / n as f64;
        s0 += (1.0 - t) * (1.0 - t);
        s1 += t * (1.0 - t);
        s2 += t * t;
    }
    let q = [[2.0 / 9.0 * s0, 2.0 / 9.0 * s1], [2.0 / 9.0 * s1, 2.0 / 9.0 * s2]];
    let q: [&[f64]; 2] = [&q[0], &q[1]];
    let beta = (n as f64 - 1.0) / (18.0 * (n * n) as f64);

    let mut h = SymmetricBanded::zeros(2 * count, 3);
    let mut r = vec![[0.0; 3]; 2 * count];
    // new columns: X = a_i + a_{i+1} − 2A_i, Y = b_i + b_{i+1} − 2B_i
    for i in 0..count {
        let x = Form { terms: &[(a_idx(i), -2.0)], constant: segs[i].a + segs[i + 1].a };
        let y = Form { terms: &[(b_idx(i), -2.0)], constant: segs[i].b + segs[i + 1].b };
        add_energy(&mut h, &mut r, &[x, y], &q);
    }
    if variant != Variant::Literal {
        // old interior columns: X = A_{i−1} + A_i − 2a_i, Y likewise, and the D-term
        for i in 1..count {
            let x = Form { terms: &[(a_idx(i - 1), 1.0), (a_idx(i), 1.0)], constant: -2.0 * segs[i].a };
            let y = Form { terms: &[(b_idx(i - 1), 1.0), (b_idx(i), 1.0)], constant: -2.0 * segs[i].b };
            add_energy(&mut h, &mut r, &[x, y], &q);
            if variant == Variant::Averaged {
                continue;
            }
            let d = Form {
                terms: &[(b_idx(i), 1.0), (a_idx(i), -1.0), (b_idx(i - 1), -1.0), (a_idx(i - 1), 1.0)],
                constant: DVec3::ZERO,
            };
            add_energy(&mut h, &mut r, &[d], &[&[beta]]);
        }
    }
    h.factor()?.solve(&mut r);
    let mut out = Vec::with_capacity(2 * segs.len() - 1);
    for i in 0..count {
        out.push(segs[i]);
        out.push(Segment::new(DVec3::from(r[a_idx(i)]), DVec3::from(r[b_idx(i)])));
    }
    out.push(segs[count]);
    RuledSurface::new(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assert_near;
    use crate::catalogue::AnalyticSurface;
    #[allow(unused_imports)]
    use crate::congruence::SmoothCongruence;
    #[allow(unused_imports)]
    use crate::ruled::SmoothRuled;
    use crate::tolerance::test::EXACT;

    fn quartic() -> RuledSurface {
        let q = AnalyticSurface::Quartic;
        q.sample(12, q.ranges()).unwrap()
    }

    /// The points of the refined strip at level k, as the umbrella formulas see them.
    fn z(s: &Segment, k: usize, n: usize) -> DVec3 {
        let t = k as f64 / n as f64;
        (1.0 - t) * s.a + t * s.b
    }

    /// F of (15) evaluated literally from (9)–(14), umbrellas at the given columns.
    fn energy(r: &RuledSurface, n: usize, all_interior: bool) -> f64 {
        let cols: Vec<Segment> = r.segments().collect();
        let mut f = 0.0;
        for j in 1..cols.len() - 1 {
            if !all_interior && j % 2 == 0 {
                continue;
            }
            for k in 1..n {
                let (l, c, rt) = (&cols[j - 1], &cols[j], &cols[j + 1]);
                let centre = z(c, k, n);
                let u1 = centre
                    - (z(c, k - 1, n) + z(c, k + 1, n) + z(l, k, n) + z(l, k - 1, n) + z(rt, k + 1, n) + z(rt, k, n))
                        / 6.0;
                let u2 = centre
                    - (z(c, k - 1, n) + z(c, k + 1, n) + z(l, k, n) + z(l, k + 1, n) + z(rt, k - 1, n) + z(rt, k, n))
                        / 6.0;
                f += u1.length_squared() + u2.length_squared();
            }
        }
        f
    }

    #[test]
    fn literal_variant_is_the_midpoint_rule() {
        let s = quartic();
        let r = refine_variational(&s, 12, Variant::Literal).unwrap();
        for i in 0..11 {
            assert_eq!(r.segment(2 * i), s.segment(i));
            assert_near!(r.segment(2 * i + 1).a, 0.5 * (s.segment(i).a + s.segment(i + 1).a), EXACT);
            assert_near!(r.segment(2 * i + 1).b, 0.5 * (s.segment(i).b + s.segment(i + 1).b), EXACT);
        }
    }

    /// The solution minimises the energy written out from (9)–(14): perturbing any new
    /// endpoint coordinate raises it, and the gradient there vanishes.
    #[test]
    fn coupled_solution_minimises_the_literal_formulas() {
        let s = quartic();
        for n in [3, 5, 12] {
            let r = refine_variational(&s, n, Variant::Coupled).unwrap();
            let f0 = energy(&r, n, true);
            let pts: Vec<DVec3> = r.points().to_vec();
            for idx in [2, 3, 10, 11, 42, 43] {
                for axis in 0..3 {
                    let mut e = DVec3::ZERO;
                    e[axis] = 1e-4;
                    let mut plus = pts.clone();
                    plus[idx] += e;
                    let mut minus = pts.clone();
                    minus[idx] -= e;
                    let fp = energy(&RuledSurface::from_trusted_points(plus), n, true);
                    let fm = energy(&RuledSurface::from_trusted_points(minus), n, true);
                    assert!(fp > f0 && fm > f0, "n={n} point {idx} axis {axis}");
                    assert!(((fp - fm) / 2e-4).abs() < 1e-9 * (1.0 + f0), "gradient {}", (fp - fm) / 2e-4);
                }
            }
        }
    }

    #[test]
    fn keeps_old_rulings_bit_for_bit() {
        let s = quartic();
        let r = refine_variational(&s, 12, Variant::Coupled).unwrap();
        assert_eq!(r.len(), 23);
        for i in 0..12 {
            assert_eq!(r.segment(2 * i), s.segment(i));
        }
    }
}
