//! The options of a G-code program as JavaScript passes them (`GcodeOptions`: the
//! controller's dialect, the machine, the job — units, tool, feeds, tolerances, stock — and the
//! safe moves), read into the core's `PostOptions` for `ToolPath.export("gcode")` and
//! `ToolPath.post`. No JS class.

use ruledlab_js::args::{self, fail_option, finite_option};

use js_sys::{Array, Object, Reflect};
use serde::Deserialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;
use wasm_bindgen::JsCast;

/// Options of `ToolPath.export("gcode", …)` and `ToolPath.post`: the controller, the machine,
/// the job and the safe moves (docs/src/cam/gcode.md). Every option is optional; lengths are in
/// the program's `units`.
#[derive(Deserialize, Default, Tsify)]
#[serde(default, rename_all = "camelCase")]
struct GcodeOptions {
    /// The controller's language: "linuxcnc" (default; rs274ngc), "heidenhain" (TNC Klartext)
    /// or "sinumerik" (Siemens 840D).
    #[tsify(optional)]
    dialect: Option<DialectName>,
    /// "machine" (default): X Y Z are machine coordinates computed with the machine's pivots and
    /// offsets (work offset 0); "tcp": tool-centre point, the controller does the kinematics
    /// (FUNCTION TCPM, TRAORI, LinuxCNC's switchable kinematics), X Y Z the tip in part
    /// coordinates.
    #[tsify(optional)]
    mode: Option<ModeName>,
    /// A preset's name (default "table-table-ac") or a machine description (`Machine`; every key
    /// at every depth checked).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(
        type = "\"table-table-ac\" | \"table-table-bc\" | \"head-table-bc\" | \"head-head-ac\" | Machine",
        optional
    )]
    machine: JsValue,
    /// The program's units, "mm" (default) or "inch"; every length of these options is in them.
    #[tsify(optional)]
    units: Option<UnitsName>,
    /// Feed at the tool tip, units/min (default 1000); slowed where the machine's axes cannot
    /// follow; blocks that turn a rotary axis get inverse time (G93) or the feed word the
    /// controller reads.
    #[tsify(optional)]
    feed: Option<f64>,
    /// Feed of the approach and retract along the tool axis, units/min (default feed / 4).
    #[tsify(optional)]
    approach_feed: Option<f64>,
    /// Units per model unit of the path (default 1).
    #[tsify(optional)]
    scale: Option<f64>,
    /// Tool number, 1–99999 (default 1): T…, its length offset (G43 H…, D1, TOOL CALL).
    #[tsify(optional)]
    tool: Option<f64>,
    /// Spindle speed, 1/min (default 10000).
    #[tsify(optional)]
    spindle: Option<f64>,
    /// The spindle's direction: "cw" (default, M3) or "ccw" (M4).
    #[tsify(optional)]
    direction: Option<DirectionName>,
    /// "flood" (default, M8), "mist" (M7) or "off".
    #[tsify(optional)]
    coolant: Option<CoolantName>,
    /// Work offset 1–6: G54–G59 (Sinumerik G54–G57, G505, G506; Heidenhain datum 1–6; default 1).
    #[tsify(optional)]
    work_offset: Option<f64>,
    /// Least part height (above the part's zero) of the points on the first and last tool axes
    /// where the safe moves turn (default 25 mm above the highest tip plus the clearance); raised
    /// where the stock, turned by the rotary axes, stands higher.
    #[tsify(optional)]
    safe_height: Option<f64>,
    /// Distance kept from the stock along the tool axis, covered at the approach feed (default 5
    /// mm, 0.2 inch).
    #[tsify(optional)]
    clearance: Option<f64>,
    /// The chordal tolerance: largest deviation of the controller's interpolation from the path,
    /// the tip's and the axis's times the tool length (default 0.01 mm, 0.0004 inch); blocks
    /// beyond it are halved.
    #[tsify(optional)]
    tolerance: Option<f64>,
    /// The angular tolerance: largest angle of the interpolated tool axis from the path's,
    /// degrees (default none).
    #[tsify(optional)]
    angular_tolerance: Option<f64>,
    /// Gauge length, spindle nose to tip: the length of the kinematics and of the controller's
    /// length offset (default the tool's length times the scale).
    #[tsify(optional)]
    gauge: Option<f64>,
    /// The tool holder, a cylinder ending at the gauge line: checked against the stock.
    #[tsify(optional)]
    holder: Option<HolderOptions>,
    /// The shank's radius, from the cutter up to the holder (default the tool's).
    #[tsify(optional)]
    shank: Option<f64>,
    /// The stock, a box in the part frame: [[xmin, ymin, zmin], [xmax, ymax, zmax]] (default the
    /// tips' box grown by 1 mm).
    #[tsify(optional)]
    stock: Option<[[f64; 3]; 2]>,
    /// Half-angle of the pole cone, degrees (default 1; 0: only the pole itself).
    #[tsify(optional)]
    pole_cone: Option<f64>,
    /// How the input the path was refined from numbers its poses: errors and warnings name its
    /// pose and line.
    #[tsify(optional)]
    input: Option<InputNumbering>,
    /// Program name (Heidenhain, Sinumerik): letters, digits, _ (default "RULEDLAB").
    #[tsify(optional)]
    name: Option<String>,
    /// The part's points the program is measured against (3 numbers per point, model units like
    /// the path): `post` then gives the deviation of the program as posted and the header states
    /// it.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array | Float32Array | number[]", optional)]
    target: JsValue,
}

/// A tool holder: radius and length (program units), down from the gauge line.
#[derive(Deserialize, Tsify)]
#[serde(deny_unknown_fields)]
struct HolderOptions {
    radius: f64,
    length: f64,
}

/// The numbering of the poses the path was refined from.
#[derive(Deserialize, Tsify)]
#[serde(deny_unknown_fields)]
struct InputNumbering {
    /// Poses of the path per input pose (2^steps of refinement).
    stride: f64,
    /// The 1-based line of each input pose in its file.
    #[serde(default)]
    #[tsify(optional)]
    lines: Vec<f64>,
}

/// The controller's language.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"linuxcnc\", \"heidenhain\" or \"sinumerik\"")]
enum DialectName {
    /// LinuxCNC (rs274ngc).
    Linuxcnc,
    /// Heidenhain TNC plain text.
    Heidenhain,
    /// Siemens Sinumerik 840D.
    Sinumerik,
}

/// Who does the kinematics.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"tcp\" or \"machine\"")]
enum ModeName {
    /// The controller (tool-centre point).
    Tcp,
    /// ruledlab (machine coordinates).
    Machine,
}

/// The program's units.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"mm\" or \"inch\"")]
enum UnitsName {
    /// Millimetres.
    Mm,
    /// Inches.
    Inch,
}

/// The spindle's direction.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"cw\" or \"ccw\"")]
enum DirectionName {
    /// Clockwise, M3.
    Cw,
    /// Counter-clockwise, M4.
    Ccw,
}

/// The coolant of the cut.
#[derive(Deserialize, Clone, Copy, Tsify)]
#[serde(rename_all = "kebab-case", expecting = "\"flood\", \"mist\" or \"off\"")]
enum CoolantName {
    /// M8.
    Flood,
    /// M7.
    Mist,
    /// None.
    Off,
}

/// The preset machine `name`, or an error naming the presets.
pub(super) fn preset(func: &str, name: &str) -> Result<ruledlab_cam::Machine, JsValue> {
    ruledlab_cam::Machine::preset(name).ok_or_else(|| {
        let known: Vec<String> = ruledlab_cam::MACHINE_PRESETS.iter().map(|p| format!("\"{p}\"")).collect();
        fail_option(func, "machine", format!("machine: unknown preset \"{name}\", expected {}", known.join(", ")))
    })
}

/// The edits (insert, delete, change one letter, swap two neighbours) that turn `a` into `b`.
fn distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for j in 0..=b.len() {
        d[0][j] = j;
    }
    for i in 1..=a.len() {
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            d[i][j] = (d[i - 1][j] + 1).min(d[i][j - 1] + 1).min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                d[i][j] = d[i][j].min(d[i - 2][j - 2] + 1);
            }
        }
    }
    d[a.len()][b.len()]
}

/// "unknown key; did you mean max?" (the known key fewest edits away, at most 2 or a third of
/// its length), or the keys there are.
fn unknown_key(path: &str, key: &str, known: &[&str]) -> String {
    let near = known
        .iter()
        .map(|k| (distance(&key.to_ascii_lowercase(), &k.to_ascii_lowercase()), *k))
        .filter(|(d, k)| *d <= 2.max(k.len() / 3))
        .min();
    match near {
        Some((_, k)) => format!("{path}: unknown key; did you mean {k}?"),
        None => format!("{path}: unknown key; the keys are {}", known.join(", ")),
    }
}

/// Every key of a machine description at every depth: an unknown one refused with its path
/// (`machine.rotary[0].maxx: unknown key; did you mean max?`).
fn check_machine_keys(func: &str, value: &JsValue) -> Result<(), JsValue> {
    let plain = |v: &JsValue| v.is_object() && !Array::is_array(v) && !v.is_function();
    let check = |object: &JsValue, path: &str, known: &[&str]| -> Result<(), JsValue> {
        for key in Object::keys(object.unchecked_ref::<Object>()).iter() {
            let key = key.as_string().unwrap_or_default();
            if !known.contains(&key.as_str()) {
                let at = format!("{path}.{key}");
                return Err(fail_option(func, &at, unknown_key(&at, &key, known)));
            }
        }
        Ok(())
    };
    if !plain(value) {
        return Ok(());
    }
    check(value, "machine", args::fields::<ruledlab_cam::Machine>())?;
    // arrays where arrays belong (serde-wasm-bindgen would say "Reflect.get called on non-object")
    for key in ["rotary", "travel", "partZero", "speed", "acceleration"] {
        let inner = Reflect::get(value, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED);
        if !(inner.is_undefined() || inner.is_null() || Array::is_array(&inner)) {
            let path = format!("machine.{key}");
            return Err(fail_option(func, &path, format!("{path} must be an array, got {}", args::describe(&inner))));
        }
    }
    let rotary = Reflect::get(value, &JsValue::from_str("rotary")).unwrap_or(JsValue::UNDEFINED);
    if Array::is_array(&rotary) {
        for (k, axis) in Array::from(&rotary).iter().enumerate() {
            if plain(&axis) {
                let path = format!("machine.rotary[{k}]");
                check(&axis, &path, args::fields::<ruledlab_cam::RotaryAxis>())?;
                let pivot = Reflect::get(&axis, &JsValue::from_str("pivot")).unwrap_or(JsValue::UNDEFINED);
                if !(pivot.is_undefined() || Array::is_array(&pivot)) {
                    let path = format!("{path}.pivot");
                    return Err(fail_option(
                        func,
                        &path,
                        format!("{path} must be an array, got {}", args::describe(&pivot)),
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The options of a program (`GcodeOptions`; `undefined` or `null` for the defaults).
pub(super) fn read_post_options(func: &'static str, options: JsValue) -> Result<ruledlab_cam::PostOptions, JsValue> {
    let o: GcodeOptions = if options.is_undefined() || options.is_null() {
        GcodeOptions::default()
    } else {
        let nested: [(&str, &'static [&'static str]); 2] =
            [("holder", args::fields::<HolderOptions>()), ("input", args::fields::<InputNumbering>())];
        args::required(func, "options", options, &nested)?
    };
    let units = match o.units {
        None | Some(UnitsName::Mm) => ruledlab_cam::Units::Mm,
        Some(UnitsName::Inch) => ruledlab_cam::Units::Inch,
    };
    // the defaults in the program's units (0.0004 in and 0.2 in for inches)
    let d = ruledlab_cam::PostOptions::defaults_in(units);
    let machine = if o.machine.is_undefined() || o.machine.is_null() {
        d.machine.clone()
    } else if let Some(name) = o.machine.as_string() {
        preset(func, &name)?
    } else {
        check_machine_keys(func, &o.machine)?;
        args::required(func, "machine", o.machine.clone(), &[])?
    };
    let integer = |name: &'static str, v: Option<f64>, default: u32| -> Result<u32, JsValue> {
        match finite_option(func, name, v)? {
            None => Ok(default),
            Some(x) if x.fract() == 0.0 && (0.0..=1e9).contains(&x) => Ok(x as u32),
            Some(x) => Err(fail_option(func, name, format!("{name}: must be an integer, got {x}"))),
        }
    };
    let numbering = match o.input {
        None => None,
        Some(n) => {
            let stride = integer("input.stride", Some(n.stride), 1)? as usize;
            let mut lines = Vec::with_capacity(n.lines.len());
            for l in n.lines {
                lines.push(integer("input.lines", Some(l), 0)? as usize);
            }
            Some(ruledlab_cam::Numbering { stride, lines })
        }
    };
    let target = if o.target.is_undefined() || o.target.is_null() {
        None
    } else {
        let flat = args::numbers(func, "target", &o.target)?;
        let points = ruledlab::points_from_flat(&flat).map_err(|e| fail_option(func, "target", e.to_string()))?;
        Some(points)
    };
    let finite3 = |name: &'static str, v: Option<[[f64; 3]; 2]>| -> Result<Option<[[f64; 3]; 2]>, JsValue> {
        if let Some(v) = v {
            for x in v.iter().flatten() {
                finite_option(func, name, Some(*x))?;
            }
        }
        Ok(v)
    };
    Ok(ruledlab_cam::PostOptions {
        dialect: match o.dialect {
            None | Some(DialectName::Linuxcnc) => ruledlab_cam::Dialect::LinuxCnc,
            Some(DialectName::Heidenhain) => ruledlab_cam::Dialect::Heidenhain,
            Some(DialectName::Sinumerik) => ruledlab_cam::Dialect::Sinumerik,
        },
        mode: match o.mode {
            None | Some(ModeName::Machine) => ruledlab_cam::Mode::Machine,
            Some(ModeName::Tcp) => ruledlab_cam::Mode::Tcp,
        },
        machine,
        units,
        feed: finite_option(func, "feed", o.feed)?.unwrap_or(d.feed),
        approach_feed: finite_option(func, "approachFeed", o.approach_feed)?,
        scale: finite_option(func, "scale", o.scale)?.unwrap_or(d.scale),
        tool: integer("tool", o.tool, d.tool)?,
        spindle: finite_option(func, "spindle", o.spindle)?.unwrap_or(d.spindle),
        direction: match o.direction {
            None | Some(DirectionName::Cw) => ruledlab_cam::SpindleDirection::Clockwise,
            Some(DirectionName::Ccw) => ruledlab_cam::SpindleDirection::CounterClockwise,
        },
        coolant: match o.coolant {
            None | Some(CoolantName::Flood) => ruledlab_cam::Coolant::Flood,
            Some(CoolantName::Mist) => ruledlab_cam::Coolant::Mist,
            Some(CoolantName::Off) => ruledlab_cam::Coolant::Off,
        },
        work_offset: integer("workOffset", o.work_offset, d.work_offset)?,
        safe_height: finite_option(func, "safeHeight", o.safe_height)?,
        clearance: finite_option(func, "clearance", o.clearance)?.unwrap_or(d.clearance),
        tolerance: finite_option(func, "tolerance", o.tolerance)?.unwrap_or(d.tolerance),
        angular_tolerance: finite_option(func, "angularTolerance", o.angular_tolerance)?,
        gauge: finite_option(func, "gauge", o.gauge)?,
        holder: match o.holder {
            None => None,
            Some(h) => Some(ruledlab_cam::Holder {
                radius: finite_option(func, "holder.radius", Some(h.radius))?.unwrap_or(h.radius),
                length: finite_option(func, "holder.length", Some(h.length))?.unwrap_or(h.length),
            }),
        },
        shank: finite_option(func, "shank", o.shank)?,
        stock: finite3("stock", o.stock)?,
        pole_cone: finite_option(func, "poleCone", o.pole_cone)?.unwrap_or(d.pole_cone),
        numbering,
        name: o.name.unwrap_or(d.name),
        target,
    })
}
