// Jeder deutsche Text der Seite und von <ruled-view>, nach Schlüssel: die Dateien dieses Ordners,
// eine je Gruppe von Schlüsselpräfixen (welche, steht oben in jeder; für jede Sprache dieselben
// Dateien). tests/node/languages.test.mjs prüft sie gegen die englischen.
import page from './page.js';
import view from './view.js';
import edit from './edit.js';
import task from './task.js';
import course from './course.js';
import errors from './errors.js';
import paper from './paper.js';
import scenes from './scenes.js';
import subdivision from './subdivision.js';
import congruences from './congruences.js';
import explanations from './explanations.js';
import developable from './developable.js';
import klein from './klein.js';

export default {
  ...page,
  ...view,
  ...edit,
  ...task,
  ...course,
  ...errors,
  ...paper,
  ...scenes,
  ...subdivision,
  ...congruences,
  ...explanations,
  ...developable,
  ...klein,
};
