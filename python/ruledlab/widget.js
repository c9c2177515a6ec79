// The front end of ruledlab's notebook widget (an anywidget module: JupyterLab, Jupyter Notebook,
// VS Code, Colab, marimo). Each view is a <ruled-view> element, defined by the one-file script
// (dist/ruledlab-embed.js, the wasm inlined) that the Python package carries: the first view of a
// page asks the kernel for it (gzipped, one binary message) and runs it; nothing comes from a
// network.
//
// Data goes both ways through the model's traits: what Python sets is applied to the element
// (attributes; parameters by setParams, which keeps the camera and an edit; your segments and the
// scene's input as binary buffers) and, once the element has shown it, the outcome goes back
// ("shown", with the revision Python counted and the errors the change raised). What the reader
// does (a slider, a dragged handle, the camera) comes back after every computation ("state":
// params, readouts, scene, the input as binary buffers, the camera), which Python sets as the
// view's traits. Figures (SVG, TikZ, PNG) and exercise checks are messages too.
//
// Messages, kernel → view: { kind: 'embed' } + [gzipped script], { kind: 'export', id, format,
// options }. View → kernel: { kind: 'hello' } (once per model, when a front end creates it:
// Python learns that a front end holds the view, which a notebook run headless has not), { kind:
// 'embed' }, { kind: 'state', state, input } (+ [doubles per
// input set]), { kind: 'shown', rev, errors }, { kind: 'error',
// error } (an error outside a change of Python's, e.g. from a worker), { kind: 'export', id, text
// | error } (+ [png bytes]), { kind: 'task', type, report }, { kind: 'still' } (+ [png bytes]: the
// picture drawn, a second after a change settled, for the view's still in the saved notebook:
// ruledlab/_still.py).

/**
 * The part of anywidget's model this module uses (@anywidget/types' AnyModel).
 * @typedef {object} Model
 * @property {(key: string) => any} get
 * @property {(content: object, callbacks?: unknown, buffers?: ArrayBuffer[]) => void} send
 * @property {(name: string, callback: (...args: any[]) => void) => void} on
 * @property {(name: string, callback?: (...args: any[]) => void) => void} off
 *
 * @typedef {import('../../www/ruled-view.js').RuledView} RuledView
 * @typedef {{message: string, code: string | null, details: object | null}} ErrorDetail
 */

/** The traits this module applies to the element (a change of one from Python is a revision). */
const FLAGS = ['controls', 'text', 'editable', 'autoplay'];
const ATTRIBUTES = ['camera', 'lang', 'height'];
const OPENING = ['scene', 'paper', 'task'];
const KEYS = [...FLAGS, ...ATTRIBUTES, ...OPENING, 'params', '_source', 'data'];

const SCRIPT = Symbol.for('ruledlab.embed');

/** How long after a change the picture is sent as the view's still (ms): once the view settled. */
const STILL_DELAY = 1000;

/**
 * Hides the views' stills (ruledlab/_still.py: the picture a saved notebook shows without a
 * kernel) in this page, where the widgets themselves are drawn: their outputs too, so that no
 * empty row is left.
 */
function hideStills() {
  if (document.getElementById('ruledlab-stills')) return;
  const style = document.createElement('style');
  style.id = 'ruledlab-stills';
  style.textContent = '.jp-OutputArea-child:has(.ruledlab-still), .ruledlab-still { display: none !important; }';
  document.head.append(style);
}

/**
 * Defines <ruled-view> in this page (once; every view waits for it): the kernel sends the
 * gzipped one-file script, which runs from a blob: URL, as anywidget runs this module.
 * @param {Model} model
 * @returns {Promise<unknown>}
 */
function defineElement(model) {
  if (customElements.get('ruled-view')) return Promise.resolve();
  const global = /** @type {Record<symbol, Promise<void> | undefined>} */ (/** @type {unknown} */ (globalThis));
  global[SCRIPT] ??= new Promise((resolve, reject) => {
    /** @param {{kind?: string}} msg @param {DataView[]} buffers */
    const onMessage = async (msg, buffers) => {
      if (msg?.kind !== 'embed') return;
      model.off('msg:custom', onMessage);
      try {
        const bytes = new Uint8Array(buffers[0].buffer, buffers[0].byteOffset, buffers[0].byteLength).slice();
        const gz = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
        const text = await new Response(gz).text();
        const url = URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
        const script = Object.assign(document.createElement('script'), { src: url });
        script.onload = () => resolve(URL.revokeObjectURL(url));
        script.onerror = () => reject(new Error('ruledlab: the bundled script did not run here'));
        document.head.append(script);
      } catch (e) {
        reject(e);
      }
    };
    model.on('msg:custom', onMessage);
    model.send({ kind: 'embed' });
  });
  // a request that failed (a kernel gone) may be made again by the next view
  global[SCRIPT].catch(() => {
    global[SCRIPT] = undefined;
  });
  return Promise.race([global[SCRIPT], customElements.whenDefined('ruled-view')]);
}

/** A parameter object as the `params` attribute writes it. @param {Record<string, unknown>} params */
function query(params) {
  return new URLSearchParams(Object.entries(params ?? {}).map(([k, v]) => [k, String(v)])).toString();
}

/** Float64Array from a buffer of the model (a DataView at any offset: copied). @param {DataView | ArrayBuffer} b */
function doubles(b) {
  const view = b instanceof DataView ? b : new DataView(b);
  return new Float64Array(view.buffer.slice(view.byteOffset, view.byteOffset + view.byteLength));
}

/** The scene's input from the model's `data`: { set: Float64Array }. @param {Record<string, DataView>} data */
function inputOf(data) {
  return Object.fromEntries(Object.entries(data).map(([k, v]) => [k, doubles(v)]));
}

/** An error thrown in this module, as the element's `error` event details it. @param {unknown} e @returns {ErrorDetail} */
function detailOf(e) {
  const error = /** @type {{message?: string, code?: string, details?: object}} */ (e);
  return { message: String(error?.message ?? e), code: error?.code ?? null, details: error?.details ?? null };
}

/** @param {RuledView} view @param {string} name @param {unknown} value */
function setAttribute(view, name, value) {
  const text = value === null || value === undefined ? '' : String(value);
  if (text) view.setAttribute(name, text);
  else view.removeAttribute(name);
}

/** Resolves once `view` is in the document (anywidget may render into an element not yet attached). @param {RuledView} view */
async function connected(view) {
  while (!view.isConnected) await new Promise((r) => setTimeout(r, 25));
}

/** @param {{model: Model, el: HTMLElement}} context */
async function render({ model, el }) {
  hideStills();
  await defineElement(model);
  const view = /** @type {RuledView} */ (document.createElement('ruled-view'));
  // keys inside the view are the view's (arrows turn it, a slider moves, an answer is typed), not
  // JupyterLab's notebook shortcuts (Lumino stops looking for shortcuts at this attribute)
  view.setAttribute('data-lm-suppress-shortcuts', 'true');
  /** @type {Record<string, unknown>} the values of the traits the element shows */
  const applied = {};
  const snapshot = () => {
    for (const key of KEYS) applied[key] = model.get(key);
  };
  for (const key of FLAGS) view.toggleAttribute(key, !!model.get(key));
  for (const key of [...ATTRIBUTES, 'paper', 'task', 'scene']) setAttribute(view, key, model.get(key));
  setAttribute(view, 'params', query(model.get('params')));
  const source = model.get('_source');
  if (source) view.data = { segments: doubles(source.segments), rows: source.rows, cols: source.cols };
  snapshot();

  /** how many changes of Python's are being applied (their errors go with their outcome) */
  let settling = 0;
  /**
   * Runs `change` on the element and waits until it shows the result (an opening the change
   * started included); resolves to the errors it fired meanwhile.
   * @param {() => void | Promise<void>} change
   * @returns {Promise<ErrorDetail[]>}
   */
  const settle = async (change) => {
    /** @type {ErrorDetail[]} */
    const errors = [];
    /** @param {Event} e */
    const onError = (e) => errors.push(/** @type {CustomEvent<ErrorDetail>} */ (e).detail);
    view.addEventListener('error', onError);
    settling++;
    try {
      await change();
      // (an attribute that reopens the scene leaves its opening here; a resolved promise otherwise)
      await view.opening;
    } catch (e) {
      errors.push(detailOf(e));
    } finally {
      settling--;
      view.removeEventListener('error', onError);
    }
    return errors;
  };

  /** @type {import('../../www/stage.js').Stage | null} the stage last seen (a new one: the element was put back) */
  let stage = null;
  /** whether the scene's input has been sent since the scene was opened */
  let inputSent = false;
  /**
   * Sends the state the element shows to Python (after every computation, and before an
   * outcome): a message of its own, not the model's sync, which ipywidgets holds back while an
   * earlier one waits for the kernel, so that an outcome never overtakes the state it reports.
   * @param {boolean} withInput   the scene's input too (binary, one buffer per handle set)
   */
  const sync = (withInput) => {
    const shown = view.view;
    if (!shown?.scene) return;
    const state = { scene: shown.scene.id, params: { ...shown.params }, readouts: view.readouts() };
    Object.assign(applied, state);
    /** @type {string[]} */
    const input = [];
    /** @type {ArrayBuffer[]} */
    const buffers = [];
    for (const [key, points] of Object.entries((withInput && view.data) || {})) {
      input.push(key);
      buffers.push(points.slice().buffer);
    }
    model.send({ kind: 'state', state, input: withInput ? input : null }, undefined, buffers);
  };
  /** Reports what Python's revision `rev` came to. @param {number} rev @param {ErrorDetail[]} errors */
  const shown = (rev, errors) => {
    sync(true);
    model.send({ kind: 'shown', rev, errors });
    still();
  };
  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let stillTimer;
  /** Sends the picture as the view's still once the view has settled (a view that cannot draw keeps the last). */
  const still = () => {
    clearTimeout(stillTimer);
    stillTimer = setTimeout(async () => {
      try {
        await queue;
        if (!view.view?.scene) return;
        const blob = await view.exportPNG({ scale: 1 });
        model.send({ kind: 'still' }, undefined, [await blob.arrayBuffer()]);
      } catch {}
    }, STILL_DELAY);
  };

  // Python's changes, one after the other
  let queue = (async () => {
    const rev = model.get('_rev');
    applied._rev = rev;
    const errors = await settle(() => {
      el.append(view);
      return connected(view);
    });
    if (model.get('data') && Object.keys(model.get('data')).length && view.view?.session.built?.input) {
      const data = model.get('data');
      const more = await settle(() => {
        view.data = inputOf(data);
      });
      errors.push(...more);
    }
    stage = view.view;
    shown(rev, errors);
  })();
  const apply = async () => {
    const changed = (/** @type {string} */ key) =>
      key === '_source' || key === 'data'
        ? model.get(key) !== applied[key]
        : JSON.stringify(model.get(key)) !== JSON.stringify(applied[key]);
    // a change of Python's comes with a new revision (in the same message); anything else is
    // the view's own state coming back (ipywidgets echoes what it receives)
    if (model.get('_rev') === applied._rev) return snapshot();
    const rev = model.get('_rev');
    applied._rev = rev;
    const errors = await settle(async () => {
      for (const key of FLAGS) if (changed(key)) view.toggleAttribute(key, !!model.get(key));
      for (const key of ATTRIBUTES) if (changed(key)) setAttribute(view, key, model.get(key));
      const src = model.get('_source');
      if (changed('_source') && src) {
        view.data = { segments: doubles(src.segments), rows: src.rows, cols: src.cols };
        inputSent = false;
      }
      if (OPENING.some(changed)) {
        setAttribute(view, 'params', query(model.get('params')));
        for (const key of ['paper', 'task', 'scene']) setAttribute(view, key, model.get(key));
        inputSent = false;
      } else if (changed('params')) view.setParams(model.get('params'));
      await view.opening;
      const data = model.get('data');
      if (changed('data') && data && Object.keys(data).length) view.data = inputOf(data);
    });
    snapshot();
    shown(rev, errors);
  };
  const onChange = () => {
    queue = queue.then(apply, apply);
  };
  model.on('change', onChange);

  // what the reader does
  view.addEventListener('scene-change', () => {
    if (stage && view.view !== stage) {
      // the element was taken out of the page and put back: it opened its attributes again
      stage = view.view;
      const params = /** @type {Record<string, string | number | boolean>} */ (applied.params);
      queue = queue.then(async () => {
        await settle(() => {
          view.setParams(params);
        });
      });
    }
    sync(!inputSent);
    inputSent = true;
    still();
  });
  view.addEventListener('change', () => {
    sync(true);
    still();
  });
  view.addEventListener('camera-change', (e) => {
    applied.camera = e.detail.camera;
    model.send({ kind: 'state', state: { camera: e.detail.camera }, input: null });
    still();
  });
  view.addEventListener('error', (e) => settling || model.send({ kind: 'error', error: e.detail }));
  for (const type of /** @type {const} */ (['task-check', 'task-solved']))
    view.addEventListener(type, (e) => model.send({ kind: 'task', type: type.slice(5), report: e.detail }));

  // figures, asked for by Python
  /** @param {{kind?: string, id?: string, format?: string, options?: object}} msg */
  const onMessage = async (msg) => {
    if (msg?.kind !== 'export') return;
    const { id, format, options = {} } = msg;
    try {
      await queue;
      if (format === 'layers') {
        // what the view draws, as the core computed it (f32 points: segments' ends, polylines, meshes' vertices)
        const layers = view.view?.session.built?.layers ?? [];
        const buffers = layers.map((l) => l.positions.slice().buffer);
        model.send(
          { kind: 'export', id, layers: layers.map((l) => ({ kind: l.kind, style: l.style })) },
          undefined,
          buffers,
        );
      } else if (format === 'png') {
        const blob = await view.exportPNG(options);
        model.send({ kind: 'export', id }, undefined, [await blob.arrayBuffer()]);
      } else {
        const text = format === 'tikz' ? view.exportTikZ(options) : view.exportSVG(options);
        model.send({ kind: 'export', id, text });
      }
    } catch (e) {
      model.send({ kind: 'export', id, error: detailOf(e) });
    }
  };
  model.on('msg:custom', onMessage);

  return () => {
    clearTimeout(stillTimer);
    model.off('change', onChange);
    model.off('msg:custom', onMessage);
    view.remove();
  };
}

/**
 * A front end made the model: say so, before anything is drawn (Python's wait() and figures need
 * a front end; without one, in a notebook run headless, they do not wait for it).
 * @param {{model: Model}} context
 */
function initialize({ model }) {
  hideStills();
  model.send({ kind: 'hello' });
}

export default { initialize, render };
