//! User Timing for the core's long operations: each measured call leaves a
//! `performance.measure("ruledlab:core:<operation>")` (e.g. `ruledlab:core:AnalyticSurface.sample`)
//! in the performance timeline of the page, worker or Node process that called it, so the
//! browser's performance panel and the page benchmark (`bench/lighthouse.mjs`) show the core's
//! time apart from drawing. Only the latest mark and measure of each name stay in the
//! timeline's buffer (a page that recomputes on every slider move would otherwise fill it); a
//! recorded trace keeps every one. Where the global has no User Timing, nothing is measured.
//!
//! The measured operations are the ones whose cost grows with the model: sampling, subdivision,
//! the invariants as fresh arrays, focal geometry, hidden lines, formulas, convergence and
//! sampling orders, tool paths and their programs. The zero-copy invariants
//! (`invariantsInto`, `invariantsInPlace`) are not: they exist for calls of a few
//! microseconds, which a measure (four calls into JavaScript) would slow down measurably.

use wasm_bindgen::{JsCast, JsValue};
use web_sys::Performance;

/// The prefix of every measure the bindings set.
pub const PREFIX: &str = "ruledlab:core:";

thread_local! {
    static PERFORMANCE: Option<Performance> = find();
}

/// The global's `performance`, if it has User Timing.
pub fn find() -> Option<Performance> {
    let value = js_sys::Reflect::get(&js_sys::global(), &JsValue::from_str("performance")).ok()?;
    let callable = |name: &str| js_sys::Reflect::get(&value, &JsValue::from_str(name)).is_ok_and(|f| f.is_function());
    ["mark", "measure", "clearMarks", "clearMeasures"].iter().all(|name| callable(name)).then(|| value.unchecked_into())
}

/// A measured call: `let _measure = Measure::start(F);` marks its start; the measure is set
/// when the guard is dropped, at the end of the call (an error return included).
pub struct Measure(Option<String>);

impl Measure {
    /// Marks the start of `operation` (the export's name, as in its error messages).
    pub fn start(operation: &str) -> Measure {
        Measure(PERFORMANCE.with(|performance| {
            let performance = performance.as_ref()?;
            let name = format!("{PREFIX}{operation}");
            performance.mark(&name).ok()?;
            Some(name)
        }))
    }
}

impl Drop for Measure {
    fn drop(&mut self) {
        let Some(name) = self.0.take() else { return };
        PERFORMANCE.with(|performance| {
            if let Some(performance) = performance {
                performance.clear_measures_with_measure_name(&name);
                // from the latest mark of the same name (marks and measures are apart)
                let _ = performance.measure_with_start_mark(&name, &name);
                performance.clear_marks_with_mark_name(&name);
            }
        });
    }
}
