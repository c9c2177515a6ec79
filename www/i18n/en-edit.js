// English texts of editing the geometry: the handles, their names, the edit's buttons, keys and
// notes (www/edit/).

export default {
  'edit.button': 'Edit',
  'edit.buttonTitle':
    'Move the points of the figure with the keyboard (E); a mouse or a finger can drag them at any time',
  'edit.undo': 'Undo',
  'edit.undoTitle': 'Undo the last move (Ctrl+Z)',
  'edit.redo': 'Redo',
  'edit.redoTitle': 'Redo (Ctrl+Shift+Z or Ctrl+Y)',
  'edit.moveLabel': 'A drag moves a point',
  'edit.mode.view': 'facing you',
  'edit.mode.viewTitle': 'in the plane through the point that faces you',
  'edit.mode.line': 'along its line',
  'edit.mode.lineTitle': 'along the ruling or axis it belongs to (or hold Shift while dragging)',
  'edit.mode.vertical': 'up and down',
  'edit.mode.verticalTitle': 'along the z-axis (or hold Alt while dragging)',
  'edit.done': 'Done',
  'edit.asData': 'Edit as data',
  'edit.from': 'Edited from: {from}.',
  'edit.restore': 'Back to the built-in input',
  'edit.reason.fixed': 'Held by your edit: “Back to the built-in input” frees it.',
  'edit.tooLarge': 'This edit has more than 200 points: the link does not carry it; this tab keeps it.',
  'edit.tooLargeNoStorage':
    'This edit has more than 200 points: the link does not carry it, and this page cannot keep it (a reload loses it).',
  'edit.entered': 'Editing {count:point:points}: Tab steps through them, the arrow keys move one, Escape stops.',
  'edit.left': 'Editing stopped.',
  'edit.undone': 'Undone',
  'edit.redone': 'Redone',
  'edit.restored': 'Back to the built-in input',
  'edit.cancelled': 'Move cancelled',
  'view.hintEdit': 'drag: turn · drag a point: move it · shift/right-drag: move · wheel: zoom · E: edit · ?: keys',

  'view.hintTouchEdit': 'one finger: turn, or drag a point · two fingers: move and zoom',

  'share.editTooLarge':
    'Your edit has more than 200 points: the link and the snippets do not carry it (the one-file download does).',

  'handle.ruling': 'ruling {i}, end {end}',
  'handle.end.a': 'a',
  'handle.end.b': 'b',
  'handle.line': 'line ({row}, {col}), point {end}',
  'handle.end.p': 'p',
  'handle.end.q': 'q',
  'handle.pose': 'pose {i}, {end}',
  'handle.end.tip': 'tip',
  'handle.end.axis': 'axis end',
  'handle.point': 'control point {i}',

  'problem.parallel': 'Rulings {i} and {j} are parallel: δ is undefined there.',
  'problem.parallelMany':
    '{count} pairs of consecutive rulings are parallel (the first: {i} and {j}): δ is undefined there.',
  'note.badInput': 'The edited input in the link does not fit this scene; the built-in input is shown.',

  'keys.editTitle': 'Editing the points (E)',
  'keys.edit': 'start or stop editing the points',
  'keys.editStep': 'next or previous point',
  'keys.editMove': 'move the point across the view',
  'keys.editDepth': 'move it away from you or towards you',
  'keys.editFine': 'held with a move: a tenth of the step',
  'keys.editEnd': 'end the move (one step of undo)',
  'keys.editCancel': 'cancel the move; again: stop editing',
  'keys.undo': 'undo',
  'keys.redo': 'redo',
  'touch.handle': 'one finger on a point',
  'touch.handleWhat': 'drag it',
  'touch.hold': 'hold a point',
  'touch.holdWhat': 'see its coordinates',

  'edit.from.surface': '{surface}, {n:ruling:rulings}',
  'edit.from.notation': 'three rulings of the hyperboloid of Example 1 around u = {u}, {spacing} apart',
  'edit.from.convergence': 'three rulings of {surface} around u = {u}',
  'edit.from.curves': 'the control polygon of Figs. 7–8',
  'edit.from.strip': '12 rulings of the quartic surface of Example 3',
  'edit.from.congruence': '{congruence}, {rows} × {cols} lines',
  'edit.from.lines': 'nine rulings of the {surface} with their endpoints slid',
  'edit.from.poses': 'the {poses} tool poses of Example 6',
  'edit.from.data': 'your imported data',
  'edit.from.example': 'the example strip',
  'edit.describe': 'Your edit of the input. {description}',
  'edit.edited': 'your edit of {what}',
  'striction.describeEdited':
    'Your edit of {n} rulings of {surface}; shown: {shown}. Without the exact surface there are no errors to measure.',
  'notation.describeEdited':
    'Your edit of three consecutive rulings, with their common perpendiculars, footpoints and the midpoint m_i; the angle between R_i and R_{i+1} is {angle} rad and their distance {distance}.',
  'convergence.describeEdited':
    'Your edit of the three rulings, with their common perpendiculars, footpoints and striction point; the mean distribution parameter at the middle ruling is {delta}.',
  'convergence.editedNote':
    'The orders are measured against the exact surface, which your edit does not have: “Back to the built-in input” measures them again.',
  'convergence.readout.delta01': 'δ_{0,1}',
  'convergence.readout.delta12': 'δ_{1,2}',
  'convergence.readout.deltaMeanEdited': 'mean δ at the middle ruling',
  'strip.describeEdited':
    'Your edit of the 12 given rulings with 11 rulings inserted by {scheme}, n = {n}; without the quartic there is no distance to measure.',
  'congruence.describeEdited':
    'Your edit of {congruence}: {rows} × {cols} given lines refined by {scheme} into {lines} lines.',
  'lines.describeEdited':
    'Your edit of the nine given rulings of the {surface}; against the schemes\u2019 rulings of the unslid surface, the endpoint scheme\u2019s new rulings turned by up to {endpointTurn} rad, the line-space scheme\u2019s by {lineTurn}.',
  'milling.describeEdited':
    'Your edit of the {poses} given poses of a ball-end tool, refined by {steps:step:steps} of {scheme} into {total} poses; the machined surface misses the target profile by at most {deviation}.',
  'edit.from.importedPoses': 'your {poses} imported tool poses',
  'milling.describeImportedEdited':
    'Your edit of {poses} imported tool poses, refined by {steps:step:steps} of {scheme} into {total} poses.',
};
