// Deprecated: the entry of `ruledlab/view` is www/index.js. This address stays for one release
// for pages that load the element by a script's address (`<script type="module"
// src="…/www/view.js">`); it is the same module.
export * from './index.js';
