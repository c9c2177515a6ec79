// The controls of a scene: one row per parameter (slider with its value and, where the paper
// uses exact values, a field that takes "1/13"; select; checkbox; formula field), built with
// the DOM from the scene's declaration. A control that does nothing in the current state is
// disabled and says why. Used by the page and by <ruled-view controls>.
import { irrelevance, parseNumber } from '../scene.js';
import { appendRich } from './richtext.js';

/**
 * @typedef {object} ControlHooks
 * @property {(key: string, value: number | string | boolean, ended: boolean) => void} onChange
 *   a value changed (`ended`: the interaction is over, e.g. the slider was released)
 * @property {(key: string) => void} onPlay   the play button of a parameter was pressed
 */

let serial = 0;

/**
 * Builds the controls of `scene` into `form`.
 * @param {HTMLFormElement} form
 * @param {import('../scene.js').Scene} scene
 * @param {import('../scene.js').Params} params  current values (read, never changed here)
 * @param {import('../i18n/index.js').Translator} i18n
 * @param {ControlHooks} hooks
 */
export function buildControls(form, scene, params, i18n, hooks) {
  const { t, format } = i18n;
  const doc = form.ownerDocument;
  const prefix = `rl${++serial}`;
  form.replaceChildren();
  form.noValidate = true;
  form.addEventListener('submit', (e) => e.preventDefault());
  /** @type {Map<string, {row: HTMLElement, input: HTMLInputElement | HTMLSelectElement, set: (v: any) => void, reason: HTMLElement, problem: HTMLElement, play?: HTMLButtonElement, param: import('../scene.js').Param}>} */
  const rows = new Map();
  for (const p of scene.params) {
    const id = `${prefix}-${p.key}`;
    const row = doc.createElement('div');
    row.className = `rl-row rl-${p.type}`;
    row.dataset.key = p.key;
    const label = appendRich(Object.assign(doc.createElement('label'), { htmlFor: id }), t(p.label));
    const cell = doc.createElement('div');
    cell.className = 'rl-cell';
    const reason = Object.assign(doc.createElement('small'), { className: 'rl-reason', id: `${id}-reason`, hidden: true });
    const problem = Object.assign(doc.createElement('small'), { className: 'rl-fielderror', id: `${id}-error`, hidden: true });
    /** @type {HTMLInputElement | HTMLSelectElement} */
    let input;
    /** @type {(v: any) => void} */
    let set;
    /** @type {HTMLButtonElement | undefined} */
    let play;
    if (p.type === 'select') {
      const select = doc.createElement('select');
      for (const [value, title] of p.options?.() ?? []) select.add(new Option(t(title), value));
      set = (v) => (select.value = String(v));
      select.addEventListener('change', () => hooks.onChange(p.key, select.value, true));
      input = select;
      cell.append(select);
    } else if (p.type === 'checkbox') {
      const box = Object.assign(doc.createElement('input'), { type: 'checkbox' });
      set = (v) => (box.checked = !!v);
      box.addEventListener('change', () => hooks.onChange(p.key, box.checked, true));
      input = box;
      cell.append(box);
    } else if (p.type === 'text') {
      const field = Object.assign(doc.createElement('input'), { type: 'text', spellcheck: false, autocomplete: 'off', maxLength: p.maxLength ?? 1000 });
      field.setAttribute('autocapitalize', 'off');
      field.className = 'rl-formula';
      set = (v) => {
        if (doc.activeElement !== field) field.value = String(v);
      };
      let timer = 0;
      field.addEventListener('input', () => {
        clearTimeout(timer);
        timer = window.setTimeout(() => hooks.onChange(p.key, field.value, false), 450);
      });
      field.addEventListener('change', () => {
        clearTimeout(timer);
        hooks.onChange(p.key, field.value, true);
      });
      input = field;
      cell.append(field);
    } else {
      const slider = Object.assign(doc.createElement('input'), { type: 'range', min: String(p.min), max: String(p.max), step: String(p.step ?? 'any') });
      const output = Object.assign(doc.createElement('output'), { htmlFor: id });
      output.setAttribute('aria-hidden', 'true');
      /** @type {HTMLInputElement | null} */
      let exact = null;
      if (p.exact) {
        exact = Object.assign(doc.createElement('input'), { type: 'text', inputMode: 'decimal', className: 'rl-exact', spellcheck: false });
        exact.setAttribute('aria-label', t('control.exactValue', { name: t(p.label) }));
        exact.title = t('control.exactHint');
        exact.addEventListener('change', () => {
          const x = parseNumber(/** @type {HTMLInputElement} */ (exact).value);
          const inRange = Number.isFinite(x) && x >= /** @type {number} */ (p.min) && x <= /** @type {number} */ (p.max);
          /** @type {HTMLInputElement} */ (exact).setAttribute('aria-invalid', String(!inRange));
          if (inRange) hooks.onChange(p.key, x, true);
        });
      }
      set = (v) => {
        slider.value = String(v);
        output.value = format(Number(v));
        slider.setAttribute('aria-valuetext', format(Number(v)));
        if (exact && doc.activeElement !== exact) exact.value = fraction(Number(v));
      };
      slider.addEventListener('input', () => hooks.onChange(p.key, Number(slider.value), false));
      slider.addEventListener('change', () => hooks.onChange(p.key, Number(slider.value), true));
      input = slider;
      const line = Object.assign(doc.createElement('span'), { className: 'rl-line' });
      line.append(slider, output);
      if (exact) line.append(exact);
      cell.append(line);
      if (p.play) {
        play = Object.assign(doc.createElement('button'), { type: 'button', className: 'rl-play' });
        play.setAttribute('aria-pressed', 'false');
        play.setAttribute('aria-label', t('control.play', { name: t(p.label) }));
        play.textContent = '▶';
        play.addEventListener('click', () => hooks.onPlay(p.key));
        line.append(play);
      }
    }
    input.id = id;
    input.name = p.key;
    cell.append(reason, problem);
    row.append(label, cell);
    form.append(row);
    rows.set(p.key, { row, input, set, reason, problem, play, param: p });
  }

  /** Shows `params`: values, and which controls are disabled and why. */
  const update = (/** @type {import('../scene.js').Params} */ values) => {
    for (const [key, r] of rows) {
      r.set(values[key]);
      const why = irrelevance(r.param, values);
      r.input.disabled = !!why;
      if (r.play) r.play.disabled = !!why;
      r.row.classList.toggle('rl-disabled', !!why);
      r.reason.hidden = !why;
      r.reason.textContent = why ? t(why) : '';
      if (why) r.input.setAttribute('aria-describedby', r.reason.id);
      else r.input.removeAttribute('aria-describedby');
    }
  };

  /** Marks the parameter being played (null: none). */
  const playing = (/** @type {string | null} */ key) => {
    for (const [k, r] of rows) {
      if (!r.play) continue;
      const on = k === key;
      r.play.textContent = on ? '⏸' : '▶';
      r.play.setAttribute('aria-pressed', String(on));
      r.play.setAttribute('aria-label', t(on ? 'control.pause' : 'control.play', { name: t(r.param.label) }));
    }
  };

  /** Marks a field as holding an error (its message shown beside it), or not (null). */
  const invalid = (/** @type {string} */ key, /** @type {string | null} */ message) => {
    const r = rows.get(key);
    if (!r) return;
    r.input.setAttribute('aria-invalid', String(!!message));
    r.problem.hidden = !message;
    r.problem.textContent = message ?? '';
    const described = [r.reason.hidden ? '' : r.reason.id, message ? r.problem.id : ''].filter(Boolean).join(' ');
    if (described) r.input.setAttribute('aria-describedby', described);
    else r.input.removeAttribute('aria-describedby');
  };

  update(params);
  return { update, playing, invalid, rows };
}

/** A number as a short fraction when it is one (1/13, −1/16), else as a decimal. */
export function fraction(/** @type {number} */ x) {
  if (!Number.isFinite(x)) return '';
  for (let q = 1; q <= 64; q++) {
    const p = Math.round(x * q);
    if (Math.abs(p / q - x) < 1e-12 * Math.max(1, Math.abs(x))) return q === 1 ? String(p) : `${p}/${q}`;
  }
  return String(Number(x.toPrecision(12)));
}
