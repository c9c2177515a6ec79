//! The invariants of Section 2 of a discrete ruled surface as data: JSON (one array per
//! quantity, as `RuledSurface.invariants()` names them; the NaN of parallel pairs as null) and
//! CSV (one row per pair of consecutive rulings: φ, h, δ, the footpoints, the central normal,
//! whether the pair is parallel).

use crate::ruled::Invariants;
use glam::DVec3;
use std::fmt::Write;

/// A number for JSON: shortest round-trip form, null where not finite.
fn json_number(x: f64) -> String {
    if x.is_finite() {
        format!("{x:?}")
    } else {
        "null".to_string()
    }
}

/// The invariants as JSON.
pub fn invariants_json(inv: &Invariants) -> String {
    let numbers = |v: &[f64]| v.iter().map(|&x| json_number(x)).collect::<Vec<_>>().join(",");
    let points = |v: &[DVec3]| v.iter().flat_map(|p| p.to_array()).map(json_number).collect::<Vec<_>>().join(",");
    let flags = |v: &[bool]| v.iter().map(|&b| if b { "1" } else { "0" }).collect::<Vec<_>>().join(",");
    format!(
        "{{\n \"angle\": [{}],\n \"distance\": [{}],\n \"distribution\": [{}],\n \"footpoints\": [{}],\n \"centralNormal\": [{}],\n \"parallel\": [{}],\n \"striction\": [{}],\n \"distributionMean\": [{}],\n \"perpendicularMidpoints\": [{}]\n}}\n",
        numbers(&inv.angle),
        numbers(&inv.distance),
        numbers(&inv.distribution),
        points(&inv.footpoints),
        points(&inv.central_normal),
        flags(&inv.parallel),
        points(&inv.striction),
        numbers(&inv.distribution_mean),
        points(&inv.perpendicular_midpoints),
    )
}

/// The invariants as CSV, one row per pair of consecutive rulings.
pub fn invariants_csv(inv: &Invariants) -> String {
    let mut out = String::from("pair,angle,distance,distribution,f0x,f0y,f0z,f1x,f1y,f1z,nx,ny,nz,parallel\n");
    for i in 0..inv.angle.len() {
        let (f0, f1, n) = (inv.footpoints[2 * i], inv.footpoints[2 * i + 1], inv.central_normal[i]);
        let cells: Vec<String> = [inv.angle[i], inv.distance[i], inv.distribution[i]]
            .into_iter()
            .chain(f0.to_array())
            .chain(f1.to_array())
            .chain(n.to_array())
            .map(|x| format!("{x:?}"))
            .collect();
        let _ = writeln!(out, "{i},{},{}", cells.join(","), u8::from(inv.parallel[i]));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ruled::RuledSurface;

    fn surface() -> RuledSurface {
        RuledSurface::from_flat(&[
            0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 2.0, 1.0, 0.0, 2.0,
        ])
        .unwrap()
    }

    #[test]
    fn json_has_every_quantity_and_reads_back() {
        let inv = surface().invariants();
        let text = invariants_json(&inv);
        for key in [
            "angle",
            "distance",
            "distribution",
            "footpoints",
            "centralNormal",
            "parallel",
            "striction",
            "distributionMean",
            "perpendicularMidpoints",
        ] {
            assert!(text.contains(&format!("\"{key}\": [")), "{key}");
        }
        assert!(text.contains(&format!("\"angle\": [{:?},{:?}]", inv.angle[0], inv.angle[1])));
    }

    #[test]
    fn csv_has_a_row_per_pair() {
        let inv = surface().invariants();
        let text = invariants_csv(&inv);
        assert_eq!(text.lines().count(), 1 + inv.angle.len());
        assert!(text.lines().nth(1).unwrap().starts_with(&format!("0,{:?},", inv.angle[0])));
    }

    #[test]
    fn csv_rows_hold_each_pairs_own_values() {
        // rulings along x at z = 0, along y at z = 1, along x at z = 2: each pair meets at a right
        // angle, one apart, with footpoints on the z-axis
        let text = invariants_csv(&surface().invariants());
        let rows: Vec<Vec<f64>> =
            text.lines().skip(1).map(|l| l.split(',').map(|c| c.parse().unwrap()).collect()).collect();
        for (i, row) in rows.iter().enumerate() {
            let z = i as f64;
            assert_eq!(row[0], z);
            assert!(
                (row[1] - std::f64::consts::FRAC_PI_2).abs() < 1e-15 && (row[2].abs() - 1.0).abs() < 1e-15,
                "{row:?}"
            );
            assert_eq!(&row[4..10], &[0.0, 0.0, z, 0.0, 0.0, z + 1.0], "footpoints of pair {i}");
            assert_eq!((row[10].abs(), row[11].abs(), row[12].abs(), row[13]), (0.0, 0.0, 1.0, 0.0));
        }
    }
}
