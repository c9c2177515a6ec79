//! Tool paths: construction, refinement, quality, deviation and every export, with the G-code
//! read back.
#![no_main]
use libfuzzer_sys::fuzz_target;
use ruledlab::RuledSurface;
use ruledlab::Scheme;
use ruledlab::{deviation, Quality};
use ruledlab::{gcode, parse_gcode, tool_path_csv as csv, tool_path_json as json, GcodeOptions};
use ruledlab::{Tool, ToolEnd, ToolPath};

#[path = "common.rs"]
mod common;

fuzz_target!(|data: &[u8]| {
    let values = common::numbers(data);
    if values.len() < 15 {
        return;
    }
    let Ok(tool) = Tool::new(values[0], values[1], if values[2] > 0.0 { ToolEnd::Ball } else { ToolEnd::Flat }) else {
        return;
    };
    let n = (values.len() - 3) / 6 * 6;
    let Ok(axes) = RuledSurface::from_flat(&values[3..3 + n.min(6 * 32)]) else { return };
    let path = ToolPath::from_surface(&axes, tool);
    let Ok(r) = path.refine(Scheme::FourPoint { w: 1.0 / 16.0 }, 1) else { return };
    let _ = Quality::of(&r);
    let _ = deviation(&r, &[glam::DVec3::ZERO, glam::DVec3::ONE]);
    let _ = (csv(&r), json(&r));
    if let Ok(text) = gcode(&r, GcodeOptions { feed: values[0].abs() + 1.0, ..Default::default() }) {
        let _ = parse_gcode(&text, 1.0);
    }
});
