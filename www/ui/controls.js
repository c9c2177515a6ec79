// The controls of a scene: one row per parameter (slider with its value and, where the paper
// uses exact values, a field that takes "1/13"; select; checkbox; formula field), built with
// the DOM from the scene's declaration. A control that does nothing in the current state is
// disabled and says why. Used by the page and by <ruled-view controls>.
import { irrelevance, parseNumber } from '../scene.js';
import { appendRich, plainRich } from './richtext.js';
import { MAX_TEXT_PARAM, ROUNDING, SLIDER_PX_PER_VALUE } from '../limits.js';

/**
 * @typedef {object} ControlHooks
 * @property {(key: string, value: number | string | boolean, ended: boolean) => void} onChange
 *   a value changed (`ended`: the interaction is over, e.g. the slider was released)
 * @property {(key: string) => void} onPlay   the play button of a parameter was pressed
 * @property {(param: import('../scene.js').Param) => string | null} [fixed]
 *   the i18n key of the reason why a control is held where it is (an edit of the input replaces
 *   it), or null
 */

let serial = 0;

/**
 * Builds the controls of `scene` into `form`.
 * @param {HTMLElement} form   the group the rows go in
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
  /** @type {Array<{row: HTMLElement, slider: HTMLInputElement, minus: HTMLButtonElement, plus: HTMLButtonElement, exact: HTMLInputElement, output: HTMLOutputElement, param: import('../scene.js').Param}>} the sliders */
  const fine = [];
  /** @type {Map<string, {row: HTMLElement, input: HTMLInputElement | HTMLSelectElement, set: (v: any, unit: string) => void, reason: HTMLElement, problem: HTMLElement, play?: HTMLButtonElement, also: Array<HTMLInputElement | HTMLButtonElement>, param: import('../scene.js').Param}>} */
  const rows = new Map();
  for (const p of scene.params) {
    const id = `${prefix}-${p.key}`;
    const row = doc.createElement('div');
    row.className = `rl-row rl-${p.type}`;
    row.dataset.key = p.key;
    const label = appendRich(Object.assign(doc.createElement('label'), { htmlFor: id }), t(p.label));
    const cell = doc.createElement('div');
    cell.className = 'rl-cell';
    const reason = Object.assign(doc.createElement('small'), {
      className: 'rl-reason',
      id: `${id}-reason`,
      hidden: true,
    });
    const problem = Object.assign(doc.createElement('small'), {
      className: 'rl-fielderror',
      id: `${id}-error`,
      hidden: true,
    });
    // said when it appears, as a formula's error is
    problem.setAttribute('role', 'alert');
    /** @type {HTMLInputElement | HTMLSelectElement} */
    let input;
    /** @type {(v: any, unit: string) => void} the value shown, with its unit (a slider's) */
    let set;
    /** @type {HTMLButtonElement | undefined} */
    let play;
    /** @type {Array<HTMLInputElement | HTMLButtonElement>} a slider's − / + and its field: held with it */
    const also = [];
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
      const field = Object.assign(doc.createElement('input'), {
        type: 'text',
        spellcheck: false,
        autocomplete: 'off',
        maxLength: p.maxLength ?? MAX_TEXT_PARAM,
      });
      field.setAttribute('autocapitalize', 'off');
      field.setAttribute('autocorrect', 'off');
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
      const slider = Object.assign(doc.createElement('input'), {
        type: 'range',
        min: String(p.min),
        max: String(p.max),
        step: String(p.step ?? 'any'),
      });
      const output = Object.assign(doc.createElement('output'), { htmlFor: id });
      output.setAttribute('aria-hidden', 'true');
      // a field for the exact value: always where the paper uses exact values ("1/13"), and for
      // any slider with more values than pixels (fit()), beside its − / + steps
      const exact = Object.assign(doc.createElement('input'), {
        type: 'text',
        // a phone's decimal keypad (iOS's) has no minus and no slash: the keyboard where the
        // value may be negative or a fraction ("1/13")
        inputMode: p.exact || Number(p.min) < 0 ? 'text' : 'decimal',
        className: 'rl-exact',
        spellcheck: false,
        autocomplete: 'off',
      });
      exact.setAttribute('aria-label', t('control.exactValue', { name: plainRich(t(p.label)) }));
      exact.title = t(p.exact ? 'control.exactHint' : 'control.numberHint');
      exact.hidden = !p.exact;
      exact.addEventListener('change', () => {
        const x = parseNumber(exact.value);
        const inRange = Number.isFinite(x) && x >= /** @type {number} */ (p.min) && x <= /** @type {number} */ (p.max);
        exact.setAttribute('aria-invalid', String(!inRange));
        // said under the field, where a finger user sees it (a title only shows on hover)
        problem.hidden = inRange;
        problem.textContent = inRange
          ? ''
          : t(
              Number.isFinite(x)
                ? 'control.outOfRange'
                : exact.title === t('control.exactHint')
                  ? 'control.notFraction'
                  : 'control.notNumber',
              // (as one types them: 0.01, not 1.00·10⁻²)
              {
                min: plain(/** @type {number} */ (p.min), i18n.lang),
                max: plain(/** @type {number} */ (p.max), i18n.lang),
              },
            );
        if (inRange) exact.removeAttribute('aria-describedby');
        else exact.setAttribute('aria-describedby', problem.id);
        if (inRange) hooks.onChange(p.key, p.exact ? x : snap(p, x), true);
      });
      const stepper = (/** @type {-1 | 1} */ sign) => {
        const b = Object.assign(doc.createElement('button'), {
          type: 'button',
          className: 'rl-step',
          textContent: sign < 0 ? '−' : '+',
          hidden: true,
        });
        b.setAttribute(
          'aria-label',
          t(sign < 0 ? 'control.decrease' : 'control.increase', { name: plainRich(t(p.label)) }),
        );
        b.addEventListener('click', () => {
          const next = snap(p, Number(slider.value) + sign * (p.step ?? span(p) / 100));
          if (next !== Number(slider.value)) hooks.onChange(p.key, next, true);
        });
        return b;
      };
      const [minus, plus] = [stepper(-1), stepper(1)];
      also.push(minus, plus, exact);
      const unit = Object.assign(doc.createElement('span'), { className: 'rl-unit', hidden: !p.unit });
      set = (v, u) => {
        slider.value = String(v);
        output.value = format(Number(v));
        unit.textContent = u;
        slider.setAttribute('aria-valuetext', u ? `${format(Number(v))} ${u}` : format(Number(v)));
        if (doc.activeElement !== exact) exact.value = p.exact ? fraction(Number(v)) : plain(Number(v), i18n.lang);
      };
      slider.addEventListener('input', () => hooks.onChange(p.key, Number(slider.value), false));
      slider.addEventListener('change', () => hooks.onChange(p.key, Number(slider.value), true));
      input = slider;
      const line = Object.assign(doc.createElement('span'), { className: 'rl-line' });
      line.append(minus, slider, plus, output, exact, unit);
      cell.append(line);
      fine.push({ row, slider, minus, plus, exact, output, param: p });
      if (p.play) {
        play = Object.assign(doc.createElement('button'), { type: 'button', className: 'rl-play' });
        play.setAttribute('aria-pressed', 'false');
        play.setAttribute('aria-label', t('control.play', { name: plainRich(t(p.label)) }));
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
    rows.set(p.key, { row, input, set, reason, problem, play, also, param: p });
  }

  /** Shows `params`: values, and which controls are disabled and why. */
  const update = (/** @type {import('../scene.js').Params} */ values) => {
    for (const [key, r] of rows) {
      r.set(values[key], r.param.unit ? t(r.param.unit(values)) : '');
      const why = hooks.fixed?.(r.param) ?? irrelevance(r.param, values);
      r.input.disabled = !!why;
      for (const c of r.also) c.disabled = !!why;
      if (r.play) r.play.disabled = !!why;
      r.row.classList.toggle('rl-disabled', !!why);
      // (an exercise says once, in its panel, that it holds the controls it does not ask about)
      const said = !!why && why !== 'task.reason.locked';
      r.reason.hidden = !said;
      r.reason.textContent = said ? t(/** @type {string} */ (why)) : '';
      if (said) r.input.setAttribute('aria-describedby', r.reason.id);
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
      // (a toggle keeps its name: pressed says that it plays)
      r.play.setAttribute('aria-label', t('control.play', { name: plainRich(t(r.param.label)) }));
    }
  };

  /** Marks a field as holding an error (its message shown beside it), or not (null). */
  const invalid = (/** @type {string} */ key, /** @type {string | null} */ message) => {
    const r = rows.get(key);
    if (!r) return;
    r.input.setAttribute('aria-invalid', String(!!message));
    r.problem.hidden = !message;
    // (the same message again is not said again)
    if (r.problem.textContent !== (message ?? '')) r.problem.textContent = message ?? '';
    const described = [r.reason.hidden ? '' : r.reason.id, message ? r.problem.id : ''].filter(Boolean).join(' ');
    if (described) r.input.setAttribute('aria-describedby', described);
    else r.input.removeAttribute('aria-describedby');
  };

  /**
   * Gives every slider whose values lie closer than the pointer can aim (SLIDER_PX_PER_VALUE: a
   * pixel with a mouse, a few with a finger) its − / + steps and a number field, which reach each
   * value in one tap. Once shown they stay, so the slider they narrow does not flip them back.
   */
  const fit = () => {
    const finger = doc.defaultView?.matchMedia?.('(pointer: coarse)').matches ?? false;
    const perValue = finger ? SLIDER_PX_PER_VALUE.coarse : SLIDER_PX_PER_VALUE.fine;
    for (const f of fine) {
      const p = f.param;
      const values = p.step ? Math.round(span(p) / p.step) + 1 : Infinity;
      const width = f.slider.getBoundingClientRect().width;
      if (width > 0 && values * perValue > width && f.minus.hidden) {
        f.minus.hidden = f.plus.hidden = f.exact.hidden = false;
        f.output.hidden = true;
        f.row.classList.add('rl-fine');
      }
    }
  };

  update(params);
  return { update, playing, invalid, rows, fit };
}

/** A number as one types it: no grouping, a decimal comma in German. */
function plain(/** @type {number} */ x, /** @type {string} */ lang) {
  const text = String(Number(x.toPrecision(12)));
  return lang === 'de' ? text.replace('.', ',') : text;
}

/** `x` on the slider's grid of steps, within its range. */
function snap(/** @type {import('../scene.js').Param} */ p, /** @type {number} */ x) {
  const min = /** @type {number} */ (p.min),
    max = /** @type {number} */ (p.max);
  const on = p.step ? min + Math.round((x - min) / p.step) * p.step : x;
  return Number(Math.min(max, Math.max(min, on)).toPrecision(12));
}

/** A number as a short fraction when it is one (1/13, −1/16), else as a decimal. */
export function fraction(/** @type {number} */ x) {
  if (!Number.isFinite(x)) return '';
  for (let q = 1; q <= 64; q++) {
    const p = Math.round(x * q);
    if (Math.abs(p / q - x) < ROUNDING * Math.max(1, Math.abs(x))) return q === 1 ? String(p) : `${p}/${q}`;
  }
  return String(Number(x.toPrecision(12)));
}

/** The length max − min of a range parameter's interval. */
function span(/** @type {import('../scene.js').Param} */ p) {
  return /** @type {number} */ (p.max) - /** @type {number} */ (p.min);
}
