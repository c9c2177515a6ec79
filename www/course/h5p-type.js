// The H5P content type H5P.RuledlabExercise: an exercise in a <ruled-view>, as H5P's question
// contract wants it — getScore, getMaxScore, getAnswerGiven, showSolutions, resetTask,
// getXAPIData, getCurrentState (the attempt, saved by H5P where the course system keeps state),
// and at each check an xAPI "answered" statement with the score (conditions met of the goal's),
// "completed" when first solved: what Moodle's and ILIAS's H5P activities record in the
// gradebook. The embed script (dist/ruledlab-embed.js) is the library's one file and registers
// the type where H5P runs it (scripts/onefile/entry.js). H5P's parameters are checked as an
// exercise from anywhere: one that cannot be read is said in the element's place, in its language.
import { taskLink } from '../task/format.js';
import { builtInTask } from '../task/builtin.js';
import { readAttempt } from '../task/attempt.js';
import { taskErrorText } from '../task/words.js';
import { translator, pickLanguage } from '../i18n/index.js';
import { H5P_HEIGHT } from '../limits.js';
import { h5pExercise } from './h5p-exercise.js';

const isObject = (/** @type {unknown} */ x) => typeof x === 'object' && x !== null && !Array.isArray(x);

/**
 * Registers the content type on `H5P` (the H5P core of the page it runs in) and returns it.
 * @param {any} H5P
 */
export function registerContentType(H5P) {
  if (H5P.RuledlabExercise) return H5P.RuledlabExercise;

  class RuledlabExercise extends H5P.EventDispatcher {
    /**
     * @param {any} params     content.json: { exercise, language, height, readers }
     * @param {number | string} contentId
     * @param {any} [extras]   { previousState, metadata, … }
     */
    constructor(params, contentId, extras = {}) {
      super();
      this.params = isObject(params) ? params : {};
      this.contentId = contentId;
      const previous = isObject(extras?.previousState) ? extras.previousState : null;
      /** the attempt H5P saved (getCurrentState), read as any that came from outside */
      this.previous = previous ? readAttempt(previous.attempt) : null;
      this.seed = this.previous?.seed ?? null;
      /** @type {import('../task/format.js').Task | null} */
      this.task = null;
      /** @type {unknown} */
      this.error = null;
      try {
        this.task = h5pExercise(this.params.exercise);
      } catch (e) {
        this.error = e;
      }
      /** @type {import('../task/panel.js').TaskReport | null} the latest check */
      this.report = null;
      /** @type {any} */
      this.view = null;
      /** @type {HTMLElement | null} */
      this.note = null;
      this.completed = false;
    }

    /** The language: the content's, else the page's. */
    lang() {
      const l = this.params.language;
      return l === 'en' || l === 'de' ? l : pickLanguage(globalThis.document?.documentElement.lang || null);
    }

    /** Shows the exercise in `$container` (H5P's jQuery object or an element). */
    attach(/** @type {any} */ $container) {
      const box = /** @type {HTMLElement} */ ($container?.get?.(0) ?? $container?.[0] ?? $container);
      const doc = box.ownerDocument;
      box.classList.add('h5p-ruledlab');
      const i18n = translator(this.lang());
      this.note = Object.assign(doc.createElement('p'), { className: 'h5p-ruledlab-note', hidden: true });
      this.note.setAttribute('role', 'status');
      if (!this.task) {
        const problem = Object.assign(doc.createElement('p'), {
          className: 'h5p-ruledlab-problem',
          textContent: i18n.t('course.h5pBroken', { reason: taskErrorText(this.error, i18n) }),
        });
        problem.setAttribute('role', 'alert');
        box.replaceChildren(problem);
        return;
      }
      const readers = isObject(this.params.readers) ? this.params.readers : {};
      const height = Number(this.params.height);
      const view = /** @type {import('../ruled-view.js').RuledView} */ (doc.createElement('ruled-view'));
      view.setAttribute(
        'task',
        taskLink(this.task, (id) => builtInTask(id) !== null),
      );
      view.setAttribute('lang', this.lang());
      view.setAttribute('height', String(height >= 240 && height <= 4000 ? height : H5P_HEIGHT));
      if (readers.controls !== false) view.setAttribute('controls', '');
      if (readers.text === true) view.setAttribute('text', '');
      if (readers.edit !== false) view.setAttribute('editable', '');
      if (this.seed !== null) view.setAttribute('seed', String(this.seed));
      view.addEventListener('task-check', (/** @type {any} */ e) => this.checked(e.detail));
      let restored = false;
      view.addEventListener('scene-change', () => {
        const api = view.exercise;
        if (!api) return;
        this.seed = api.seed;
        // the attempt H5P kept, once the exercise is there (once)
        if (!restored && this.previous) {
          restored = true;
          api.restore(this.previous);
        }
        this.safely(() => this.trigger('resize'));
      });
      this.view = view;
      box.replaceChildren(view, this.note);
    }

    /** Runs a call into H5P; if H5P throws, says so under the exercise (the attempt stays). */
    safely(/** @type {() => void} */ call) {
      try {
        call();
        return true;
      } catch (e) {
        if (this.note) {
          const i18n = translator(this.lang());
          this.note.hidden = false;
          this.note.textContent = i18n.t('course.h5pRefused', {
            detail: String(/** @type {Error} */ (e)?.message ?? e).slice(0, 200),
          });
        }
        return false;
      }
    }

    /** An xAPI statement with the score of `report` (verb: answered or completed). */
    statement(/** @type {string} */ verb, /** @type {import('../task/panel.js').TaskReport} */ report) {
      const event = this.createXAPIEventTemplate(verb);
      const definition = event.getVerifiedStatementValue?.(['object', 'definition']);
      if (definition) {
        const title = this.task?.title.en ?? this.task?.title.de ?? '';
        definition.name = { 'en-US': title };
        definition.type = 'http://adlnet.gov/expapi/activities/cmi.interaction';
        definition.interactionType = 'other';
      }
      event.setScoredResult(report.passed, report.of, this, true, report.solved);
      // what she typed (never what was expected), and her numbers drawn
      event.data.statement.result.response = JSON.stringify({ answers: report.answers, drawn: report.drawn });
      return event;
    }

    /** A check of the exercise: the answered statement (completed the first time it is solved). */
    checked(/** @type {import('../task/panel.js').TaskReport} */ report) {
      this.report = report;
      if (this.note && this.safely(() => this.trigger(this.statement('answered', report)))) this.note.hidden = true;
      if (report.solved && !this.completed) {
        this.completed = true;
        this.safely(() => this.trigger(this.statement('completed', report)));
      }
    }

    getScore() {
      return this.report?.passed ?? 0;
    }

    getMaxScore() {
      return this.task?.goal.length ?? 0;
    }

    getAnswerGiven() {
      return this.report !== null;
    }

    showSolutions() {
      const report = this.view?.exercise?.showSolution();
      if (report) this.report = report;
    }

    resetTask() {
      this.view?.exercise?.startOver();
      this.report = null;
      this.completed = false;
    }

    getXAPIData() {
      const report = this.report ?? {
        passed: 0,
        of: this.getMaxScore(),
        solved: false,
        answers: {},
        drawn: null,
        task: this.task?.id ?? '',
        title: '',
        conditions: [],
        seed: this.seed,
      };
      return { statement: this.statement('answered', report).data.statement };
    }

    /** What H5P saves for the student (where the course system keeps state): the attempt. */
    getCurrentState() {
      const attempt = this.view?.exercise?.attempt();
      return attempt ? { attempt } : this.previous ? { attempt: this.previous } : undefined;
    }
  }
  H5P.RuledlabExercise = RuledlabExercise;
  return RuledlabExercise;
}
