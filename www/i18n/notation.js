// Labels that are notation, written alike in every language: the translators read them after
// the language's table and English (i18n/translate.js). tests/node/languages.test.mjs fails
// where a language defines one of them too.
// Keys: formula.param.ax … ez, formulaCongruence.param.px … ez

export default {
  'formula.param.ax': 'a(u): x',
  'formula.param.ay': 'a(u): y',
  'formula.param.az': 'a(u): z',
  'formula.param.ex': 'e(u): x',
  'formula.param.ey': 'e(u): y',
  'formula.param.ez': 'e(u): z',
  'formulaCongruence.param.px': 'p(u, v): x',
  'formulaCongruence.param.py': 'p(u, v): y',
  'formulaCongruence.param.pz': 'p(u, v): z',
  'formulaCongruence.param.ex': 'e(u, v): x',
  'formulaCongruence.param.ey': 'e(u, v): y',
  'formulaCongruence.param.ez': 'e(u, v): z',
};
