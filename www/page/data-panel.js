// The page's data panel, in the stage's panel: your own segments pasted or uploaded (read by the
// core's importSegments, errors said at the paste box), your tool poses (importToolPoses: the
// columns CAM systems write, their units, each pose's line) and the target curve they should
// machine (importTarget), and the menu of exports of what is shown — drawings (SVG, TikZ, PNG,
// the plot) and data files (written by the core).
import { importSegments, detectImport } from '../../pkg/ruledlab.js';
import { cam, startCam } from '../cam.js';
import { download } from '../ui/download.js';
import { linkable } from '../link.js';
import { describeError } from '../ui/errors.js';
import { dataFile } from '../export/files.js';
import { store } from '../platform.js';
import { MAX_LINK_RULINGS, PRINT_WIDTH } from '../limits.js';
import { exportName } from './file-names.js';
import { diagramOf } from '../scene.js';

/** Session storage key of an import too large for the link. */
export const STORED = 'ruledlab.data';

/** The data files of the export menu: file name suffix, the core's format, MIME type. */
const DATA_FILES = /** @type {const} */ ({
  obj: ['.obj', 'obj', 'model/obj'],
  csv: ['.csv', 'csv', 'text/csv'],
  json: ['.json', 'json', 'application/json'],
  invariants: ['-invariants.json', 'invariants-json', 'application/json'],
  invariantsCsv: ['-invariants.csv', 'invariants-csv', 'text/csv'],
});

/** The exports that are numbers rather than pictures: held while an exercise is open. */
const DATA_KINDS = /** @type {const} */ (['obj', 'csv', 'json', 'invariants', 'invariantsCsv']);

/** Every export button, in menu order, with the i18n key of its label. */
const EXPORTS = /** @type {const} */ ([
  ['svg', 'export.svg'],
  ['svgBw', 'export.svgBw'],
  ['tikz', 'export.tikz'],
  ['tikzBw', 'export.tikzBw'],
  ['png', 'export.png'],
  ['png2', 'export.png2'],
  ['png4', 'export.png4'],
  ['obj', 'export.obj'],
  ['csv', 'export.csv'],
  ['json', 'export.json'],
  ['invariants', 'export.invariants'],
  ['invariantsCsv', 'export.invariantsCsv'],
  ['plot', 'export.plot'],
]);

/** Imported data kept in session storage, or null. */
export function parseStored(/** @type {string} */ text) {
  try {
    const { segments, rows, cols, poses, tool, units, lines, target } = JSON.parse(text);
    return poses
      ? {
          segments: new Float64Array(segments),
          poses: true,
          tool,
          ...(units ? { units } : {}),
          ...(lines ? { lines } : {}),
          ...(target ? { target: new Float64Array(target) } : {}),
        }
      : { segments: new Float64Array(segments), rows, cols };
  } catch {
    return null;
  }
}

/**
 * The panel, put into the stage's panel before its explanation.
 * @param {import('../stage.js').Stage} stage
 * @param {{ i18n: () => import('../i18n/index.js').Translator, onData: (data: import('../scene.js').ImportedData) => void, onTask?: (json: string) => Promise<string | null> }} options
 *   onData: the page shows imported data (in the "data" scene); onTask: it opens an exercise file
 *   (the promise says why it could not, or null)
 */
export function dataPanel(stage, { i18n, onData, onTask }) {
  const doc = stage.els.panel.ownerDocument;
  const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
    Object.assign(doc.createElement(tag), props);
  const io = el('details', { className: 'io' });
  const summary = el('summary');
  const pasteLabel = el('label', { htmlFor: 'import-text' });
  const paste = /** @type {HTMLTextAreaElement} */ (el('textarea', { id: 'import-text', rows: 4, spellcheck: false }));
  paste.placeholder = '0,0,0,1,0,0\n0,0,1,0,1,1\n0,0,2,-1,0,2';
  // what the text holds: recognised, or chosen (tool poses: tip and axis per row)
  const kindLabel = el('label', { htmlFor: 'import-kind' });
  const kind = /** @type {HTMLSelectElement} */ (el('select', { id: 'import-kind' }));
  for (const k of ['auto', 'segments', 'poses', 'target']) kind.append(el('option', { value: k }));
  // the units of tool poses and targets: as the file says (millimetres when it says nothing), or chosen
  const unitsLabel = el('label', { htmlFor: 'import-units' });
  const units = /** @type {HTMLSelectElement} */ (el('select', { id: 'import-units' }));
  for (const k of ['auto', 'mm', 'inch']) units.append(el('option', { value: k }));
  const kindRow = el('div', { className: 'io-row' });
  kindRow.append(kindLabel, kind, unitsLabel, units);
  const row = el('div', { className: 'io-row' });
  const upload = /** @type {HTMLInputElement} */ (
    el('input', { type: 'file', id: 'import-file', accept: '.csv,.json,.txt,.exercise,text/csv,application/json' })
  );
  const showButton = el('button', { type: 'button', id: 'import-button' });
  row.append(upload, showButton);
  const importError = el('p', { className: 'io-error', id: 'import-error', hidden: true });
  importError.setAttribute('role', 'alert');
  const storedNote = el('p', { className: 'io-note io-stored', hidden: true });
  const exportsLabel = el('p', { className: 'io-label' });
  // the printed width of the SVG and TikZ figures: their lines, dashes and type are sized for it
  const widthLabel = el('label', { htmlFor: 'print-width' });
  const printWidth = /** @type {HTMLInputElement} */ (
    el('input', {
      type: 'number',
      id: 'print-width',
      min: PRINT_WIDTH.min,
      max: PRINT_WIDTH.max,
      step: 0.5,
      value: PRINT_WIDTH.default,
      inputMode: 'decimal',
    })
  );
  const widthRow = el('div', { className: 'io-row io-width' });
  widthRow.append(widthLabel, printWidth);
  /** The printed width asked for, in its range (the field shows what is used). */
  const width = () => {
    const asked = Number(printWidth.value);
    const cm = Number.isFinite(asked) && printWidth.value !== '' ? asked : PRINT_WIDTH.default;
    const used = Math.min(PRINT_WIDTH.max, Math.max(PRINT_WIDTH.min, cm));
    if (used !== asked) printWidth.value = String(used);
    return used;
  };
  const exports = el('div', { className: 'io-row', id: 'exports' });
  /** @type {Record<string, HTMLButtonElement>} */
  const buttons = {};
  for (const [kind] of EXPORTS) {
    buttons[kind] = /** @type {HTMLButtonElement} */ (el('button', { type: 'button' }));
    buttons[kind].dataset.export = kind;
    exports.append(buttons[kind]);
  }
  // in an exercise the data files wait (a table of δ or of the footpoints would be the answer)
  const heldNote = el('p', { className: 'io-note io-held', hidden: true });
  io.append(
    summary,
    pasteLabel,
    paste,
    kindRow,
    row,
    importError,
    storedNote,
    exportsLabel,
    widthRow,
    exports,
    heldNote,
  );
  stage.els.panel.insertBefore(io, stage.els.text);

  // import: pasted text or an uploaded file; an error is said at the paste box, and the scene
  // stays as it is
  const show = async (/** @type {string} */ text) => {
    // an exercise file (the book: teaching/exercises.md) opens as the exercise it is
    if (onTask && /^\s*\{[\s\S]*"ruledlab"\s*:\s*"exercise"/.test(text)) {
      importError.hidden = true;
      paste.removeAttribute('aria-invalid');
      paste.removeAttribute('aria-describedby');
      onTask(text).then((problem) => {
        if (!problem) return;
        importError.hidden = false;
        importError.textContent = problem;
        paste.setAttribute('aria-invalid', 'true');
        paste.setAttribute('aria-describedby', importError.id);
      });
      return;
    }
    /** @type {import('../scene.js').ImportedData} */
    let data;
    try {
      const detected = kind.value === 'auto' ? detectImport(text) : kind.value;
      // tool poses and target curves are the CAM module's to read: started now, if not yet
      if (detected !== 'segments') await startCam();
      if (detected === 'poses') {
        // tool poses: tip and axis, 6 numbers each, with their tool, units and lines; rotary
        // angles (x y z a b c) for the machine the milling scene has chosen
        const machine = stage.scene?.id === 'milling' ? String(stage.params.machine) : undefined;
        const got = cam().importToolPoses(
          text,
          undefined,
          machine ? { machine: /** @type {any} */ (machine) } : undefined,
        );
        const fileUnits = units.value === 'auto' ? (got.units ?? 'mm') : units.value;
        data = {
          segments: got.poses,
          poses: true,
          ...(got.tool ? { tool: got.tool } : {}),
          units: /** @type {'mm' | 'inch'} */ (fileUnits),
          lines: Array.from(got.lines),
        };
      } else if (detected === 'target') {
        // a target curve for the tool poses on screen
        const got = cam().importTarget(text);
        if (!stage.data?.poses) throw Object.assign(new Error(i18n().t('io.targetNeedsPoses')), { localized: true });
        data = { ...stage.data, target: got.points };
      } else {
        const got = importSegments(text);
        data = { segments: got.segments, rows: got.rows, cols: got.cols };
      }
    } catch (e) {
      importError.hidden = false;
      // what stays on screen: the previous import, the example data, or the scene as it was
      const onScreen =
        stage.scene?.id !== 'data' && stage.scene?.id !== 'milling'
          ? ''
          : stage.data
            ? i18n().t('io.stale')
            : i18n().t('io.staleExample');
      importError.textContent = onScreen ? `${describeError(e, i18n())} ${onScreen}` : describeError(e, i18n());
      paste.setAttribute('aria-invalid', 'true');
      paste.setAttribute('aria-describedby', importError.id);
      return;
    }
    importError.hidden = true;
    paste.removeAttribute('aria-invalid');
    paste.removeAttribute('aria-describedby');
    // too large for the link: kept in the tab's session storage, where there is one
    const keptThere = store(
      STORED,
      linkable(data)
        ? null
        : JSON.stringify({
            ...data,
            segments: Array.from(data.segments),
            ...(data.target ? { target: Array.from(data.target) } : {}),
          }),
    );
    storedNote.hidden = linkable(data);
    storedNote.textContent = i18n().t(keptThere ? 'io.stored' : 'io.notStored', { max: MAX_LINK_RULINGS });
    onData(data);
  };
  showButton.addEventListener('click', () => show(paste.value));
  upload.addEventListener('change', async () => {
    const file = upload.files?.[0];
    if (file) show(await file.text());
  });

  // exports of what is shown
  exports.addEventListener('click', async (e) => {
    const kind = /** @type {HTMLElement} */ (e.target).dataset?.export;
    const built = stage.session.built;
    if (!kind || !built || !stage.scene) return;
    try {
      const data = built.data;
      if (kind === 'png' || kind === 'png2' || kind === 'png4') {
        const scale = kind === 'png' ? 1 : Number(kind.slice(3));
        // the figure exports are loaded when first asked for
        const { png } = await import('../export/png.js');
        download(exportName(stage, 'png', { scale }), await png(stage, { scale }));
      } else if (kind === 'svg' || kind === 'svgBw') {
        const bw = kind === 'svgBw';
        const { exportSvg } = await import('../export/svg.js');
        download(exportName(stage, 'svg', { bw }), exportSvg(stage, { bw, width: width() }), 'image/svg+xml');
      } else if (kind === 'tikz' || kind === 'tikzBw') {
        const bw = kind === 'tikzBw';
        const { exportTikz } = await import('../export/tikz.js');
        download(exportName(stage, 'tikz', { bw }), exportTikz(stage, { bw, width: width() }), 'text/x-tex');
      } else if (kind === 'plot' && diagramOf(built)) {
        const diagram = /** @type {() => SVGElement} */ (diagramOf(built));
        download(exportName(stage, 'plot'), new XMLSerializer().serializeToString(diagram()), 'image/svg+xml');
      } else if (data && kind in DATA_FILES) {
        const [suffix, format, type] = DATA_FILES[/** @type {keyof typeof DATA_FILES} */ (kind)];
        const name = exportName(stage, 'data', { suffix });
        download(name, dataFile(data.segments, format, { grid: data.grid, name: stage.scene.id }), type);
      }
    } catch (err) {
      stage.fail(err);
    }
  });

  return {
    /** The texts in the current language. */
    localize() {
      const { t } = i18n();
      summary.textContent = t('io.summary');
      pasteLabel.textContent = t('io.paste');
      upload.setAttribute('aria-label', t('io.upload'));
      showButton.textContent = t('io.show');
      kindLabel.textContent = t('io.kind');
      for (const option of kind.options) option.textContent = t(`io.kind.${option.value}`);
      unitsLabel.textContent = t('io.units');
      // ("in" alone names nothing: the name begins with the word shown and says what it is)
      units.setAttribute('aria-label', t('io.unitsName'));
      for (const option of units.options) option.textContent = t(`io.units.${option.value}`);
      exportsLabel.textContent = t('io.exports');
      widthLabel.textContent = t('io.printWidth');
      for (const [kind, key] of EXPORTS) buttons[kind].textContent = t(key);
      heldNote.textContent = t('io.heldInTask');
    },
    /** The exports a computed scene has: data files where it has data, the plot where it draws one. */
    update(/** @type {import('../scene.js').Built} */ built) {
      const data = built.data;
      for (const k of ['obj', 'csv', 'json']) buttons[k].disabled = !data;
      for (const k of ['invariants', 'invariantsCsv']) buttons[k].disabled = !data || !!data.grid;
      buttons.plot.disabled = !diagramOf(built);
      const inTask = !!stage.task;
      for (const k of DATA_KINDS) buttons[k].hidden = inTask;
      heldNote.hidden = !inTask;
    },
  };
}
