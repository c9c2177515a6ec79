//! The programs themselves, to the byte: every dialect in both modes on every preset machine for
//! the paper's example, the blade and the wall (`jobs`), and each dialect with the other units,
//! coolant, spindle direction, tool, work offset and tolerances — each program's FNV-1a hash
//! against the table below. A change of the post that changes a program fails here; where it
//! should, say why in the commit and write the table anew with `RULEDLAB_BLESS=1 cargo test -p
//! ruledlab-cam --test programs -- --nocapture` (it prints it).
#![cfg(not(target_family = "wasm"))]

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
    ("example table-table-ac Machine linuxcnc", 0xd54a6d6195dae353),
    ("example table-table-ac Machine heidenhain", 0x68dfc68855fef7fe),
    ("example table-table-ac Machine sinumerik", 0xb237a49a9a67d072),
    ("example table-table-ac Tcp linuxcnc", 0xb5bd379324ce2365),
    ("example table-table-ac Tcp heidenhain", 0x94e9cfdd27eedc3c),
    ("example table-table-ac Tcp sinumerik", 0x25ad504335c37ccf),
    ("example table-table-bc Machine linuxcnc", 0x09163b2e07dc0ebb),
    ("example table-table-bc Machine heidenhain", 0x4884d02052a7af66),
    ("example table-table-bc Machine sinumerik", 0x2494c59cbc635350),
    ("example table-table-bc Tcp linuxcnc", 0xb9628f5087e0a217),
    ("example table-table-bc Tcp heidenhain", 0x0b09182f938f759e),
    ("example table-table-bc Tcp sinumerik", 0x82611944dd36836e),
    ("example head-table-bc Machine linuxcnc", 0x69ea6b983b8fb2d2),
    ("example head-table-bc Machine heidenhain", 0xc809009265bf76cc),
    ("example head-table-bc Machine sinumerik", 0x20917f1075eac2c0),
    ("example head-table-bc Tcp linuxcnc", 0xc0a836dc002f684c),
    ("example head-table-bc Tcp heidenhain", 0x55ee149587688431),
    ("example head-table-bc Tcp sinumerik", 0xea83bf6b82e18e02),
    ("example head-head-ac Machine linuxcnc", 0xafab5ace13238d1e),
    ("example head-head-ac Machine heidenhain", 0x71351cc8cce0ba5d),
    ("example head-head-ac Machine sinumerik", 0x51eaddd957aa1025),
    ("example head-head-ac Tcp linuxcnc", 0x571c166ec0f3bf6d),
    ("example head-head-ac Tcp heidenhain", 0x012a2a61cb18000c),
    ("example head-head-ac Tcp sinumerik", 0xc5e44f60cb3e2939),
    ("blade table-table-ac Machine linuxcnc", 0xd68111a9a9a0c388),
    ("blade table-table-ac Machine heidenhain", 0xb6553f3cd875ecad),
    ("blade table-table-ac Machine sinumerik", 0x9594c2d7f58321ac),
    ("blade table-table-ac Tcp linuxcnc", 0xa82ce0c123aa9eff),
    ("blade table-table-ac Tcp heidenhain", 0x644bc35ddf9a830e),
    ("blade table-table-ac Tcp sinumerik", 0x8bc00b7640219c8f),
    ("blade table-table-bc Machine linuxcnc", 0x60b97a3f4391a528),
    ("blade table-table-bc Machine heidenhain", 0xc9e740af337cba62),
    ("blade table-table-bc Machine sinumerik", 0x930bb26bcd6c56d6),
    ("blade table-table-bc Tcp linuxcnc", 0xe0f0693bc2719bd8),
    ("blade table-table-bc Tcp heidenhain", 0x8b1535c8057a2542),
    ("blade table-table-bc Tcp sinumerik", 0x97159879d2454143),
    ("blade head-table-bc Machine linuxcnc", 0xfe8560063a9ac478),
    ("blade head-table-bc Machine heidenhain", 0xb9ae858fedafc8fb),
    ("blade head-table-bc Machine sinumerik", 0x017f21e1cc4b6010),
    ("blade head-table-bc Tcp linuxcnc", 0xb011c8ab7a42e3fe),
    ("blade head-table-bc Tcp heidenhain", 0x01b229de860c21da),
    ("blade head-table-bc Tcp sinumerik", 0x38a89a65e0dcb968),
    ("blade head-head-ac Machine linuxcnc", 0x61b4f6733d5e40f7),
    ("blade head-head-ac Machine heidenhain", 0x70ca163e656d8f1a),
    ("blade head-head-ac Machine sinumerik", 0x599c04d047bad950),
    ("blade head-head-ac Tcp linuxcnc", 0xd66440bfe3b91473),
    ("blade head-head-ac Tcp heidenhain", 0xcc5c4118baa4321d),
    ("blade head-head-ac Tcp sinumerik", 0x9b45f74fdb44ef46),
    ("wall table-table-ac Machine linuxcnc", 0x5bcb8ddbff0959a5),
    ("wall table-table-ac Machine heidenhain", 0xe01dbcea279e9b4d),
    ("wall table-table-ac Machine sinumerik", 0x4a0281886cd3e93c),
    ("wall table-table-ac Tcp linuxcnc", 0xa7e341c1eba23fcc),
    ("wall table-table-ac Tcp heidenhain", 0x7d74cf860ab6b547),
    ("wall table-table-ac Tcp sinumerik", 0x24e628c97d6c1f1c),
    ("wall table-table-bc Machine linuxcnc", 0x10631d824de2b42b),
    ("wall table-table-bc Machine heidenhain", 0x020368ea622c701b),
    ("wall table-table-bc Machine sinumerik", 0x0d4aa7e42da417cc),
    ("wall table-table-bc Tcp linuxcnc", 0x4459e1c1834211c7),
    ("wall table-table-bc Tcp heidenhain", 0xe3c7c4b3e7d1aedb),
    ("wall table-table-bc Tcp sinumerik", 0xfdab7e8f6abc5bb6),
    ("wall head-table-bc Machine linuxcnc", 0x323c0ef89461b33d),
    ("wall head-table-bc Machine heidenhain", 0xaeddadbaccf19058),
    ("wall head-table-bc Machine sinumerik", 0x054b4398e3c2a5e0),
    ("wall head-table-bc Tcp linuxcnc", 0x8648643463c35709),
    ("wall head-table-bc Tcp heidenhain", 0x4d6cf5df5e8754f2),
    ("wall head-table-bc Tcp sinumerik", 0x167a0474f5c7027a),
    ("wall head-head-ac Machine linuxcnc", 0x1e2a43a91f9ba0e6),
    ("wall head-head-ac Machine heidenhain", 0x0c5565460659cd03),
    ("wall head-head-ac Machine sinumerik", 0x4bb2da0605606226),
    ("wall head-head-ac Tcp linuxcnc", 0x06418a9ea2c3f912),
    ("wall head-head-ac Tcp heidenhain", 0xd75a6ab9ab43911c),
    ("wall head-head-ac Tcp sinumerik", 0x69ceb12b21f83760),
    ("inch Machine linuxcnc", 0x6e5198f2a1327a01),
    ("inch Machine heidenhain", 0xb2b08e5b1033e8dc),
    ("inch Machine sinumerik", 0xd88750fe9ef9cfd4),
    ("inch Tcp linuxcnc", 0xc11b6d7f3046ec06),
    ("inch Tcp heidenhain", 0xf57e19a3983b16fd),
    ("inch Tcp sinumerik", 0x9bf9da677bebdffd),
];
