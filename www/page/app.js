// The page: a Stage (the view with its controls) and the page's own parts around it — the chrome
// (page/chrome.js: scene, figure and language pickers, Share), the data panel (page/data-panel.js:
// import and exports), the address (page/address.js: the state in the URL hash, Back returns to
// the previous scene), the Share dialog (share.js) and the exercise author (author.js). This
// module puts them together; the package's `ruledlab/view` ships none of www/page/.
import { liveObjects } from '../../pkg/ruledlab.js';
import { start, memoryBytes } from '../core.js';
import { afterPaint, nextTurn } from '../schedule.js';
import { Stage } from '../stage.js';
import { SCENES } from '../scenes/index.js';
import { findPreset } from '../paper.js';
import { readLink } from '../link.js';
import { translator, pickLanguage, loadLanguage } from '../i18n/translate.js';
import { adoptStyles } from '../ui/css.js';
import { showFailure } from '../ui/failure.js';
import { appendRich } from '../ui/richtext.js';
import { storedCourse, storedHash } from './onefile.js';
import { stored } from '../platform.js';
import { onChosen, pageChrome, plainTitle } from './chrome.js';
import { dataPanel, parseStored, STORED } from './data-panel.js';
import { importParams } from '../layers/job.js';
import { pageAddress } from './address.js';
import { keepInput, keptInput } from './stored-input.js';
import { readParams } from '../scene.js';
import { builtInTask } from '../task/builtin.js';
import { linkSeed, readTask, say, taskLink } from '../task/format.js';
import { keepAttempt, keptAttempt, markSolved } from '../task/progress.js';
import { attemptOf } from '../stage/exercise-api.js';
import { postToParent } from '../task/message.js';
import { taskErrorText } from '../task/words.js';
import { encodeInput } from '../edit/input.js';
import { DEFAULT_SOLUTION_RULE, readSolutionRule } from '../task/solution-rule.js';
import { MAX_SOLUTION_AFTER } from '../limits.js';
import { openView } from '../stage/open.js';
import { lazy } from './lazy.js';

/**
 * The page (see the module documentation).
 * @param {{oneFile?: boolean, embedScript?: () => string}} [options]  oneFile: this page is the
 *   one-file build; embedScript: its own script, which is also its embed script
 */
export async function startPage({ oneFile = false, embedScript } = {}) {
  const doc = document;
  // the production page and the one-file build carry the page's shell and the styles of the view
  // in their HTML (page/shell.js): painted before this runs, taken over as they are
  const shell = doc.documentElement.hasAttribute('data-shell');
  if (!shell) adoptStyles(doc);
  // the core downloads and compiles while the page around the view is built, each part in a
  // task of its own (tasks.js); the link is read once the core is there (its values are checked
  // against the core's catalogue)
  const core = start();
  core.catch(() => {});
  const link = new URLSearchParams((location.hash || (oneFile ? `#${storedHash()}` : '')).replace(/^#/, ''));
  // a SCORM package's page: its attempts live in the course system alone (course.js), never in
  // this browser's storage under the exercise's id, which every learner on this computer shares
  const setup = oneFile ? storedCourse() : null;
  /** An exercise's attempt kept in this browser (none in a package's page). */
  const ownAttempt = (/** @type {import('../task/format.js').Task} */ task) => (setup ? null : keptAttempt(task.id));
  /** What the address asks for, as read last (the link's codec, link.js); the view's state is the stage's. @type {import('../link.js').LinkState} */
  let asked;
  let lang = pickLanguage(link.get('lang'));
  await Promise.all([loadLanguage(lang), nextTurn()]);
  let i18n = translator(lang);

  // "Loading …" (boot.js) goes over the view while the core loads, and says why if it cannot start
  const boot = doc.getElementById('boot');
  const chrome = pageChrome(doc, translator('en'));
  const share = /** @type {HTMLDialogElement} */ (
    Object.assign(doc.createElement('dialog'), { className: 'share', id: 'share-dialog' })
  );
  /** What is on screen, as the address and the Share dialog write it. */
  const shown = () =>
    stage.scene && {
      ...asked,
      scene: stage.scene,
      params: stage.params,
      camera: stage.viewer.camera.toArray(),
      lang,
      data: stage.data,
      input: stage.input,
      paper: stage.paper?.id ?? null,
      view: stage.view,
      projection: stage.projection,
      task: stage.task ? taskLink(stage.task, (id) => builtInTask(id) !== null) : null,
      seed: stage.task?.drawn ? String(stage.task.drawn.seed) : null,
    };
  const address = pageAddress({ oneFile, state: shown });
  await nextTurn();
  // (the viewer's WebGL context and the compilation of its shaders start here)
  const stage = new Stage(chrome.main, {
    lang,
    page: true,
    editable: !link.has('embed') || link.has('edit'),
    // Leave the exercise: in a frame only where the snippet allows it
    mayLeaveTask: () => !asked?.embed || !!asked.leave,
    // when the solution is offered: the link says (a lecturer's package or snippet), else after a first check
    solutionRule: () => readSolutionRule(asked?.solution) ?? DEFAULT_SOLUTION_RULE,
    onChange: ({ reason, ended }) => {
      // an edit too large for the link stays in the tab (and the page says so)
      if (ended && stage.scene && (reason === 'input' || reason === 'reset'))
        stage.setInputNote(keepInput(stage.scene.id, stage.input));
      address.save(reason === 'scene' ? 'push' : 'replace', ended);
    },
    onBuilt: (built) => data.update(built),
    onEditAsData: (imported) =>
      go(/** @type {import('../scene.js').Scene} */ (SCENES.find((s) => s.id === 'data')), {}, { data: imported }),
    onTask: (type, report) => {
      // solved exercises are marked in the menu (where the browser keeps anything; not in a package's page)
      if (type === 'solved' && !setup) {
        markSolved(report.task);
        localize();
      }
      // the attempt is kept where the browser keeps anything; a package's page records it (course.js)
      keepTaskAttempt();
      if (type === 'check' || type === 'solution') course?.checked(report);
      const input = stage.input;
      postToParent(type, report, {
        scene: stage.scene?.id ?? '',
        params: { ...stage.params },
        input: input ? encodeInput(input) : null,
      });
    },
    onLeaveTask: () => {
      stage.leaveExercise();
      address.save('push');
      localize();
    },
  });
  doc.body.append(share);
  /** @type {Awaited<ReturnType<import('./course.js').startCourse>> | null} a SCORM package's side (course.js) */
  let course = null;
  /** Keeps the attempt at the exercise shown in this browser (task/progress.js). */
  const keepTaskAttempt = () => {
    const attempt = attemptOf(stage);
    if (attempt && stage.task && !setup) keepAttempt(stage.task.id, attempt);
  };
  await nextTurn();

  /** Opens `scene` (with `params` and `options`), then records it as a new history entry. */
  const go = (
    /** @type {import('../scene.js').Scene} */ scene,
    /** @type {import('../scene.js').Params} */ params,
    /** @type {Parameters<Stage['open']>[2]} */ options,
  ) =>
    stage.open(scene, params, options).then(() => {
      address.save('push');
      localize();
    });
  await nextTurn();
  const data = dataPanel(stage, {
    i18n: () => i18n,
    // an exercise file, pasted or uploaded: opened as the exercise (its reason when it cannot be)
    onTask: async (json) => {
      try {
        await openView(stage, { task: readTask(json) });
        address.save('push');
        localize();
        return null;
      } catch (e) {
        return taskErrorText(e, i18n);
      }
    },
    // tool poses go to the milling scene (at their file's scale, in its units, with its tool; a
    // target curve added keeps the job as it is), segments to "Your data"
    onData: (imported) =>
      go(
        /** @type {import('../scene.js').Scene} */ (SCENES.find((s) => s.id === (imported.poses ? 'milling' : 'data'))),
        imported.poses ? (imported.target ? { ...stage.params } : importParams(imported)) : {},
        { data: imported },
      ),
  });

  /** Texts of the page in the current language. */
  const localize = () => {
    doc.documentElement.lang = lang;
    doc.title = `ruledlab · ${plainTitle(i18n.t(stage.scene?.title ?? 'app.subtitle'))}`;
    chrome.localize(i18n, lang, {
      scene: stage.scene?.id ?? null,
      paper: stage.paper?.id ?? null,
      task: stage.task?.id ?? null,
    });
    data.localize();
    course?.localize();
  };

  /**
   * Opens what the current address asks for (on load, Back/Forward, or an edited link); on load
   * `inSteps`: in tasks of their own (stage/open.js's enterInSteps).
   */
  const openAddress = async ({ inSteps = false } = {}) => {
    asked = readLink(address.current(), SCENES);
    if (asked.lang && pickLanguage(asked.lang) !== lang) await setLanguage(pickLanguage(asked.lang), false);
    doc.body.classList.toggle('embed', asked.embed);
    stage.setPanel(!asked.embed || asked.controls, !asked.embed || asked.text);
    stage.setEditable(!asked.embed || !!asked.edit);
    stage.setView(asked.view ?? 'space');
    stage.setProjection(asked.projection ?? null);
    const text = stored(STORED);
    // an edit: the link's, or one too large for it that this tab kept
    const input = asked.input ?? keptInput(asked.scene.id);
    // an exercise's drawn numbers: the link's seed (one that is not a seed is said, and a new one drawn)
    const { seed, note } = linkSeed(asked.seed);
    const notes = [...asked.notes, ...(note ? [note] : [])];
    if (asked.solution != null && !readSolutionRule(asked.solution))
      notes.push({ key: 'solution', note: 'note.badSolution', vars: { max: String(MAX_SOLUTION_AFTER) } });
    await openView(stage, {
      scene: asked.scene,
      params: asked.params,
      // an exercise: its scene and start, with the reader's progress from the link
      task: asked.task,
      progress: progressOf,
      taskInput: asked.input,
      seed,
      attempt: ownAttempt,
      camera: asked.camera,
      data: asked.data ?? (text ? parseStored(text) : null),
      notes,
      autoplay: asked.autoplay,
      paper: findPreset(asked.paper) ?? null,
      input,
      inputNote: input && !asked.input ? keepInput(asked.scene.id, input) : '',
    });
    if (inSteps) await nextTurn();
    localize();
  };

  /**
   * The reader's parameters in the exercise of the address: those the link sets (the exercise
   * keeps the ones it lets change).
   * @param {import('../scene.js').Scene} scene   the exercise's
   */
  const progressOf = (scene) => {
    const q = new URLSearchParams(address.current().replace(/^#/, ''));
    const read = readParams(scene, q).params;
    return Object.fromEntries(Object.entries(read).filter(([k]) => q.has(k)));
  };

  /**
   * Opens an exercise from its start (the menu, "Try it", a pasted file), as a new history entry;
   * false (and its reason in a note) when it cannot be read or does not fit its scene.
   * @param {string | import('../task/format.js').Task} value
   */
  const startTask = async (value) => {
    try {
      await openView(stage, { task: value, attempt: ownAttempt });
      address.save('push');
      return true;
    } catch (e) {
      stage.showNotes([{ key: 'task', note: 'note.badTask', vars: { reason: taskErrorText(e, i18n) } }]);
      return false;
    } finally {
      localize();
    }
  };

  /** @param {string} code @param {boolean} [write] */
  const setLanguage = async (code, write = true) => {
    await loadLanguage(code);
    lang = code;
    i18n = translator(lang);
    stage.setLanguage(code);
    localize();
    if (share.open) openShare();
    if (write) address.save('replace');
  };

  // (a choice stepped to with the arrow keys waits for the last step: chrome.js)
  onChosen(chrome.picker, () => {
    const scene = SCENES.find((s) => s.id === chrome.picker.value);
    if (scene && scene !== stage.scene) go(scene, {}, {});
  });
  onChosen(chrome.paperPicker, () => {
    const preset = findPreset(chrome.paperPicker.value);
    const scene = SCENES.find((s) => s.id === (preset?.scene ?? stage.scene?.id));
    if (scene) go(scene, preset ? preset.params : stage.params, { paper: preset ?? null });
  });
  onChosen(chrome.langPicker, () => setLanguage(chrome.langPicker.value));
  onChosen(chrome.taskPicker, () => {
    const id = chrome.taskPicker.value;
    if (!id) {
      if (stage.task) {
        stage.leaveExercise();
        address.save('push');
      }
      return;
    }
    startTask(id);
  });
  window.addEventListener('popstate', () => openAddress());
  window.addEventListener('hashchange', () => openAddress());

  // sharing: the link, an iframe, a <ruled-view>, and the view as one HTML file, and "Make an
  // exercise" from the view on screen (Share → Make an exercise) — share.js and author.js,
  // loaded when first opened (one that could not be loaded is said over the view, and loaded again
  // at the next click; the sentence goes when it is there)
  let unsaid = '';
  const unloaded = (/** @type {Error} */ e) => {
    unsaid = stage.fail(e);
  };
  const loaded = () => {
    if (unsaid && stage.els.error.textContent === unsaid) stage.els.error.hidden = true;
    unsaid = '';
  };
  const shareModule = lazy(
    () =>
      import('./share.js').then(({ shareDialog }) => {
        loaded();
        return shareDialog(share, {
          stage,
          i18n: () => i18n,
          state: () => ({ .../** @type {NonNullable<ReturnType<typeof shown>>} */ (shown()), lang }),
          oneFile,
          embedScript,
          author: () => authoring().then((author) => author.show(), ignore),
        });
      }),
    unloaded,
  );
  const openShare = () => shareModule().then((dialog) => dialog.open(), ignore);
  const authoring = lazy(
    () =>
      import('./author.js').then(({ Author }) => {
        loaded();
        return new Author(stage.authorBox, {
          i18n: () => i18n,
          stage: () => stage,
          snippets: (task) =>
            shareModule().then((dialog) =>
              dialog.taskSnippets(
                taskLink(task, (id) => builtInTask(id) !== null),
                say(task.title, lang),
              ),
            ),
          source: () => ({ oneFile, embedScript }),
          tryIt: (task) => {
            authoring().then((made) => made.close(), ignore);
            startTask(taskLink(task, (id) => builtInTask(id) !== null));
          },
        });
      }),
    unloaded,
  );
  chrome.shareButton.addEventListener('click', () => openShare());

  // for the page tests and the curious
  Object.assign(window, {
    ruledlab: {
      stage,
      scenes: SCENES,
      wasm: { live: liveObjects, memory: memoryBytes },
      get asked() {
        return asked;
      },
    },
  });
  stage.viewer.onFrame = (n) => {
    doc.body.dataset.frames = String(n);
  };
  localize();
  if (boot && boot.parentElement !== stage.els.view) stage.els.view.append(boot);
  // the linked scene's heading while the core loads (the shell's first lines have shown it
  // already; a view in a frame, which may show no text, and an exercise, which may hide some,
  // wait for the link to be read). Its explanation comes with its controls, under them: shown
  // now, it would move down when they arrive
  if (!link.has('embed') && !link.has('task')) {
    const scene = SCENES.find((s) => s.id === (link.get('scene') ?? findPreset(link.get('paper'))?.scene)) ?? SCENES[0];
    const heading = stage.els.heading;
    const wanted = appendRich(doc.createElement('h2'), i18n.t(scene.title));
    if (heading.innerHTML !== wanted.innerHTML) heading.replaceChildren(...wanted.childNodes);
  }
  await Promise.all([core, afterPaint()]);
  // the first scene in two frames: its controls, text and numbers (the page's layout and paint),
  // then the figure (the buffers' upload and the first WebGL frame) — the viewer's drawing held
  // until the first is painted, so that no one task does both
  const viewer = stage.viewer;
  const holding = !viewer.pending;
  if (holding) viewer.pending = true;
  // a SCORM package's page: the course system's runtime records its exercises (course.js), which
  // it opens itself — until then the exercise waits, unseen, so that no answer goes unrecorded
  if (setup) stage.els.root.classList.add('rl-waiting');
  stage.inSteps = true;
  try {
    await openAddress({ inSteps: true });
    if (setup)
      course = await import('./course.js').then((m) =>
        m.startCourse(setup, { stage, i18n: () => i18n, before: chrome.main, opened: () => address.save('replace') }),
      );
  } finally {
    // (also where the start fails: what could be shown is shown, and the view draws)
    stage.els.root.classList.remove('rl-waiting');
    stage.inSteps = false;
    if (holding) {
      await afterPaint();
      await viewer.prepareFirst().catch(() => {});
      viewer.pending = false;
      viewer.requestRender();
    }
  }
  address.save('replace');
  window.addEventListener('pagehide', keepTaskAttempt);
  doc.getElementById('boot')?.remove();
  doc.documentElement.dataset.started = '1';
}

/** For a part that could not be loaded: said already (lazy.js). */
const ignore = () => {};

/** Says, in the reader's language, that the page could not start (and why); rethrows. */
export function showStartFailure(/** @type {unknown} */ e) {
  const box = document.getElementById('boot') ?? document.body.appendChild(document.createElement('p'));
  // boot.js's later "does not start" must not replace the reason said here
  document.documentElement.dataset.failed = '1';
  const i18n = translator(pickLanguage(new URLSearchParams(location.hash.slice(1)).get('lang')));
  showFailure(box, e, i18n);
  throw e;
}
