// ruledlab/view: the viewer as a package entry. Importing it defines <ruled-view>; it also
// exports the pieces a page of one's own needs: the Stage (a view with controls), the Viewer,
// the scene list and contract, the wasm start-up (configure({ wasm }) to pass a URL or bytes),
// the link's codec (a view in the URL hash and back), the styles and the languages.
export { RuledView } from './ruled-view.js';
export { Stage } from './stage.js';
export { Viewer } from './viewer.js';
export { SCENES } from './scenes/index.js';
export { PRESETS, findPreset } from './paper.js';
export { configure, start } from './core.js';
export { readLink, writeLink } from './link.js';
/** @deprecated the earlier name of readLink */
export { readLink as readState } from './link.js';
/** @deprecated the earlier name of writeLink */
export { writeLink as writeState } from './link.js';
export { defineScene, scoped, bounds, readParams, defaults, RESERVED_KEYS } from './scene.js';
export { STYLES, PALETTE } from './theme.js';
export { translator, pickLanguage, LANGUAGE_CODES } from './i18n/index.js';
export { readTask, writeTask, TaskError } from './task/format.js';
export { builtInTasks, builtInTask } from './task/builtin.js';

// The types of the pieces above, for TypeScript users (pkg/view/www/view.d.ts is generated from
// this JSDoc and the sources' own: scripts/view-types.mjs).
/**
 * @typedef {import('./core.js').WasmSource} WasmSource
 * @typedef {import('./scene.js').Scene} Scene
 * @typedef {import('./scene.js').Param} Param
 * @typedef {import('./scene.js').Params} Params
 * @typedef {import('./scene.js').Context} Context
 * @typedef {import('./scene.js').Built} Built
 * @typedef {import('./scene.js').Layer} Layer
 * @typedef {import('./scene.js').Label} Label
 * @typedef {import('./scene.js').LegendEntry} LegendEntry
 * @typedef {import('./scene.js').Readout} Readout
 * @typedef {import('./scene.js').Download} Download
 * @typedef {import('./scene.js').Claim} Claim
 * @typedef {import('./scene.js').ImportedData} ImportedData
 * @typedef {import('./scene.js').Input} Input
 * @typedef {import('./scene.js').HandleSet} HandleSet
 * @typedef {import('./scene.js').Editable} Editable
 * @typedef {import('./scene.js').SnapTargets} SnapTargets
 * @typedef {import('./edit/rules.js').EditRules} EditRules
 * @typedef {import('./edit/rules.js').HeldHandle} HeldHandle
 * @typedef {import('./paper.js').PaperPreset} PaperPreset
 * @typedef {import('./link.js').LinkState} LinkState
 * @typedef {import('./link.js').LinkState} ViewState   (deprecated: the earlier name of LinkState)
 * @typedef {import('./store.js').StageState} StageState
 * @typedef {import('./store.js').StageChange} StageChange
 * @typedef {import('./theme.js').Style} Style
 * @typedef {import('./theme.js').LineStyle} LineStyle
 * @typedef {import('./theme.js').PointStyle} PointStyle
 * @typedef {import('./theme.js').AreaStyle} AreaStyle
 * @typedef {import('./theme.js').Hatch} Hatch
 * @typedef {import('./i18n/index.js').Translator} Translator
 * @typedef {import('./camera.js').OrbitCamera} OrbitCamera
 * @typedef {import('./stage/options.js').StageOptions} StageOptions
 * @typedef {import('./stage/options.js').OpenOptions} OpenOptions
 * @typedef {import('./task/panel.js').SolutionRule} SolutionRule
 * @typedef {import('./stage/options.js').Notes} Notes
 * @typedef {import('./export/svg.js').FigureOptions} FigureOptions
 * @typedef {import('./ruled-view-events.js').SceneChangeDetail} SceneChangeDetail
 * @typedef {import('./ruled-view-events.js').ViewChangeDetail} ViewChangeDetail
 * @typedef {import('./ruled-view-events.js').CameraChangeDetail} CameraChangeDetail
 * @typedef {import('./ruled-view-events.js').RuledViewErrorDetail} RuledViewErrorDetail
 * @typedef {import('./ruled-view-events.js').EditDetail} EditDetail
 * @typedef {import('./ruled-view-events.js').HandleInfo} HandleInfo
 * @typedef {import('./ruled-view-events.js').RuledViewEvents} RuledViewEvents
 * @typedef {import('./ruled-view-events.js').RuledViewEventMap} RuledViewEventMap
 * @typedef {import('./task/format.js').Task} Task
 * @typedef {import('./task/panel.js').TaskReport} TaskReport
 * @typedef {import('./task/check.js').Answers} Answers
 * @typedef {import('./task/format.js').Answer} Answer
 * @typedef {import('./task/format.js').Condition} Condition
 * @typedef {import('./task/format.js').Words} Words
 * @typedef {import('./task/format.js').TaskState} TaskState
 * @typedef {import('./task/format.js').Bound} Bound
 * @typedef {import('./task/format.js').Draw} Draw
 * @typedef {import('./task/format.js').Drawn} Drawn
 * @typedef {import('./task/panel.js').PanelAttempt} PanelAttempt
 * @typedef {import('./task/panel.js').Check} Check
 * @typedef {import('./task/attempt.js').Attempt} Attempt
 * @typedef {import('./stage/exercise-api.js').ExerciseApi} ExerciseApi
 */
