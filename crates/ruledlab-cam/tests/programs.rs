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
    ("example table-table-ac Machine linuxcnc", 0xe99f09698623e10f),
    ("example table-table-ac Machine heidenhain", 0x7a2c1c36683f855f),
    ("example table-table-ac Machine sinumerik", 0x97efa7eba6f47702),
    ("example table-table-ac Tcp linuxcnc", 0xd32d327a1e7faf20),
    ("example table-table-ac Tcp heidenhain", 0xcb0743876f28a2a3),
    ("example table-table-ac Tcp sinumerik", 0x3a3d3a68d4303474),
    ("example table-table-bc Machine linuxcnc", 0xfde65f8332104a67),
    ("example table-table-bc Machine heidenhain", 0x2057ebee4fd1f1e0),
    ("example table-table-bc Machine sinumerik", 0xb425e1d0aae585c8),
    ("example table-table-bc Tcp linuxcnc", 0x3f2bcfabaf80e572),
    ("example table-table-bc Tcp heidenhain", 0x696d10e01095eeb4),
    ("example table-table-bc Tcp sinumerik", 0x41f0c2425a2fffcd),
    ("example head-table-bc Machine linuxcnc", 0x67c6299e466a1dae),
    ("example head-table-bc Machine heidenhain", 0xe92581af711ed87a),
    ("example head-table-bc Machine sinumerik", 0xcd6fcc11ad714658),
    ("example head-table-bc Tcp linuxcnc", 0x9bca961b2ca7f1a1),
    ("example head-table-bc Tcp heidenhain", 0xd5eec43fe9aeebbf),
    ("example head-table-bc Tcp sinumerik", 0x6ae156f47090757b),
    ("example head-head-ac Machine linuxcnc", 0xc8e81cb80cc22f26),
    ("example head-head-ac Machine heidenhain", 0x7299757a755a4856),
    ("example head-head-ac Machine sinumerik", 0x4485a75a64c824bd),
    ("example head-head-ac Tcp linuxcnc", 0x8d60e6283b4ea724),
    ("example head-head-ac Tcp heidenhain", 0x7c4900bc8b7ad985),
    ("example head-head-ac Tcp sinumerik", 0xdd2ee07f82719e6e),
    ("blade table-table-ac Machine linuxcnc", 0xe9d5be03ba60e6f0),
    ("blade table-table-ac Machine heidenhain", 0xa762f348901f324f),
    ("blade table-table-ac Machine sinumerik", 0x0981cba9afd50bfc),
    ("blade table-table-ac Tcp linuxcnc", 0x1b8afce55bfc0edc),
    ("blade table-table-ac Tcp heidenhain", 0xcb9db48518d69332),
    ("blade table-table-ac Tcp sinumerik", 0x67b94542b4862b60),
    ("blade table-table-bc Machine linuxcnc", 0xbceefb272b743d54),
    ("blade table-table-bc Machine heidenhain", 0x47d745a5a30ebb8f),
    ("blade table-table-bc Machine sinumerik", 0xe9758fbf2dae80c6),
    ("blade table-table-bc Tcp linuxcnc", 0xd3fc7efaa9ea5647),
    ("blade table-table-bc Tcp heidenhain", 0xf59847a5100c02b9),
    ("blade table-table-bc Tcp sinumerik", 0xe79d8ea3aa8fc15a),
    ("blade head-table-bc Machine linuxcnc", 0x9d9dd169d0f0e66c),
    ("blade head-table-bc Machine heidenhain", 0xc2e30f3c6eb84035),
    ("blade head-table-bc Machine sinumerik", 0x94142c1f1174b520),
    ("blade head-table-bc Tcp linuxcnc", 0x162129fb82bd53b9),
    ("blade head-table-bc Tcp heidenhain", 0x0d9fbd2caa5c20d1),
    ("blade head-table-bc Tcp sinumerik", 0x638ba26bd43f63f1),
    ("blade head-head-ac Machine linuxcnc", 0x86ee04975fef3703),
    ("blade head-head-ac Machine heidenhain", 0x7be83ea9b8da6d2b),
    ("blade head-head-ac Machine sinumerik", 0x6d2959678c7950f8),
    ("blade head-head-ac Tcp linuxcnc", 0xfdc060e089b8212a),
    ("blade head-head-ac Tcp heidenhain", 0x006c27631bda9bf6),
    ("blade head-head-ac Tcp sinumerik", 0xf1ec512b0d391bad),
    ("wall table-table-ac Machine linuxcnc", 0xc1bd47bde03491ad),
    ("wall table-table-ac Machine heidenhain", 0x59ea2f68f6d295ab),
    ("wall table-table-ac Machine sinumerik", 0xf270d4db53b35f94),
    ("wall table-table-ac Tcp linuxcnc", 0x36a759edaf5bda57),
    ("wall table-table-ac Tcp heidenhain", 0xf5b14a16e0c82535),
    ("wall table-table-ac Tcp sinumerik", 0x198b7ed1c03ea8f9),
    ("wall table-table-bc Machine linuxcnc", 0x0e5060425be78c23),
    ("wall table-table-bc Machine heidenhain", 0xcbbd698b8ad1b00b),
    ("wall table-table-bc Machine sinumerik", 0xdb08fadb0e36517c),
    ("wall table-table-bc Tcp linuxcnc", 0xcaf12e46afd3f8ca),
    ("wall table-table-bc Tcp heidenhain", 0x1d033b67d79df97d),
    ("wall table-table-bc Tcp sinumerik", 0x61c909dee031b697),
    ("wall head-table-bc Machine linuxcnc", 0x4b52ed7b5224c4c5),
    ("wall head-table-bc Machine heidenhain", 0xdda3f5967a07397c),
    ("wall head-table-bc Machine sinumerik", 0xeae1d45d32d8c720),
    ("wall head-table-bc Tcp linuxcnc", 0x5fcfaa85798a7dac),
    ("wall head-table-bc Tcp heidenhain", 0xde0edae8c4836ab8),
    ("wall head-table-bc Tcp sinumerik", 0x94dc0e6b7f1e5803),
    ("wall head-head-ac Machine linuxcnc", 0xe79a5bfe4af3d30c),
    ("wall head-head-ac Machine heidenhain", 0xc6e17451f8e4baef),
    ("wall head-head-ac Machine sinumerik", 0xed7387e02bf1f42a),
    ("wall head-head-ac Tcp linuxcnc", 0xa0e2f1a71e85e6f1),
    ("wall head-head-ac Tcp heidenhain", 0x6e1a56bbdc07f7fb),
    ("wall head-head-ac Tcp sinumerik", 0xf785ae1e29668ee7),
    ("inch Machine linuxcnc", 0xd4c30bf66ff27df6),
    ("inch Machine heidenhain", 0xfb57db6b22aab30f),
    ("inch Machine sinumerik", 0x6b3066dc2090003d),
    ("inch Tcp linuxcnc", 0xf1176884100d4070),
    ("inch Tcp heidenhain", 0x28ff8ee8168949ca),
    ("inch Tcp sinumerik", 0x278b3869e3d9cceb),
];
