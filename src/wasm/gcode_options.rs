//! The options of a G-code program as JavaScript passes them (`GcodeOptions`: the
//! controller's dialect, the machine, the feeds and the safe moves), read into the core's
//! `PostOptions` for `ToolPath.export("gcode")` and `ToolPath.post`. No JS class.

use super::args::{self, fail_option, finite_option};
use crate::milling::{machine, post};
use serde::Deserialize;
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `ToolPath.export("gcode", …)` and `ToolPath.post`: the controller, the machine,
/// the feeds and the safe moves (docs/src/cam/gcode.md). Every option is optional.
#[derive(Deserialize, Default, Tsify)]
#[serde(default, rename_all = "camelCase")]
struct GcodeOptions {
    /// The controller's language: "linuxcnc" (default; rs274ngc), "heidenhain" (TNC Klartext)
    /// or "sinumerik" (Siemens 840D).
    #[tsify(optional)]
    dialect: Option<DialectName>,
    /// "machine" (default): X Y Z are machine coordinates computed with the machine's pivots and
    /// offsets (work offset 0); "tcp": tool-centre point, the controller does the kinematics
    /// (FUNCTION TCPM, TRAORI, a TCP kinematics on LinuxCNC), X Y Z the tip in part coordinates.
    #[tsify(optional)]
    mode: Option<ModeName>,
    /// A preset's name (default "table-table-ac") or a machine description (`Machine`).
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(
        type = "\"table-table-ac\" | \"table-table-bc\" | \"head-table-bc\" | \"head-head-ac\" | Machine",
        optional
    )]
    machine: JsValue,
    /// Feed at the tool tip, mm/min (default 1000); blocks that turn a rotary axis get inverse
    /// time (G93) so that the tip keeps it.
    #[tsify(optional)]
    feed: Option<f64>,
    /// Feed of the approach and retract along the tool axis, mm/min (default feed / 4).
    #[tsify(optional)]
    approach_feed: Option<f64>,
    /// Millimetres per model unit (default 1).
    #[tsify(optional)]
    scale: Option<f64>,
    /// Tool number, 1–99999 (default 1): T…, its length offset (G43 H…, D1, TOOL CALL).
    #[tsify(optional)]
    tool: Option<f64>,
    /// Spindle speed, 1/min (default 10000).
    #[tsify(optional)]
    spindle: Option<f64>,
    /// "flood" (default, M8), "mist" (M7) or "off".
    #[tsify(optional)]
    coolant: Option<CoolantName>,
    /// Work offset 1–6: G54–G59 (Sinumerik G54–G57, G505, G506; Heidenhain datum 1–6; default 1).
    #[tsify(optional)]
    work_offset: Option<f64>,
    /// Part height (mm above the part's zero) of the points on the first and last tool axes where
    /// the safe moves turn (default 25 mm above the highest tip plus the clearance).
    #[tsify(optional)]
    safe_height: Option<f64>,
    /// Distance along the tool axis covered at the approach feed, mm (default 5).
    #[tsify(optional)]
    clearance: Option<f64>,
    /// Largest deviation of the controller's linear interpolation from the path, mm (default
    /// 0.01): blocks beyond it are halved.
    #[tsify(optional)]
    tolerance: Option<f64>,
    /// Program name (Heidenhain, Sinumerik): letters, digits, _ (default "RULEDLAB").
    #[tsify(optional)]
    name: Option<String>,
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
pub(super) fn preset(func: &str, name: &str) -> Result<machine::Machine, JsValue> {
    machine::Machine::preset(name).ok_or_else(|| {
        let known: Vec<String> = machine::MACHINE_PRESETS.iter().map(|p| format!("\"{p}\"")).collect();
        fail_option(func, "machine", format!("machine: unknown preset \"{name}\", expected {}", known.join(", ")))
    })
}

/// The options of a program (`GcodeOptions`; `undefined` or `null` for the defaults).
pub(super) fn read_post_options(func: &'static str, options: JsValue) -> Result<post::PostOptions, JsValue> {
    let o: GcodeOptions = args::options(func, options)?;
    let d = post::PostOptions::default();
    let machine = if o.machine.is_undefined() || o.machine.is_null() {
        d.machine.clone()
    } else if let Some(name) = o.machine.as_string() {
        preset(func, &name)?
    } else {
        // arrays where arrays belong (serde-wasm-bindgen would say "Reflect.get called on non-object")
        let array = |v: &JsValue, key: &str, path: &str| -> Result<(), JsValue> {
            let inner = js_sys::Reflect::get(v, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED);
            if inner.is_undefined() || js_sys::Array::is_array(&inner) {
                Ok(())
            } else {
                Err(fail_option(func, path, format!("{path} must be an array, got {}", args::describe(&inner))))
            }
        };
        if o.machine.is_object() {
            for key in ["rotary", "travel", "partZero"] {
                array(&o.machine, key, &format!("machine.{key}"))?;
            }
            let rotary = js_sys::Reflect::get(&o.machine, &JsValue::from_str("rotary")).unwrap_or(JsValue::UNDEFINED);
            if js_sys::Array::is_array(&rotary) {
                for (k, axis) in js_sys::Array::from(&rotary).iter().enumerate() {
                    if axis.is_object() {
                        array(&axis, "pivot", &format!("machine.rotary[{k}].pivot"))?;
                    }
                }
            }
        }
        args::required(func, "machine", o.machine.clone(), &[])?
    };
    let integer = |name: &'static str, v: Option<f64>, default: u32| -> Result<u32, JsValue> {
        match finite_option(func, name, v)? {
            None => Ok(default),
            Some(x) if x.fract() == 0.0 && (0.0..=1e9).contains(&x) => Ok(x as u32),
            Some(x) => Err(fail_option(func, name, format!("{name}: must be an integer, got {x}"))),
        }
    };
    Ok(post::PostOptions {
        dialect: match o.dialect {
            None | Some(DialectName::Linuxcnc) => post::Dialect::LinuxCnc,
            Some(DialectName::Heidenhain) => post::Dialect::Heidenhain,
            Some(DialectName::Sinumerik) => post::Dialect::Sinumerik,
        },
        mode: match o.mode {
            None | Some(ModeName::Machine) => post::Mode::Machine,
            Some(ModeName::Tcp) => post::Mode::Tcp,
        },
        machine,
        feed: finite_option(func, "feed", o.feed)?.unwrap_or(d.feed),
        approach_feed: finite_option(func, "approachFeed", o.approach_feed)?,
        scale: finite_option(func, "scale", o.scale)?.unwrap_or(d.scale),
        tool: integer("tool", o.tool, d.tool)?,
        spindle: finite_option(func, "spindle", o.spindle)?.unwrap_or(d.spindle),
        coolant: match o.coolant {
            None | Some(CoolantName::Flood) => post::Coolant::Flood,
            Some(CoolantName::Mist) => post::Coolant::Mist,
            Some(CoolantName::Off) => post::Coolant::Off,
        },
        work_offset: integer("workOffset", o.work_offset, d.work_offset)?,
        safe_height: finite_option(func, "safeHeight", o.safe_height)?,
        clearance: finite_option(func, "clearance", o.clearance)?.unwrap_or(d.clearance),
        tolerance: finite_option(func, "tolerance", o.tolerance)?.unwrap_or(d.tolerance),
        name: o.name.unwrap_or(d.name),
    })
}
