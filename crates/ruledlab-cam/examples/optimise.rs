//! The pose optimisation's suite (the book's table, docs/src/cam/tool-paths.md): for each flank
//! cut the ruling-aligned poses and the optimised ones, the deviation of the posted program's
//! sweep from the part in µm, and the optimisation's time.
//! `cargo run --release -p ruledlab-cam --example optimise`
#[path = "../tests/suite/mod.rs"]
mod suite;

use ruledlab_cam::{gcode, optimise_poses, ruling_aligned, OptimiseOptions};
use std::time::Instant;

fn main() {
    println!(
        "{:<28} {:>5} {:>22} {:>22} {:>9} {:>8} {:>6}",
        "case", "poses", "baseline gouge/leave/rms", "optimised gouge/leave/rms", "largest", "time", "rounds"
    );
    for case in suite::cases() {
        let baseline = ruling_aligned(&case.rulings, case.tool, case.side);
        let o = suite::post_options(&case);
        let before = gcode(&baseline, &o).expect("posts").deviation.expect("measured");
        let start = Instant::now();
        let opt =
            optimise_poses(&baseline, &case.targets, &OptimiseOptions::default(), &mut |_| {}).expect("optimises");
        let took = start.elapsed().as_secs_f64();
        let after = gcode(&opt.path, &o).expect("posts").deviation.expect("measured");
        let um = |d: &ruledlab_cam::EnvelopeDeviation| {
            format!("{:.1}/{:.1}/{:.1}", 1e3 * d.gouge, 1e3 * d.leave, 1e3 * d.rms)
        };
        let largest = |d: &ruledlab_cam::EnvelopeDeviation| d.gouge.abs().max(d.leave);
        println!(
            "{:<28} {:>5} {:>22} {:>22} {:>8.1}% {:>7.2}s {:>6}   path's own sweep: {:.1} -> {:.1} µm",
            case.name,
            baseline.poses.len(),
            um(&before),
            um(&after),
            100.0 * (1.0 - largest(&after) / largest(&before)),
            took,
            opt.rounds,
            1e3 * largest(&opt.before),
            1e3 * largest(&opt.after),
        );
    }
}
