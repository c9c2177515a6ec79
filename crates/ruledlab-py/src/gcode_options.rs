//! The options of a G-code program as Python passes them (the keyword arguments of
//! `ToolPath.export("gcode", …)` and `ToolPath.post(…)`, read by name from one list), read into `ruledlab_cam::PostOptions`,
//! as `crates/ruledlab-cam-wasm/src/gcode_options.rs` reads JavaScript's `GcodeOptions` (the
//! book's "G-code and its dialects"): the same names in snake_case, every one optional. A machine
//! is a preset's name or its JSON description as a dict (keys as the book writes them:
//! `partZero`), every key at every depth checked.

use crate::args::{self, describe};
use crate::arrays;
use crate::error::fail_option;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use ruledlab_cam::{Coolant, Dialect, Holder, Machine, Mode, Numbering, PostOptions, SpindleDirection, Units};

/// The options' names, as the book's "G-code and its dialects" lists them (`target`: the
/// part's points, (M, 3) in model units, the program measured against them).
pub const POST_OPTIONS: [&str; 24] = [
    "dialect",
    "mode",
    "machine",
    "units",
    "feed",
    "approach_feed",
    "scale",
    "tool",
    "spindle",
    "direction",
    "coolant",
    "work_offset",
    "safe_height",
    "clearance",
    "tolerance",
    "angular_tolerance",
    "gauge",
    "holder",
    "shank",
    "stock",
    "pole_cone",
    "input",
    "name",
    "target",
];

/// The keyword arguments of a program, as given: each of [`POST_OPTIONS`] or left out (a
/// keyword not among them refused with the list: [`args::keywords`]).
pub struct PostArgs<'py> {
    values: Vec<Option<Bound<'py, PyAny>>>,
}

impl<'py> PostArgs<'py> {
    /// The options among `kwargs`.
    pub fn read(func: &str, kwargs: Option<&Bound<'py, PyDict>>) -> PyResult<Self> {
        Ok(PostArgs { values: args::keywords(func, kwargs, &POST_OPTIONS)? })
    }

    /// The option `name` (one of [`POST_OPTIONS`]), if given.
    fn get(&self, name: &str) -> Option<&Bound<'py, PyAny>> {
        let i = POST_OPTIONS.iter().position(|k| *k == name).unwrap_or_else(|| unreachable!("an option's name"));
        self.values[i].as_ref()
    }

    /// Whether any option was given.
    pub fn any(&self) -> bool {
        self.values.iter().any(Option::is_some)
    }
}

/// The preset machine `name`, or an error naming the presets.
pub fn preset(func: &str, name: &str) -> PyResult<Machine> {
    Machine::preset(name).ok_or_else(|| {
        let known: Vec<String> = ruledlab_cam::MACHINE_PRESETS.iter().map(|p| format!("\"{p}\"")).collect();
        fail_option(func, "machine", format!("machine: unknown preset \"{name}\", expected {}", known.join(", ")))
    })
}

/// A machine: a preset's name, or a description (a dict read by serde, unknown keys refused
/// with their path).
fn machine(func: &str, value: &Bound<'_, PyAny>) -> PyResult<Machine> {
    if let Ok(name) = value.cast::<PyString>() {
        return preset(func, &name.to_string());
    }
    if !value.is_instance_of::<PyDict>() {
        return Err(fail_option(
            func,
            "machine",
            format!("machine must be a preset's name or a machine description (a dict), got {}", describe(value)),
        ));
    }
    let mut reader = pythonize::Depythonizer::from_object(value);
    serde_path_to_error::deserialize(&mut reader).map_err(|e| {
        let path = e.path().to_string();
        let at = if path == "." { "machine".to_string() } else { format!("machine.{path}") };
        fail_option(func, &at, format!("{at}: {}", e.into_inner()))
    })
}

/// A number option that must be a non-negative integer (tool number, work offset, stride).
fn whole(func: &str, name: &str, value: Option<&Bound<'_, PyAny>>, default: u32) -> PyResult<u32> {
    Ok(args::optional_integer(func, name, value, 0, 1_000_000_000, default as usize)? as u32)
}

/// A dict with exactly `keys` (others refused), its values.
fn fields<'py>(
    func: &str,
    name: &str,
    value: &Bound<'py, PyAny>,
    keys: &[&str],
) -> PyResult<Vec<Option<Bound<'py, PyAny>>>> {
    let dict = value.cast::<PyDict>().map_err(|_| {
        fail_option(func, name, format!("{name} must be a dict {{{}}}, got {}", keys.join(", "), describe(value)))
    })?;
    for key in dict.keys() {
        let key = key.str()?.to_string();
        if !keys.contains(&key.as_str()) {
            return Err(fail_option(
                func,
                &format!("{name}.{key}"),
                format!("{name}: unknown key \"{key}\"; the keys are {}", keys.join(", ")),
            ));
        }
    }
    keys.iter().map(|k| dict.get_item(k)).collect()
}

/// The options of a program from the keyword arguments.
pub fn read_post_options(func: &str, a: &PostArgs<'_>) -> PyResult<PostOptions> {
    let units = match args::choice(func, "units", a.get("units"), &["mm", "inch"])? {
        None | Some(0) => Units::Mm,
        _ => Units::Inch,
    };
    // the defaults of the program's units (an inch program: 0.0004 in, 0.2 in)
    let d = PostOptions::defaults_in(units);
    let number = |name: &str, v| args::optional_number(func, name, v);
    let holder = match a.get("holder") {
        None => None,
        Some(h) => {
            let f = fields(func, "holder", h, &["radius", "length"])?;
            let part = |k: usize, name: &str| -> PyResult<f64> {
                match &f[k] {
                    Some(v) => args::number(func, &format!("holder.{name}"), v),
                    None => Err(fail_option(func, &format!("holder.{name}"), format!("holder.{name} is required"))),
                }
            };
            Some(Holder { radius: part(0, "radius")?, length: part(1, "length")? })
        }
    };
    let numbering = match a.get("input") {
        None => None,
        Some(i) => {
            let f = fields(func, "input", i, &["stride", "lines"])?;
            let Some(stride) = &f[0] else {
                return Err(fail_option(func, "input.stride", "input.stride is required"));
            };
            let stride = whole(func, "input.stride", Some(stride), 1)? as usize;
            let mut lines = Vec::new();
            if let Some(l) = &f[1] {
                let given = arrays::numbers(func, "input.lines", l)?;
                arrays::vector(func, "input.lines", &given)?;
                for &x in given.slice() {
                    if !(x.fract() == 0.0 && (0.0..=1e9).contains(&x)) {
                        return Err(fail_option(
                            func,
                            "input.lines",
                            format!("input.lines: must be integers, got {x}"),
                        ));
                    }
                    lines.push(x as usize);
                }
            }
            Some(Numbering { stride, lines })
        }
    };
    let stock = match a.get("stock") {
        None => None,
        Some(s) => {
            let given = arrays::numbers(func, "stock", s)?;
            if given.shape() != [2, 3] {
                return Err(fail_option(
                    func,
                    "stock",
                    format!(
                        "stock must be [[xmin, ymin, zmin], [xmax, ymax, zmax]], shape (2, 3), got {}",
                        arrays::shape_text(given.shape())
                    ),
                ));
            }
            let x = given.slice();
            if let Some(bad) = x.iter().find(|x| !x.is_finite()) {
                return Err(fail_option(func, "stock", format!("stock must be finite, got {bad}")));
            }
            Some([[x[0], x[1], x[2]], [x[3], x[4], x[5]]])
        }
    };
    Ok(PostOptions {
        dialect: match args::choice(func, "dialect", a.get("dialect"), &["linuxcnc", "heidenhain", "sinumerik"])? {
            None | Some(0) => Dialect::LinuxCnc,
            Some(1) => Dialect::Heidenhain,
            _ => Dialect::Sinumerik,
        },
        mode: match args::choice(func, "mode", a.get("mode"), &["machine", "tcp"])? {
            None | Some(0) => Mode::Machine,
            _ => Mode::Tcp,
        },
        machine: match a.get("machine") {
            None => d.machine.clone(),
            Some(m) => machine(func, m)?,
        },
        units,
        feed: number("feed", a.get("feed"))?.unwrap_or(d.feed),
        approach_feed: number("approach_feed", a.get("approach_feed"))?,
        scale: number("scale", a.get("scale"))?.unwrap_or(d.scale),
        tool: whole(func, "tool", a.get("tool"), d.tool)?,
        spindle: number("spindle", a.get("spindle"))?.unwrap_or(d.spindle),
        direction: match args::choice(func, "direction", a.get("direction"), &["cw", "ccw"])? {
            None | Some(0) => SpindleDirection::Clockwise,
            _ => SpindleDirection::CounterClockwise,
        },
        coolant: match args::choice(func, "coolant", a.get("coolant"), &["flood", "mist", "off"])? {
            None | Some(0) => Coolant::Flood,
            Some(1) => Coolant::Mist,
            _ => Coolant::Off,
        },
        work_offset: whole(func, "work_offset", a.get("work_offset"), d.work_offset)?,
        safe_height: number("safe_height", a.get("safe_height"))?,
        clearance: number("clearance", a.get("clearance"))?.unwrap_or(d.clearance),
        tolerance: number("tolerance", a.get("tolerance"))?.unwrap_or(d.tolerance),
        angular_tolerance: number("angular_tolerance", a.get("angular_tolerance"))?,
        gauge: number("gauge", a.get("gauge"))?,
        holder,
        shank: number("shank", a.get("shank"))?,
        stock,
        pole_cone: number("pole_cone", a.get("pole_cone"))?.unwrap_or(d.pole_cone),
        numbering,
        name: args::optional_text(func, "name", a.get("name"))?.unwrap_or(d.name),
        target: match a.get("target") {
            None => None,
            Some(t) => {
                let given = arrays::numbers(func, "target", t)?;
                let n = arrays::rows(func, "target", &given, 3, "point")?;
                let points = ruledlab::points_from_flat(given.slice()).map_err(|e| {
                    crate::error::fail_input(
                        func,
                        e,
                        &crate::layout::Layout::One { name: "target", shape: vec![n, 3], lead: 1 },
                    )
                })?;
                Some(points)
            }
        },
    })
}
