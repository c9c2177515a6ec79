// Every English text of the page and of <ruled-view>, by key: the files of this folder, one per
// group of key prefixes (the prefixes each holds are at its top; the same files for every
// language). tests/node/languages.test.mjs fails on a key defined twice, one a language lacks,
// a key outside its file's prefixes, and placeholders that differ between languages.
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
