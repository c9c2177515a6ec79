// The events of <ruled-view> and what each carries (types only; ruled-view.js fires them, the
// package's declarations name them): scene-change, view-change, camera-change, error, input and
// change of the reader's edits, task-check, task-solved and task-solution of an exercise, and what handles()
// returns.

/**
 * @typedef {object} SceneChangeDetail   `scene-change`: the scene shown and its parameters
 * @property {string} scene
 * @property {import('./scene.js').Params} params
 *
 * @typedef {object} ViewChangeDetail    `view-change`, during a camera move
 * @property {number} yaw
 * @property {number} pitch
 * @property {number} distance
 * @property {number[]} target
 *
 * @typedef {ViewChangeDetail & { camera: string }} CameraChangeDetail   `camera-change`, once a
 *   move ends: `camera` is the value of the element's `camera` attribute for this view
 *
 * @typedef {object} RuledViewErrorDetail   `error`: the message in the element's language
 * @property {string} message
 * @property {string | null} code           the error’s stable code (the book’s chapter "Errors")
 * @property {object | null} details        the core's details (reason, args, option, …)
 *
 * @typedef {object} EditDetail   `input` (during a drag) and `change` (at its end): what the reader made
 * @property {string} scene
 * @property {import('./scene.js').Input} data       the scene's input, per handle set (copies)
 * @property {Array<{key: string, label: string, value: number | string}>} readouts   the numbers
 *   shown: the label's i18n key, its text, and the value (a number, or a word)
 *
 * @typedef {object} HandleInfo   one handle of `handles()`
 * @property {string} set         the handle set's key ("rulings", "lines", "poses", "points")
 * @property {number} index       the handle's index in its set (pairs: 2k and 2k + 1 are line k's ends)
 * @property {string} name        its name, as the element says it ("ruling 5, end b")
 * @property {number[]} point     where it is, in the scene's coordinates
 * @property {number} x           where it is drawn, in CSS px from the element's left
 * @property {number} y           … and top
 * @property {boolean} visible    in front of the camera
 *
 * @typedef {object} RuledViewEvents       the events of <ruled-view> and their details
 * @property {CustomEvent<import('./task/panel.js').TaskReport>} task-check   how an exercise stands after a check
 * @property {CustomEvent<import('./task/panel.js').TaskReport>} task-solved   … the first time it is solved
 * @property {CustomEvent<import('./task/panel.js').TaskReport>} task-solution   the solution was shown (`counted` false: it earns nothing)
 * @property {CustomEvent<EditDetail>} input
 * @property {CustomEvent<EditDetail>} change
 * @property {CustomEvent<SceneChangeDetail>} scene-change
 * @property {CustomEvent<ViewChangeDetail>} view-change
 * @property {CustomEvent<CameraChangeDetail>} camera-change
 * @property {CustomEvent<RuledViewErrorDetail>} error
 *
 * @typedef {Omit<HTMLElementEventMap, 'error' | 'input' | 'change'> & RuledViewEvents} RuledViewEventMap
 */

export {};
