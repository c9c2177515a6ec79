// Loads the built package in Node the documented way: initSync with the wasm bytes.
import { readFileSync } from 'node:fs';
import * as ruledlab from '../../pkg/ruledlab.js';

ruledlab.initSync({ module: readFileSync(new URL('../../pkg/ruledlab_bg.wasm', import.meta.url)) });

export default ruledlab;
