// The H5P content type H5P.RuledlabExercise: one exercise, or a problem set of several, in a
// <ruled-view>, as H5P's question contract wants it — getScore, getMaxScore, getAnswerGiven,
// showSolutions, resetTask, getXAPIData, getCurrentState (the attempt, saved by H5P where the
// course system keeps state). The embed script (dist/ruledlab-embed.js) is the library's one file
// and registers the content type where H5P runs it (scripts/onefile/entry.js). H5P's parameters
// are checked as an exercise from anywhere: one that cannot be read is said in the element's
// place, in its language.
//
// What a course system records: Moodle's H5P activity makes a new attempt of every top-level
// xAPI statement with a result whose verb is "answered" or "completed"
// (mod/h5pactivity/classes/xapi/handler.php), and grades only attempts whose result says
// completion (mod/h5pactivity/classes/local/manager.php). So one attempt sends one statement:
// "answered", with the score (conditions met over the goals' conditions, summed over the
// exercises), completion and success, when every exercise is solved by the student's own checks
// or when she ends the attempt — not at every check, which would make each a graded attempt. A
// solution shown sends nothing and changes no score (showSolutions only shows); what is checked
// after it counts for nothing. resetTask (H5P's Retry) begins a new attempt.
import { say, taskLink } from '../task/format.js';
import { builtInTask } from '../task/builtin.js';
import { bestCheck, readAttempt } from '../task/attempt.js';
import { taskErrorText } from '../task/words.js';
import { drawTask, randomSeed, seedOf } from '../task/draw.js';
import { writeSolutionRule, readSolutionRule } from '../task/solution-rule.js';
import { translator, pickLanguage } from '../i18n/index.js';
import { H5P_HEIGHT, MAX_PACKAGE_TASKS, MAX_SEED } from '../limits.js';
import { h5pExercises } from './h5p-exercise.js';

const isObject = (/** @type {unknown} */ x) => typeof x === 'object' && x !== null && !Array.isArray(x);

/**
 * @typedef {import('../task/attempt.js').Attempt} Attempt
 * @typedef {import('../task/format.js').Task} Task
 */

/**
 * Registers the content type on `H5P` (the H5P core of the page it runs in) and returns it.
 * @param {any} H5P
 */
export function registerContentType(H5P) {
  if (H5P.RuledlabExercise) return H5P.RuledlabExercise;

  class RuledlabExercise extends H5P.EventDispatcher {
    /**
     * @param {any} params     content.json: { exercise, more, title, language, height, readers, draw }
     * @param {number | string} contentId
     * @param {any} [extras]   { previousState, metadata, … }
     */
    constructor(params, contentId, extras = {}) {
      super();
      this.params = isObject(params) ? params : {};
      this.contentId = contentId;
      /** @type {Task[]} */
      this.tasks = [];
      /** @type {unknown} */
      this.error = null;
      try {
        this.tasks = h5pExercises(this.params);
      } catch (e) {
        this.error = e;
      }
      // the attempt H5P saved (getCurrentState), read as anything that came from outside; the
      // first form held one exercise's attempt ({ attempt })
      const previous = isObject(extras?.previousState) ? extras.previousState : {};
      const stored = Array.isArray(previous.attempts) ? previous.attempts : [previous.attempt];
      /** @type {Array<Attempt | null>} each exercise's attempt */
      this.attempts = this.tasks.map((_, k) => readAttempt(stored[k] ?? null));
      this.at = Number.isInteger(previous.at) && previous.at >= 0 && previous.at < this.tasks.length ? previous.at : 0;
      /** @type {{raw: number, max: number} | null} what this attempt's statement recorded (null: not yet) */
      this.recorded =
        isObject(previous.recorded) && Number.isInteger(previous.recorded.raw)
          ? { raw: previous.recorded.raw, max: this.getMaxScore() }
          : null;
      const seeds = this.attempts.map((a) => a?.seed).filter((x) => Number.isInteger(x));
      /** the seed of the numbers drawn: the learner's (where the lecturer chose so), else this attempt's */
      this.seed =
        this.learnerSeed() ??
        (Number.isInteger(previous.seed) && previous.seed >= 0 && previous.seed <= MAX_SEED
          ? previous.seed
          : (seeds[0] ?? randomSeed()));
      /** @type {any} */
      this.view = null;
      /** @type {Attempt | null} an attempt to restore once the view shows its exercise */
      this.pending = this.attempts[this.at];
      /** @type {Record<string, HTMLElement>} */
      this.els = {};
    }

    /** The language: the content's, else the page's. */
    lang() {
      const l = this.params.language;
      return l === 'en' || l === 'de' ? l : pickLanguage(globalThis.document?.documentElement.lang || null);
    }

    /** The seed of exercise `k`'s numbers: the attempt's, or null where it draws none. */
    seedFor(/** @type {number} */ k) {
      return Object.keys(this.tasks[k]?.draw ?? {}).length ? this.seed : null;
    }

    /** The seed of a learner's numbers where the lecturer draws them per learner and H5P names her; else null. */
    learnerSeed() {
      /** @type {any} */
      let user = null;
      try {
        // (H5P plays content in a frame of the course page; its integration may be the parent's)
        user =
          /** @type {any} */ (globalThis).H5PIntegration?.user ??
          /** @type {any} */ (globalThis.parent)?.H5PIntegration?.user;
      } catch {}
      const id = String(user?.id ?? user?.mail ?? '');
      return this.params.draw === 'learner' && id ? seedOf(`${id}\u0000${this.contentId}`) : null;
    }

    /** Shows the exercises in `$container` (H5P's jQuery object or an element). */
    attach(/** @type {any} */ $container) {
      const box = /** @type {HTMLElement} */ ($container?.get?.(0) ?? $container?.[0] ?? $container);
      const doc = box.ownerDocument;
      box.classList.add('h5p-ruledlab');
      const i18n = translator(this.lang());
      const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
        Object.assign(doc.createElement(tag), props);
      if (!this.tasks.length) {
        const problem = el('p', {
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
      view.setAttribute('lang', this.lang());
      view.setAttribute('height', String(height >= 240 && height <= 4000 ? height : H5P_HEIGHT));
      if (readers.controls !== false) view.setAttribute('controls', '');
      if (readers.text === true) view.setAttribute('text', '');
      if (readers.edit !== false) view.setAttribute('editable', '');
      if (readers.leave === true) view.setAttribute('leave', '');
      const rule = writeSolutionRule(readSolutionRule(String(readers.solution ?? '')));
      if (rule) view.setAttribute('solution', rule);
      view.setAttribute('seed', String(this.seed));
      view.addEventListener('task-check', (/** @type {any} */ e) => this.changed(e.detail));
      view.addEventListener('task-solution', () => this.changed(null));
      view.addEventListener('scene-change', () => {
        const api = view.exercise;
        if (!api) return;
        // the attempt kept for this exercise, once it is there (once; a scene shown on the way waits)
        const attempt = this.pending;
        if (attempt && api.id === this.tasks[this.at]?.id) {
          this.pending = null;
          api.restore({ ...attempt, seed: this.seedFor(this.at) });
        }
        this.localize();
        this.safely(() => this.trigger('resize'));
      });
      this.view = view;
      // a problem set: its title and a menu of its exercises
      const heading = el('h2', { className: 'h5p-ruledlab-title' });
      const choose = el('label', { className: 'h5p-ruledlab-choose' });
      const picker = /** @type {HTMLSelectElement} */ (el('select', { name: 'h5p-ruledlab-task' }));
      choose.append(el('span'), picker);
      picker.addEventListener('change', () => this.open(Number(picker.value)));
      const status = el('p', { className: 'h5p-ruledlab-status' });
      status.setAttribute('role', 'status');
      const end = el('button', { type: 'button', className: 'h5p-ruledlab-end', name: 'h5p-ruledlab-end' });
      const confirm = el('div', { className: 'h5p-ruledlab-confirm', hidden: true });
      const confirmText = el('p');
      const yes = el('button', { type: 'button', name: 'h5p-ruledlab-end-yes' });
      const no = el('button', { type: 'button', name: 'h5p-ruledlab-end-no' });
      confirm.append(confirmText, yes, no);
      end.addEventListener('click', () => {
        confirm.hidden = false;
        no.focus();
      });
      no.addEventListener('click', () => {
        confirm.hidden = true;
        end.focus();
      });
      yes.addEventListener('click', () => {
        confirm.hidden = true;
        this.keep();
        this.send();
        status.focus();
      });
      status.tabIndex = -1;
      const note = el('p', { className: 'h5p-ruledlab-note', hidden: true });
      note.setAttribute('role', 'alert');
      this.els = { heading, choose, picker, status, end, confirm, confirmText, yes, no, note };
      box.replaceChildren(heading, choose, view, status, end, confirm, note);
      this.open(this.at, false);
    }

    /** Shows exercise `k` (its attempt restored once it is there). */
    open(/** @type {number} */ k, keep = true) {
      if (keep) this.keep();
      this.at = k;
      this.pending = this.attempts[k];
      this.view?.setAttribute(
        'task',
        taskLink(this.tasks[k], (id) => builtInTask(id) !== null),
      );
      this.localize();
    }

    /** The attempt at the exercise shown, as the view has it now, kept. */
    keep() {
      const attempt = this.view?.exercise?.attempt();
      if (attempt && this.view?.exercise?.id === this.tasks[this.at]?.id) this.attempts[this.at] = attempt;
    }

    /** The texts around the view, in the content's language, as the attempt stands. */
    localize() {
      const { heading, choose, status, end, confirmText, yes, no } = this.els;
      if (!heading) return;
      const picker = /** @type {HTMLSelectElement} */ (this.els.picker);
      const { t } = translator(this.lang());
      const title = String(this.params.title ?? '').slice(0, 200);
      heading.textContent = title;
      heading.hidden = !title;
      /** @type {HTMLElement} */ (choose.firstChild).textContent = `${t('course.exercise')} `;
      choose.hidden = this.tasks.length < 2;
      picker.replaceChildren(
        ...this.tasks.map((task, k) => {
          const best = bestCheck(this.attempts[k]);
          const mark = best && best.passed === best.of ? '✓ ' : '';
          const words = say(drawTask(task, this.seed).title, this.lang());
          return new Option(`${mark}${k + 1}. ${words}`, String(k));
        }),
      );
      picker.value = String(this.at);
      const raw = this.getScore();
      const max = this.getMaxScore();
      status.textContent = this.recorded
        ? t('course.h5pRecorded', { raw: this.recorded.raw, max })
        : t('course.h5pPending', { raw, max });
      end.textContent = t('course.end');
      end.hidden = !!this.recorded;
      confirmText.textContent = t('course.endConfirm', { raw, max });
      yes.textContent = t('course.endYes');
      no.textContent = t('course.endNo');
    }

    /** Runs a call into H5P; if H5P throws, says so under the exercise (the attempt stays). */
    safely(/** @type {() => void} */ call) {
      const note = this.els.note;
      try {
        call();
        if (note) note.hidden = true;
        return true;
      } catch (e) {
        if (note) {
          const i18n = translator(this.lang());
          note.hidden = false;
          note.textContent = i18n.t('course.h5pRefused', {
            detail: String(/** @type {Error} */ (e)?.message ?? e).slice(0, 200),
          });
        }
        return false;
      }
    }

    /** Whether every exercise is solved by a check of the student's own. */
    solved() {
      return this.tasks.every((_, k) => {
        const best = bestCheck(this.attempts[k]);
        return !!best && best.passed === best.of;
      });
    }

    /** The statement of this attempt: answered, with its score, completion and success. */
    statement() {
      const event = this.createXAPIEventTemplate('answered');
      const definition = event.getVerifiedStatementValue?.(['object', 'definition']);
      if (definition) {
        const title = String(this.params.title ?? '') || (this.tasks[0]?.title.en ?? this.tasks[0]?.title.de ?? '');
        definition.name = { 'en-US': title };
        definition.type = 'http://adlnet.gov/expapi/activities/cmi.interaction';
        definition.interactionType = 'other';
      }
      const raw = this.recorded?.raw ?? this.getScore();
      event.setScoredResult(raw, this.getMaxScore(), this, true, raw === this.getMaxScore());
      // what she typed (never what was expected), and her numbers drawn, per exercise
      event.data.statement.result.response = JSON.stringify(
        this.tasks.map((task, k) => ({ task: task.id, answers: this.attempts[k]?.answers ?? {}, seed: this.seed })),
      );
      return event;
    }

    /** Ends the attempt: its one statement sent (once), with the score as it stands. */
    send() {
      if (this.recorded) return;
      this.recorded = { raw: this.getScore(), max: this.getMaxScore() };
      this.safely(() => this.trigger(this.statement()));
      this.localize();
    }

    /** After a check (or a solution shown: `report` null): the attempt kept; sent once every exercise is solved. */
    changed(/** @type {import('../task/panel.js').TaskReport | null} */ report) {
      this.keep();
      if (report?.counted && this.solved()) this.send();
      this.localize();
    }

    /** Conditions met: each exercise's best check that counts, summed. */
    getScore() {
      return this.tasks.reduce((sum, _, k) => sum + (bestCheck(this.attempts[k])?.passed ?? 0), 0);
    }

    getMaxScore() {
      return this.tasks.reduce((sum, task) => sum + task.goal.length, 0);
    }

    getAnswerGiven() {
      return this.attempts.some((a) => bestCheck(a) !== null);
    }

    /** Shows the solution of the exercise shown, where it is offered; it records and scores nothing. */
    showSolutions() {
      this.view?.exercise?.showSolution();
      this.keep();
      this.localize();
    }

    /**
     * H5P's Retry: a new attempt. Numbers drawn per attempt are drawn anew; where they stay the
     * same (none drawn, or drawn per learner), a solution shown stays shown for them.
     */
    resetTask() {
      this.keep();
      const fresh = this.learnerSeed() === null;
      if (fresh) this.seed = randomSeed();
      /** @type {(a: Attempt | null) => Attempt} */
      const blank = (a) => ({
        seed: this.seed,
        params: {},
        input: null,
        answers: {},
        hints: 0,
        checks: [],
        shown: !!a?.shown,
      });
      this.attempts = this.attempts.map((a, k) =>
        a?.shown && (!fresh || !Object.keys(this.tasks[k].draw).length) ? blank(a) : null,
      );
      this.recorded = null;
      this.at = 0;
      this.pending = this.attempts[0];
      const view = this.view;
      if (view) {
        const link = taskLink(this.tasks[0], (id) => builtInTask(id) !== null);
        if (view.getAttribute('task') !== link || view.getAttribute('seed') !== String(this.seed)) {
          // (both at once: the element opens once, with both)
          view.setAttribute('seed', String(this.seed));
          view.setAttribute('task', link);
        } else {
          this.pending = null;
          view.exercise?.restore(blank(this.attempts[0]));
        }
      }
      this.localize();
    }

    getXAPIData() {
      return { statement: this.statement().data.statement };
    }

    /** What H5P saves for the student (where the course system keeps state): the attempt. */
    getCurrentState() {
      this.keep();
      return {
        v: 2,
        at: this.at,
        seed: this.seed,
        attempts: this.attempts.slice(0, MAX_PACKAGE_TASKS),
        ...(this.recorded ? { recorded: { raw: this.recorded.raw } } : {}),
      };
    }
  }
  H5P.RuledlabExercise = RuledlabExercise;
  return RuledlabExercise;
}
