// Jeder deutsche Text der Seite und von <ruled-view>, nach Schlüssel: die Dateien dieses Ordners,
// eine je Gruppe von Schlüsselpräfixen (welche, steht oben in jeder; für jede Sprache dieselben
// Dateien). tests/node/languages.test.mjs prüft sie gegen die englischen.
import * as tables from './tables.js';

/** Die Tabellen als eine (ihre Schlüssel sind disjunkt: tests/node/languages.test.mjs). */
export default /** @type {Record<string, string>} */ (Object.assign({}, ...Object.values(tables)));
