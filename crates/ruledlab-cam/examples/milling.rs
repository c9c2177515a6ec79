//! Example 6: the tool path of Figs. 16–18 refined by each scheme; deviation of the machined
//! surface from the target profile and smoothness of the orientation.
//! `cargo run --release --example milling`
use ruledlab::{Scheme, Variant};
use ruledlab_cam::{deviation, example_profile, example_tool_path, Quality};

fn main() {
    let path = example_tool_path(7).expect("example");
    let target = example_profile(2000);
    let worst = |p: &ruledlab_cam::ToolPath| deviation(p, &target).iter().fold(0.0f64, |m, d| m.max(d.abs()));
    println!("7 given poses: max |deviation| {:.2e}", worst(&path));
    let schemes = [
        ("linear (midpoints)", Scheme::BSpline { degree: 1 }),
        ("four-point w=1/16", Scheme::FourPoint { w: 1.0 / 16.0 }),
        ("variational coupled", Scheme::Variational { n: 12, variant: Variant::Coupled }),
        ("variational averaged", Scheme::Variational { n: 12, variant: Variant::Averaged }),
    ];
    println!("{:<22} {:>6} {:>12} {:>14} {:>16}", "scheme", "steps", "max |dev|", "max angle step", "max 2nd diff");
    for (name, scheme) in schemes {
        for steps in 1..=3 {
            let r = path.refine(scheme, steps).expect("refines");
            let q = Quality::of(&r);
            println!(
                "{name:<22} {steps:>6} {:>12.2e} {:>14.2e} {:>16.2e}",
                worst(&r),
                q.max_angle_step(),
                q.max_second_difference()
            );
        }
    }
}
