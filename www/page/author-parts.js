// Parts of the exercise author's panel (page/author.js): the answers the reader types — a number
// (compared with a value the scene computes, or with a number), δ(u) or s(u) (compared with the
// exact curve the scene knows) — and a parameter drawn per attempt. Each builds its controls
// from the author's state and writes back into it; the panel is built again after a change.
import { valueName } from '../task/words.js';
import { MAX_TASK_ANSWERS, MAX_TASK_TITLE, MAX_TEXT_PARAM, TASK_SAMPLES } from '../limits.js';

/**
 * An answer being written.
 * @typedef {object} AnswerRow
 * @property {'number' | 'function' | 'curve'} kind
 * @property {string} label
 * @property {string} target    number: the value it is compared with ('' : the number in `bound`)
 * @property {string} bound     number: what it is compared with when `target` is ''
 * @property {string} within
 * @property {string} samples   function, curve: at how many points ('' : the default)
 * @property {string[]} solution   the answer in the solution: one text (three for a curve)
 *
 * A parameter drawn per attempt, as typed.
 * @typedef {{from: string, to: string, step: string}} DrawRow
 *
 * @typedef {(tag: string, props?: Record<string, any>) => HTMLElement} El
 */

/** A new answer of `kind`, compared with the first value the scene computes (a number: its own bound). */
export function newAnswer(/** @type {AnswerRow['kind']} */ kind, /** @type {string} */ firstValue) {
  return /** @type {AnswerRow} */ ({
    kind,
    label: kind === 'function' ? 'δ(u)' : kind === 'curve' ? 's(u)' : '',
    target: kind === 'number' ? firstValue : '',
    bound: '',
    within: kind === 'number' ? '0.001' : '1e-6',
    samples: '',
    solution: kind === 'curve' ? ['', '', ''] : [''],
  });
}

/**
 * The answers' fieldset: per answer its kind, label, what it is compared with and how closely,
 * and the answer in the solution; "Add an answer".
 * @param {{rows: AnswerRow[], values: Record<string, number>, preview: (key: string) => string,
 *   exact: {function: boolean, curve: boolean}, i18n: import('../i18n/index.js').Translator, el: El, render: () => void}} o
 *   preview: a value's figure as the menus show it (now, or over the numbers drawn)
 */
export function answersBox({ rows, values, preview, exact, i18n, el, render }) {
  const { t } = i18n;
  const box = el('fieldset', { className: 'rl-author-answers' });
  box.append(el('legend', { textContent: t('author.answers') }));
  const labelled = (/** @type {string} */ label, /** @type {HTMLElement} */ input) => {
    const row = el('label', { className: 'rl-author-field' });
    row.append(el('span', { textContent: label }), input);
    return row;
  };
  const text = (
    /** @type {string} */ name,
    /** @type {string} */ value,
    /** @type {(v: string) => void} */ set,
    max = MAX_TEXT_PARAM,
  ) => {
    const input = /** @type {HTMLInputElement} */ (
      el('input', { type: 'text', name, value, maxLength: max, spellcheck: false })
    );
    // (a field's change fires as Tab leaves it: the panel is rebuilt after the focus has moved on)
    input.addEventListener('change', () => {
      set(input.value);
      setTimeout(render);
    });
    return input;
  };
  rows.forEach((r, k) => {
    const row = el('div', { className: 'rl-author-answer' });
    const kind = /** @type {HTMLSelectElement} */ (el('select', { name: `author-answer-kind-${k}` }));
    for (const v of /** @type {const} */ (['number', 'function', 'curve']))
      if (v === 'number' || exact[v]) kind.add(new Option(t(`author.answer.${v}`), v));
    kind.value = r.kind;
    kind.addEventListener('change', () => {
      rows[k] = newAnswer(/** @type {AnswerRow['kind']} */ (kind.value), Object.keys(values)[0] ?? '');
      render();
    });
    row.append(labelled(t('author.answer.kind', { index: k + 1 }), kind));
    row.append(
      labelled(
        t('author.answer.label'),
        text(`author-answer-label-${k}`, r.label, (v) => (r.label = v), MAX_TASK_TITLE),
      ),
    );
    if (r.kind === 'number') {
      const target = /** @type {HTMLSelectElement} */ (el('select', { name: `author-answer-target-${k}` }));
      for (const key of Object.keys(values)) target.add(new Option(`${valueName(key, i18n)} (${preview(key)})`, key));
      target.add(new Option(t('author.answer.aNumber'), ''));
      target.value = r.target;
      target.addEventListener('change', () => {
        r.target = target.value;
        render();
      });
      row.append(labelled(t('author.answer.target'), target));
      if (!r.target)
        row.append(
          labelled(
            t('author.answer.bound'),
            text(`author-answer-bound-${k}`, r.bound, (v) => (r.bound = v)),
          ),
        );
    }
    row.append(
      labelled(
        t('author.within'),
        text(`author-answer-within-${k}`, r.within, (v) => (r.within = v)),
      ),
    );
    if (r.kind !== 'number')
      row.append(
        labelled(
          t('author.answer.samples', { samples: TASK_SAMPLES }),
          text(`author-answer-samples-${k}`, r.samples, (v) => (r.samples = v)),
        ),
      );
    // the answer in the solution (a number compared with a computed value: that value, by itself)
    if (r.kind === 'curve')
      ['x', 'y', 'z'].forEach((c, i) => {
        row.append(
          labelled(
            t('author.answer.solutionPart', { part: `${c}(u)` }),
            text(`author-answer-solution-${k}-${c}`, r.solution[i] ?? '', (v) => (r.solution[i] = v)),
          ),
        );
      });
    else if (r.kind === 'function' || !r.target)
      row.append(
        labelled(
          t('author.answer.solution'),
          text(`author-answer-solution-${k}`, r.solution[0] ?? '', (v) => (r.solution[0] = v)),
        ),
      );
    const remove = el('button', { type: 'button', textContent: '×', name: `author-answer-remove-${k}` });
    remove.setAttribute('aria-label', t('author.answer.remove', { index: k + 1 }));
    remove.addEventListener('click', () => {
      rows.splice(k, 1);
      render();
    });
    row.append(remove);
    box.append(row);
  });
  const add = el('button', {
    type: 'button',
    name: 'author-answer-add',
    textContent: t('author.answer.add'),
    disabled: rows.length >= MAX_TASK_ANSWERS,
  });
  add.addEventListener('click', () => {
    rows.push(newAnswer('number', Object.keys(values)[0] ?? ''));
    render();
    /** @type {HTMLElement | null} */ (
      box.ownerDocument.querySelector(`[name="author-answer-kind-${rows.length - 1}"]`)
    )?.focus();
  });
  box.append(add);
  return box;
}

/**
 * The fields of a parameter drawn per attempt: from, to, step (a range), and a note saying how
 * the texts name it.
 * @param {{key: string, row: DrawRow, i18n: import('../i18n/index.js').Translator, el: El, render: () => void}} o
 */
export function drawFields({ key, row, i18n, el, render }) {
  const { t } = i18n;
  const box = el('div', { className: 'rl-author-draw' });
  for (const part of /** @type {const} */ (['from', 'to', 'step'])) {
    const input = /** @type {HTMLInputElement} */ (
      el('input', { type: 'text', inputMode: 'decimal', name: `author-draw-${key}-${part}`, value: row[part] })
    );
    input.addEventListener('change', () => {
      row[part] = input.value;
      setTimeout(render);
    });
    const label = el('label', { className: 'rl-author-field' });
    label.append(el('span', { textContent: t(`author.draw.${part}`) }), input);
    box.append(label);
  }
  box.append(el('p', { className: 'rl-author-note', textContent: t('author.draw.note', { name: `{${key}}` }) }));
  return box;
}

/** Greek letters by their names (a title about δ(u) keeps its δ in the id as "delta"). */
const GREEK = Object.fromEntries(
  'alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi omicron pi rho sigma tau upsilon phi chi psi omega'
    .split(' ')
    .map((name, k) => [String.fromCharCode(0x3b1 + k + (k > 16 ? 1 : 0)), ` ${name} `]),
);

/**
 * An id from a title that keeps its letters: "Was heißt δ(u)?" → "was-heisst-delta-u" (ä → ae,
 * ß → ss, Greek letters by name, other accents dropped), at most `max` characters.
 */
export function slug(/** @type {string} */ title, /** @type {number} */ max) {
  return title
    .toLowerCase()
    .replace(/[α-ω]/g, (c) => GREEK[c] ?? c)
    .replace(/ς/g, ' sigma ')
    .replace(/ä/g, 'ae')
    .replace(/ö/g, 'oe')
    .replace(/ü/g, 'ue')
    .replace(/ß/g, 'ss')
    .replace(/æ/g, 'ae')
    .replace(/œ/g, 'oe')
    .replace(/ø/g, 'o')
    .normalize('NFKD')
    .replace(/[\u0300-\u036f]/g, '')
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-|-$/g, '')
    .slice(0, max)
    .replace(/-$/, '');
}
