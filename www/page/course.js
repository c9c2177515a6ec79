// A SCORM package's page (course/scorm-package.js): the one-file page whose state block holds the
// package's exercises. It shows a bar above the view — the exercises (one to choose, each marked
// when solved), the score so far and whether the course system took it — finds the course
// system's runtime (page/scorm.js) and records there after every check; a student who leaves and
// comes back finds her exercise, numbers, answers, hints and checks again (suspend_data, and the
// browser's own storage where there is any). Without a runtime the exercises work as anywhere.
// The package's setup is read like anything from outside: what is not one is said, in the
// page's language, and the page shows what it can.
import { packageTasks } from '../course/scorm-package.js';
import { readAttempt, bestCheck } from '../task/attempt.js';
import { keptAttempt } from '../task/progress.js';
import { say } from '../task/format.js';
import { describeCondition, taskErrorText } from '../task/words.js';
import { drawTask, randomSeed } from '../task/draw.js';
import { attemptOf } from '../stage/exercise-api.js';
import { openExercise } from '../stage/open.js';
import { decodeInput } from '../edit/input.js';
import { decimal, findRuntime, scormValues, ScormSession } from './scorm.js';
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

/** The suspend_data of an attempt at a package: which exercise is shown, the seed, each exercise's attempt, the interactions' order. */
function suspendOf(
  /** @type {number} */ at,
  /** @type {number} */ seed,
  /** @type {Array<Attempt | null>} */ attempts,
  /** @type {string[]} */ order,
  /** @type {number} */ limit,
) {
  const data = { v: 1, seed, at, i: order, a: attempts.map((a) => a && { ...a, seed: undefined }) };
  let text = JSON.stringify(data);
  // too long for the runtime (SCORM 1.2 keeps 4096 characters): the older checks go first (the
  // best one stays: the score is made of it), then the edits of exercises not shown, then answers
  const trims = [
    (/** @type {any} */ a) => {
      const best = bestCheck(a);
      a.checks = a.checks.filter(
        (/** @type {any} */ c, /** @type {number} */ k) => c === best || k === a.checks.length - 1,
      );
    },
    (/** @type {any} */ a, /** @type {number} */ k) => {
      if (k !== at) a.input = null;
    },
    (/** @type {any} */ a) => {
      a.answers = {};
    },
  ];
  for (const trim of trims) {
    if (text.length <= limit) break;
    data.a.forEach((a, k) => {
      if (a) trim(a, k);
    });
    text = JSON.stringify(data);
  }
  return text;
}

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
  const problem = doc.createElement('p');
  problem.className = 'rl-course-problem';
  problem.hidden = true;
  bar.append(heading, choose, status, problem);
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
  const kept = session?.resume() ?? { suspend: '', entry: '', learner: '' };
  /** @type {any} */
  let saved = null;
  try {
    saved = kept.suspend ? JSON.parse(kept.suspend) : null;
  } catch {}
  const seedSaved = Number.isInteger(saved?.seed) && saved.seed >= 0 && saved.seed <= MAX_SEED ? saved.seed : null;
  const seed = seedSaved ?? randomSeed();
  /** @type {string[]} */
  const order = Array.isArray(saved?.i)
    ? saved.i.filter((/** @type {unknown} */ x) => typeof x === 'string').slice(0, 200)
    : [];
  /** each exercise's attempt: the course system's, else this browser's (same seed), else none */
  const attempts = tasks.map((t, k) => {
    // (an exercise that draws nothing has no seed)
    const own = Object.keys(t.draw).length ? seed : null;
    const mine = readAttempt(Array.isArray(saved?.a) ? saved.a[k] : null);
    if (mine) return { ...mine, seed: own };
    const local = keptAttempt(t.id);
    return local && local.seed === own ? local : null;
  });
  let at = Number.isInteger(saved?.at) && saved.at >= 0 && saved.at < tasks.length ? saved.at : 0;

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
    const where = !session
      ? t('course.noRuntime')
      : recordedAt && !trouble
        ? t('course.recorded', { time: recordedAt.toLocaleTimeString(lang) })
        : session.open
          ? t('course.connected', { standard: found?.version ?? '' })
          : '';
    status.textContent = broken
      ? ''
      : `${t('course.score', { raw, max })} ${where}${kept.learner ? ` ${t('course.learner', { name: kept.learner.slice(0, 100) })}` : ''}`;
    problem.hidden = !trouble && !broken;
    problem.setAttribute('role', 'alert');
    problem.textContent = broken
      ? t('course.broken', { reason: taskErrorText(broken, i18n) })
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
    await openExercise(stage, tasks[k], {
      seed,
      attempt,
      params: () => attempt?.params ?? {},
      input: attempt?.input ? decodeInput(attempt.input) : null,
    });
    hooks.opened();
    localize();
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
                  return {
                    id: `${task.id}.c${j + 1}`,
                    holds: c.holds,
                    numeric: value !== '',
                    // what she typed, or the value she reached — never what was expected
                    response: condition.answer
                      ? Array.isArray(typed)
                        ? typed.join('; ')
                        : String(typed ?? '')
                      : value,
                    description: describeCondition(condition, drawn, i18n),
                  };
                })
              : null,
        };
      }),
      order,
      { seconds: session.seconds(), now: new Date() },
    );
    trouble = null;
    const ok = session.record(values, suspendOf(at, seed, attempts, order, session.limit));
    recordedAt = ok ? new Date() : recordedAt;
    localize();
  };

  picker.addEventListener('change', () => {
    attempts[at] = attemptOf(stage);
    const k = Number(picker.value);
    show(k).then(() => record(null));
  });
  const done = () =>
    tasks.length > 0 &&
    tasks.every((_, k) => {
      const best = bestCheck(attempts[k]);
      return best && best.passed === best.of;
    });
  win.addEventListener('pagehide', () => {
    if (!session?.open) return;
    attempts[at] = attemptOf(stage) ?? attempts[at];
    record(null);
    session.finish(done());
  });

  localize();
  if (tasks.length) await show(at);
  return {
    /** After a check (or the first solve) of the exercise shown. */
    checked: (/** @type {import('../task/panel.js').TaskReport} */ report) => {
      attempts[at] = attemptOf(stage);
      record(report);
    },
    localize,
  };
}
