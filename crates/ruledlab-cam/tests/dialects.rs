//! The Heidenhain and Sinumerik programs of the G-code post checked against the rules their
//! manuals document (no controller of theirs ran them: the book, "G-code and its dialects"),
//! each rule a test naming its source: the program frame, block numbers, tool-centre-point
//! control on and off, comments, every block one of the kinds the post writes with its words
//! in order; the feed word's range, the retract, the tolerance cycle, the continuous-path mode;
//! and the rotary axes' limits handled alike in every dialect and mode. LinuxCNC's rules are
//! read back by its own interpreter in `controller.rs`.
#![cfg(not(target_family = "wasm"))]

#[allow(dead_code)] // the ring and the targets are measured in sweep.rs
mod jobs;

use ruledlab::{Scheme, Variant};
use ruledlab_cam::{example_tool_path, gcode, AxisName, Dialect, Machine, Mode, PostOptions, Program, RotaryAxis};
use ruledlab_cam::{Limit, MACHINE_PRESETS};

fn programs(dialect: Dialect) -> Vec<(String, Mode, Program)> {
    let path =
        example_tool_path(7).unwrap().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 2).unwrap();
    MACHINE_PRESETS
        .iter()
        .flat_map(|name| [Mode::Tcp, Mode::Machine].map(|mode| (name.to_string(), mode)))
        .map(|(name, mode)| {
            let machine = Machine::preset(&name).unwrap();
            let o = PostOptions { dialect, mode, machine, scale: 10.0, name: "PART_7".into(), ..Default::default() };
            let p = gcode(&path, &o).unwrap();
            (name, mode, p)
        })
        .collect()
}

/// A signed Heidenhain coordinate: `+12.3456`, `-0.5000` (5.4: TNC user's manual, "Input format
/// and unit of TNC functions", positions −99 999.9999 to +99 999.9999).
fn signed(word: &str) -> bool {
    let Some(rest) = word.strip_prefix(['+', '-']) else { return false };
    let (int, frac) = rest.split_once('.').unwrap_or((rest, ""));
    !int.is_empty()
        && int.len() <= 5
        && int.bytes().all(|b| b.is_ascii_digit())
        && frac.len() == 4
        && frac.bytes().all(|b| b.is_ascii_digit())
}

/// A Heidenhain feed word: `F` and 0 to 99 999.999 with 3 decimals (5.3: the same table, "Feed
/// rates 0 to 99 999.999 mm/min").
fn feed_word(word: &str) -> bool {
    let Some(rest) = word.strip_prefix('F') else { return false };
    let Some((int, frac)) = rest.split_once('.') else { return false };
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    !int.is_empty()
        && int.len() <= 5
        && digits(int)
        && frac.len() == 3
        && digits(frac)
        && rest.parse::<f64>().is_ok_and(|f| f <= 99_999.999)
}

/// The Klartext syntax of the TNC 640 user's manual for Klartext programming: `BEGIN PGM … MM`,
/// blocks numbered from 0, `;` comments, `BLK FORM`, cycle 247 with its Q parameter, `TOOL CALL
/// … Z S…`, `FUNCTION TCPM …` / `FUNCTION RESET TCPM`, straight lines `L` with signed
/// coordinates, `R0`, a feed word or `FMAX`, then M functions; `END PGM`.
#[test]
fn heidenhain_klartext() {
    for (name, mode, p) in programs(Dialect::Heidenhain) {
        let lines: Vec<&str> = p.text.lines().collect();
        assert_eq!(lines[0], "0 BEGIN PGM PART_7 MM", "{name}");
        let last = lines.last().unwrap();
        let mut expected = 0;
        let mut tcpm = Vec::new();
        for line in &lines {
            if line.starts_with("  Q339=+1 ;DATUM NUMBER") {
                continue; // the parameter line of cycle 247
            }
            let (number, block) = line.split_once(' ').unwrap();
            assert_eq!(number.parse::<usize>().unwrap(), expected, "{name}: block numbers count up from 0: {line}");
            expected += 1;
            let words: Vec<&str> = block.split(' ').collect();
            match words[0] {
                "BEGIN" | "END" => assert_eq!(&words[1..], ["PGM", "PART_7", "MM"]),
                ";" => assert!(!block[1..].contains([';', '(', ')'])),
                "BLK" => assert!(block.starts_with("BLK FORM 0.1 Z X") || block.starts_with("BLK FORM 0.2 X")),
                "CYCL" => assert!(
                    block == "CYCL DEF 247 DATUM SETTING ~" || block.starts_with("CYCL DEF 32."),
                    "{name}: {line}"
                ),
                "TOOL" => assert_eq!(block, "TOOL CALL 1 Z S10000"),
                "FUNCTION" => tcpm.push(block.to_string()),
                "L" if block == "L M140 MB MAX" => {}
                "L" => {
                    // L, coordinates with signs, R0, a feed or FMAX, then M functions
                    let mut k = 1;
                    while k < words.len() && words[k].len() > 1 && "XYZABC".contains(&words[k][..1]) {
                        assert!(signed(&words[k][1..]), "{name}: {line}");
                        k += 1;
                    }
                    assert!(k > 1 && words[k] == "R0", "{name}: {line}");
                    assert!(words[k + 1] == "FMAX" || feed_word(words[k + 1]), "{name}: {line}");
                    assert!(words[k + 2..].iter().all(|w| w.starts_with('M')), "{name}: {line}");
                }
                other => panic!("{name}: unexpected block {other}: {line}"),
            }
        }
        assert_eq!(*last, format!("{} END PGM PART_7 MM", expected - 1));
        match mode {
            Mode::Tcp => assert_eq!(tcpm, ["FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS", "FUNCTION RESET TCPM"]),
            Mode::Machine => assert!(tcpm.is_empty()),
        }
        assert!(lines[lines.len() - 2].ends_with(" M30"), "{name}");
        // one L block per pose of the cut, between the comments
        let cut = lines.iter().position(|l| l.ends_with("; cut")).unwrap();
        let end = lines.iter().position(|l| l.ends_with("; end of cut")).unwrap();
        assert_eq!(end - cut - 1, p.poses.len() - 1, "{name}");
    }
}

/// The feed word's range: at most 99 999.999 with 3 decimals (TNC user's manual, "Input format
/// and unit of TNC functions": feed rates 0 to 99 999.999 mm/min, format 5.3). A machine with no
/// speed limits passing the blade's pole in machine coordinates would need more — the table
/// swings the part's tip round fast while the tip creeps — so those blocks are slowed until
/// their F fits (their limit: the feed word), and every F written is within the range.
#[test]
fn heidenhain_feed_words_stay_within_the_tncs_range() {
    let mut m = Machine::preset("table-table-ac").unwrap();
    m.speed = None;
    m.acceleration = None;
    m.rotary = m.rotary.map(|r| RotaryAxis { speed: None, acceleration: None, ..r });
    for mode in [Mode::Machine, Mode::Tcp] {
        let o = PostOptions {
            dialect: Dialect::Heidenhain,
            mode,
            machine: m.clone(),
            feed: 20_000.0,
            ..Default::default()
        };
        let p = gcode(&jobs::blade_refined(), &o).unwrap();
        let words: Vec<&str> = p
            .text
            .split_whitespace()
            .filter(|w| w.starts_with('F') && w[1..].starts_with(|c: char| c.is_ascii_digit()))
            .collect();
        assert!(words.len() > 50);
        for w in &words {
            assert!(feed_word(w), "{mode:?}: {w}");
        }
        if mode == Mode::Machine {
            assert!(p.motion.iter().any(|b| b.limit == Limit::FeedWord), "some block needed more than F99999.999");
        }
    }
    // a feed beyond the word is refused, not written
    let e = gcode(
        &example_tool_path(3).unwrap(),
        &PostOptions { dialect: Dialect::Heidenhain, feed: 100_000.0, ..Default::default() },
    );
    assert_eq!(e.unwrap_err().details().option.as_deref(), Some("feed"));
}

/// The retract along the tool axis with `M140 MB MAX` (TNC 640 user's manual, Klartext,
/// "Retraction in the tool-axis direction: M140": MB MAX moves to the end of the traverse
/// range), at the start before the rotary axes turn and at the end before they go home: no
/// positioning in machine coordinates with M91.
#[test]
fn heidenhain_retracts_with_m140_mb_max() {
    for (name, _, p) in programs(Dialect::Heidenhain) {
        let blocks: Vec<&str> = p.text.lines().filter_map(|l| l.split_once(' ').map(|(_, b)| b)).collect();
        assert_eq!(blocks.iter().filter(|b| **b == "L M140 MB MAX").count(), 2, "{name}");
        assert!(!p.text.contains("M91"), "{name}");
        let retract = blocks.iter().position(|b| *b == "L M140 MB MAX").unwrap();
        assert!(
            blocks[retract + 1].starts_with("L ") && blocks[retract + 1].contains(" R0 FMAX"),
            "{name}: the rotary axes turn after it"
        );
    }
}

/// Cycle 32 TOLERANCE (TNC 640 user's manual for cycle programming, "TOLERANCE (Cycle 32)": T
/// the path tolerance in mm, HSC-MODE 0 finishing, TA the tolerance of the rotary axes in
/// degrees; "Resetting: program the cycle without T"): defined before the cut with the job's
/// chordal and angular tolerances, reset after it.
#[test]
fn heidenhain_cycle_32_holds_the_tolerance() {
    let path = example_tool_path(5).unwrap();
    let o = PostOptions {
        dialect: Dialect::Heidenhain,
        scale: 10.0,
        tolerance: 0.02,
        angular_tolerance: Some(0.5),
        ..Default::default()
    };
    let text = gcode(&path, &o).unwrap().text;
    let blocks: Vec<&str> = text.lines().filter_map(|l| l.split_once(' ').map(|(_, b)| b)).collect();
    let at = |b: &str| blocks.iter().position(|x| *x == b);
    let define = at("CYCL DEF 32.1 T0.0200").expect("T");
    assert_eq!(blocks[define - 1], "CYCL DEF 32.0 TOLERANCE");
    assert_eq!(blocks[define + 1], "CYCL DEF 32.2 HSC-MODE:0 TA0.5000");
    let reset = at("CYCL DEF 32.1").expect("the reset");
    let (cut, end) = (at("; cut").unwrap(), at("; end of cut").unwrap());
    assert!(define < cut && end < reset);
    let plain = gcode(&path, &PostOptions { angular_tolerance: None, ..o }).unwrap().text;
    assert!(plain.contains(" CYCL DEF 32.2 HSC-MODE:0\n"));
}

/// The Sinumerik 840D programming manual's syntax (fundamentals, and job planning for TRAORI):
/// the archive header, blocks N10, N20, …, `;` comments, every block's words known, G93 with F
/// in every block.
#[test]
fn sinumerik_840d() {
    for (name, mode, p) in programs(Dialect::Sinumerik) {
        let lines: Vec<&str> = p.text.lines().collect();
        assert_eq!(lines[0], "%_N_PART_7_MPF");
        assert_eq!(lines[1], ";$PATH=/_N_MPF_DIR");
        let mut expected = 10;
        let mut traori = Vec::new();
        let mut inverse = false;
        for line in &lines[2..] {
            if let Some(comment) = line.strip_prefix("; ") {
                assert!(!comment.contains([';', '(', ')']), "{line}");
                continue;
            }
            let (number, block) = line.split_once(' ').unwrap();
            assert_eq!(number, format!("N{expected}"), "{name}: {line}");
            expected += 10;
            if block.starts_with("TRA") {
                traori.push(block.to_string());
            }
            if block.contains("G93") {
                inverse = true;
            }
            if block.contains("G94") {
                inverse = false;
            }
            if inverse && block.contains("G1 ") {
                assert!(block.contains(" F"), "G93 needs F in every block: {line}");
            }
            for word in block.split(' ') {
                let ok = word.starts_with(['G', 'X', 'Y', 'Z', 'A', 'B', 'C', 'F', 'S', 'M', 'T', 'D'])
                    || ["SUPA", "TRAORI", "ORIWKS", "ORIVECT", "TRAFOOF"].contains(&word);
                assert!(ok, "{name}: {word} in {line}");
            }
        }
        assert!(lines.last().unwrap().ends_with(" M30"));
        match mode {
            Mode::Tcp => {
                assert_eq!(traori, ["TRAORI ORIWKS ORIVECT", "TRAFOOF"]);
                assert!(p.text.contains(" A3=") && p.text.contains(" C3="));
            }
            Mode::Machine => assert!(traori.is_empty() && !p.text.contains("A3=")),
        }
        assert!(p.text.contains("G0 SUPA Z") && p.text.contains("T1 D1 M6") && p.text.contains("G54"));
    }
}

/// Continuous-path mode with CYCLE832 instead of modal exact stop (SINUMERIK 840D sl programming
/// manual, job planning, "High speed settings - CYCLE832": _TOL the contour tolerance, _TOLM
/// units 1 finishing and tens 1 "orientation tolerance in parameter _OTOL", 0 deselection;
/// fundamentals, "Exact stop (G60)" and "Continuous-path mode (G64)"): G64 on the first line, no
/// G60 anywhere, the cycle with the job's tolerances before the cut and deselected after it.
#[test]
fn sinumerik_cuts_in_continuous_path_mode_with_cycle832() {
    for (name, _, p) in programs(Dialect::Sinumerik) {
        let blocks: Vec<&str> =
            p.text.lines().filter(|l| l.starts_with('N')).map(|l| l.split_once(' ').unwrap().1).collect();
        assert_eq!(blocks[0], "G17 G71 G90 G94 G40 G64", "{name}");
        assert!(!p.text.contains("G60"), "{name}");
        let on = blocks.iter().position(|b| *b == "CYCLE832(0.0100,1,1)").expect("the cycle");
        let off = blocks.iter().position(|b| *b == "CYCLE832(0,0,1)").expect("its deselection");
        let first_cut = blocks.iter().position(|b| b.contains("G1 ")).unwrap();
        assert!(on < first_cut && off > blocks.iter().rposition(|b| b.contains("G1 ")).unwrap(), "{name}");
    }
    let o =
        PostOptions { dialect: Dialect::Sinumerik, scale: 10.0, angular_tolerance: Some(0.2), ..Default::default() };
    let text = gcode(&example_tool_path(5).unwrap(), &o).unwrap().text;
    assert!(text.contains(" CYCLE832(0.0100,11,0.2000)\n"), "{text}");
}

/// Sinumerik's tool-centre point writes the tool axis as a vector, so the controller picks the
/// rotary values: the post checks them against the limits all the same, and where the fork
/// head's C must unwind on the wall it switches the transformation off (TRAFOOF), turns C in
/// machine coordinates, and switches it on again (TRAORI) — out of the part, as in every
/// dialect and mode: the same unwinds everywhere.
#[test]
fn every_dialect_and_mode_unwinds_the_same_and_sinumerik_tcp_turns_with_traori_off() {
    let wall = jobs::wall();
    let head = Machine::preset("head-head-ac").unwrap();
    let mut counts = Vec::new();
    for dialect in [Dialect::LinuxCnc, Dialect::Heidenhain, Dialect::Sinumerik] {
        for mode in [Mode::Machine, Mode::Tcp] {
            let o = PostOptions { dialect, mode, machine: head.clone(), feed: 1200.0, ..Default::default() };
            let p = gcode(&wall, &o).unwrap();
            counts.push(p.unwound.iter().filter(|u| u.is_some()).count());
            if dialect == Dialect::Sinumerik && mode == Mode::Tcp {
                let blocks: Vec<&str> =
                    p.text.lines().filter(|l| l.starts_with('N')).map(|l| l.split_once(' ').unwrap().1).collect();
                let off =
                    blocks.iter().enumerate().filter(|(_, b)| **b == "TRAFOOF").map(|(k, _)| k).collect::<Vec<_>>();
                assert_eq!(off.len(), 2, "once for the unwind, once at the end");
                assert!(
                    blocks[off[0] + 1].starts_with("G0 C") && blocks[off[0] + 2] == "TRAORI ORIWKS ORIVECT",
                    "{:?}",
                    &blocks[off[0]..off[0] + 3]
                );
            }
        }
    }
    assert!(counts.iter().all(|&c| c == counts[0] && c > 0), "{counts:?}");
    // beyond a limit it cannot unwind (A of the trunnion at 130°), every dialect and mode refuses
    // the same pose with the same words
    let mut far = example_tool_path(5).unwrap();
    let t = 130f64.to_radians();
    far.poses[3].axis = glam::DVec3::new(0.0, t.sin(), t.cos());
    let mut said = Vec::new();
    for dialect in [Dialect::LinuxCnc, Dialect::Heidenhain, Dialect::Sinumerik] {
        for mode in [Mode::Machine, Mode::Tcp] {
            let e = gcode(&far, &PostOptions { dialect, mode, scale: 10.0, ..Default::default() }).unwrap_err();
            said.push(e.to_string());
        }
    }
    assert!(
        said.iter().all(|s| s == &said[0]) && said[0].starts_with("pose 3 cannot be reached: A would be"),
        "{said:?}"
    );
}

/// The work offset chosen is the one written: 1 … 6 are G54 … G59 in LinuxCNC.
#[test]
fn linuxcnc_work_offsets() {
    let path = example_tool_path(7).unwrap();
    for (k, word) in (1..=6).zip(["G54", "G55", "G56", "G57", "G58", "G59"]) {
        let o = PostOptions { dialect: Dialect::LinuxCnc, work_offset: k, ..Default::default() };
        let p = gcode(&path, &o).unwrap();
        let offsets: Vec<&str> = p.text.lines().filter(|l| l.starts_with("G5") && !l.starts_with("G53")).collect();
        assert_eq!(offsets, [word], "work offset {k}");
    }
}

/// A bridge mill's head, C carrying B, is LinuxCNC's `5axiskins` (its man page kins(9)): the
/// header of a program with the tool-centre point names it with the INI line it needs.
#[test]
fn a_head_with_c_carrying_b_is_linuxcncs_5axiskins() {
    let mut m = Machine::preset("head-head-ac").unwrap();
    m.rotary[1].name = AxisName::B;
    let o = PostOptions { machine: m, mode: Mode::Tcp, scale: 10.0, ..Default::default() };
    // the header's comments as one text (long ones wrap onto lines of their own)
    let text = gcode(&example_tool_path(5).unwrap(), &o).unwrap().text.replace(")\n(  ", " ");
    assert!(text.contains("[KINS] KINEMATICS = 5axiskins sparm=identityfirst"), "{text}");
}

/// Each controller's name, as its errors say it ("must be at most … a minute for a Heidenhain
/// TNC").
#[test]
fn each_controller_says_its_name() {
    let names = [Dialect::LinuxCnc, Dialect::Heidenhain, Dialect::Sinumerik].map(|d| d.controller().name());
    assert_eq!(names, ["LinuxCNC", "a Heidenhain TNC", "a Sinumerik 840D"]);
}
