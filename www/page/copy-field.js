// A snippet to hand out: a labelled read-only text with a Copy button (the Clipboard API, else
// the old copy command, else the text stays selected for Ctrl+C) and a note under it — the Share
// dialog's and the exercise author's.

/**
 * @param {Document} doc
 * @param {(key: string, vars?: Record<string, string | number>) => string} t
 * @param {{label: string, id: string, value: string, note?: string, rows?: number}} field   label: the text shown
 */
export function copyField(doc, t, { label, id, value, note, rows = 3 }) {
  const el = (/** @type {string} */ tag, /** @type {Record<string, any>} */ props = {}) =>
    Object.assign(doc.createElement(tag), props);
  const wrap = el('div', { className: 'share-row' });
  const area = el('textarea', { id, rows, readOnly: true, spellcheck: false, value });
  const copy = el('button', { type: 'button', textContent: t('share.copy'), className: 'copy' });
  copy.setAttribute('aria-label', t('share.copyWhat', { what: label }));
  const done = el('span', { className: 'share-done' });
  done.setAttribute('aria-live', 'polite');
  copy.addEventListener('click', async () => {
    area.select();
    let copied = false;
    try {
      // a frame whose page does not allow clipboard-write: straight to the old way (the
      // Clipboard API would log a policy violation there)
      const policy = /** @type {any} */ (doc).permissionsPolicy ?? /** @type {any} */ (doc).featurePolicy;
      if (policy?.allowsFeature?.('clipboard-write') === false || !navigator.clipboard) throw new Error('no clipboard');
      await navigator.clipboard.writeText(area.value);
      copied = true;
    } catch {
      copied = doc.execCommand?.('copy') ?? false;
    }
    // a sandboxed frame may refuse both: the text stays selected for Ctrl+C; copied, the keyboard
    // stays on the button (selecting the text had taken it into the field)
    done.textContent = t(copied ? 'share.copied' : 'share.selectCopy');
    if (copied) copy.focus();
  });
  wrap.append(el('label', { htmlFor: id, textContent: label }), area, copy, done);
  if (note) wrap.append(el('p', { className: 'share-note', textContent: note }));
  return wrap;
}
