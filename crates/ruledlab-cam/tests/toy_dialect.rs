//! A controller of one's own, written here alone through the public trait
//! (`ruledlab_cam::controller`): a toy language that writes the post's steps its own way, and a
//! toy ISO controller that hands its words to the shared ISO writer. Each posts the paper's
//! example and the wall of `jobs` with [`gcode_with`], and what the trait answers is what the
//! post does: the header's lines, the feed word's bound, the interpolation of the tool axis and
//! the unwinds it implies.
#![cfg(not(target_family = "wasm"))]

#[allow(dead_code)] // the blade is not posted here
mod jobs;

use glam::DVec3;
use ruledlab::{Scheme, Variant};
use ruledlab_cam::controller::{
    comment_lines, iso, number, Context, Controller, Iso, LinuxCnc, Mode, Op, Orientation, Rate, Sinumerik, Units,
    Waypoint, Words,
};
use ruledlab_cam::{
    example_tool_path, gcode, gcode_with, Dialect, Limit, Machine, Pose, PostOptions, Program, Tool, ToolEnd, ToolPath,
};

/// A toy language: `TOY <name>`, one line a step (`RAPID`/`FEED x y z | i j k`, the tool axis as
/// a vector), `# …` comments, a feed word of at most 5000 a minute.
struct Toy {
    orientation: Orientation,
}

fn at(t: &Waypoint) -> String {
    let v = |x: f64| number(x, false);
    format!("{} {} {} | {} {} {}", v(t.xyz.x), v(t.xyz.y), v(t.xyz.z), v(t.axis.x), v(t.axis.y), v(t.axis.z))
}

impl Controller for Toy {
    fn name(&self) -> &str {
        "a toy"
    }

    fn orientation(&self) -> Orientation {
        self.orientation
    }

    fn max_feed(&self) -> Option<f64> {
        Some(5000.0)
    }

    fn feed_words(&self, _: Mode) -> &'static str {
        "F the feed at the tip"
    }

    fn tcp_mode(&self, machine: &Machine) -> Vec<String> {
        vec![format!("mode: toy tool-centre point on {}", machine.rotary[0].name.letter())]
    }

    fn write(&self, ops: &[Op], c: &Context) -> String {
        let mut out = format!("TOY {}\n", c.name);
        for op in ops {
            let lines = match op {
                Op::Comment(text) => comment_lines(text).into_iter().map(|l| format!("# {l}")).collect(),
                Op::Rapid(t, _) => vec![format!("RAPID {}", at(t))],
                Op::Feed(t, Rate::PerMinute(f)) => vec![format!("FEED {} F{}", at(t), number(*f, false))],
                Op::Feed(t, Rate::Simultaneous { minutes, distance, .. }) => {
                    vec![format!("FEED {} F{}", at(t), number(distance / minutes, false))]
                }
                Op::Rotate(r) => vec![format!("TURN {} {}", number(r[0], false), number(r[1], false))],
                Op::Tcp(on) => vec![format!("TCP {}", if *on { "ON" } else { "OFF" })],
                Op::End => vec!["END".to_string()],
                _ => vec![],
            };
            for l in lines {
                out.push_str(&l);
                out.push('\n');
            }
        }
        out
    }
}

/// An ISO controller built on LinuxCNC's: every word as LinuxCNC says it (its header's too), but
/// blocks numbered N10, N20, … and its tool-centre point switched with `G43.4`.
struct NumberedIso;

impl Iso for NumberedIso {
    fn numbered(&self) -> bool {
        true
    }
    fn comment(&self, text: &str) -> String {
        LinuxCnc.comment(text)
    }
    fn start(&self, units: Units) -> &'static str {
        LinuxCnc.start(units)
    }
    fn tolerance(&self, chordal: f64, angular: f64) -> String {
        LinuxCnc.tolerance(chordal, angular)
    }
    fn work_offset(&self, k: u32) -> &'static str {
        LinuxCnc.work_offset(k)
    }
    fn tool_change(&self, tool: u32) -> Vec<String> {
        LinuxCnc.tool_change(tool)
    }
    fn retract(&self, z: &str) -> String {
        LinuxCnc.retract(z)
    }
    fn tcp(&self, on: bool) -> Vec<&'static str> {
        vec![if on { "G43.4 H1" } else { "G49" }]
    }
    fn g94_alone(&self) -> bool {
        LinuxCnc.g94_alone()
    }
}

impl Controller for NumberedIso {
    fn name(&self) -> &str {
        "a numbered ISO controller"
    }
    fn orientation(&self) -> Orientation {
        LinuxCnc.orientation()
    }
    fn feed_words(&self, mode: Mode) -> &'static str {
        LinuxCnc.feed_words(mode)
    }
    fn machine_mode(&self) -> String {
        LinuxCnc.machine_mode()
    }
    fn tcp_mode(&self, _: &Machine) -> Vec<String> {
        vec!["mode: tool-centre point - G43.4".into()]
    }
    fn write(&self, ops: &[Op], c: &Context) -> String {
        iso::program(self, ops, c)
    }
}

fn example() -> ToolPath {
    example_tool_path(7).unwrap().refine(Scheme::Variational { n: 12, variant: Variant::Coupled }, 2).unwrap()
}

fn post(path: &ToolPath, o: &PostOptions, c: &dyn Controller) -> Program {
    gcode_with(path, o, c, &mut |_| {}).unwrap()
}

/// The toy's program: its own first line, a line a step, one `FEED` a pose of the cut; the
/// header in its words where it speaks of the controller (its tool-centre point, its feed word),
/// the trait's default for machine coordinates.
#[test]
fn a_toy_dialect_writes_the_posts_steps_in_its_own_words() {
    let toy = Toy { orientation: Orientation::Angles };
    for mode in [Mode::Tcp, Mode::Machine] {
        let o = PostOptions { mode, scale: 10.0, name: "TOYJOB".into(), ..Default::default() };
        let p = post(&example(), &o, &toy);
        let lines: Vec<&str> = p.text.lines().collect();
        assert_eq!((lines[0], *lines.last().unwrap()), ("TOY TOYJOB", "END"));
        let mode_line = match mode {
            Mode::Tcp => "# mode: toy tool-centre point on A",
            Mode::Machine => {
                "# mode: machine coordinates - X Y Z are the machine position of the tip, the work offset must be 0"
            }
        };
        assert!(lines.contains(&mode_line), "{mode:?}");
        assert!(lines.iter().any(|l| l.contains(", F the feed at the tip, approach ")), "{mode:?}");
        let cut = lines.iter().position(|l| *l == "# cut").unwrap();
        let end = lines.iter().position(|l| *l == "# end of cut").unwrap();
        assert!(lines[cut + 1..end].iter().all(|l| l.starts_with("FEED ")));
        assert_eq!(end - cut - 1, p.poses.len() - 1);
        assert_eq!(lines.iter().filter(|l| l.starts_with("TCP ")).count(), if mode == Mode::Tcp { 2 } else { 0 });
    }
}

/// Its feed word's bound: a feed beyond it is refused by name, with the controller's name; one
/// at it posts.
#[test]
fn a_toy_dialects_feed_word_bounds_the_feed() {
    let toy = Toy { orientation: Orientation::Angles };
    let o = |feed| PostOptions { feed, scale: 10.0, ..Default::default() };
    let e = gcode_with(&example_tool_path(5).unwrap(), &o(5000.5), &toy, &mut |_| {}).unwrap_err();
    assert_eq!(e.to_string(), "feed: must be at most 5000 a minute for a toy, got 5000.5");
    assert!(gcode_with(&example_tool_path(5).unwrap(), &o(5000.0), &toy, &mut |_| {}).is_ok());
    // a registered dialect without a bound takes it
    assert!(gcode(&example_tool_path(5).unwrap(), &o(5000.5)).is_ok());
    // the feed word measured by the tip's distance (the trait's default) in the program's units:
    // a feed at most the bound is never slowed by it, in millimetres or in inches, short blocks
    // (the 33 poses of the example, 10 times smaller: blocks of about a millimetre) included
    for (units, feed) in [(Units::Mm, 300.0), (Units::Inch, 12.0)] {
        let o = PostOptions { feed, units, scale: 1.0, ..Default::default() };
        let p = gcode_with(&example_tool_path(33).unwrap(), &o, &toy, &mut |_| {}).unwrap();
        assert!(p.motion.iter().all(|b| b.limit != Limit::FeedWord), "{units:?} {feed}");
        assert!(p.motion.iter().any(|b| b.limit == Limit::Feed), "{units:?} {feed}: blocks at the feed");
    }
    // nor are blocks of 0.05 mm, which a fixed measure of 1 would slow (1/5000 min > 0.05/300
    // min), or at 500 in/min the distance in mm (0.05/5000 min > 0.05/12700 min)
    let short = ToolPath {
        poses: (0..11).map(|k| Pose { tip: DVec3::new(0.05 * k as f64, 0.0, 0.0), axis: DVec3::Z }).collect(),
        tool: Tool::new(3.0, 30.0, ToolEnd::Flat).unwrap(),
    };
    for (units, feed) in [(Units::Mm, 300.0), (Units::Inch, 500.0)] {
        let o = PostOptions { feed, units, ..Default::default() };
        let p = gcode_with(&short, &o, &toy, &mut |_| {}).unwrap();
        assert!(p.motion.iter().all(|b| b.limit == Limit::Feed), "{units:?}: {:?}", p.motion);
    }
}

/// The interpolation it names is the one the post checks and times: given the angles, the toy's
/// poses and axis values are LinuxCNC's; given the axis as a vector, Sinumerik's, and on the
/// wall, where the fork head's C unwinds, it turns with tool-centre-point control off as
/// Sinumerik does.
#[test]
fn a_toy_dialect_is_interpolated_and_unwinds_as_its_orientation_says() {
    let head = Machine::preset("head-head-ac").unwrap();
    let o = PostOptions { mode: Mode::Tcp, machine: head, feed: 1200.0, ..Default::default() };
    let wall = jobs::wall();
    for (orientation, dialect) in [(Orientation::Angles, Dialect::LinuxCnc), (Orientation::Vector, Dialect::Sinumerik)]
    {
        let toy = post(&wall, &o, &Toy { orientation });
        let theirs = gcode(&wall, &PostOptions { dialect, ..o.clone() }).unwrap();
        assert_eq!((&toy.poses, &toy.joints, &toy.unwound), (&theirs.poses, &theirs.joints, &theirs.unwound));
        assert!(toy.unwound.iter().any(Option::is_some));
        let steps: Vec<&str> = toy.text.lines().filter(|l| !l.starts_with('#')).collect();
        let turns: Vec<usize> = (0..steps.len()).filter(|&k| steps[k].starts_with("TURN ")).collect();
        // the first turn and the last go home; the unwinds lie between
        let unwinds = &turns[1..turns.len() - 1];
        assert!(!unwinds.is_empty());
        for &k in unwinds {
            let around = (steps[k - 1], steps[k + 1]);
            match orientation {
                Orientation::Vector => assert_eq!(around, ("TCP OFF", "TCP ON")),
                Orientation::Angles => assert!(around.0.starts_with("RAPID ") && around.1.starts_with("RAPID ")),
            }
        }
    }
}

/// The ISO writer is one function a controller calls with its words: a toy built on LinuxCNC's
/// words writes LinuxCNC's program but for its block numbers; under tool-centre-point control its
/// own `G43.4` and `G49`.
#[test]
fn a_toy_iso_controller_shares_the_iso_writer() {
    for preset in ["table-table-ac", "head-head-ac"] {
        let o = PostOptions { machine: Machine::preset(preset).unwrap(), scale: 10.0, ..Default::default() };
        let toy = post(&example(), &o, &NumberedIso);
        let linuxcnc = gcode(&example(), &PostOptions { dialect: Dialect::LinuxCnc, ..o.clone() }).unwrap();
        let mut n = 0;
        let unnumbered: String = toy
            .text
            .lines()
            .map(|l| match l.strip_prefix('N') {
                Some(rest) => {
                    n += 10;
                    let (number, block) = rest.split_once(' ').unwrap();
                    assert_eq!(number.parse::<u32>().unwrap(), n);
                    format!("{block}\n")
                }
                None => format!("{l}\n"),
            })
            .collect();
        assert_eq!(unnumbered, linuxcnc.text, "{preset}");
        let tcp = post(&example(), &PostOptions { mode: Mode::Tcp, ..o }, &NumberedIso);
        let blocks: Vec<&str> = tcp.text.lines().filter_map(|l| l.split_once(' ').map(|(_, b)| b)).collect();
        assert_eq!(blocks.iter().filter(|b| ["G43.4 H1", "G49"].contains(b)).count(), 2);
        assert!(tcp.text.contains("(mode: tool-centre point - G43.4)\n"));
    }
}

/// The shared ISO writer leaves inverse time (`G93`) before a rapid as each controller says: in
/// a `G94` block of its own for LinuxCNC, as a word of the rapid's block for Sinumerik. (The
/// post's own plans leave every cut with a feed move, so only a controller of one's own, or
/// ops of one's own, reach this.)
#[test]
fn a_rapid_after_inverse_time_leaves_it_as_the_controller_says() {
    let at = |x: f64| Waypoint { xyz: DVec3::new(x, 0.0, 0.0), rotary: [x, 0.0], axis: DVec3::Z };
    let ops = [
        Op::Feed(at(1.0), Rate::Simultaneous { minutes: 0.5, distance: 1.0, linear: 1.0, turn: 1.0 }),
        Op::Rapid(at(2.0), Words::All),
    ];
    let c = Context {
        letters: ["A", "C"],
        mode: Mode::Machine,
        name: "rapid".into(),
        bounds: (DVec3::ZERO, DVec3::ONE),
        units: Units::Mm,
    };
    let linuxcnc: Vec<String> = iso::program(&LinuxCnc, &ops, &c).lines().map(String::from).collect();
    assert_eq!(
        linuxcnc,
        ["G93 G1 X1.0000 Y0.0000 Z0.0000 A1.0000 C0.0000 F2.0000", "G94", "G0 X2.0000 Y0.0000 Z0.0000 A2.0000 C0.0000"]
    );
    let sinumerik: Vec<String> = iso::program(&Sinumerik, &ops, &c).lines().map(String::from).collect();
    assert_eq!(sinumerik.last().map(String::as_str), Some("N20 G94 G0 X2.0000 Y0.0000 Z0.0000 A2.0000 C0.0000"));
}
