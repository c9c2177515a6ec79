// A part of the page loaded when first used (Share, the exercise author). A load that failed —
// the connection dropped, or a new release replaced the file — is said, and tried again at the
// next use instead of failing for good (where the browser fetches a module that failed anew, as
// Chromium here does; one that remembers the failure until a reload is why the sentence also
// says to reload).

/**
 * `load`, called once and remembered; after a failure (said by `onError`, with the code
 * "not-loaded"), called again at the next use. The promise returned rejects on a failure.
 * @template T
 * @param {() => Promise<T>} load
 * @param {(error: Error) => void} onError
 * @returns {() => Promise<T>}
 */
export function lazy(load, onError) {
  /** @type {Promise<T> | null} */
  let loading = null;
  return () => {
    loading ??= load().catch((/** @type {unknown} */ e) => {
      loading = null;
      const error = Object.assign(new Error(`a part of the page could not be loaded: ${String(e)}`, { cause: e }), {
        code: 'not-loaded',
      });
      onError(error);
      throw error;
    });
    return loading;
  };
}
