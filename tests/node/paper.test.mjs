// The paper's figures and examples as presets (www/paper.js): every figure 1–18 and example 1–6
// is there, each names a real scene with valid values and texts in every language, `#paper=…`
// links open and restore it, and the book's page of the figures is generated from the same list.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import './load.mjs';
import { SCENES } from '../../www/scenes/index.js';
import { PRESETS, findPreset, atPreset } from '../../www/paper.js';
import { readValue, serialize, defaults } from '../../www/scene.js';
import { readLink, writeLink } from '../../www/link.js';
import { translator, LANGUAGE_CODES } from '../../www/i18n/index.js';

test('every figure (1–18) and example (1–6) has a preset, ids unique', () => {
  const ids = PRESETS.map((p) => p.id);
  assert.equal(new Set(ids).size, ids.length);
  for (let k = 1; k <= 18; k++) assert.ok(ids.includes(`fig${k}`), `Fig. ${k}`);
  for (let k = 1; k <= 6; k++) assert.ok(ids.includes(`ex${k}`), `Example ${k}`);
  // the two cases of Fig. 5 (caption fails / holds) and both halves of Fig. 13
  for (const id of ['fig5-orthogonal', 'fig13-right']) assert.ok(ids.includes(id), id);
});

test('each preset names a scene, its keys and valid values, and texts in every language', () => {
  for (const preset of PRESETS) {
    const scene = SCENES.find((s) => s.id === preset.scene);
    assert.ok(scene, `${preset.id}: scene ${preset.scene}`);
    for (const [key, value] of Object.entries(preset.params)) {
      const p = scene.params.find((q) => q.key === key);
      assert.ok(p, `${preset.id}: ${scene.id} has no parameter ${key}`);
      const read = readValue(p, serialize(p, value));
      assert.equal(read.note, undefined, `${preset.id}: ${key} = ${value} is not valid`);
      assert.equal(read.value, value, `${preset.id}: ${key} does not survive a link`);
    }
    for (const lang of LANGUAGE_CODES) {
      const { has } = translator(lang);
      for (const key of [preset.label, preset.caption, preset.note, preset.beyond, `paper.data.${preset.data}`].filter(
        Boolean,
      )) {
        assert.ok(has(/** @type {string} */ (key)), `${lang}: ${key}`);
      }
    }
    assert.ok(atPreset(preset, scene, { ...defaults(scene), ...preset.params }), `${preset.id} is at its own settings`);
  }
});

test('#paper=… opens the figure; a link written from it restores it; link values override; unknown ids are noted', () => {
  for (const preset of PRESETS) {
    const state = readLink(`#paper=${preset.id}`, SCENES);
    assert.equal(state.scene.id, preset.scene);
    assert.equal(state.paper, preset.id);
    for (const [k, v] of Object.entries(preset.params)) assert.equal(state.params[k], v, `${preset.id}: ${k}`);
    const again = readLink(writeLink(state), SCENES);
    assert.equal(again.paper, preset.id);
    assert.deepEqual(again.params, state.params);
    assert.deepEqual(again.notes, []);
  }
  const fig3 = /** @type {import('../../www/paper.js').PaperPreset} */ (findPreset('fig3'));
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === 'striction'));
  const changed = readLink('#paper=fig3&n=72', SCENES);
  assert.equal(changed.params.n, 72);
  assert.equal(changed.params.midpoints, true);
  assert.equal(atPreset(fig3, scene, changed.params), false);
  // a link naming another scene shows that scene without the figure
  const other = readLink('#paper=fig3&scene=curves', SCENES);
  assert.equal(other.scene.id, 'curves');
  assert.equal(other.paper, null);
  const unknown = readLink('#paper=fig99', SCENES);
  assert.equal(unknown.paper, null);
  assert.deepEqual(
    unknown.notes.map((n) => n.note),
    ['note.unknownFigure'],
  );
});

test("a parameter that does nothing at the figure's settings does not count as a change", () => {
  const fig12 = /** @type {import('../../www/paper.js').PaperPreset} */ (findPreset('fig12'));
  const scene = /** @type {import('../../www/scene.js').Scene} */ (SCENES.find((s) => s.id === 'congruence'));
  // steps is disabled for the diagonal scheme
  assert.ok(atPreset(fig12, scene, { ...defaults(scene), ...fig12.params, steps: 3 }));
  assert.ok(!atPreset(fig12, scene, { ...defaults(scene), ...fig12.params, congruence: 'sphere' }));
});

test('the book\'s page "The paper, figure by figure" is generated from the presets and current', () => {
  execFileSync(process.execPath, [new URL('../../scripts/paper-table.mjs', import.meta.url).pathname, '--check'], {
    stdio: 'pipe',
  });
});
