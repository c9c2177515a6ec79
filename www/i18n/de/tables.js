// Die Tabellen dieses Ordners, eine je Gruppe von Schlüsselpräfixen: index.js fügt sie zusammen.
export { default as page } from './page.js';
export { default as view } from './view.js';
export { default as edit } from './edit.js';
export { default as task } from './task.js';
export { default as course } from './course.js';
export { default as errors } from './errors.js';
export { default as paper } from './paper.js';
export { default as scenes } from './scenes.js';
export { default as subdivision } from './subdivision.js';
export { default as congruences } from './congruences.js';
export { default as explanations } from './explanations.js';
export { default as developable } from './developable.js';
export { default as klein } from './klein.js';
