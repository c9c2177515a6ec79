//! The Heidenhain and Sinumerik programs of the G-code post checked against the syntax their
//! manuals document (no controller of theirs ran them: the book, "G-code and its dialects"): the program frame,
//! block numbers, tool-centre-point control on and off, comments, and every block one of the
//! kinds the post writes, with its words in order.
#![cfg(not(target_family = "wasm"))]

use ruledlab::{example_tool_path, gcode, Dialect, Machine, Mode, PostOptions, Program};
use ruledlab::{Scheme, Variant, MACHINE_PRESETS};

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

/// A signed Heidenhain number: `+12.3456`, `-0.5000`.
fn signed(word: &str) -> bool {
    let Some(rest) = word.strip_prefix(['+', '-']) else { return false };
    let (int, frac) = rest.split_once('.').unwrap_or((rest, ""));
    !int.is_empty()
        && int.bytes().all(|b| b.is_ascii_digit())
        && frac.len() == 4
        && frac.bytes().all(|b| b.is_ascii_digit())
}

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
                "CYCL" => assert_eq!(block, "CYCL DEF 247 DATUM SETTING ~"),
                "TOOL" => assert_eq!(block, "TOOL CALL 1 Z S10000"),
                "FUNCTION" => tcpm.push(block.to_string()),
                "L" => {
                    // L, coordinates with signs, R0, a feed or FMAX, then M functions
                    let mut k = 1;
                    while k < words.len() && words[k].len() > 1 && "XYZABC".contains(&words[k][..1]) {
                        assert!(signed(&words[k][1..]), "{name}: {line}");
                        k += 1;
                    }
                    assert!(k > 1 && words[k] == "R0", "{name}: {line}");
                    assert!(words[k + 1] == "FMAX" || words[k + 1].starts_with('F'), "{name}: {line}");
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
        assert!(p.text.contains(" M91"), "the retract in machine coordinates");
        assert!(lines[lines.len() - 2].ends_with(" M30"), "{name}");
        // one L block per pose of the cut, between the comments
        let cut = lines.iter().position(|l| l.ends_with("; cut")).unwrap();
        let end = lines.iter().position(|l| l.ends_with("; end of cut")).unwrap();
        assert_eq!(end - cut - 1, p.poses.len() - 1, "{name}");
    }
}

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
