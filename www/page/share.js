// The Share dialog: what the page hands out, and only what works from where the page is.
//   served page (an http(s) address):   a link, an <iframe> and a <ruled-view> snippet whose
//                                       script is the one-file embed script of this site (a
//                                       classic script: it loads from any other origin), and
//                                       the view as one HTML file
//   the one-file page with an address:  the same, the element snippet with the exact script
//                                       to upload beside it ("Download ruledlab-embed.js")
//   no address (file://, srcdoc, about:blank): no link or iframe (nobody else could open
//                                       them), a sentence saying so, the one-file download and
//                                       the element snippet with its script to upload
// Every snippet carries the scene, its parameters, the figure of the paper, the language, the
// camera and the reader's edit of the input (up to MAX_LINK_HANDLES handles), and what readers
// may do there — edit the geometry, see the controls, see the explanation, leave an exercise,
// when its solution may be shown (the dialog's options; Leave is not offered in a frame unless
// allowed). On an exercise the snippets carry the exercise, the language and those options — not
// this view's camera or the answers typed here — each reader drawing her own numbers, and it goes
// out as a SCORM package or an H5P file too (page/packages.js). Each snippet has a Copy button; the tests paste
// each into a page on another origin and require it to draw.
import { writeProjection } from '../klein-projection.js';
import { defaults } from '../scene.js';
import { writeLink } from '../link.js';
import { encodeInput, linkableInput } from '../edit/input.js';
import { download } from '../ui/download.js';
import { oneFileWithState } from './onefile.js';
import { place } from '../platform.js';
import { MAX_LINK_HANDLES } from '../limits.js';
import { copyField } from './copy-field.js';
import { packageButtons } from './packages.js';
import { taskLink, say } from '../task/format.js';
import { plainRich } from '../ui/richtext.js';
import { builtInTask } from '../task/builtin.js';
import { undrawn } from '../task/draw.js';
import { writeSolutionRule } from '../task/solution-rule.js';

/** What `npm run build` made beside the served page (dist/manifest.json names the embed script). */
const MANIFEST = new URL('../../dist/manifest.json', import.meta.url).href;

/** The file name the embed script is handed out under. */
export const EMBED_FILE = 'ruledlab-embed.js';

/**
 * What readers may do where a snippet puts the view (the Share dialog's options).
 * @typedef {object} Readers
 * @property {boolean} controls   see the controls and the readout
 * @property {boolean} text       see the scene's explanation
 * @property {boolean} edit       drag the points (a scene that has them)
 * @property {boolean} leave      leave the exercise for the scene alone
 * @property {number | null} [solution]   have the solution shown after this many checks that do
 *   not solve it (null: never; default 1)
 */

/** The hash flags of what readers may do in a frame (after "embed"). */
const flags = (/** @type {Readers} */ r) =>
  ['controls', 'edit', 'text', 'leave'].filter((k) => r[/** @type {'controls' | 'edit' | 'text' | 'leave'} */ (k)]);

/** When the solution is offered, as a link and an attribute write it (null: the default). */
const solutionOf = (/** @type {Readers} */ r) =>
  writeSolutionRule(r.solution === undefined ? null : { after: r.solution });

/** The element's attributes of what readers may do. */
const attributes = (/** @type {Readers} */ r) => {
  const rule = solutionOf(r);
  return `${r.controls ? ' controls' : ''}${r.text ? ' text' : ''}${r.edit ? ' editable' : ''}${r.leave ? ' leave' : ''}${rule ? ` solution="${rule}"` : ''}`;
};

/** An exercise's hash: its link value, the language, and when its solution is offered. */
const exerciseHash = (/** @type {string} */ value, /** @type {string} */ lang, /** @type {Readers} */ r) => {
  const q = new URLSearchParams({ task: value, lang });
  const rule = solutionOf(r);
  if (rule) q.set('solution', rule);
  return q.toString();
};

/**
 * @typedef {object} ShareContext
 * @property {import('../stage.js').Stage} stage
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {() => Omit<import('../link.js').LinkState, 'notes'>} state   the view as the link writes it
 * @property {boolean} oneFile       this page is the one-file build
 * @property {(() => string) | undefined} embedScript   the one-file build's own script (its embed script)
 * @property {() => void} [author]   opens "Make an exercise" on this view (the page)
 */

/**
 * The Share dialog of the page.
 * @param {HTMLDialogElement} dialog
 * @param {ShareContext} context
 * @returns {{open: () => Promise<void>, taskSnippets: (value: string, title: string, readers?: Readers) => Promise<{link: string | null, iframe: string | null, element: string}>}}
 */
export function shareDialog(dialog, context) {
  /** What readers may do (the options, kept while the page is open; edit: null until first set, then the scene's). */
  const readers = {
    controls: true,
    text: false,
    edit: /** @type {boolean | null} */ (null),
    leave: false,
    solution: /** @type {number | null} */ (1),
  };
  const doc = dialog.ownerDocument;
  const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
    Object.assign(doc.createElement(tag), props);
  /** The URL of this site's one-file embed script, or null (checked once, when the dialog first opens). */
  let embedServed = /** @type {Promise<string | null> | null} */ (null);

  /** The script of the element snippet from where the page is, and what to say about it. */
  const scriptOf = async () => {
    const { t } = context.i18n();
    /** @type {{src: string, module?: boolean}} */
    let script = { src: EMBED_FILE };
    let scriptNote = t('share.elementUpload', { file: EMBED_FILE });
    if (!context.oneFile && place().address) {
      embedServed ??= fetch(MANIFEST)
        .then((r) => (r.ok ? r.json() : null))
        .then(
          (m) => (typeof m?.embed === 'string' ? new URL(m.embed, MANIFEST).href : null),
          () => null,
        );
      const embed = await embedServed;
      if (embed) {
        script = { src: embed };
        scriptNote = t('share.elementServed');
      } else {
        script = { src: new URL('../index.js', import.meta.url).href, module: true };
        scriptNote = t('share.elementModule');
      }
    }
    return { script, scriptNote };
  };

  /**
   * The snippets of an exercise (a link value, task/format.js): a link and an iframe where the
   * page has an address, and the element.
   * @param {string} value
   * @param {string} title
   * @param {Readers} [who]   what readers may do (default: see the controls; an exercise says itself whether its points move)
   */
  const taskSnippets = async (value, title, who = { controls: true, text: false, edit: false, leave: false }) => {
    const lang = context.state().lang ?? context.i18n().lang;
    const hash = exerciseHash(value, lang, who);
    const base = location.href.split('#')[0];
    const { script } = await scriptOf();
    const address = place().address;
    return {
      link: address ? `${base}#${hash}` : null,
      iframe: address ? iframeSnippet(base, hash, title, who) : null,
      element: taskElementSnippet(value, lang, script, who),
    };
  };

  const open = async () => {
    const { stage, oneFile } = context;
    const i18n = context.i18n();
    const { t } = i18n;
    const where = place();
    // (every reader of a snippet draws her own numbers: the seed stays out)
    const state = { ...context.state(), seed: null };
    const hash = writeLink(state);
    const base = location.href.split('#')[0];
    const task = stage.task;
    const lang = state.lang ?? i18n.lang;
    // a figure's snippets are named after the figure, an exercise's after it, others after the scene
    // (an exercise that draws its numbers is named without the numbers drawn here)
    const written = task?.drawn?.from ?? task;
    const title = written
      ? say(undrawn(written.title, written), lang)
      : stage.paper
        ? t(stage.paper.label)
        : t(stage.scene?.title ?? '');
    const { script, scriptNote } = await scriptOf();
    /** @type {HTMLElement[]} */
    const rows = [];
    // (an exercise says itself whether its points may be dragged)
    const handles = stage.editor.sets.length > 0 && !task;
    readers.edit ??= stage.editor.active;
    const who = { ...readers, edit: handles && !!readers.edit, leave: !!task && readers.leave };
    const input = stage.input && linkableInput(stage.input) ? stage.input : null;
    const value = task ? taskLink(task, (id) => builtInTask(id) !== null) : '';
    const taskHash = exerciseHash(value, lang, who);
    if (where.address) {
      rows.push(field(task ? 'share.taskLink' : 'share.link', 'share-link', `${base}#${task ? taskHash : hash}`));
      rows.push(field('share.iframe', 'share-iframe', iframeSnippet(base, task ? taskHash : hash, title, who)));
    } else {
      rows.push(
        el('p', {
          className: 'share-nowhere',
          id: 'share-nowhere',
          textContent: t(where.file ? 'share.fromFile' : 'share.noAddress'),
        }),
      );
    }
    const element = field(
      'share.element',
      'share-element',
      task
        ? taskElementSnippet(value, lang, script, who)
        : elementSnippet(
            /** @type {import('../scene.js').Scene} */ (stage.scene),
            stage.params,
            lang,
            script,
            stage.paper,
            state.camera,
            { input, readers: who, klein: state.view === 'split', projection: state.projection ?? null },
          ),
      scriptNote,
    );
    rows.push(element);
    // an exercise as a file the course system records: SCORM 1.2, SCORM 2004, H5P
    if (task)
      rows.push(
        packageButtons(
          doc,
          context.i18n,
          () => [/** @type {import('../task/format.js').Task} */ (written)],
          () => ({ oneFile, embedScript: context.embedScript, lang, readers: who, title }),
          'share',
        ),
      );
    // an edit too large for a link is in none of the snippets: say so
    if (stage.input && !input)
      rows.push(
        el('p', {
          className: 'share-note',
          id: 'share-edit-large',
          textContent: t('share.editTooLarge', { max: MAX_LINK_HANDLES }),
        }),
      );
    if (script.src === EMBED_FILE) {
      const embed = el('button', {
        type: 'button',
        id: 'share-embed',
        textContent: t('share.embedDownload', { file: EMBED_FILE }),
      });
      const embedNote = el('p', { className: 'share-note', hidden: true });
      embed.addEventListener('click', () => {
        const text = context.embedScript?.();
        if (text) download(EMBED_FILE, text, 'text/javascript');
        else {
          embedNote.hidden = false;
          embedNote.textContent = t('share.embedMissing', { file: EMBED_FILE });
        }
      });
      element.append(embed, embedNote);
    }
    const onefile = el('button', { type: 'button', id: 'share-onefile', textContent: t('app.onefile') });
    const onefileNote = el('p', { className: 'share-note', hidden: true });
    onefile.addEventListener('click', async () => {
      try {
        download(
          `ruledlab-${stage.paper?.id ?? stage.scene?.id ?? 'view'}.html`,
          await oneFileWithState(oneFile, writeLink(state, { wholeInput: true })),
          'text/html',
        );
      } catch {
        onefileNote.hidden = false;
        onefileNote.textContent = t('app.onefileMissing');
      }
    });
    const onefileRow = el('div', { className: 'share-onefile' });
    onefileRow.append(onefile, el('p', { className: 'share-note', textContent: t('share.onefileNote') }), onefileNote);
    const close = el('button', { type: 'button', className: 'share-close', textContent: t('share.close') });
    close.addEventListener('click', () => dialog.close());
    // an exercise made from this view (task/author.js), where the page offers it
    const exercise = el('button', {
      type: 'button',
      id: 'share-exercise',
      textContent: t('author.open'),
      hidden: !context.author,
    });
    exercise.addEventListener('click', () => {
      dialog.close();
      context.author?.();
    });
    dialog.setAttribute('aria-label', t('share.title'));
    dialog.replaceChildren(
      el('h2', { textContent: t('share.title') }),
      el('p', { textContent: t(task ? 'share.introTask' : 'share.intro') }),
      options(i18n, handles, !!task),
      ...rows,
      onefileRow,
      exercise,
      // a framed page cannot tell whether the page around it allows downloads: say what to do if not
      ...(where.framed
        ? [el('p', { className: 'share-note', id: 'share-framed', textContent: t('share.framed') })]
        : []),
      close,
    );
    dialog.dataset.ready = '1';
    if (!dialog.open) dialog.showModal();
  };

  /**
   * A labelled read-only field with a Copy button (and a note under it).
   * @param {string} label  i18n key
   * @param {string} id
   * @param {string} value
   * @param {string} [note]
   */
  const field = (label, id, value, note) => {
    const { t } = context.i18n();
    return copyField(doc, t, { label: t(label), id, value, note });
  };

  /**
   * What readers may do: a checkbox each (the points only where the scene has them, Leave only
   * on an exercise); a change makes the snippets again, the keyboard staying on the checkbox.
   * @param {import('../i18n/index.js').Translator} i18n
   * @param {boolean} handles
   * @param {boolean} exercise
   */
  const options = ({ t }, handles, exercise) => {
    const box = el('fieldset', { className: 'share-readers' });
    box.append(el('legend', { textContent: t('course.readers') }));
    const offered = /** @type {Array<'edit' | 'controls' | 'text' | 'leave'>} */ ([
      ...(handles ? ['edit'] : []),
      'controls',
      'text',
      ...(exercise ? ['leave'] : []),
    ]);
    for (const key of offered) {
      const name = `share-reader-${key}`;
      const input = el('input', { type: 'checkbox', name, id: name, checked: !!readers[key] });
      input.addEventListener('change', () => {
        readers[key] = input.checked;
        open().then(() => /** @type {HTMLElement | null} */ (dialog.querySelector(`[name="${name}"]`))?.focus());
      });
      const row = el('label', { className: 'share-reader', htmlFor: name });
      row.append(input, ` ${t(`course.reader.${key}`)}`);
      box.append(row);
    }
    // on an exercise: when its solution may be shown (whenever it is, it earns nothing)
    if (exercise) {
      const name = 'share-reader-solution';
      const select = /** @type {HTMLSelectElement} */ (el('select', { name, id: name }));
      for (const n of [0, 1, 2, 3, 5])
        select.add(
          new Option(n === 0 ? t('course.solution.atOnce') : t('course.solution.after', { count: n }), String(n)),
        );
      select.add(new Option(t('course.solution.never'), 'never'));
      select.value = readers.solution === null ? 'never' : String(readers.solution);
      select.addEventListener('change', () => {
        readers.solution = select.value === 'never' ? null : Number(select.value);
        open().then(() => /** @type {HTMLElement | null} */ (dialog.querySelector(`[name="${name}"]`))?.focus());
      });
      const row = el('label', { className: 'share-reader', htmlFor: name });
      row.append(`${t('course.solution')} `, select);
      box.append(row);
    }
    return box;
  };

  return { open, taskSnippets };
}

/**
 * A <ruled-view> showing an exercise (its link value), after the script that defines the element;
 * `readers`: what readers may do there (default: see the controls).
 */
export function taskElementSnippet(
  /** @type {string} */ value,
  /** @type {string} */ lang,
  /** @type {{src: string, module?: boolean}} */ script,
  /** @type {Readers} */ readers = { controls: true, text: false, edit: false, leave: false },
) {
  const tag = script.module
    ? `<script type="module" src="${attr(script.src)}"></script>`
    : `<script defer src="${attr(script.src)}"></script>`;
  return `${tag}\n<ruled-view task="${attr(value)}" lang="${attr(lang)}"${attributes(readers)} height="640"></ruled-view>`;
}

/** Text for an HTML attribute value in double quotes. */
const attr = (/** @type {string} */ s) => s.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;');

/** A scene title in plain text, its scripts as everywhere ("R_{i}" → "Rᵢ"). */
const plainTitle = (/** @type {string} */ s) => plainRich(s);

/**
 * An <iframe> of this page in embed mode, with what readers may do there (the controls, dragging
 * the handles, the explanation, leaving an exercise). Sized by attributes, not a style
 * attribute: a course page's Content-Security-Policy (style-src 'self') refuses inline styles.
 */
export function iframeSnippet(
  /** @type {string} */ base,
  /** @type {string} */ hash,
  /** @type {string} */ title,
  /** @type {Readers} */ readers = { controls: true, text: false, edit: false, leave: false },
) {
  const rest = hash.replace(/^embed&?|(^|&)(controls|edit|text|leave)(?=&|$)/g, '').replace(/^&/, '');
  // (an exercise's hash carries its solution rule already)
  const src = `${base}#${['embed', ...flags(readers), rest].filter(Boolean).join('&')}`;
  return `<iframe src="${attr(src)}" title="${attr(plainTitle(title))}" width="100%" height="560" frameborder="0" allow="fullscreen" loading="lazy"></iframe>`;
}

/**
 * A <ruled-view> element showing this scene with these parameters, language and camera (and
 * the figure of the paper shown, if any: then only the values that differ from the figure's
 * are listed), after the script that defines the element; its height an attribute (no inline
 * style, which a strict Content-Security-Policy refuses).
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params
 * @param {string} lang
 * @param {{src: string, module?: boolean}} script   the script that defines <ruled-view>: the
 *   one-file embed script (a classic script, loads from anywhere) or the module `ruledlab/view`
 * @param {import('../paper.js').PaperPreset | null} [paper]
 * @param {number[] | null} [camera]   yaw, pitch, distance, target x, y, z
 * @param {{input?: import('../scene.js').Input | null, readers?: Readers, klein?: boolean,
 *   projection?: import('../klein-projection.js').KleinProjection | null}} [edit]   the edit of the
 *   input to show, what readers may do (default: see the controls), whether the Klein view
 *   stands beside the 3D view, and the image it is drawn in (null: the scene's own)
 */
export function elementSnippet(scene, params, lang, script, paper = null, camera = null, edit = {}) {
  /** @type {import('../scene.js').Params} */
  const base = { ...defaults(scene), ...(paper?.params ?? {}) };
  const q = new URLSearchParams();
  for (const p of scene.params)
    if (params[p.key] !== base[p.key])
      q.set(p.key, p.type === 'checkbox' ? (params[p.key] ? '1' : '0') : String(params[p.key]));
  const figure = paper ? ` paper="${attr(paper.id)}"` : '';
  const view = camera ? ` camera="${attr(camera.map((x) => Number(x.toPrecision(6))).join(','))}"` : '';
  // deferred: the course page is not held up while the script loads; the element upgrades then
  const tag = script.module
    ? `<script type="module" src="${attr(script.src)}"></script>`
    : `<script defer src="${attr(script.src)}"></script>`;
  const input = edit.input ? ` input="${attr(encodeInput(edit.input))}"` : '';
  const klein = edit.klein ? (edit.projection ? ` klein="${attr(writeProjection(edit.projection))}"` : ' klein') : '';
  const readers = edit.readers ?? { controls: true, text: false, edit: false, leave: false };
  return `${tag}\n<ruled-view scene="${attr(scene.id)}"${figure} params="${attr(q.toString())}"${view}${input} lang="${attr(lang)}"${attributes({ ...readers, leave: false })}${klein} height="560"></ruled-view>`;
}
