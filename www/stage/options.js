// The options of a stage (what its owner, the page or <ruled-view>, tells it and is told), and
// how a scene is opened in it. Types only.

/**
 * @typedef {object} StageOptions
 * @property {boolean} [controls]   show the controls (and the readout)
 * @property {boolean} [text]       show the explanation
 * @property {string | null} [lang]
 * @property {boolean} [page]       the stage is the page's (the page scrolls; a narrow view stays at the top of the screen)
 * @property {boolean} [editable]   the reader may drag the scene's handles (the page; <ruled-view editable>)
 * @property {'space' | 'split'} [view]   the 3D view alone (default), or the Klein view of the scene's lines beside it
 * @property {{mix: number, turn: number, unit: number} | null} [projection]   the image the Klein
 *   view beside draws in (α, β in degrees, ℓ; default: the scene's own); each number held in its range
 * @property {(data: import('../scene.js').ImportedData) => void} [onEditAsData]   "Edit as data" of a
 *   scene without handles: show its sample as your data (the "data" scene)
 * @property {(change: {reason: 'scene' | 'param' | 'camera' | 'lang' | 'reset' | 'input' | 'view', ended: boolean}) => void} [onChange]
 * @property {(type: 'check' | 'solved' | 'solution', report: import('../task/panel.js').TaskReport) => void} [onTask]
 *   an exercise was checked, solved, or its solution shown (which counts for nothing)
 * @property {() => import('../task/panel.js').SolutionRule} [solutionRule]   when the solution is offered
 *   (default: after a first check that does not solve the exercise)
 * @property {() => void} [onLeaveTask]   the reader leaves the exercise (the page; an element with `leave`)
 * @property {() => boolean} [mayLeaveTask]   whether Leave is offered now (a page in a frame: only where allowed)
 * @property {(error: unknown, message: string) => void} [onError]   with the sentence shown
 * @property {(built: import('../scene.js').Built) => void} [onBuilt]
 */

/** @typedef {Array<{key: string, note: string, vars?: Record<string, string>}>} Notes */

/**
 * How to open a scene (Stage.open).
 * @typedef {object} OpenOptions
 * @property {number[] | null} [camera]   the camera (default: fitted to the scene)
 * @property {boolean} [fit]
 * @property {import('../scene.js').ImportedData | null} [data]   your data (the "data" scene)
 * @property {Notes} [notes]   link values that were not used, said in the view
 * @property {boolean} [autoplay]   play the first playable parameter (not if the reader prefers reduced motion)
 * @property {import('../paper.js').PaperPreset | null} [paper]   the paper's figure shown (if it is this scene's)
 * @property {import('../scene.js').Input | null} [input]   an edit of the scene's input (kept where it fits its handles)
 * @property {string} [inputNote]   a note about the edit (an i18n key)
 */

export {};
