// The SCORM runtime of a course system, as a package's page talks to it (page/course.js): found
// the standard way (the `API_1484_11` object of SCORM 2004 or the `API` of SCORM 1.2 in this
// window, its parents, then its opener's), and what the page records there — score (raw, min,
// max: the share of conditions met in percent; scaled in 2004), status, one objective per
// exercise, one interaction per condition (its id, correct, wrong or — the solution shown —
// neutral, what the student typed or the value she reached, never the expected value), the time
// spent, and the attempt in suspend_data; committed on every check, terminated when the page goes.
//
// The status keeps the attempt open until the student is done — every exercise solved, or she
// ends the attempt: SCORM 1.2's lesson_status stays "incomplete" (2004: completion_status
// "incomplete", success_status "unknown") until then, because a course system treats "passed",
// "failed" and "completed" as a finished attempt and opens the next launch for review (Moodle:
// mod/scorm/lib.php, scorm_check_mode; ILIAS: SCORM1_2standard.js, LMSInitialize). The score is
// written with every check meanwhile (Moodle grades score.raw whatever the status:
// locallib.php, scorm_grade_user_attempt). An attempt the course system opens for review or
// browsing (lesson_mode / cmi.mode) or without credit is read, shown and said, and nothing that
// counts is written to it (Moodle saves whatever a package writes, even in review:
// mod/scorm/datamodel.php). Every call is guarded: a runtime that throws or answers "false" —
// its Initialize too — is said in the page (its error code and text), and the student's work
// stays in the page and goes again with her next check.
import {
  SCORM_FRAMES,
  SCORM12_RESPONSE,
  SCORM12_SUSPEND,
  SCORM2004_DESCRIPTION,
  SCORM2004_RESPONSE,
  SCORM2004_SUSPEND,
} from '../limits.js';

/**
 * @typedef {'1.2' | '2004'} Version
 *
 * What the course system is told of one exercise.
 * @typedef {object} TaskRecord
 * @property {string} id
 * @property {string} title
 * @property {number} of          conditions of its goal
 * @property {{passed: number, of: number} | null} best   its best check that counts (null: none yet)
 * @property {Array<{id: string, holds: boolean, shown: boolean, response: string, numeric: boolean, description: string}> | null} conditions
 *   how each condition stood at its latest check (null: nothing new to record); `shown`: the
 *   check was the solution shown or came after it, and counts for nothing (result "neutral")
 *
 * How the course system opened the attempt.
 * @typedef {object} Launch
 * @property {string} suspend   suspend_data
 * @property {string} entry     "ab-initio", "resume" or ""
 * @property {string} learner   the learner's name
 * @property {string} learnerId the learner's id
 * @property {'normal' | 'review' | 'browse'} mode
 * @property {boolean} credit   whether the attempt counts (cmi.core.credit / cmi.credit "credit")
 *
 * @typedef {object} Problem   what went wrong in a call
 * @property {string} call     the call ("LMSSetValue cmi.core.score.raw")
 * @property {string} code     the runtime's error code ("" when it threw)
 * @property {string} text     its error text, or the exception's message
 */

/**
 * The runtime of `version` (or, failing that, the other) in `win`, its parents, its opener and
 * the opener's parents; null where there is none (the page works on, recording nothing).
 * @param {Window} win
 * @param {Version} [prefer]
 * @returns {{version: Version, api: any} | null}
 */
export function findRuntime(win, prefer = '1.2') {
  const look = (/** @type {any} */ w, /** @type {string} */ name) => {
    for (let k = 0; w && k < SCORM_FRAMES; k++) {
      try {
        if (w[name]) return w[name];
        if (w.parent === w) return null;
        w = w.parent;
      } catch {
        // a window of another origin: the search stops there
        return null;
      }
    }
    return null;
  };
  const names = /** @type {Array<[string, Version]>} */ ([
    ['API', '1.2'],
    ['API_1484_11', '2004'],
  ]);
  if (prefer === '2004') names.reverse();
  for (const [name, version] of names) {
    let api = look(win, name);
    try {
      api ??= win.opener ? look(win.opener, name) : null;
    } catch {}
    if (api && typeof api === 'object') return { version, api };
  }
  return null;
}

/** A decimal as SCORM writes it (no exponent; at most 7 decimals, no trailing zeros). */
export function decimal(/** @type {number} */ x) {
  if (!Number.isFinite(x) || Math.abs(x) >= 1e10) return '';
  return x.toFixed(7).replace(/\.?0+$/, '') || '0';
}

/**
 * Seconds as SCORM 1.2's CMITimespan (HHHH:MM:SS.SS) or 2004's ISO 8601 duration (PT…H…M…S).
 * Always two decimals: 1.2 allows one or two, but Moodle's AddTime reads the fraction as
 * hundredths (".5" would count as 5/100 s: mod/scorm/datamodels/scorm_12.js).
 */
export function timespan(/** @type {number} */ seconds, /** @type {Version} */ version) {
  const s = Math.max(0, seconds);
  const h = Math.floor(s / 3600);
  const m = Math.floor((s % 3600) / 60);
  const rest = (s % 60).toFixed(2);
  if (version === '2004') return `PT${h}H${m}M${rest}S`;
  return `${String(h).padStart(4, '0')}:${String(m).padStart(2, '0')}:${rest.padStart(5, '0')}`;
}

/** A moment as SCORM 1.2's CMITime (hh:mm:ss, local) or 2004's timestamp (YYYY-MM-DDThh:mm:ss). */
export function moment(/** @type {Date} */ d, /** @type {Version} */ version) {
  const p = (/** @type {number} */ n) => String(n).padStart(2, '0');
  const time = `${p(d.getHours())}:${p(d.getMinutes())}:${p(d.getSeconds())}`;
  return version === '2004' ? `${d.getFullYear()}-${p(d.getMonth() + 1)}-${p(d.getDate())}T${time}` : time;
}

/**
 * What the page writes after a check, in order: the score, the status, the objectives, the
 * interactions of the conditions checked (at the indices `order` gives them: appended in the
 * order they were first checked, as SCORM wants them), and the time. The status stays open
 * (1.2 "incomplete"; 2004 "incomplete" and "unknown") until every exercise is solved or `ended`
 * (the student ended the attempt).
 * @param {Version} version
 * @param {TaskRecord[]} tasks
 * @param {string[]} order    the interactions' ids so far, in their order (new ones are appended)
 * @param {{seconds: number, now: Date, ended?: boolean}} time
 * @returns {Array<[string, string]>}
 */
export function scormValues(version, tasks, order, { seconds, now, ended = false }) {
  /** @type {Array<[string, string]>} */
  const out = [];
  const raw = tasks.reduce((s, t) => s + (t.best?.passed ?? 0), 0);
  const max = tasks.reduce((s, t) => s + t.of, 0);
  const solved = tasks.every((t) => t.best && t.best.passed === t.of);
  const done = solved || ended;
  const share = (/** @type {number} */ passed, /** @type {number} */ of) => (of ? passed / of : 0);
  // the score is the share of conditions met, in percent (0 to 100: SCORM 1.2's range, and what
  // course systems that grade by score.raw expect); each exercise's own count is its objective's
  const percent = decimal(Math.round(10000 * share(raw, max)) / 100);
  if (version === '1.2') {
    out.push(['cmi.core.score.min', '0'], ['cmi.core.score.max', '100'], ['cmi.core.score.raw', percent]);
    out.push(['cmi.core.lesson_status', solved ? 'passed' : done ? 'failed' : 'incomplete']);
  } else {
    out.push(['cmi.score.min', '0'], ['cmi.score.max', '100'], ['cmi.score.raw', percent]);
    out.push(['cmi.score.scaled', decimal(share(raw, max))]);
    out.push(['cmi.completion_status', done ? 'completed' : 'incomplete']);
    out.push(['cmi.success_status', solved ? 'passed' : done ? 'failed' : 'unknown']);
    // (what is solved of the whole; 1 only once the attempt is done)
    const progress = done ? 1 : Math.min(share(raw, max), 0.99);
    out.push(['cmi.progress_measure', decimal(progress)]);
  }
  tasks.forEach((t, k) => {
    const o = `cmi.objectives.${k}`;
    const passed = t.best?.passed ?? 0;
    out.push([`${o}.id`, t.id]);
    if (version === '1.2') {
      // (SCORM 1.2 keeps a score within 0 to 100: a goal has at most MAX_TASK_GOAL conditions)
      out.push([`${o}.score.min`, '0'], [`${o}.score.max`, String(t.of)]);
      if (t.best) out.push([`${o}.score.raw`, String(passed)]);
      out.push([`${o}.status`, t.best && passed === t.of ? 'passed' : done ? 'failed' : 'incomplete']);
    } else {
      out.push([`${o}.score.min`, '0'], [`${o}.score.max`, String(t.of)]);
      if (t.best) out.push([`${o}.score.raw`, String(passed)], [`${o}.score.scaled`, decimal(share(passed, t.of))]);
      const own = t.best && passed === t.of;
      out.push([`${o}.completion_status`, own || done ? 'completed' : 'incomplete']);
      out.push([`${o}.success_status`, own ? 'passed' : done ? 'failed' : 'unknown']);
    }
  });
  for (const t of tasks)
    for (const c of t.conditions ?? []) {
      let n = order.indexOf(c.id);
      if (n < 0) n = order.push(c.id) - 1;
      const i = `cmi.interactions.${n}`;
      out.push([`${i}.id`, c.id]);
      if (version === '1.2') {
        out.push([`${i}.type`, c.numeric ? 'numeric' : 'fill-in'], [`${i}.weighting`, '1']);
        out.push([`${i}.student_response`, c.response.slice(0, SCORM12_RESPONSE)]);
        out.push(
          [`${i}.result`, c.shown ? 'neutral' : c.holds ? 'correct' : 'wrong'],
          [`${i}.time`, moment(now, version)],
        );
      } else {
        out.push([`${i}.type`, c.numeric ? 'numeric' : 'other'], [`${i}.weighting`, '1']);
        out.push([`${i}.description`, c.description.slice(0, SCORM2004_DESCRIPTION)]);
        if (c.response) out.push([`${i}.learner_response`, c.response.slice(0, SCORM2004_RESPONSE)]);
        out.push(
          [`${i}.result`, c.shown ? 'neutral' : c.holds ? 'correct' : 'incorrect'],
          [`${i}.timestamp`, moment(now, version)],
        );
      }
    }
  out.push([version === '1.2' ? 'cmi.core.session_time' : 'cmi.session_time', timespan(seconds, version)]);
  return out;
}

/** The calls and elements of each version. */
const NAMES = {
  1.2: {
    initialize: 'LMSInitialize',
    get: 'LMSGetValue',
    set: 'LMSSetValue',
    commit: 'LMSCommit',
    finish: 'LMSFinish',
    error: 'LMSGetLastError',
    errorText: 'LMSGetErrorString',
    suspend: 'cmi.suspend_data',
    entry: 'cmi.core.entry',
    learner: 'cmi.core.student_name',
    learnerId: 'cmi.core.student_id',
    mode: 'cmi.core.lesson_mode',
    credit: 'cmi.core.credit',
    exit: 'cmi.core.exit',
  },
  2004: {
    initialize: 'Initialize',
    get: 'GetValue',
    set: 'SetValue',
    commit: 'Commit',
    finish: 'Terminate',
    error: 'GetLastError',
    errorText: 'GetErrorString',
    suspend: 'cmi.suspend_data',
    entry: 'cmi.entry',
    learner: 'cmi.learner_name',
    learnerId: 'cmi.learner_id',
    mode: 'cmi.mode',
    credit: 'cmi.credit',
    exit: 'cmi.exit',
  },
};

/** A course system's runtime, every call guarded (see the module's documentation). */
export class ScormSession {
  /**
   * @param {{version: Version, api: any}} found
   * @param {(problem: Problem) => void} onProblem
   */
  constructor(found, onProblem) {
    this.version = found.version;
    this.api = found.api;
    this.names = NAMES[found.version];
    this.onProblem = onProblem;
    this.open = false;
    /** @type {Problem | null} why Initialize failed (said until the page goes: nothing is recorded) */
    this.refused = null;
    /** the attempt is open for review or browsing: nothing is written to it */
    this.readOnly = false;
    /** the attempt counts for nothing (no credit): only the student's work is kept, no score or status */
    this.noCredit = false;
    this.started = Date.now();
    /** the longest suspend_data the runtime keeps */
    this.limit = found.version === '1.2' ? SCORM12_SUSPEND : SCORM2004_SUSPEND;
  }

  /**
   * One call of the runtime; its answer as a string, or null when it threw or said "false"
   * (then `onProblem` has the runtime's error code and text).
   * @param {string} name
   * @param {string[]} args
   * @param {string} what   the call as the page says it
   */
  call(name, args, what) {
    let result;
    try {
      const fn = this.api[name];
      if (typeof fn !== 'function') throw new Error(`${name} is not a function`);
      result = fn.apply(this.api, args);
    } catch (e) {
      this.onProblem({ call: what, code: '', text: String(/** @type {Error} */ (e)?.message ?? e).slice(0, 200) });
      return null;
    }
    if (result === false || result === 'false') {
      let code = '';
      let text = '';
      try {
        code = String(this.api[this.names.error]?.() ?? '');
        text = String(this.api[this.names.errorText]?.(code) ?? '');
      } catch {}
      this.onProblem({ call: what, code: code.slice(0, 20), text: text.slice(0, 200) });
      return null;
    }
    return result === undefined || result === null ? '' : String(result);
  }

  /** Initialize (or LMSInitialize); whether the runtime took it (if not, why stays in `refused`). */
  initialize() {
    const said = this.onProblem;
    this.onProblem = (/** @type {Problem} */ p) => {
      this.refused = p;
      said(p);
    };
    this.open = this.call(this.names.initialize, [''], this.names.initialize) !== null;
    this.onProblem = said;
    this.started = Date.now();
    return this.open;
  }

  /** A value of the data model ("" when there is none or the call failed). */
  get(/** @type {string} */ element) {
    if (!this.open) return '';
    const value = this.call(this.names.get, [element], `${this.names.get} ${element}`);
    // (a GetValue of an element not set yet answers "" with an error code: not a problem)
    return value ?? '';
  }

  /**
   * What the course system kept of the attempt and how it opened it: suspend_data, whether it
   * resumes, the learner's name and id, the mode (a review or browsing is read-only here) and the credit.
   * @returns {Launch}
   */
  resume() {
    const quiet = this.onProblem;
    this.onProblem = () => {};
    const mode = this.get(this.names.mode);
    const out = {
      suspend: this.get(this.names.suspend),
      entry: this.get(this.names.entry),
      learner: this.get(this.names.learner),
      learnerId: this.get(this.names.learnerId),
      mode: /** @type {Launch['mode']} */ (mode === 'review' || mode === 'browse' ? mode : 'normal'),
      // (a runtime that does not say is taken to give credit, as SCORM's default is)
      credit: this.get(this.names.credit) !== 'no-credit',
    };
    this.onProblem = quiet;
    this.readOnly = out.mode !== 'normal';
    this.noCredit = !out.credit;
    return out;
  }

  /**
   * Writes `values` and the attempt (suspend_data, at most the runtime's limit), then commits;
   * whether every call succeeded.
   * @param {Array<[string, string]>} values
   * @param {string} suspend
   */
  record(values, suspend) {
    if (!this.open) return false;
    // a review or browsing keeps the attempt as it was; without credit only the work is kept
    if (this.readOnly) return true;
    let ok = true;
    for (const [element, value] of this.noCredit ? [] : values)
      ok = this.call(this.names.set, [element, value], `${this.names.set} ${element}`) !== null && ok;
    if (suspend.length <= this.limit)
      ok =
        this.call(this.names.set, [this.names.suspend, suspend], `${this.names.set} ${this.names.suspend}`) !== null &&
        ok;
    return this.call(this.names.commit, [''], this.names.commit) !== null && ok;
  }

  /** The time since Initialize, in seconds. */
  seconds() {
    return (Date.now() - this.started) / 1000;
  }

  /**
   * Leaves: exit ("suspend" while the attempt is open, so that the next launch resumes it; ""
   * in 1.2 or "normal" in 2004 once it is done), the time, a last commit, then Terminate (or
   * LMSFinish). Once. A review writes nothing but ends the session.
   * @param {boolean} done   every exercise solved, or the student ended the attempt
   */
  finish(done) {
    if (!this.open) return;
    if (!this.readOnly) {
      const exit = done ? (this.version === '1.2' ? '' : 'normal') : 'suspend';
      this.call(this.names.set, [this.names.exit, exit], `${this.names.set} ${this.names.exit}`);
      const session = this.version === '1.2' ? 'cmi.core.session_time' : 'cmi.session_time';
      this.call(this.names.set, [session, timespan(this.seconds(), this.version)], `${this.names.set} ${session}`);
      this.call(this.names.commit, [''], this.names.commit);
    }
    this.call(this.names.finish, [''], this.names.finish);
    this.open = false;
  }
}
