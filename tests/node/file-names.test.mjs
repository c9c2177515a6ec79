// The names of the page's downloads say what the figure is: the paper's figure and scene, the
// counts a scene is made of, what differs from the defaults, an edit and imported data by a hash;
// two different views of every scene and figure never get the same name.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { PRESETS } from '../../www/paper.js';
import { defaults } from '../../www/scene.js';
import { fileStem } from '../../www/page/file-names.js';

const scene = (/** @type {string} */ id) =>
  /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === id));
const preset = (/** @type {string} */ id) =>
  /** @type {import('../../www/paper.js').PaperPreset} */ (PRESETS.find((p) => p.id === id));

test('a scene: its counts always, what differs from its defaults as key and value, choice, or switch', () => {
  const striction = scene('striction');
  assert.equal(fileStem({ scene: striction, params: defaults(striction) }), 'striction-n36');
  assert.equal(
    fileStem({
      scene: striction,
      params: { ...defaults(striction), n: 48, exact: true, strip: false, surface: 'helicoid' },
    }),
    'striction-helicoid-n48-no-strip-exact',
  );
  const curves = scene('curves');
  assert.equal(fileStem({ scene: curves, params: { ...defaults(curves), w: 0.125 } }), 'curves-steps4-w0.125');
  assert.equal(fileStem({ scene: scene('notation'), params: {} }), 'notation');
});

test('a figure of the paper: its name and scene, then what the reader changed', () => {
  const fig13 = preset('fig13');
  const fig15 = preset('fig15');
  const congruence = scene('congruence');
  const at = (/** @type {typeof fig13} */ p) => ({ ...defaults(congruence), ...p.params });
  assert.equal(fileStem({ scene: congruence, params: at(fig13), paper: fig13 }), 'fig13-congruence');
  assert.equal(fileStem({ scene: congruence, params: at(fig15), paper: fig15 }), 'fig15-congruence');
  assert.equal(
    fileStem({ scene: congruence, params: { ...at(fig13), steps: 2 }, paper: fig13 }),
    'fig13-congruence-steps2',
  );
  // Fig. 15 is the scene's default view: without the figure chosen it is named as the scene
  assert.equal(fileStem({ scene: congruence, params: at(fig15) }), 'congruence-steps1');
});

test('an edit, imported data and typed formulas are told apart by a hash; a long name is shortened', () => {
  const striction = scene('striction');
  const params = defaults(striction);
  const a = fileStem({ scene: striction, params, input: { rulings: new Float64Array([0, 0, 0, 1, 0, 0]) } });
  const b = fileStem({ scene: striction, params, input: { rulings: new Float64Array([0, 0, 0, 1, 0, 0.5]) } });
  assert.match(a, /^striction-n36-edited-[0-9a-f]{6}$/);
  assert.notEqual(a, b);
  const data = scene('data');
  assert.match(
    fileStem({ scene: data, params: defaults(data), data: { segments: new Float64Array([0, 0, 0, 1, 1, 1]) } }),
    /^data-data-[0-9a-f]{6}$/,
  );
  const formula = scene('formula');
  const x = fileStem({ scene: formula, params: { ...defaults(formula), az: 'u' } });
  const y = fileStem({ scene: formula, params: { ...defaults(formula), az: 'v' } });
  assert.match(x, /^formula-n36-levels8-steps1-formulas-[0-9a-f]{6}$/);
  assert.notEqual(x, y);
  const long = fileStem({
    scene: formula,
    params: {
      ...defaults(formula),
      a: 1.25,
      b: -2.5,
      c: 0.75,
      u: 1.5,
      h0: 0.45,
      t: 0.5,
      tool: 'isometry',
      closed: false,
      az: 'u',
    },
  });
  assert.match(long, /^formula-[0-9a-f]{6}$/);
  assert.equal(
    fileStem({ scene: formula, params: { ...defaults(formula), h0: 0.45 } }),
    'formula-n36-h0_0.45-levels8-steps1',
  );
  assert.match(fileStem({ scene: formula, params: defaults(formula) }), /^[\w.-]+$/);
});

test('no two views of a scene that differ in one control, and no two figures of the paper, share a name', () => {
  /** @type {Map<string, string>} */
  const seen = new Map();
  const name = (/** @type {string} */ what, /** @type {string} */ stem) => {
    assert.ok(!seen.has(stem) || seen.get(stem) === what, `${what} and ${seen.get(stem)} are both ${stem}`);
    seen.set(stem, what);
  };
  for (const s of SCENES) {
    const base = defaults(s);
    name(`${s.id}`, fileStem({ scene: s, params: base }));
    for (const p of s.params) {
      /** @type {Array<number | string | boolean>} */
      const others =
        p.type === 'checkbox'
          ? [!base[p.key]]
          : p.type === 'select'
            ? (p.options?.() ?? []).map(([v]) => v).filter((v) => v !== base[p.key])
            : p.type === 'range'
              ? [p.min, p.max].filter((v) => v !== base[p.key])
              : [`${base[p.key]}+1`];
      for (const v of others) name(`${s.id} ${p.key}=${v}`, fileStem({ scene: s, params: { ...base, [p.key]: v } }));
    }
  }
  for (const p of PRESETS) {
    const s = scene(p.scene);
    name(`paper ${p.id}`, fileStem({ scene: s, params: { ...defaults(s), ...p.params }, paper: p }));
  }
});
