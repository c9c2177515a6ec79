// ruledlab/view: the viewer as a package entry. Importing it defines <ruled-view>; it also
// exports the pieces a page of one's own needs: the Stage (a view with controls), the Viewer,
// the scene list and contract, the wasm start-up (configure({ wasm }) to pass a URL or bytes),
// the URL-hash state, the styles and the languages.
export { RuledView } from './ruled-view.js';
export { Stage } from './stage.js';
export { Viewer } from './viewer.js';
export { SCENES } from './scenes/index.js';
export { PRESETS, findPreset } from './paper.js';
export { configure, start } from './core.js';
export { readState, writeState } from './state.js';
export { defineScene, scoped, bounds, readParams, defaults, RESERVED_KEYS } from './scene.js';
export { STYLES, PALETTE } from './theme.js';
export { translator, pickLanguage, LANGUAGE_CODES } from './i18n/index.js';
