// Every scene of the page, in menu order (shared by the page and the <ruled-view> element).
import { scene as notation } from './notation.js';
import { scene as striction } from './striction.js';
import { scene as convergence } from './convergence.js';
import { scene as isometry } from './isometry.js';
import { scene as curves } from './curves.js';
import { scene as strip } from './strip.js';
import { scene as congruence } from './congruence.js';
import { scene as milling } from './milling.js';
import { scene as lines } from './lines.js';
import { scene as large } from './large.js';
import { scene as data } from './data.js';

export const SCENES = [striction, notation, convergence, isometry, curves, strip, congruence, milling, lines, large, data];
