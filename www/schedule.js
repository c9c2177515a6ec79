// Long work split into turns of the event loop (the browser's "tasks"; in ruledlab a task is an
// exercise): between two turns the browser paints and answers the reader, so no turn of the
// page's start blocks it for long (a phone runs the same work several times slower than a
// desktop).

/**
 * Resolves in a later turn of the event loop (scheduler.yield where the browser has it: the rest
 * of the work then comes before other queued turns).
 * @returns {Promise<void>}
 */
export function nextTurn() {
  const scheduler = /** @type {{yield?: () => Promise<void>} | undefined} */ (
    /** @type {any} */ (globalThis).scheduler
  );
  if (typeof scheduler?.yield === 'function') return scheduler.yield();
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/** Resolves once the browser has painted what is on the page now (after its next frame). */
export function afterPaint() {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}
