// What a stage says to screen readers (its polite live region): a step in words when it happens
// ("ruling 5 moved"), and the readout in a sentence once an interaction ends — at most once a
// second, so that a slider dragged across its range is not read out value by value, and only
// when it says something new (a step that changes no number is not read out again).

/** Least time between two announcements of the readout (ms). */
const ANNOUNCE_EVERY = 1000;

export class Announcer {
  /**
   * @param {HTMLElement} status   the live region
   * @param {() => string | null} sentence   the readout now, in a sentence (null: nothing computed)
   */
  constructor(status, sentence) {
    this.status = status;
    this.sentence = sentence;
    this.last = 0;
    this.timer = 0;
  }

  /**
   * Says `text` now. A readout still waiting for its second is dropped: it would be said after
   * `text` and speak over it (an undo's readout over the snap of the drag that follows).
   */
  say(/** @type {string} */ text) {
    clearTimeout(this.timer);
    this.status.textContent = text;
  }

  /** Says the readout (after `prefix`, what the step did) once the last announcement is a second old. */
  announce(prefix = '') {
    clearTimeout(this.timer);
    const speak = () => {
      this.last = performance.now();
      const sentence = this.sentence();
      const text = [prefix, sentence ?? ''].filter(Boolean).join('. ');
      // (a live region given the text it holds would say it again)
      if (text && text !== this.status.textContent) this.say(text);
    };
    const wait = this.last + ANNOUNCE_EVERY - performance.now();
    if (wait <= 0) speak();
    else this.timer = window.setTimeout(speak, wait);
  }

  /** Forgets an announcement waiting for its second (a new figure is said instead). */
  cancel() {
    clearTimeout(this.timer);
  }

  dispose() {
    clearTimeout(this.timer);
  }
}
