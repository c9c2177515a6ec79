// One scene on one viewer: computes it for a set of parameters (through the scene's create(),
// which asks the core for ready buffers), shows it, swaps in the result of heavy work done in
// a worker, and drops results that a newer computation has superseded.
import { measured } from './timing.js';

/**
 * @typedef {object} SessionHooks
 * @property {(built: import('./scene.js').Built, final: boolean) => void} onBuilt
 * @property {(error: unknown) => void} onError
 * @property {(fraction: number | null) => void} onProgress   null when no work is pending
 */

export class SceneSession {
  /**
   * @param {import('./viewer.js').Viewer} viewer
   * @param {SessionHooks} hooks
   */
  constructor(viewer, hooks) {
    this.viewer = viewer;
    this.hooks = hooks;
    this.generation = 0;
    /** @type {import('./scene.js').Built | null} */
    this.built = null;
  }

  /**
   * Computes `scene` for `params` and shows it; returns the result (or null after an error,
   * which goes to `onError`, the previous picture staying on screen).
   * @param {import('./scene.js').Scene} scene
   * @param {import('./scene.js').Params} params
   * @param {import('./scene.js').Context} context
   * @param {{fit?: boolean}} [options]
   */
  show(scene, params, context, { fit = false } = {}) {
    const mine = ++this.generation;
    let built;
    try {
      built = measured('ruledlab:compute', () => scene.create(params, context));
    } catch (e) {
      this.hooks.onProgress(null);
      this.hooks.onError(e);
      return null;
    }
    this.built = built;
    this.viewer.show(built, { fit });
    this.hooks.onBuilt(built, !built.later);
    if (!built.later) {
      this.hooks.onProgress(null);
      return built;
    }
    this.hooks.onProgress(0);
    built
      .later((fraction) => {
        if (mine === this.generation) this.hooks.onProgress(fraction);
      })
      .then((done) => {
        if (mine !== this.generation) return;
        this.built = done;
        this.viewer.show(done);
        this.hooks.onBuilt(done, true);
      })
      .catch((e) => {
        if (mine === this.generation && !e?.superseded) this.hooks.onError(e);
      })
      .finally(() => {
        if (mine === this.generation) this.hooks.onProgress(null);
      });
    return built;
  }

  /**
   * Stops pending work (the view's Cancel): its result will be dropped, and the picture shown
   * meanwhile is replaced by what it says it is once the work is stopped (Built.cancelled).
   */
  cancel() {
    const shown = this.built;
    this.dispose();
    const stopped = shown?.later ? shown.cancelled : undefined;
    if (!stopped) return;
    this.built = stopped;
    this.viewer.show(stopped);
    this.hooks.onBuilt(stopped, true);
  }

  /** Forgets pending work (its result will be dropped). */
  dispose() {
    this.generation++;
    this.built = null;
  }
}
