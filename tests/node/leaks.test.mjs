// Memory: explicit free keeps wasm memory flat over 10⁴ create/compute/free cycles, and objects
// that are never freed are reclaimed by the FinalizationRegistry (wasm-bindgen --weak-refs)
// without breaking explicit free. Needs --expose-gc (scripts/test.sh passes it).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import * as ruledlab from '../../pkg/ruledlab.js';

const wasm = ruledlab.initSync({ module: readFileSync(new URL('../../pkg/ruledlab_bg.wasm', import.meta.url)) });
const { AnalyticSurface, RuledSurface } = ruledlab;
const megabytes = () => wasm.memory.buffer.byteLength / 2 ** 20;
const settle = async () => {
  for (let k = 0; k < 3; k++) {
    global.gc();
    await new Promise((r) => setTimeout(r, 10)); // finalizers run after the collection
  }
};

test('10⁴ create/compute/free cycles keep wasm memory flat', () => {
  const hyp = AnalyticSurface.byName('hyperboloid');
  const cycle = () => {
    const s = hyp.sample(1000);
    s.invariants();
    const r = s.subdivide({ scheme: 'four-point' });
    const c = r.conoidal();
    for (const o of [s, r, c]) o.free();
  };
  for (let i = 0; i < 200; i++) cycle();
  const before = megabytes();
  for (let i = 0; i < 10000; i++) cycle();
  const after = megabytes();
  console.log(`# explicit free: wasm memory ${before} MiB → ${after} MiB over 10⁴ cycles`);
  assert.equal(after, before);
});

test('objects never freed are reclaimed by the FinalizationRegistry; explicit free still works', {
  skip: typeof global.gc !== 'function' && 'needs --expose-gc',
}, async () => {
  const hyp = AnalyticSurface.byName('hyperboloid');
  for (let i = 0; i < 100; i++) hyp.sample(5000).subdivide({ scheme: 'chaikin' });
  await settle();
  const before = megabytes();
  for (let round = 0; round < 20; round++) {
    for (let i = 0; i < 100; i++) hyp.sample(5000).subdivide({ scheme: 'chaikin' }); // ~0.7 MB each, never freed
    await settle();
  }
  const after = megabytes();
  console.log(`# no free: wasm memory ${before} MiB → ${after} MiB over 2000 unfreed pairs (~1.4 GB if leaked)`);
  assert.ok(after - before < 64, `grew by ${after - before} MiB`);
  // explicit free after the registry exists: no double free, the module keeps working
  const s = RuledSurface.fromSegments(hyp.sample(10).segments());
  s.free();
  await settle();
  assert.equal(hyp.sample(10).length, 10);
});
