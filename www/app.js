// The page: a Stage (the view with its controls) plus the page's own chrome: the scene picker,
// the language switch, sharing (link, iframe and <ruled-view> snippets, the view as one HTML
// file), import and export. The state lives in the URL hash: a scene change adds a history
// entry, parameter and camera moves replace it, so Back returns to the previous scene.
import { importSegments, liveObjects } from '../pkg/ruledlab.js';
import { start, memoryBytes } from './core.js';
import { Stage, download } from './stage.js';
import { SCENES } from './scenes/index.js';
import { PRESETS, findPreset } from './paper.js';
import { defaults } from './scene.js';
import { readState, writeState, linkable } from './state.js';
import { translator, pickLanguage, LANGUAGE_CODES } from './i18n/index.js';
import { adoptStyles } from './ui/css.js';
import { appendRich } from './ui/richtext.js';
import { describeError } from './ui/errors.js';
import { showFailure } from './ui/failure.js';
import { dataFile } from './export/files.js';
import { png } from './export/png.js';
import { exportSvg } from './export/svg.js';
import { exportTikz } from './export/tikz.js';
import { storedHash } from './export/onefile.js';
import { shareDialog } from './share.js';
import { stored, store, writeHistory } from './platform.js';

/** Session storage key of an import too large for the link. */
const STORED = 'ruledlab.data';

/** The page's language names, in their own language. */
/** The data files of the export menu: file name suffix, the core's format, MIME type. */
const DATA_FILES = /** @type {const} */ ({
  obj: ['.obj', 'obj', 'model/obj'],
  csv: ['.csv', 'csv', 'text/csv'],
  json: ['.json', 'json', 'application/json'],
  invariants: ['-invariants.json', 'invariants-json', 'application/json'],
  invariantsCsv: ['-invariants.csv', 'invariants-csv', 'text/csv'],
});
const NATIVE = { en: 'English', de: 'Deutsch' };

/**
 * The page (see the module documentation).
 * @param {{oneFile?: boolean, embedScript?: () => string}} [options]  oneFile: this page is the
 *   one-file build; embedScript: its own script, which is also its embed script
 */
export async function startPage({ oneFile = false, embedScript } = {}) {
  const doc = document;
  adoptStyles(doc);
  await start();
  let state = readState(location.hash || (oneFile ? `#${storedHash()}` : ''), SCENES);
  let lang = pickLanguage(state.lang);
  let i18n = translator(lang);
  const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) => Object.assign(doc.createElement(tag), props);

  // chrome
  const skip = el('a', { className: 'skip', href: '#main' });
  skip.addEventListener('click', (e) => {
    e.preventDefault();
    /** @type {HTMLElement | null} */ (doc.querySelector('.rl-controls [name]'))?.focus();
  });
  const header = el('header', { className: 'page-header' });
  const title = el('h1', { textContent: 'ruledlab' });
  const subtitle = el('p', { className: 'subtitle' });
  const pickerLabel = el('label', { className: 'picker' });
  const picker = el('select', { id: 'scene' });
  pickerLabel.append(el('span'), picker);
  const paperLabel = el('label', { className: 'picker' });
  const paperPicker = el('select', { id: 'paper' });
  paperLabel.append(el('span'), paperPicker);
  const langLabel = el('label', { className: 'picker' });
  const langPicker = el('select', { id: 'lang' });
  for (const code of LANGUAGE_CODES) langPicker.add(new Option(NATIVE[/** @type {keyof typeof NATIVE} */ (code)] ?? code, code));
  langLabel.append(el('span'), langPicker);
  const shareButton = el('button', { type: 'button', id: 'share' });
  header.append(title, subtitle, pickerLabel, paperLabel, langLabel, shareButton);
  const main = el('main', { id: 'main' });
  doc.body.replaceChildren(skip, header, main);

  // import and export, in the stage's panel
  const io = el('details', { className: 'io' });
  const ioSummary = el('summary');
  const pasteLabel = el('label', { htmlFor: 'import-text' });
  const paste = el('textarea', { id: 'import-text', rows: 4, spellcheck: false });
  paste.placeholder = '0,0,0,1,0,0\n0,0,1,0,1,1\n0,0,2,-1,0,2';
  const ioRow = el('div', { className: 'io-row' });
  const upload = el('input', { type: 'file', id: 'import-file', accept: '.csv,.json,.txt,text/csv,application/json' });
  const showButton = el('button', { type: 'button', id: 'import-button' });
  ioRow.append(upload, showButton);
  const importError = el('p', { className: 'io-error', id: 'import-error', hidden: true });
  importError.setAttribute('role', 'alert');
  const storedNote = el('p', { className: 'io-note', hidden: true });
  const exportsLabel = el('p', { className: 'io-label' });
  const exports = el('div', { className: 'io-row', id: 'exports' });
  /** @type {Record<string, HTMLButtonElement>} */
  const exportButtons = {};
  for (const kind of ['svg', 'svgBw', 'tikz', 'png', 'png2', 'png4', 'obj', 'csv', 'json', 'invariants', 'invariantsCsv', 'plot']) {
    exportButtons[kind] = /** @type {HTMLButtonElement} */ (el('button', { type: 'button' }));
    exportButtons[kind].dataset.export = kind;
    exports.append(exportButtons[kind]);
  }
  io.append(ioSummary, pasteLabel, paste, ioRow, importError, storedNote, exportsLabel, exports);

  // share dialog
  const share = /** @type {HTMLDialogElement} */ (el('dialog', { className: 'share', id: 'share-dialog' }));

  const stage = new Stage(main, {
    lang,
    page: true,
    onChange: ({ reason, ended }) => saveHash(reason === 'scene' ? 'push' : 'replace', ended),
    onBuilt: (built) => updateExports(built),
  });
  stage.panel.insertBefore(io, stage.text);
  doc.body.append(share);

  /** Texts of the chrome in the current language. */
  const localize = () => {
    const { t } = i18n;
    doc.documentElement.lang = lang;
    doc.title = `ruledlab · ${t(stage.scene?.title ?? 'app.subtitle').replace(/[_^]\{?([^}]*)\}?/g, '$1')}`;
    subtitle.textContent = t('app.subtitle');
    skip.textContent = t('app.skip');
    /** @type {Text} */ (pickerLabel.firstChild).textContent = `${t('app.scene')} `;
    /** @type {Text} */ (langLabel.firstChild).textContent = `${t('app.language')} `;
    langPicker.value = lang;
    picker.replaceChildren(...SCENES.map((s) => new Option(t(s.title).replace(/[_^]\{?([^}]*)\}?/g, '$1'), s.id)));
    if (stage.scene) picker.value = stage.scene.id;
    /** @type {Text} */ (paperLabel.firstChild).textContent = `${t('app.figures')} `;
    paperPicker.replaceChildren(new Option(t('paper.none'), ''), ...PRESETS.map((p) => new Option(t(p.label).replace(/[_^]\{?([^}]*)\}?/g, '$1'), p.id)));
    paperPicker.value = stage.paper?.id ?? '';
    shareButton.textContent = t('app.share');
    ioSummary.textContent = t('io.summary');
    pasteLabel.textContent = t('io.paste');
    upload.setAttribute('aria-label', t('io.upload'));
    showButton.textContent = t('io.show');
    exportsLabel.textContent = t('io.exports');
    const names = { svg: 'export.svg', svgBw: 'export.svgBw', tikz: 'export.tikz', png: 'export.png', png2: 'export.png2', png4: 'export.png4', obj: 'export.obj', csv: 'export.csv', json: 'export.json', invariants: 'export.invariants', invariantsCsv: 'export.invariantsCsv', plot: 'export.plot' };
    for (const [kind, b] of Object.entries(exportButtons)) b.textContent = t(names[/** @type {keyof typeof names} */ (kind)]);
  };

  // the URL: a scene change is a new history entry, everything else replaces the current one;
  // where the document cannot write its address (srcdoc, about:blank, some sandboxes) the
  // state lives in `kept` only
  let hashTimer = 0;
  let kept = '';
  const currentHash = () => location.hash || kept || (oneFile ? `#${storedHash()}` : '');
  /** @param {'push' | 'replace'} mode @param {boolean} [now] */
  const saveHash = (mode, now = true) => {
    clearTimeout(hashTimer);
    const write = () => {
      if (!stage.scene) return;
      const hash = `#${writeState({ ...state, scene: stage.scene, params: stage.params, camera: stage.viewer.camera.toArray(), lang: state.lang, data: stage.data, paper: stage.paper?.id ?? null })}`;
      if (hash === (location.hash || kept)) return;
      if (!writeHistory(mode, hash)) kept = hash;
    };
    if (now || mode === 'push') write();
    else hashTimer = window.setTimeout(write, 200);
  };

  /** Opens the state of the current hash (on load, Back/Forward, or an edited link). */
  const openHash = async () => {
    state = readState(currentHash(), SCENES);
    if (state.lang && pickLanguage(state.lang) !== lang) setLanguage(pickLanguage(state.lang), false);
    doc.body.classList.toggle('embed', state.embed);
    stage.setPanel(!state.embed || state.controls, !state.embed || state.text);
    const text = stored(STORED);
    const data = state.data ?? (text ? parseStored(text) : null);
    await stage.open(state.scene, state.params, { camera: state.camera, data, notes: state.notes, autoplay: state.autoplay, paper: findPreset(state.paper) ?? null });
    picker.value = state.scene.id;
    localize();
  };

  /** @param {string} code @param {boolean} [write] */
  const setLanguage = (code, write = true) => {
    lang = code;
    i18n = translator(lang);
    state.lang = code;
    stage.setLanguage(code);
    localize();
    if (share.open) sharing.open();
    if (write) saveHash('replace');
  };

  picker.addEventListener('change', () => {
    const scene = SCENES.find((s) => s.id === picker.value);
    if (!scene) return;
    stage.open(scene, {}, {}).then(() => {
      saveHash('push');
      localize();
    });
  });
  paperPicker.addEventListener('change', () => {
    const preset = findPreset(paperPicker.value);
    const scene = SCENES.find((s) => s.id === (preset?.scene ?? stage.scene?.id));
    if (!scene) return;
    stage.open(scene, preset ? preset.params : stage.params, { paper: preset ?? null }).then(() => {
      saveHash('push');
      localize();
    });
  });
  langPicker.addEventListener('change', () => setLanguage(langPicker.value));
  window.addEventListener('popstate', () => openHash());
  window.addEventListener('hashchange', () => openHash());

  // import: pasted text or an uploaded file, shown in the "data" scene
  const showImport = (/** @type {string} */ text) => {
    let got;
    try {
      got = importSegments(text);
    } catch (e) {
      importError.hidden = false;
      // what stays on screen: the previous import, the example data, or the scene as it was
      const onScreen = stage.scene?.id !== 'data' ? '' : stage.data ? i18n.t('io.stale') : i18n.t('io.staleExample');
      importError.textContent = onScreen ? `${describeError(e, i18n)} ${onScreen}` : describeError(e, i18n);
      paste.setAttribute('aria-invalid', 'true');
      paste.setAttribute('aria-describedby', importError.id);
      return;
    }
    importError.hidden = true;
    paste.removeAttribute('aria-invalid');
    paste.removeAttribute('aria-describedby');
    const data = { segments: got.segments, rows: got.rows, cols: got.cols };
    // too large for the link: kept in the tab's session storage, where there is one
    const keptThere = store(STORED, linkable(data) ? null : JSON.stringify({ segments: Array.from(data.segments), rows: data.rows, cols: data.cols }));
    storedNote.hidden = linkable(data);
    storedNote.textContent = i18n.t(keptThere ? 'io.stored' : 'io.notStored');
    const scene = /** @type {import('./scene.js').Scene} */ (SCENES.find((s) => s.id === 'data'));
    stage.open(scene, {}, { data }).then(() => {
      picker.value = 'data';
      saveHash('push');
    });
  };
  showButton.addEventListener('click', () => showImport(paste.value));
  upload.addEventListener('change', async () => {
    const file = upload.files?.[0];
    if (file) showImport(await file.text());
  });

  // exports of what is shown
  /** @param {import('./scene.js').Built} built */
  const updateExports = (built) => {
    const data = built.data;
    for (const k of ['obj', 'csv', 'json']) exportButtons[k].disabled = !data;
    for (const k of ['invariants', 'invariantsCsv']) exportButtons[k].disabled = !data || !!data.grid;
    exportButtons.plot.disabled = !built.figure;
  };
  exports.addEventListener('click', async (e) => {
    const kind = /** @type {HTMLElement} */ (e.target).dataset?.export;
    const built = stage.session.built;
    if (!kind || !built || !stage.scene) return;
    const name = stage.scene.id;
    try {
      const data = built.data;
      if (kind === 'png' || kind === 'png2' || kind === 'png4') download(`${name}${kind === 'png' ? '' : `-${kind.slice(3)}x`}.png`, await png(stage, { scale: kind === 'png' ? 1 : Number(kind.slice(3)) }));
      else if (kind === 'svg' || kind === 'svgBw') download(`${name}${kind === 'svgBw' ? '-bw' : ''}.svg`, exportSvg(stage, { bw: kind === 'svgBw' }), 'image/svg+xml');
      else if (kind === 'tikz') download(`${name}.tikz`, exportTikz(stage), 'text/x-tex');
      else if (kind === 'plot' && built.figure) download(`${name}-plot.svg`, new XMLSerializer().serializeToString(built.figure()), 'image/svg+xml');
      else if (data && kind in DATA_FILES) {
        const [suffix, format, type] = DATA_FILES[/** @type {keyof typeof DATA_FILES} */ (kind)];
        download(`${name}${suffix}`, dataFile(data.segments, format, { grid: data.grid, name }), type);
      }
    } catch (err) {
      stage.fail(err);
    }
  });

  // sharing: the link, an iframe, a <ruled-view>, and the view as one HTML file
  const viewState = () => ({ ...state, scene: /** @type {import('./scene.js').Scene} */ (stage.scene), params: stage.params, camera: stage.viewer.camera.toArray(), lang, data: stage.data, paper: stage.paper?.id ?? null });
  const sharing = shareDialog(share, { stage, i18n: () => i18n, state: viewState, oneFile, embedScript });
  shareButton.addEventListener('click', () => sharing.open());

  stage.viewer.onFrame = (n) => (doc.body.dataset.frames = String(n));
  localize();
  await openHash();
  saveHash('replace');
  doc.getElementById('boot')?.remove();
  doc.documentElement.dataset.started = '1';
  // for the page tests and the curious
  Object.assign(window, { ruledlab: { stage, scenes: SCENES, wasm: { live: liveObjects, memory: memoryBytes }, get state() { return state; } } });
}

/** Says, in the reader's language, that the page could not start (and why); rethrows. */
export function showStartFailure(/** @type {unknown} */ e) {
  const box = document.getElementById('boot') ?? document.body.appendChild(document.createElement('p'));
  const i18n = translator(pickLanguage(new URLSearchParams(location.hash.slice(1)).get('lang')));
  showFailure(box, e, i18n);
  throw e;
}

/** Imported data kept in session storage. */
function parseStored(/** @type {string} */ text) {
  try {
    const { segments, rows, cols } = JSON.parse(text);
    return { segments: new Float64Array(segments), rows, cols };
  } catch {
    return null;
  }
}
