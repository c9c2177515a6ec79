// The view's own buttons — the Klein view beside it, Fit, Reset, Fullscreen, ? (the list of keys and gestures) and Cancel
// of long work — and the view's texts that depend on the language but not on the scene (its
// name, the hint, the labels of the legend, controls and readout). Each button asks the stage for
// what it does (`actions`).
import { canFullscreen } from '../platform.js';
import { labelButton } from './elements.js';
import { touchScreen } from './touch.js';

/**
 * Wires the view's buttons to what they ask of the stage.
 * @param {import('./elements.js').StageElements} els
 * @param {{fit: () => void, reset: () => void, fullscreen: () => void, klein: () => void, help: () => void, cancel: () => void}} actions
 */
export function wireToolbar(els, actions) {
  const { buttons, cancel, progress } = els;
  buttons.fit.addEventListener('click', actions.fit);
  buttons.reset.addEventListener('click', actions.reset);
  buttons.fullscreen.addEventListener('click', actions.fullscreen);
  // a toggle: pressed while the stage is full screen (the event comes to the element that is)
  buttons.fullscreen.setAttribute('aria-pressed', 'false');
  els.root.addEventListener('fullscreenchange', () => {
    const on = els.root.ownerDocument.fullscreenElement === els.root;
    buttons.fullscreen.setAttribute('aria-pressed', String(on));
  });
  // a toggle: pressed while the Klein view stands beside the 3D view (the stage sets it from its state)
  buttons.klein.addEventListener('click', actions.klein);
  buttons.klein.setAttribute('aria-pressed', 'false');
  buttons.help.addEventListener('click', actions.help);
  cancel.addEventListener('click', () => {
    actions.cancel();
    progress.hidden = true;
  });
}

/**
 * The view's texts in the stage's language.
 * @param {import('./elements.js').StageElements} els
 * @param {import('../i18n/index.js').Translator} i18n
 */
export function labelToolbar(els, { t }) {
  const { canvas, buttons, cancel, legend, form, readout, hint } = els;
  canvas.setAttribute('aria-label', t('view.label'));
  canvas.setAttribute('aria-roledescription', t('view.role'));
  labelButton(buttons.fit, '⌂', t('view.fit'));
  buttons.fit.title = t('view.fitTitle');
  labelButton(buttons.reset, '↺', t('view.reset'));
  buttons.reset.title = t('view.resetTitle');
  labelButton(buttons.fullscreen, '⤢', t('view.fullscreen'));
  // a frame without allow="fullscreen" cannot: no button that does nothing
  buttons.fullscreen.hidden = !canFullscreen(canvas.ownerDocument);
  labelButton(buttons.klein, 'M', t('view.klein'));
  buttons.klein.title = t('view.kleinTitle');
  buttons.help.textContent = '?';
  buttons.help.setAttribute('aria-label', t('view.shortcuts'));
  buttons.help.title = t('view.shortcuts');
  cancel.textContent = t('view.cancel');
  legend.setAttribute('aria-label', t('view.legend'));
  form.setAttribute('aria-label', t('panel.controls'));
  readout.setAttribute('aria-label', t('panel.readout'));
  hint.textContent = t(touchScreen() ? 'view.hintTouch' : 'view.hintMouse');
}
