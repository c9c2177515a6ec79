// The page's address: the view's state in the URL hash. A scene change is a new history entry
// (Back returns to the previous scene), a parameter or camera move replaces the current one,
// while a slider is dragged at most every 200 ms. Where the document cannot write its address
// (srcdoc, about:blank, some sandboxes) the state lives here, in memory, only; the one-file
// page starts from the state stored in it.
import { writeLink } from '../link.js';
import { writeHistory } from '../platform.js';
import { storedHash } from './onefile.js';

/** Least time between two writes of the address while a control moves (ms). */
const WRITE_EVERY = 200;

/**
 * @param {{ oneFile: boolean, state: () => Omit<import('../link.js').LinkState, 'notes'> | null }} options
 *   state: what is on screen now (null before a scene is shown)
 */
export function pageAddress({ oneFile, state }) {
  let timer = 0;
  let kept = '';
  return {
    /** The hash of the state to open: the address's, the one kept in memory, or the one-file page's own. */
    current() {
      return location.hash || kept || (oneFile ? `#${storedHash()}` : '');
    },
    /**
     * Writes what is on screen: `push` a new entry, `replace` the current one; `now` false waits
     * for a pause in the moves.
     * @param {'push' | 'replace'} mode
     * @param {boolean} [now]
     */
    save(mode, now = true) {
      clearTimeout(timer);
      const write = () => {
        const shown = state();
        if (!shown) return;
        const hash = `#${writeLink(shown)}`;
        if (hash === (location.hash || kept)) return;
        if (!writeHistory(mode, hash)) kept = hash;
      };
      if (now || mode === 'push') write();
      else timer = window.setTimeout(write, WRITE_EVERY);
    },
  };
}
