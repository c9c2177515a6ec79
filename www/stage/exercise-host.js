// An exercise in a stage: the panel (task/panel.js: prompt, answers, Check, hints, solution,
// Start over, Leave) and what the exercise asks of the view — its start (parameters and edit)
// and its solution's state, each a change the stage makes (`ports.enter`). The exercise itself is
// the state's (store.js); a check is reported through `ports.report` (the page posts it to a
// parent frame, the element fires events).
import { TaskPanel } from '../task/panel.js';
import { decodeInput } from '../edit/input.js';
import { withChoices } from '../scene.js';

/**
 * What the exercise asks of its stage.
 * @typedef {object} ExercisePorts
 * @property {() => import('../store.js').StageState} state
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {() => {scene: import('../scene.js').Scene, params: import('../scene.js').Params, context: import('../scene.js').Context, built: import('../scene.js').Built} | null} view
 *   what is shown now (null while the scene cannot be computed)
 * @property {(params: import('../scene.js').Params, input: import('../scene.js').Input | null, keepCamera: boolean) => void} enter
 *   the scene shown anew with these parameters and edit (keepCamera: from where it is seen now)
 * @property {(() => void) | null} leave   the owner leaves the exercise (an element cannot unless allowed)
 * @property {() => boolean} mayLeave
 * @property {() => import('../task/panel.js').SolutionRule} solutionRule
 * @property {(type: 'check' | 'solved' | 'solution', report: import('../task/panel.js').TaskReport) => void} report
 * @property {(text: string) => void} say
 */

export class ExerciseHost {
  /**
   * @param {HTMLElement} box   the exercise's place in the panel
   * @param {ExercisePorts} ports
   */
  constructor(box, ports) {
    this.box = box;
    this.ports = ports;
    this.panel = new TaskPanel(box, {
      i18n: ports.i18n,
      state: ports.view,
      startOver: () => this.start(),
      showSolution: () => this.solve(),
      leave: ports.leave,
      mayLeave: ports.mayLeave,
      solutionRule: ports.solutionRule,
      report: (type, report) => {
        // (where the panel is shown its verdict, a status, says it: once is enough)
        if (type === 'solved' && box.offsetParent === null) ports.say(ports.i18n().t('task.solved'));
        ports.report(type, report);
      },
    });
  }

  /** The exercise's start edit (its handles as it begins), or null outside one. */
  startInput() {
    const task = this.ports.state().exercise;
    return task?.input ? decodeInput(task.input) : null;
  }

  /** Back to the exercise's start (its parameters and edit). */
  start() {
    const { scene, exercise } = this.ports.state();
    if (!exercise || !scene) return;
    this.ports.enter(withChoices(scene, exercise.params), this.startInput(), false);
  }

  /** The exercise's solution on screen (its parameters and edit). */
  solve() {
    const { scene, exercise } = this.ports.state();
    if (!exercise?.solution || !scene) return;
    const solution = exercise.solution;
    const input = solution.input ? decodeInput(solution.input) : this.startInput();
    this.ports.enter(withChoices(scene, { ...exercise.params, ...(solution.params ?? {}) }), input, true);
  }
}
