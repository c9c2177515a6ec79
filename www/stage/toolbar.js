// The view's own buttons — Fit, Reset, Fullscreen, ? (the list of keys and gestures) and Cancel
// of long work — and the view's texts that depend on the language but not on the scene (its
// name, the hint, the labels of the legend, controls and readout). Each button asks the stage for
// what it does.
import { canFullscreen } from '../platform.js';
import { labelButton } from './elements.js';
import { touchScreen } from './touch.js';
import { cancelWork } from '../compute.js';

/** Wires the view's buttons. @param {import('../stage.js').Stage} stage */
export function wireToolbar(stage) {
  const { buttons, cancel, progress } = stage.els;
  buttons.fit.addEventListener('click', () => {
    stage.viewer.fit();
    stage.report('camera', true);
  });
  buttons.reset.addEventListener('click', () => stage.reset());
  buttons.fullscreen.addEventListener('click', () => stage.toggleFullscreen());
  // a toggle: pressed while the stage is full screen (the event comes to the element that is)
  buttons.fullscreen.setAttribute('aria-pressed', 'false');
  stage.els.root.addEventListener('fullscreenchange', () => {
    const on = stage.els.root.ownerDocument.fullscreenElement === stage.els.root;
    buttons.fullscreen.setAttribute('aria-pressed', String(on));
  });
  buttons.help.addEventListener('click', () => stage.shortcuts.open());
  cancel.addEventListener('click', () => {
    stage.session.dispose();
    // a long job in the worker (a tool path's post) stops there too
    cancelWork();
    progress.hidden = true;
  });
}

/** The view's texts in the stage's language. @param {import('../stage.js').Stage} stage */
export function labelToolbar(stage) {
  const { t } = stage.i18n;
  const { canvas, buttons, cancel, legend, form, readout, hint } = stage.els;
  canvas.setAttribute('aria-label', t('view.label'));
  canvas.setAttribute('aria-roledescription', t('view.role'));
  labelButton(buttons.fit, '⌂', t('view.fit'));
  buttons.fit.title = t('view.fitTitle');
  labelButton(buttons.reset, '↺', t('view.reset'));
  buttons.reset.title = t('view.resetTitle');
  labelButton(buttons.fullscreen, '⤢', t('view.fullscreen'));
  // a frame without allow="fullscreen" cannot: no button that does nothing
  buttons.fullscreen.hidden = !canFullscreen(canvas.ownerDocument);
  buttons.help.textContent = '?';
  buttons.help.setAttribute('aria-label', t('view.shortcuts'));
  buttons.help.title = t('view.shortcuts');
  cancel.textContent = t('view.cancel');
  legend.setAttribute('aria-label', t('view.legend'));
  form.setAttribute('aria-label', t('panel.controls'));
  readout.setAttribute('aria-label', t('panel.readout'));
  hint.textContent = t(touchScreen() ? 'view.hintTouch' : 'view.hintMouse');
}
