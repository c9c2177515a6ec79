// An exercise in a stage: the panel (task/panel.js: prompt, answers, Check, hints, solution,
// Start over, Leave) and what the exercise holds — its start (parameters and edit), which
// parameters it lets change, whether handles may move. Opening, starting over and showing the
// solution are changes of the stage's state (Stage.enter); a check is reported through the
// stage's options (`onTask`: the page posts it to a parent frame, the element fires events).
import { TaskPanel } from '../task/panel.js';
import { decodeInput } from '../edit/input.js';
import { withChoices } from '../scene.js';

export class ExerciseHost {
  /** @param {import('../stage.js').Stage} stage */
  constructor(stage) {
    this.stage = stage;
    /** @type {import('../scene.js').Input | null} the exercise's start edit */
    this.input = null;
    const { options } = stage;
    this.panel = new TaskPanel(stage.els.taskBox, {
      i18n: () => stage.i18n,
      state: () => {
        const built = stage.session.built;
        if (!built || !stage.scene || stage.els.root.classList.contains('rl-stale')) return null;
        return { scene: stage.scene, params: stage.params, context: stage.context(), built };
      },
      startOver: () => this.start(),
      showSolution: () => this.solve(),
      leave: options.onLeaveTask
        ? () => {
            options.onLeaveTask?.();
            // (the panel is gone, and the button with it)
            stage.keepKeyboard();
          }
        : null,
      mayLeave: () => options.mayLeaveTask?.() ?? true,
      solutionRule: () => options.solutionRule?.() ?? { after: 1 },
      report: (type, report) => {
        // (where the panel is shown its verdict, a status, says it: once is enough)
        if (type === 'solved' && stage.els.taskBox.offsetParent === null)
          stage.announcer.say(stage.i18n.t('task.solved'));
        options.onTask?.(type, report);
      },
    });
  }

  /** What "back" of the editor restores in an exercise (its start edit), or null outside one. */
  startInput() {
    return this.stage.task ? this.input : null;
  }

  /**
   * Takes `task` as the stage's exercise (null: none): its start edit, and whether its handles
   * may move. The stage's state changes in Stage.openTask.
   * @param {import('../task/format.js').Task | null} task
   */
  take(task) {
    this.input = task?.input ? decodeInput(task.input) : null;
    this.stage.edit.enabled = task ? task.change.includes('handles') : !!this.stage.options.editable;
  }

  /** Back to the exercise's start (its parameters and edit). */
  start() {
    const { stage } = this;
    const task = stage.task;
    if (!task || !stage.scene) return;
    stage.enter(stage.scene, withChoices(stage.scene, task.params), { fit: true, input: this.input });
    stage.report('reset', true);
  }

  /** The exercise's solution on screen (its parameters and edit). */
  solve() {
    const { stage } = this;
    const task = stage.task;
    if (!task?.solution || !stage.scene) return;
    const solution = task.solution;
    const input = solution.input ? decodeInput(solution.input) : this.input;
    stage.enter(stage.scene, withChoices(stage.scene, { ...task.params, ...(solution.params ?? {}) }), {
      camera: stage.viewer.camera.toArray(),
      fit: false,
      input,
    });
    stage.report('param', true);
  }
}
