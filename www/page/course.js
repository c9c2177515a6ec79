// A SCORM package's page (course/scorm-package.js): the one-file page whose state block holds the
// package's exercises. It shows a bar above the view — the activity's title, the exercises (one to
// choose, each marked when solved), the score so far, whether the course system took it, and
// "End the attempt" — finds the course system's runtime (page/scorm.js) and records there after
// every check. The attempt stays open until every exercise is solved or the student ends it, so a
// student who leaves and comes back finds her exercise, numbers, answers, hints and checks again
// (suspend_data: page/suspend.js). A course system's review or browsing shows her recorded work
// and writes nothing; without credit nothing that counts is written; each is said.
//
// Only the course system's store counts in a course system: every package of a site runs on one
// origin, so every learner of a lab computer shares the browser's storage. The page's own copy
// of the attempt (kept in case a commit fails) is keyed by the learner's id and the package, read
// only for that learner's open attempt of that package, and forgotten once the attempt ends; a
// launch that names no learner keeps none.
//
// Without a runtime the exercises work as anywhere. The package's setup is read like anything
// from outside: what is not one is said, in the page's language, and the page shows what it can.
import { packageTasks } from '../course/scorm-package.js';
import { readAttempt, bestCheck } from '../task/attempt.js';
import { say } from '../task/format.js';
import { describeCondition, taskErrorText } from '../task/words.js';
import { drawTask, randomSeed, seedOf } from '../task/draw.js';
import { attemptOf } from '../stage/exercise-api.js';
import { openView } from '../stage/open.js';
import { decodeInput } from '../edit/input.js';
import { forget, keep, kept } from '../platform.js';
import { decimal, findRuntime, scormValues, ScormSession } from './scorm.js';
import { readSuspend, writeSuspend } from './suspend.js';
import { MAX_SEED } from '../limits.js';

/**
 * @typedef {import('../task/format.js').Task} Task
 * @typedef {import('../task/attempt.js').Attempt} Attempt
 *
 * @typedef {object} CourseHooks
 * @property {import('../stage.js').Stage} stage
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {HTMLElement} before   the bar goes before it
 * @property {() => void} opened    an exercise was opened (the page writes its link and titles)
 */

/** The prefix of the page's own copies of course attempts (with the package's key and the learner's). */
const COPY = 'ruledlab.course.';

/**
 * Starts the package's side of the page (see the module's documentation), or does nothing when
 * the page is no package. Returns what the page calls after each check, or null.
 * @param {unknown} setup   the state block's `course`
 * @param {CourseHooks} hooks
 */
export async function startCourse(setup, hooks) {
  const { stage } = hooks;
  const doc = stage.els.root.ownerDocument;
  const win = /** @type {Window} */ (doc.defaultView);
  const s = /** @type {any} */ (setup);
  const standard = s?.standard === 'scorm2004' ? 'scorm2004' : 'scorm12';
  /** @type {Task[]} */
  let tasks = [];
  /** @type {unknown} */
  let broken = null;
  try {
    tasks = packageTasks(s?.tasks);
  } catch (e) {
    broken = e;
  }
  const ids = tasks.map((t) => t.id);
  const bar = doc.createElement('nav');
  bar.className = 'rl-course';
  const heading = doc.createElement('h2');
  const choose = doc.createElement('label');
  const picker = doc.createElement('select');
  picker.name = 'course-task';
  choose.append(doc.createElement('span'), picker);
  const status = doc.createElement('p');
  status.className = 'rl-course-status';
  status.setAttribute('role', 'status');
  status.tabIndex = -1;
  const mode = doc.createElement('p');
  mode.className = 'rl-course-mode';
  mode.hidden = true;
  const end = Object.assign(doc.createElement('button'), { type: 'button', name: 'course-end', hidden: true });
  const confirm = doc.createElement('div');
  confirm.className = 'rl-course-confirm';
  confirm.hidden = true;
  const confirmText = doc.createElement('p');
  const confirmYes = Object.assign(doc.createElement('button'), { type: 'button', name: 'course-end-yes' });
  const confirmNo = Object.assign(doc.createElement('button'), { type: 'button', name: 'course-end-no' });
  confirm.append(confirmText, confirmYes, confirmNo);
  const problem = doc.createElement('p');
  problem.className = 'rl-course-problem';
  problem.hidden = true;
  bar.append(heading, choose, status, mode, end, confirm, problem);
  hooks.before.before(bar);

  /** The latest problem of the runtime (said until a record succeeds). */
  let trouble = /** @type {import('./scorm.js').Problem | null} */ (null);
  let recordedAt = /** @type {Date | null} */ (null);
  const found = findRuntime(win, standard === 'scorm2004' ? '2004' : '1.2');
  const session = found
    ? new ScormSession(found, (p) => {
        trouble = p;
      })
    : null;
  session?.initialize();
  /** @type {import('./scorm.js').Launch} */
  const launch = session?.open
    ? session.resume()
    : { suspend: '', entry: '', learner: '', learnerId: '', mode: 'normal', credit: true };

  // the page's own copy of this learner's open attempt at this package (none without a learner)
  const packageKey = seedOf(JSON.stringify([standard, s?.title ?? '', s?.tasks ?? []])).toString(36);
  const copyKey = launch.learnerId ? `${COPY}${packageKey}.${seedOf(launch.learnerId).toString(36)}` : null;
  const fromSystem = readSuspend(launch.suspend, ids);
  // (the copy is read only where the course system kept nothing and the attempt is open: a commit that failed)
  const fromCopy = !fromSystem && copyKey && !session?.readOnly ? readSuspend(kept(copyKey) ?? '', ids) : null;
  const saved = fromSystem ?? fromCopy;
  const restoredHere = !fromSystem && !!fromCopy;
  let ended = !!saved?.ended;

  // the numbers drawn: per learner where the lecturer chose so (and the course system names her),
  // else the attempt's own, kept in suspend_data
  const perLearner = s?.draw === 'learner' && !!launch.learnerId;
  const seedSaved =
    Number.isInteger(saved?.seed) &&
    /** @type {number} */ (saved?.seed) >= 0 &&
    /** @type {number} */ (saved?.seed) <= MAX_SEED
      ? /** @type {number} */ (saved?.seed)
      : null;
  const seed = perLearner ? seedOf(`${launch.learnerId}\u0000${packageKey}`) : (seedSaved ?? randomSeed());
  /** @type {string[]} */
  const order = (saved?.order ?? []).slice(0, 2000);
  /** each exercise's attempt: the course system's (or this learner's copy), else none */
  const attempts = tasks.map((t, k) => {
    const mine = readAttempt(saved?.attempts[k] ?? null);
    return mine ? { ...mine, seed: Object.keys(t.draw).length ? seed : null } : null;
  });
  let at =
    Number.isInteger(saved?.at) &&
    /** @type {number} */ (saved?.at) >= 0 &&
    /** @type {number} */ (saved?.at) < tasks.length
      ? /** @type {number} */ (saved?.at)
      : 0;

  /** Every exercise solved (by a check that counts). */
  const solved = () =>
    tasks.length > 0 &&
    tasks.every((_, k) => {
      const best = bestCheck(attempts[k]);
      return best && best.passed === best.of;
    });
  /** Whether what the student does now is recorded as a grade. */
  const counting = () => !!session?.open && !session.readOnly && !session.noCredit && !ended;

  const localize = () => {
    const i18n = hooks.i18n();
    const { t, lang } = i18n;
    bar.setAttribute('aria-label', t('course.bar'));
    heading.textContent = String(s?.title ?? '').slice(0, 200) || t('course.bar');
    /** @type {HTMLElement} */ (choose.firstChild).textContent = `${t('course.exercise')} `;
    choose.hidden = tasks.length < 2;
    picker.replaceChildren(
      ...tasks.map((task, k) => {
        const best = bestCheck(attempts[k]);
        const mark = best && best.passed === best.of ? '✓ ' : '';
        return new Option(`${mark}${k + 1}. ${say(drawTask(task, seed).title, lang)}`, String(k));
      }),
    );
    picker.value = String(at);
    const raw = tasks.reduce((sum, _, k) => sum + (bestCheck(attempts[k])?.passed ?? 0), 0);
    const max = tasks.reduce((sum, task) => sum + task.goal.length, 0);
    // (a runtime that would not start says so in the problem below, and claims nothing here)
    const where = !found
      ? t('course.noRuntime')
      : ended && !session?.readOnly
        ? t('course.ended')
        : !session?.open || session.readOnly || session.noCredit
          ? ''
          : recordedAt && !trouble
            ? t('course.recorded', { time: recordedAt.toLocaleTimeString(lang) })
            : t('course.connected', { standard: found.version });
    const learner = launch.learner ? ` ${t('course.learner', { name: launch.learner.slice(0, 100) })}` : '';
    status.textContent = broken
      ? ''
      : `${t(session?.readOnly ? 'course.scoreRecorded' : 'course.score', { raw, max })} ${where}${learner}`;
    // how the course system opened the attempt, when it is not an ordinary one
    mode.hidden = !(session?.readOnly || session?.noCredit || restoredHere);
    mode.textContent = session?.readOnly
      ? t(launch.mode === 'browse' ? 'course.browse' : 'course.review')
      : session?.noCredit
        ? t('course.noCredit')
        : restoredHere
          ? t('course.restored')
          : '';
    end.hidden = !counting() || broken !== null || !tasks.length;
    end.textContent = t('course.end');
    confirmText.textContent = t('course.endConfirm', { raw, max });
    confirmYes.textContent = t('course.endYes');
    confirmNo.textContent = t('course.endNo');
    if (end.hidden) confirm.hidden = true;
    const initFailed = found && !session?.open ? session?.refused : null;
    problem.hidden = !trouble && !broken && !initFailed;
    problem.setAttribute('role', 'alert');
    problem.textContent = broken
      ? t('course.broken', { reason: taskErrorText(broken, i18n) })
      : initFailed
        ? t(initFailed.code ? 'course.notStarted' : 'course.startThrew', {
            call: initFailed.call,
            code: initFailed.code,
            text: initFailed.text || '—',
          })
        : trouble
          ? t(trouble.code ? 'course.refused' : 'course.threw', {
              call: trouble.call,
              code: trouble.code,
              text: trouble.text || '—',
            })
          : '';
  };

  /** Opens exercise `k` with its attempt. */
  const show = async (/** @type {number} */ k) => {
    const attempt = attempts[k];
    at = k;
    await openView(stage, {
      task: tasks[k],
      seed,
      attempt,
      progress: () => attempt?.params ?? {},
      taskInput: attempt?.input ? decodeInput(attempt.input) : null,
    });
    hooks.opened();
    localize();
  };

  /** Keeps the attempt in this browser for this learner and package while it is open (and forgets it once it ends). */
  const keepCopy = (/** @type {string} */ suspend) => {
    if (!copyKey || session?.readOnly) return;
    if (ended || solved()) forget(copyKey);
    else keep(copyKey, suspend);
  };

  /** Everything the course system is told now (the conditions of `checked`: their latest check). */
  const record = (/** @type {import('../task/panel.js').TaskReport | null} */ checked) => {
    if (!session) return;
    const i18n = hooks.i18n();
    const values = scormValues(
      session.version,
      tasks.map((task, k) => {
        const best = bestCheck(attempts[k]);
        const drawn = stage.task && k === at ? stage.task : drawTask(task, seed);
        return {
          id: task.id,
          title: say(task.title, i18n.lang),
          of: task.goal.length,
          best: best && { passed: best.passed, of: best.of },
          conditions:
            checked && k === at
              ? checked.conditions.map((c, j) => {
                  const condition = drawn.goal[j];
                  const typed = condition.answer ? checked.answers[condition.answer] : undefined;
                  const value = condition.answer || c.value === null ? '' : decimal(c.value);
                  const words = describeCondition(condition, drawn, i18n);
                  return {
                    id: `${task.id}.c${j + 1}`,
                    holds: c.holds,
                    // the solution shown, or a check after it: recorded, and marked as counting for nothing
                    shown: !checked.counted,
                    numeric: value !== '',
                    // what she typed, or the value she reached — never what was expected
                    response: condition.answer
                      ? Array.isArray(typed)
                        ? typed.join('; ')
                        : String(typed ?? '')
                      : value,
                    description: checked.counted ? words : `${i18n.t('course.shownDescription')} ${words}`,
                  };
                })
              : null,
        };
      }),
      order,
      { seconds: session.seconds(), now: new Date(), ended },
    );
    trouble = null;
    const suspend = writeSuspend({ seed, at, ended, order, attempts }, ids, session.limit, bestCheck);
    keepCopy(suspend);
    const ok = session.record(values, suspend);
    recordedAt = ok && !session.readOnly ? new Date() : recordedAt;
    localize();
  };

  picker.addEventListener('change', () => {
    attempts[at] = attemptOf(stage);
    const k = Number(picker.value);
    show(k).then(() => record(null));
  });
  // ending the attempt: asked once more (it cannot be undone), then recorded as done and the session ended
  end.addEventListener('click', () => {
    confirm.hidden = false;
    confirmNo.focus();
  });
  confirmNo.addEventListener('click', () => {
    confirm.hidden = true;
    end.focus();
  });
  confirmYes.addEventListener('click', () => {
    attempts[at] = attemptOf(stage) ?? attempts[at];
    ended = true;
    confirm.hidden = true;
    record(null);
    session?.finish(true);
    localize();
    status.focus();
  });
  win.addEventListener('pagehide', () => {
    if (!session?.open) return;
    attempts[at] = attemptOf(stage) ?? attempts[at];
    record(null);
    session.finish(ended || solved());
  });

  localize();
  if (tasks.length) await show(at);
  return {
    /** After a check of the exercise shown, or its solution shown. */
    checked: (/** @type {import('../task/panel.js').TaskReport} */ report) => {
      attempts[at] = attemptOf(stage);
      record(report);
    },
    /** Whether the attempt is the course system's only (the page keeps no copy of its own elsewhere). */
    counting,
    localize,
  };
}
