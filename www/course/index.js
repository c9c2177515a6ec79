// ruledlab/course: exercises as packages a course system records — a SCORM 1.2 or 2004 package of
// one or more exercises (the score their sum), an .h5p file of one, and what reads them back. In a
// browser the page files they carry are fetched next to these modules; in Node, give them:
//   import { readFileSync } from 'node:fs';
//   import { createRequire } from 'node:module';
//   import { scormPackage, h5pPackage } from 'ruledlab/course';
//   const require = createRequire(import.meta.url);
//   const page = readFileSync(require.resolve('ruledlab/ruledlab.html'), 'utf8');
//   const zip = await scormPackage(['torsal-pair', 'chaikin-count'], { standard: 'scorm2004', page });
export { scormPackage, scormManifest, packageTasks, LAUNCH } from './scorm-package.js';
export { h5pPackage, h5pParams, readH5p, libraryJson, semanticsJson, H5P_LIBRARY, H5P_FOLDER } from './h5p-package.js';
export { readScorm } from './read.js';
export { makeZip, readZip, PackageError } from './zip.js';

// The types of the pieces above, for TypeScript users (generated from this JSDoc and the sources').
/**
 * @typedef {import('./scorm-package.js').ScormOptions} ScormOptions
 * @typedef {import('./scorm-package.js').Readers} Readers
 * @typedef {import('./h5p-package.js').H5PParams} H5PParams
 * @typedef {import('./h5p-package.js').H5POptions} H5POptions
 * @typedef {import('../task/format.js').Task} Task
 */
