// What the place a view runs in allows. A course system shows user content in sandboxed
// iframes (an opaque origin: no storage, no history entries, no cookies), as srcdoc or
// about:blank documents (no address of their own), without `allow="fullscreen"`, and behind a
// Content-Security-Policy of its own. Every use of such a facility goes through here and does
// without it where it is missing; the page says so only where the user asked for the missing
// thing (the book: guide/course-systems.md).

/**
 * Where this document is.
 * @typedef {object} Place
 * @property {boolean} address   it has an http(s) address that others can open (a link to it works)
 * @property {boolean} file      opened from disk (file://)
 * @property {boolean} framed    shown inside a frame of another page
 * @property {boolean} opaque    an opaque origin (a sandboxed frame without allow-same-origin)
 */

/** @returns {Place} */
export function place() {
  const protocol = globalThis.location?.protocol ?? '';
  let framed = false;
  try {
    framed = window.top !== window.self;
  } catch {
    framed = true;
  }
  return {
    address: protocol === 'http:' || protocol === 'https:',
    file: protocol === 'file:',
    framed,
    opaque: globalThis.origin === 'null',
  };
}

/**
 * A storage of the browser, or null where there is none (a sandboxed frame throws on the mere
 * access; a browser with storage disabled throws on use).
 * @param {'sessionStorage' | 'localStorage'} kind
 * @returns {Storage | null}
 */
function storage(kind) {
  try {
    const s = globalThis[kind];
    const probe = 'ruledlab.probe';
    s.setItem(probe, '1');
    s.removeItem(probe);
    return s;
  } catch {
    return null;
  }
}

/** The tab's session storage, or null. */
const session = () => storage('sessionStorage');

/** Whether this document can keep data in session storage. */
export function hasStorage() {
  return session() !== null;
}

/** A stored text, or null (also where there is no storage). */
export function stored(/** @type {string} */ key) {
  try {
    return session()?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/**
 * Keeps `value` under `key` (null: removes it); false where there is no storage or it is full.
 * @param {string} key
 * @param {string | null} value
 */
export function store(key, value) {
  const s = session();
  if (!s) return false;
  try {
    if (value === null) s.removeItem(key);
    else s.setItem(key, value);
    return true;
  } catch {
    return false;
  }
}

/**
 * Writes `hash` into the address bar as a new history entry (`push`) or in place of the
 * current one; false where the document cannot (a srcdoc or about:blank document, a sandbox
 * that forbids it): the state then lives only in the page.
 * @param {'push' | 'replace'} mode
 * @param {string} hash   with its "#"
 */
export function writeHistory(mode, hash) {
  try {
    if (mode === 'push') history.pushState(null, '', hash);
    else history.replaceState(null, '', hash);
    return true;
  } catch {
    return false;
  }
}

/** Whether the element may go full screen here (a frame needs `allow="fullscreen"`). */
export function canFullscreen(/** @type {Document} */ doc = document) {
  return doc.fullscreenEnabled === true && typeof doc.documentElement.requestFullscreen === 'function';
}

/** The browser's lasting storage (kept between visits), or null. */
const lasting = () => storage('localStorage');

/** A text kept between visits, or null (also where there is no storage). */
export function kept(/** @type {string} */ key) {
  try {
    return lasting()?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/** Keeps `value` under `key` between visits; false where there is no storage or it is full. */
export function keep(/** @type {string} */ key, /** @type {string} */ value) {
  const s = lasting();
  if (!s) return false;
  try {
    s.setItem(key, value);
    return true;
  } catch {
    return false;
  }
}

/** Forgets what is kept under `key` (nothing where there is no storage). */
export function forget(/** @type {string} */ key) {
  try {
    lasting()?.removeItem(key);
  } catch {}
}
