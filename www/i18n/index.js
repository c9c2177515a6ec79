// Languages, every one loaded: i18n/translate.js with the German tables added, for what needs
// every language at hand without waiting (the package's ruledlab/view, <ruled-view>, the
// one-file build, Node). The page imports translate.js and loads the language it shows.
import de from './de.js';
import { addLanguage } from './translate.js';

addLanguage('de', de);

export {
  LANGUAGES,
  LANGUAGE_CODES,
  addLanguage,
  loadLanguage,
  pickLanguage,
  superscript,
  translator,
} from './translate.js';

/** @typedef {import('./translate.js').Translator} Translator */
