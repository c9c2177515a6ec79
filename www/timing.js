// User Timing of the page: marks and measures named "ruledlab:…" in the performance timeline,
// so the browser's performance panel and the page benchmark (bench/lighthouse.mjs) show where
// the time goes. The page sets ruledlab:wasm-compiled (core.js: the module compiled and
// instantiated), ruledlab:first-frame (viewer.js: the first frame of a scene drawn) and
// ruledlab:first-frame-presented (the next animation frame: the GPU's part of it done), and the
// measures ruledlab:compute (a scene's create(): the core and the buffers it returns),
// ruledlab:upload (buffers to the GPU, shaders compiled) and ruledlab:draw (a frame's draw
// calls); the core's own operations are measured by the bindings (ruledlab:core:…,
// src/wasm/timing.rs). Only the latest entry of each name stays in the timeline's buffer (a
// page that draws on every frame would otherwise fill it); a recorded trace keeps every one.

const timeline = typeof performance === 'object' && typeof performance.measure === 'function' ? performance : null;

/** Marks `name` now (once: a later mark of the same name replaces it). */
export function mark(/** @type {string} */ name) {
  if (!timeline) return;
  timeline.clearMarks(name);
  timeline.mark(name);
}

/**
 * Runs `work` and measures it as `name`; returns what it returns (and throws what it throws).
 * @template T
 * @param {string} name
 * @param {() => T} work
 * @returns {T}
 */
export function measured(name, work) {
  if (!timeline) return work();
  const start = timeline.now();
  try {
    return work();
  } finally {
    timeline.clearMeasures(name);
    timeline.measure(name, { start, end: timeline.now() });
  }
}
