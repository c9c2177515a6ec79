// Every scene, in menu order (shared by the page, <ruled-view> and the one-file build).
import { scene as striction } from './striction.js';
import { scene as notation } from './notation.js';
import { scene as convergence } from './convergence.js';
import { scene as isometry } from './isometry.js';
import { scene as curves } from './curves.js';
import { scene as strip } from './strip.js';
import { scene as developable } from './developable.js';
import { scene as congruence } from './congruence.js';
import { scene as milling } from './milling.js';
import { scene as formula } from './formula.js';
import { scene as formulaCongruence } from './formula-congruence.js';
import { scene as focal } from './focal.js';
import { scene as lines } from './lines.js';
import { scene as klein } from './klein.js';
import { scene as large } from './large.js';
import { scene as data } from './data.js';

/** @type {import('../scene.js').Scene[]} */
export const SCENES = [
  striction,
  notation,
  convergence,
  isometry,
  curves,
  strip,
  developable,
  congruence,
  milling,
  formula,
  formulaCongruence,
  focal,
  lines,
  klein,
  large,
  data,
];
