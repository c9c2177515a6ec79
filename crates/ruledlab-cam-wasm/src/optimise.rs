//! `optimisePoses` for JavaScript: a tool path's poses optimised against the part's points
//! (`ruledlab_cam::optimise_poses`: the deviation of the path's sweep from the target in least
//! squares, the variational schemes' fairness keeping the poses smooth), with progress.

use crate::tool_path::ToolPath;
use ruledlab::{points_from_flat, Error};
use ruledlab_cam::tolerance::MAX_OPTIMISE_ROUNDS;
use ruledlab_cam::EnvelopeDeviation;
use ruledlab_js::args::{self, fail, finite_option, integer_option, numbers, to_js};
use ruledlab_js::timing::Measure;

use js_sys::Float64Array;
use serde::{Deserialize, Serialize};
use tsify_next::Tsify;
use wasm_bindgen::prelude::*;

/// Options of `optimisePoses`.
#[derive(Deserialize, Default, Tsify)]
#[serde(rename_all = "camelCase")]
struct OptimiseOptions {
    /// The fairness weight λ ≥ 0: how much the second differences of the tips and the axis ends
    /// weigh against the squared deviations of the target points (default 0.01).
    #[serde(default)]
    #[tsify(optional, type = "number")]
    fairness: Option<f64>,
    /// Most rounds (each one step tried; default 40, at most 1000).
    #[serde(default)]
    #[tsify(optional, type = "number")]
    rounds: Option<f64>,
}

/// The deviation of the target from a path's own sweep, model units.
#[derive(Serialize, Tsify)]
struct SweepDeviation {
    /// The deepest gouge (≤ 0).
    gouge: f64,
    /// The most material left (≥ 0).
    leave: f64,
    /// The root mean square.
    rms: f64,
    /// The deviation of largest size.
    largest: f64,
}

impl SweepDeviation {
    fn of(d: &EnvelopeDeviation) -> Self {
        SweepDeviation { gouge: d.gouge, leave: d.leave, rms: d.rms, largest: d.largest() }
    }
}

/// What `optimisePoses` gives.
#[derive(Serialize, Tsify)]
struct OptimiseResult {
    /// The optimised poses, 6 numbers each (tip x, y, z, unit axis i, j, k), as many as given:
    /// `ToolPath.fromPoses(poses, path.tool)` is the optimised path.
    #[serde(with = "serde_wasm_bindgen::preserve")]
    #[tsify(type = "Float64Array")]
    poses: Float64Array,
    /// The target's deviation from the given path's sweep (the tip on the chords, the axis on the
    /// arcs).
    before: SweepDeviation,
    /// The target's deviation from the optimised path's sweep.
    after: SweepDeviation,
    /// The energy (squared deviations and fairness) of the given and the optimised poses.
    energy: [f64; 2],
    /// Rounds taken: the steps tried, the refused ones among them.
    rounds: usize,
}

/// The poses of `path` optimised against `targets` (the part's points, 3 numbers each, model
/// units): the squared deviations of the points from the tool swept through the path, plus the
/// fairness of the poses, least (Levenberg–Marquardt). Start from the ruling-aligned poses of a
/// flank cut; measure what a machinist signs off with `post({ target })` of the path they give.
/// `onProgress(fraction)` is called as the rounds go on.
#[wasm_bindgen(js_name = optimisePoses, unchecked_return_type = "OptimiseResult")]
pub fn optimise_poses(
    path: &ToolPath,
    #[wasm_bindgen(unchecked_param_type = "Float64Array | Float32Array | number[]")] targets: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "OptimiseOptions")] options: JsValue,
    #[wasm_bindgen(unchecked_optional_param_type = "(fraction: number) => void")] on_progress: JsValue,
) -> Result<JsValue, JsValue> {
    const F: &str = "optimisePoses";
    let _measure = Measure::start(F);
    let t = points_from_flat(&numbers(F, "targets", &targets)?).map_err(|e| fail(F, e))?;
    if t.is_empty() {
        return Err(fail(F, Error::TooFew { what: "target points", got: 0, min: 1 }));
    }
    let o: OptimiseOptions = args::options(F, options)?;
    let defaults = ruledlab_cam::OptimiseOptions::default();
    let fairness = finite_option(F, "fairness", o.fairness)?.unwrap_or(defaults.fairness);
    let rounds = integer_option(F, "rounds", o.rounds, 0, MAX_OPTIMISE_ROUNDS)?.unwrap_or(defaults.rounds);
    let mut progress = args::progress_reporter(F, on_progress)?;
    let r = ruledlab_cam::optimise_poses(
        path.core(),
        &t,
        &ruledlab_cam::OptimiseOptions { fairness, rounds },
        &mut progress,
    )
    .map_err(|e| fail(F, e))?;
    let poses: Vec<f64> = r.path.poses.iter().flat_map(|p| [p.tip.to_array(), p.axis.to_array()]).flatten().collect();
    to_js(
        F,
        &OptimiseResult {
            poses: Float64Array::from(&poses[..]),
            before: SweepDeviation::of(&r.before),
            after: SweepDeviation::of(&r.after),
            energy: [r.energy.0, r.energy.1],
            rounds: r.rounds,
        },
    )
}
