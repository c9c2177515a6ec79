// The page: loads the wasm core, builds the controls of the current scene, keeps the scene
// and its parameters in the URL hash, and redraws when anything changes.
import init, { importSegments } from '../pkg/ruledlab.js';
import { imported } from './scenes/data.js';
import { obj, segmentsText, invariantsJson, invariantsCsv, png } from './exporters.js';
import { Viewer } from './viewer.js';
import { COLORS, css } from './theme.js';
import { SCENES } from './scenes/index.js';


const $ = (id) => document.getElementById(id);

/** Reads `#scene=…&key=value…` into { scene, params } (unknown keys ignored). */
export function readHash(hash = location.hash) {
  const q = new URLSearchParams(hash.replace(/^#/, ''));
  const scene = SCENES.find((s) => s.id === q.get('scene')) ?? SCENES[0];
  const params = {};
  for (const p of scene.params) {
    const raw = q.get(p.key);
    params[p.key] = raw === null ? p.value : parseParam(p, raw);
  }
  const view = (q.get('view') ?? '').split(',').map(Number);
  return { scene, params, view: view.length === 6 && view.every(Number.isFinite) ? view : null, embed: q.has('embed') };
}

function parseParam(p, raw) {
  if (p.type === 'checkbox') return raw === '1' || raw === 'true';
  if (p.type === 'range') {
    const x = Number(raw);
    return Number.isFinite(x) ? Math.min(p.max, Math.max(p.min, x)) : p.value;
  }
  return raw;
}

function writeHash({ scene, params, embed }, camera) {
  const q = new URLSearchParams(embed ? { embed: '' } : {});
  q.set('scene', scene.id);
  for (const p of scene.params) q.set(p.key, p.type === 'checkbox' ? (params[p.key] ? '1' : '0') : params[p.key]);
  const { yaw, pitch, distance, target } = camera;
  q.set('view', [yaw, pitch, distance, ...target].map((x) => Number(x.toPrecision(6))).join(','));
  history.replaceState(null, '', `#${q}`);
}

/** Sets the camera from a `view` hash entry: yaw, pitch, distance, target x, y, z. */
function applyView(camera, view) {
  const [yaw, pitch, distance, ...target] = view;
  Object.assign(camera, { yaw, pitch, distance: Math.max(distance, 1e-6), target });
}

function buildControls(state, changed) {
  const form = $('controls');
  form.replaceChildren();
  for (const p of state.scene.params) {
    const id = `param-${p.key}`;
    const label = Object.assign(document.createElement('label'), { htmlFor: id, textContent: p.label });
    let input;
    if (p.type === 'select') {
      input = document.createElement('select');
      for (const [value, title] of p.options()) input.add(new Option(title, value));
      input.value = state.params[p.key];
    } else {
      input = Object.assign(document.createElement('input'), { type: p.type });
      if (p.type === 'checkbox') input.checked = state.params[p.key];
      else Object.assign(input, { min: p.min, max: p.max, step: p.step, value: state.params[p.key] });
    }
    input.id = id;
    input.name = p.key;
    const cell = document.createElement('span');
    cell.append(input);
    let output;
    if (p.type === 'range') {
      output = Object.assign(document.createElement('output'), { htmlFor: id, value: state.params[p.key] });
      cell.append(output);
    }
    input.addEventListener('input', () => {
      const v = p.type === 'checkbox' ? input.checked : p.type === 'range' ? Number(input.value) : input.value;
      if (output) output.value = v;
      state.params[p.key] = v;
      changed(p);
    });
    form.append(label, cell);
  }
}

/**
 * Legend entries [colour, html, when?]: `when` is a param key (shown while it is on) or a
 * predicate of the params.
 */
function showLegend(scene, params) {
  const visible = (when) => !when || (typeof when === 'function' ? when(params) : params[when]);
  $('legend').replaceChildren(
    ...scene.legend
      .filter(([, , when]) => visible(when))
      .map(([color, html]) => {
        const li = document.createElement('li');
        const sw = Object.assign(document.createElement('span'), { className: 'swatch' });
        sw.style.background = css(COLORS[color]);
        const label = document.createElement('span');
        label.innerHTML = html;
        li.append(sw, label);
        return li;
      }),
  );
}

function showReadout(readout, extraLabels = {}) {
  const fmt = (x) => (typeof x !== 'number' ? x : Number.isInteger(x) ? String(x) : Math.abs(x) >= 0.1 && Math.abs(x) < 1000 ? x.toFixed(3) : x.toExponential(2));
  const labels = {
    rulings: 'rulings N',
    parallelPairs: 'parallel pairs',
    footpointError: 'max |fᵢ,ᵢ₊₁ − s(uᵢ)|',
    midpointError: 'max |mᵢ − s(uᵢ)|',
    meanDelta: 'δ̄ at the middle ruling',
    nonDevelopability: 'non-developability (height of the conoidal model)',
    isometryError: 'max relative change of polygon edge lengths',
    insertedDistance: 'max distance of inserted rulings from the surface',
    distanceError: 'max distance of new points from the exact d₁ points',
    angleError: 'max angle of new lines to the exact lines (rad)',
  };
  $('readout').replaceChildren(
    ...Object.entries(readout).flatMap(([k, v]) => [
      Object.assign(document.createElement('dt'), { textContent: extraLabels[k] ?? labels[k] ?? k }),
      Object.assign(document.createElement('dd'), { textContent: fmt(v) }),
    ]),
  );
}

/** Downloads `content` (a string or a Blob) as `filename`. */
function download(filename, content, type = 'text/plain') {
  const blob = content instanceof Blob ? content : new Blob([content], { type });
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: filename });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

/** Buttons that download text the scene made (exports). */
function showActions(actions) {
  $('actions').replaceChildren(
    ...actions.map(({ label, filename, content, type }) => {
      const button = Object.assign(document.createElement('button'), { type: 'button', textContent: label });
      button.addEventListener('click', () => download(filename, content, type));
      return button;
    }),
  );
}

function showError(e) {
  const box = $('error');
  box.hidden = !e;
  box.textContent = e ? String(e.message ?? e) : '';
}

async function main() {
  await init({ module_or_path: new URL('../pkg/ruledlab_bg.wasm', import.meta.url) });
  const viewer = new Viewer($('view'));
  const initial = readHash();
  const state = { scene: initial.scene, params: initial.params, embed: initial.embed };
  // #embed: the view alone, without header and panel, for iframes
  document.body.classList.toggle('embed', initial.embed);
  const picker = $('scene');
  for (const s of SCENES) picker.add(new Option(s.title, s.id));

  let hashTimer = 0;
  const saveHash = () => {
    clearTimeout(hashTimer);
    hashTimer = setTimeout(() => writeHash(state, viewer.camera), 150);
  };
  let generation = 0;
  let current = null;
  const update = ({ fit = false, view = null } = {}) => {
    const mine = ++generation;
    try {
      const t0 = performance.now();
      const built = state.scene.create(state.params);
      viewer.setScene(built, { fit });
      document.body.dataset.updateMs = (performance.now() - t0).toFixed(1);
      // heavy work the scene handed to a worker: show progress, swap the result in when done
      const progress = $('progress');
      progress.hidden = !built.later;
      if (built.later) {
        progress.value = 0;
        document.body.dataset.busy = '1';
        built
          .later((fraction) => mine === generation && (progress.value = fraction))
          .then((done) => {
            if (mine !== generation) return;
            viewer.setScene(done);
            showReadout(done.readout, done.readoutLabels);
          })
          .catch((e) => e.superseded || showError(e))
          .finally(() => {
            if (mine !== generation) return;
            progress.hidden = true;
            delete document.body.dataset.busy;
          });
      } else {
        delete document.body.dataset.busy;
      }
      if (view) applyView(viewer.camera, view);
      showReadout(built.readout, built.readoutLabels);
      $('figure').innerHTML = built.figure ?? '';
      $('figure').hidden = !built.figure;
      showActions(built.actions ?? []);
      current = built;
      for (const b of document.querySelectorAll('#exports button')) {
        b.disabled = b.dataset.export === 'svg' ? !built.figure : ['obj', 'csv', 'json', 'invariants', 'invariants-csv'].includes(b.dataset.export) && !built.data;
      }
      if (built.data?.grid) for (const k of ['invariants', 'invariants-csv']) document.querySelector(`[data-export="${k}"]`).disabled = true;
      showLegend(state.scene, state.params);
      showError(null);
    } catch (e) {
      showError(e);
    }
    writeHash(state, viewer.camera);
  };
  const enter = ({ scene, params, view }) => {
    Object.assign(state, { scene, params });
    picker.value = scene.id;
    $('text').innerHTML = scene.text;
    buildControls(state, (p) => update({ fit: p.type === 'select' }));
    update({ fit: true, view });
    animate();
  };
  // Checkbox params with `animate: { key, period }` sweep that slider back and forth.
  let animation = 0;
  const animate = () => {
    cancelAnimationFrame(animation);
    const driver = state.scene.params.find((p) => p.animate && state.params[p.key]);
    if (!driver) return;
    const { key, period } = driver.animate;
    const slider = document.getElementById(`param-${key}`);
    const t0 = performance.now();
    const tick = (now) => {
      const phase = ((now - t0) / 1000 / period) % 1;
      const value = Number((0.5 - 0.5 * Math.cos(2 * Math.PI * phase)).toFixed(2));
      if (slider && Number(slider.value) !== value) {
        slider.value = value;
        slider.dispatchEvent(new Event('input'));
      }
      animation = requestAnimationFrame(tick);
    };
    animation = requestAnimationFrame(tick);
  };
  $('controls').addEventListener('input', (e) => e.target.type === 'checkbox' && animate());
  picker.addEventListener('change', () => enter(readHash(`scene=${picker.value}`)));
  window.addEventListener('hashchange', () => enter(readHash()));
  viewer.onCameraChange = saveHash;

  // import: pasted text or an uploaded file, shown in the "Your data" scene
  const showImport = (text) => {
    try {
      const got = importSegments(text);
      Object.assign(imported, { segments: got.segments, rows: got.rows, cols: got.cols });
      const next = readHash('scene=data');
      enter(next);
    } catch (e) {
      showError(e);
    }
  };
  $('import-button').addEventListener('click', () => showImport($('import-text').value));
  $('import-file').addEventListener('change', async (e) => {
    const file = e.target.files?.[0];
    if (file) showImport(await file.text());
  });
  // exports of the current scene
  $('exports').addEventListener('click', async (e) => {
    const kind = e.target.dataset?.export;
    if (!kind || !current) return;
    const name = state.scene.id;
    try {
      if (kind === 'png') download(`${name}.png`, await png(viewer));
      else if (kind === 'svg') download(`${name}.svg`, current.figure.replace('<svg ', '<svg xmlns="http://www.w3.org/2000/svg" '), 'image/svg+xml');
      else if (kind === 'obj') download(`${name}.obj`, obj(current.data.segments, { faces: !current.data.grid, name }), 'model/obj');
      else if (kind === 'csv' || kind === 'json') download(`${name}.${kind}`, segmentsText(current.data.segments, kind, current.data.grid), kind === 'csv' ? 'text/csv' : 'application/json');
      else if (kind === 'invariants') download(`${name}-invariants.json`, invariantsJson(current.data.segments), 'application/json');
      else if (kind === 'invariants-csv') download(`${name}-invariants.csv`, invariantsCsv(current.data.segments), 'text/csv');
    } catch (err) {
      showError(err);
    }
  });
  $('fit').addEventListener('click', () => {
    viewer.camera.reset();
    viewer.requestRender();
    saveHash();
  });
  enter(initial);
  window.ruledlab = { viewer, state, scenes: SCENES };
  viewer.onFrame = (n) => {
    document.body.dataset.frames = String(n);
  };
}

main().catch((e) => {
  showError(e);
  throw e;
});
