// Loads the built package in Node the documented way: initSync with the wasm bytes — the teaching
// module, and the CAM module (`ruledlab/cam`) through www/cam.js, as a page starts it (the scenes
// that need it call cam()).
import { readFileSync } from 'node:fs';
import * as ruledlab from '../../pkg/ruledlab.js';
import { setCamSource, startCam } from '../../www/cam.js';

ruledlab.initSync({ module: readFileSync(new URL('../../pkg/ruledlab_bg.wasm', import.meta.url)) });
setCamSource(readFileSync(new URL('../../pkg/cam/ruledlab_cam_bg.wasm', import.meta.url)));

export default ruledlab;

/** The CAM module, started. */
export const cam = await startCam();

/**
 * `n` rulings of a named analytic surface (default ranges), the surface object freed.
 * @param {string} name @param {number} n @param {Parameters<ruledlab.AnalyticSurface['sample']>[1]} [options]
 */
export function sampled(name, n, options) {
  const analytic = ruledlab.AnalyticSurface.byName(name);
  const surface = analytic.sample(n, options);
  analytic.free();
  return surface;
}
