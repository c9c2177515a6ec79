// Waiting for the GPU without blocking the page: a fence after the work, looked at between tasks
// (its status is updated there; reading it does not wait for the GPU, unlike a read of pixels or
// the browser presenting a frame that is still being drawn).

/** How often the fence is looked at (ms), and for how long at most. */
const POLL = 8;
const LIMIT = 4000;

/**
 * Resolves once the GPU has done every command given to `gl` so far (at once where the context
 * has no fences or is lost; after LIMIT ms at most).
 * @param {WebGL2RenderingContext} gl
 * @returns {Promise<void>}
 */
export async function finished(gl) {
  if (gl.isContextLost()) return;
  const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl.flush();
  if (!fence) return;
  const until = performance.now() + LIMIT;
  try {
    while (
      !gl.isContextLost() &&
      gl.getSyncParameter(fence, gl.SYNC_STATUS) !== gl.SIGNALED &&
      performance.now() < until
    )
      await new Promise((resolve) => setTimeout(resolve, POLL));
  } finally {
    gl.deleteSync(fence);
  }
}
