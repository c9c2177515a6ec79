//! Paper models (Section 3's development of discrete developables, made cuttable): the flat
//! patterns' SVG and DXF read back by real readers — librsvg's `rsvg-convert` (the SVG's size in
//! millimetres, the check square and rulings measured on its rendering) and ezdxf (the DXF's
//! version, layers, cut line and rulings) — with the lengths compared to the 3D strip's.
//!
//! Without `rsvg-convert` on PATH or ezdxf in `.venv/` (scripts/setup.sh --browser installs both) the
//! test says so and passes, unless `RULEDLAB_REQUIRE_READERS` is set (scripts/test.sh sets it).

use glam::{DVec2, DVec3};
use ruledlab::{
    cone, overlapping_faces, page_svg, pieces, sheet_dxf, sheet_svg, tangent_surface, tile, Paper, RuledSurface, Sheet,
    SheetOptions, Span, Unfolding,
};
use std::path::{Path, PathBuf};
use std::process::Command;

fn required() -> bool {
    std::env::var_os("RULEDLAB_REQUIRE_READERS").is_some()
}

/// A scratch directory of this test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ruledlab-paper-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The pixel size of the PNG `rsvg-convert` makes of `svg` with `args`, or None without the program.
fn rsvg(svg: &Path, args: &[&str]) -> Option<(u32, u32)> {
    let png = svg.with_extension(format!("{}.png", args.join("").replace(['-', '=', '.'], "")));
    let status = Command::new("rsvg-convert").args(args).arg(svg).arg("-o").arg(&png).status();
    match status {
        Ok(s) => assert!(s.success(), "rsvg-convert {args:?} failed"),
        Err(_) => {
            assert!(!required(), "rsvg-convert (librsvg2-bin) not found on PATH");
            return None;
        }
    }
    let head = std::fs::read(&png).unwrap();
    assert_eq!(&head[1..4], b"PNG");
    let be = |k: usize| u32::from_be_bytes(head[k..k + 4].try_into().unwrap());
    Some((be(16), be(20)))
}

/// The Python of `.venv/` if it has ezdxf.
fn ezdxf_python() -> Option<PathBuf> {
    let python = Path::new(env!("CARGO_MANIFEST_DIR")).join(".venv/bin/python");
    let ok = Command::new(&python).args(["-c", "import ezdxf"]).status().map(|s| s.success()).unwrap_or(false);
    assert!(ok || !required(), "ezdxf not found in .venv/ (bash scripts/setup.sh --browser installs it)");
    ok.then_some(python)
}

/// A cone over a helix-like polygon with its apex off the axis: rulings of many lengths.
fn cone_strip() -> RuledSurface {
    let c: Vec<DVec3> = (0..=30)
        .map(|i| {
            let u = 0.8 * std::f64::consts::TAU * i as f64 / 30.0;
            DVec3::new(u.cos(), 0.7 * u.sin(), 0.1 * u)
        })
        .collect();
    cone(&c, DVec3::new(0.3, 0.2, 2.0), Span { from: 0.25, to: 1.0 }).unwrap()
}

/// The length of ruling i and of the edges a_i a_{i+1}, b_i b_{i+1} of the 3D strip.
fn ruling(s: &RuledSurface, i: usize) -> f64 {
    s.segment(i).length()
}

#[test]
fn the_svg_is_read_by_librsvg_at_one_to_one_in_millimetres() {
    let s = cone_strip();
    let flat = Unfolding::of(&s).unwrap();
    let parts = pieces(&flat.points, &overlapping_faces(&flat.points));
    let o = SheetOptions { scale: 60.0, fold_angle: 1.0, ..SheetOptions::default() };
    let sheet = Sheet::lay_out(&s, &flat.points, &parts, &o).unwrap();
    let dir = scratch("svg");
    let path = dir.join("pattern.svg");
    std::fs::write(&path, sheet_svg(&sheet)).unwrap();
    // 254 dpi: ten pixels a millimetre
    let Some((w, h)) = rsvg(&path, &["--dpi-x=254", "--dpi-y=254"]) else {
        eprintln!("skipped: rsvg-convert not found on PATH");
        return;
    };
    assert!((w as f64 - 10.0 * sheet.size.x).abs() <= 1.0, "{w} px for {} mm", sheet.size.x);
    assert!((h as f64 - 10.0 * sheet.size.y).abs() <= 1.0, "{h} px for {} mm", sheet.size.y);
    // one element alone is rendered in user units (millimetres), here zoomed ten times: the check
    // square's ink is its side and its stroke (0.2 mm)
    let (sw, sh) = rsvg(&path, &["--zoom=10", "--export-id=check-square"]).unwrap();
    for side in [sw, sh] {
        assert!((side as f64 / 10.0 - 100.2).abs() <= 0.2, "the check square measures {} mm", side as f64 / 10.0);
    }
    // the geometry as librsvg read it: its cairo SVG output has every drawn line as a path in
    // millimetres (a matrix of 96/25.4 px per mm applied); the rulings (stroke 0.1) in the order
    // drawn, each with the length of its ruling on the strip
    let out = Command::new("rsvg-convert").args(["-f", "svg"]).arg(&path).output().unwrap();
    assert!(out.status.success());
    let read = String::from_utf8(out.stdout).unwrap();
    let svg_tag = &read[read.find("<svg").unwrap()..];
    let head = &svg_tag[..svg_tag.find('>').unwrap()];
    let width_px: f64 = head.split(" width=\"").nth(1).unwrap().split('"').next().unwrap().parse().unwrap();
    assert!((width_px * 25.4 / 96.0 - sheet.size.x).abs() < 1e-3, "{width_px} px");
    // the drawn paths (glyphs of the labels are defined apart, without the page's matrix)
    let paths: Vec<(&str, Vec<f64>)> = read
        .split("<path style=\"")
        .skip(1)
        .filter(|p| p[..p.find("/>").unwrap()].contains("transform=\"matrix(3.779528,0,0,3.779528,"))
        .map(|p| {
            let style = p.split('"').next().unwrap();
            let d = p.split(" d=\"").nth(1).unwrap().split('"').next().unwrap();
            (style, d.split(' ').filter_map(|t| t.parse::<f64>().ok()).collect())
        })
        .collect();
    let rulings: Vec<&Vec<f64>> =
        paths.iter().filter(|(style, _)| style.contains("stroke-width:0.1;")).map(|(_, d)| d).collect();
    let drawn: Vec<usize> = sheet.pieces.iter().flat_map(|p| p.rulings_drawn.iter().filter_map(|r| r.ruling)).collect();
    assert!(drawn.len() > 20);
    assert_eq!(rulings.len(), drawn.len());
    for (d, &i) in rulings.iter().zip(&drawn) {
        let measured = (d[2] - d[0]).hypot(d[3] - d[1]);
        let exact = 60.0 * ruling(&s, i);
        assert!((measured - exact).abs() <= 2e-3, "ruling {i}: {measured} mm drawn, {exact} mm on the strip");
    }
    // the check square: the last path, closed, four sides of 100 mm
    let square = &paths.last().unwrap().1;
    for k in 0..4 {
        let side = (square[2 * k + 2] - square[2 * k]).hypot(square[2 * k + 3] - square[2 * k + 1]);
        assert!((side - 100.0).abs() <= 2e-3, "{side}");
    }
    // a tiled page: the paper's size
    let tiling = tile(sheet.size, Paper::A4, 10.0, 10.0).unwrap();
    let page = dir.join("page.svg");
    std::fs::write(&page, page_svg(&sheet, &tiling, tiling.tiles.len() - 1)).unwrap();
    assert_eq!(rsvg(&page, &["--dpi-x=254", "--dpi-y=254"]).unwrap(), (2100, 2970));
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_dxf_is_read_by_ezdxf_with_the_strips_lengths() {
    let s = cone_strip();
    let flat = Unfolding::of(&s).unwrap();
    let n = s.len();
    let o = SheetOptions { scale: 50.0, tabs: false, fold_angle: 0.02, ..SheetOptions::default() };
    let sheet = Sheet::lay_out(&s, &flat.points, std::slice::from_ref(&(0..n - 1)), &o).unwrap();
    let Some(python) = ezdxf_python() else {
        eprintln!("skipped: ezdxf not found in .venv/");
        return;
    };
    let dir = scratch("dxf");
    let path = dir.join("pattern.dxf");
    std::fs::write(&path, sheet_dxf(&sheet)).unwrap();
    let script = r#"
import sys, math, ezdxf
doc = ezdxf.readfile(sys.argv[1])
print("version", doc.dxfversion)
print("audit", len(doc.audit().errors))
print("layers", " ".join(sorted(l.dxf.name for l in doc.layers)))
for e in doc.modelspace():
    if e.dxftype() == "LINE":
        print("line", e.dxf.layer, math.dist(e.dxf.start, e.dxf.end))
    elif e.dxftype() == "POLYLINE":
        p = [v.dxf.location for v in e.vertices]
        closed = e.is_closed
        print("polyline", e.dxf.layer, int(closed), sum(math.dist(p[k], p[(k + 1) % len(p)]) for k in range(len(p))))
    elif e.dxftype() == "TEXT":
        print("text", e.dxf.layer, e.dxf.text)
"#;
    let out = Command::new(python).arg("-c").arg(script).arg(&path).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let lines: Vec<Vec<&str>> = text.lines().map(|l| l.split(' ').collect()).collect();
    let field = |key: &str| lines.iter().find(|l| l[0] == key).unwrap()[1..].join(" ");
    assert_eq!(field("version"), "AC1009");
    assert_eq!(field("audit"), "0");
    for layer in ["CUT", "SCORE", "RULING", "TEXT", "CHECK"] {
        assert!(field("layers").split(' ').any(|l| l == layer), "{}", field("layers"));
    }
    let number = |l: &Vec<&str>| l.last().unwrap().parse::<f64>().unwrap();
    // every interior ruling scored, with its 3D length
    let mut scored: Vec<f64> = lines.iter().filter(|l| l[..2] == ["line", "SCORE"]).map(number).collect();
    let mut exact: Vec<f64> = (1..n - 1).map(|i| 50.0 * ruling(&s, i)).collect();
    scored.sort_by(f64::total_cmp);
    exact.sort_by(f64::total_cmp);
    assert_eq!(scored.len(), exact.len());
    for (a, b) in scored.iter().zip(&exact) {
        assert!((a - b).abs() <= 1e-5, "{a} vs {b}");
    }
    // the cut line: the boundary of the strip, its edges' 3D lengths summed
    let p = s.points();
    let boundary: f64 =
        (0..n - 1).map(|i| (p[2 * i + 2] - p[2 * i]).length() + (p[2 * i + 3] - p[2 * i + 1]).length()).sum::<f64>()
            + ruling(&s, 0)
            + ruling(&s, n - 1);
    let cut: Vec<&Vec<&str>> = lines.iter().filter(|l| l[..2] == ["polyline", "CUT"]).collect();
    assert_eq!(cut.len(), 1);
    assert_eq!(cut[0][2], "1", "closed");
    assert!((number(cut[0]) - 50.0 * boundary).abs() <= 1e-4, "{} vs {}", number(cut[0]), 50.0 * boundary);
    let check: Vec<&Vec<&str>> = lines.iter().filter(|l| l[..2] == ["polyline", "CHECK"]).collect();
    assert!((number(check[0]) - 400.0).abs() <= 1e-9);
    assert!(lines.iter().any(|l| l[..2] == ["text", "TEXT"] && l[2] == "1"));
    std::fs::remove_dir_all(dir).unwrap();
}

/// The tangent surface of a helix over one and a half turns unrolls onto itself (its edge of
/// regression develops onto a circle of turning angle 9 rad): the pattern is split, and no piece
/// overlaps itself; the sheet glues the pieces with letters.
#[test]
fn a_pattern_that_overlaps_itself_is_split_into_pieces_that_do_not() {
    let c: Vec<DVec3> = (0..121)
        .map(|i| {
            let u = 1.5 * std::f64::consts::TAU * i as f64 / 120.0;
            DVec3::new(u.cos(), u.sin(), 0.3 * u)
        })
        .collect();
    let s = tangent_surface(&c, Span { from: 0.0, to: 1.2 }).unwrap();
    let flat = Unfolding::of(&s).unwrap();
    let overlaps = overlapping_faces(&flat.points);
    assert!(!overlaps.is_empty());
    let parts = pieces(&flat.points, &overlaps);
    assert!(parts.len() >= 2, "{parts:?}");
    for r in &parts {
        assert!(overlaps.iter().all(|&(i, j)| !(r.start <= i && j < r.end)), "piece {r:?} overlaps itself");
    }
    let sheet =
        Sheet::lay_out(&s, &flat.points, &parts, &SheetOptions { scale: 40.0, ..SheetOptions::default() }).unwrap();
    assert_eq!(sheet.pieces.len(), parts.len());
    // one letter per join, on a tab and on the next piece's first ruling
    assert_eq!(sheet.labels.iter().filter(|l| l.text == "A").count(), 2);
    // each piece, laid out alone, is a rigid motion of its part of the pattern: pairwise distances kept
    for (piece, r) in sheet.pieces.iter().zip(&parts) {
        let m = glam::DMat2::from_angle(piece.rotation);
        let place = |q: DVec2| m * (q * 40.0) + piece.shift;
        for i in r.start..=r.end {
            let (a, b) = (place(flat.points[2 * i]), place(flat.points[2 * i + 1]));
            assert!(((b - a).length() - 40.0 * ruling(&s, i)).abs() <= 1e-9);
        }
    }
}
