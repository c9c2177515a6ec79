//! The programs themselves, to the byte: every dialect in both modes on every preset machine for
//! the paper's example, the blade and the wall (`jobs`), and each dialect with the other units,
//! coolant, spindle direction, tool, work offset and tolerances — each program's FNV-1a hash
//! against the table below. A change of the post that changes a program fails here; where it
//! should, say why in the commit and write the table anew with `RULEDLAB_BLESS=1 cargo test -p
//! ruledlab-cam --test programs -- --nocapture` (it prints it).
#![cfg(not(target_family = "wasm"))]

#[allow(dead_code)] // the ring and the targets are measured in sweep.rs
mod jobs;

use ruledlab::{Scheme, Variant};
use ruledlab_cam::{example_tool_path, gcode, Coolant, Dialect, Machine, Mode, PostOptions, SpindleDirection, Units};
use ruledlab_cam::{ToolPath, MACHINE_PRESETS};

/// FNV-1a, 64 bits.
fn fnv(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

const DIALECTS: [(&str, Dialect); 3] =
    [("linuxcnc", Dialect::LinuxCnc), ("heidenhain", Dialect::Heidenhain), ("sinumerik", Dialect::Sinumerik)];

/// Every program of the table, labelled.
fn programs() -> Vec<(String, String)> {
    let example =
        example_tool_path(7).unwrap().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 2).unwrap();
    let jobs: [(&str, ToolPath, f64); 3] =
        [("example", example, 10.0), ("blade", jobs::blade_refined(), 1.0), ("wall", jobs::wall(), 1.0)];
    let mut out = Vec::new();
    for (job, path, scale) in &jobs {
        for preset in MACHINE_PRESETS {
            for mode in [Mode::Machine, Mode::Tcp] {
                for (name, dialect) in DIALECTS {
                    let machine = Machine::preset(preset).unwrap();
                    let o = PostOptions { dialect, machine, mode, scale: *scale, feed: 1200.0, ..Default::default() };
                    out.push((format!("{job} {preset} {mode:?} {name}"), gcode(path, &o).unwrap().text));
                }
            }
        }
    }
    let path = example_tool_path(5).unwrap();
    for mode in [Mode::Machine, Mode::Tcp] {
        for (name, dialect) in DIALECTS {
            let o = PostOptions {
                dialect,
                mode,
                machine: Machine::preset("head-table-bc").unwrap(),
                units: Units::Inch,
                scale: 10.0 / 25.4,
                feed: 40.0,
                clearance: 0.2,
                tolerance: 0.0005,
                angular_tolerance: Some(0.2),
                coolant: Coolant::Mist,
                direction: SpindleDirection::CounterClockwise,
                tool: 7,
                spindle: 12000.5,
                work_offset: 6,
                name: "P_1".into(),
                ..Default::default()
            };
            out.push((format!("inch {mode:?} {name}"), gcode(&path, &o).unwrap().text));
        }
    }
    out
}

#[test]
fn every_program_is_the_one_written_before() {
    let now: Vec<(String, u64)> = programs().into_iter().map(|(label, text)| (label, fnv(&text))).collect();
    if std::env::var_os("RULEDLAB_BLESS").is_some() {
        println!("const TABLE: [(&str, u64); {}] = [", now.len());
        for (label, hash) in &now {
            println!("    (\"{label}\", {hash:#018x}),");
        }
        println!("];");
        return;
    }
    let changed: Vec<&str> = now
        .iter()
        .zip(TABLE.iter())
        .filter(|((label, hash), (l, h))| label != l || hash != h)
        .map(|((label, _), _)| label.as_str())
        .collect();
    assert_eq!(now.len(), TABLE.len(), "the table has a row a program");
    assert!(changed.is_empty(), "{} programs changed: {changed:?}", changed.len());
}

const TABLE: [(&str, u64); 78] = [
    ("example table-table-ac Machine linuxcnc", 0x107da6e733bf784d),
    ("example table-table-ac Machine heidenhain", 0x9392e66070c20465),
    ("example table-table-ac Machine sinumerik", 0xba3ac0927427944e),
    ("example table-table-ac Tcp linuxcnc", 0x8ec340dd2014ec66),
    ("example table-table-ac Tcp heidenhain", 0xc5aa8ad0fe70b4db),
    ("example table-table-ac Tcp sinumerik", 0xdc1af0cbbc2de136),
    ("example table-table-bc Machine linuxcnc", 0xb33c703de91c3709),
    ("example table-table-bc Machine heidenhain", 0x0fd9421b3ce47808),
    ("example table-table-bc Machine sinumerik", 0xb4a3f7d848cb592c),
    ("example table-table-bc Tcp linuxcnc", 0xa6c3bf1ba4a0e8d0),
    ("example table-table-bc Tcp heidenhain", 0x8b123a3d5c2dabe0),
    ("example table-table-bc Tcp sinumerik", 0x60f84c2fc676d41f),
    ("example head-table-bc Machine linuxcnc", 0x3efd53c390e397d7),
    ("example head-table-bc Machine heidenhain", 0x80d89df9270e8c21),
    ("example head-table-bc Machine sinumerik", 0x5c1ff57e2ae674e9),
    ("example head-table-bc Tcp linuxcnc", 0xb0a1ada82c5c3d5f),
    ("example head-table-bc Tcp heidenhain", 0x458b981d81d1962f),
    ("example head-table-bc Tcp sinumerik", 0x36ea29185cdf1b51),
    ("example head-head-ac Machine linuxcnc", 0xc4c7e6447b757f0a),
    ("example head-head-ac Machine heidenhain", 0x8f965573e7897a90),
    ("example head-head-ac Machine sinumerik", 0x01121775f2bf3129),
    ("example head-head-ac Tcp linuxcnc", 0xab47cce5ea19549a),
    ("example head-head-ac Tcp heidenhain", 0xaf7e28d571b1edcd),
    ("example head-head-ac Tcp sinumerik", 0xb510cc3cf32e9868),
    ("blade table-table-ac Machine linuxcnc", 0xc9dd60ebbfbfc0fe),
    ("blade table-table-ac Machine heidenhain", 0xedf1840e5cc63be1),
    ("blade table-table-ac Machine sinumerik", 0x56d9546f76752b9e),
    ("blade table-table-ac Tcp linuxcnc", 0x02e03c781c5adf29),
    ("blade table-table-ac Tcp heidenhain", 0x1532e5dbe88914fb),
    ("blade table-table-ac Tcp sinumerik", 0x711cffb7ca82e725),
    ("blade table-table-bc Machine linuxcnc", 0x6372e79a99c112c2),
    ("blade table-table-bc Machine heidenhain", 0x6cdf82d477b01539),
    ("blade table-table-bc Machine sinumerik", 0xd2883eff4d5d50b4),
    ("blade table-table-bc Tcp linuxcnc", 0x011c3206d9d345a8),
    ("blade table-table-bc Tcp heidenhain", 0xa2207153aec21b90),
    ("blade table-table-bc Tcp sinumerik", 0x341a31089e58eb7f),
    ("blade head-table-bc Machine linuxcnc", 0x568973697e354289),
    ("blade head-table-bc Machine heidenhain", 0x60be72dc63d0bafa),
    ("blade head-table-bc Machine sinumerik", 0x2adbcc2200a93679),
    ("blade head-table-bc Tcp linuxcnc", 0x2c5c688597fc29a8),
    ("blade head-table-bc Tcp heidenhain", 0xf9782e508ee6757c),
    ("blade head-table-bc Tcp sinumerik", 0x9be43b3187f221a4),
    ("blade head-head-ac Machine linuxcnc", 0x676092eaaeed3b73),
    ("blade head-head-ac Machine heidenhain", 0xea5f00dd909917d9),
    ("blade head-head-ac Machine sinumerik", 0xb7a5932cd63e470c),
    ("blade head-head-ac Tcp linuxcnc", 0x0163c31a46536423),
    ("blade head-head-ac Tcp heidenhain", 0x08a66ed694ddc723),
    ("blade head-head-ac Tcp sinumerik", 0x5849a12b5a2ac950),
    ("wall table-table-ac Machine linuxcnc", 0xbcf43b15344f2e30),
    ("wall table-table-ac Machine heidenhain", 0xd22fefa964108f80),
    ("wall table-table-ac Machine sinumerik", 0x8d1e1c0dc03b0b9d),
    ("wall table-table-ac Tcp linuxcnc", 0xacbbdcccaac84f32),
    ("wall table-table-ac Tcp heidenhain", 0x594b20008d34b82a),
    ("wall table-table-ac Tcp sinumerik", 0xa8b7ef32fbffe33e),
    ("wall table-table-bc Machine linuxcnc", 0x71347c0b2c42fc3a),
    ("wall table-table-bc Machine heidenhain", 0x9f46156e308cc746),
    ("wall table-table-bc Machine sinumerik", 0xb9826b5efbf26319),
    ("wall table-table-bc Tcp linuxcnc", 0xd978cd7cbbd2a801),
    ("wall table-table-bc Tcp heidenhain", 0xf76d595f1f6d9084),
    ("wall table-table-bc Tcp sinumerik", 0x9f502673591f63c8),
    ("wall head-table-bc Machine linuxcnc", 0xab7e01bac543f311),
    ("wall head-table-bc Machine heidenhain", 0x2924213ae2fa79a2),
    ("wall head-table-bc Machine sinumerik", 0x6fc87f41021b45f8),
    ("wall head-table-bc Tcp linuxcnc", 0x53aedb49ee2cd3fb),
    ("wall head-table-bc Tcp heidenhain", 0x46e5743aef180629),
    ("wall head-table-bc Tcp sinumerik", 0xa5b182e58aa67c64),
    ("wall head-head-ac Machine linuxcnc", 0x24f4c79efd36a909),
    ("wall head-head-ac Machine heidenhain", 0xfb917896c645c9b8),
    ("wall head-head-ac Machine sinumerik", 0xd9240a13d1ab0fb5),
    ("wall head-head-ac Tcp linuxcnc", 0x944f461554510158),
    ("wall head-head-ac Tcp heidenhain", 0x14a743d779599c3e),
    ("wall head-head-ac Tcp sinumerik", 0x1d293b960fbbe6cc),
    ("inch Machine linuxcnc", 0x4fdf0a9131cf4140),
    ("inch Machine heidenhain", 0xfaa2a7d14c365a95),
    ("inch Machine sinumerik", 0xbe2d8dc419d23223),
    ("inch Tcp linuxcnc", 0x597830dfc4e53e65),
    ("inch Tcp heidenhain", 0x0c3d17083b5f09d5),
    ("inch Tcp sinumerik", 0x124de166d8e1d426),
];
