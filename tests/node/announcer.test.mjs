// What a stage says to screen readers (www/stage/announcer.js): the readout waits for its second,
// and a step said now drops a readout still waiting — an undo's readout must not be read out over
// the snap of the drag that follows it.
import { test, mock } from 'node:test';
import assert from 'node:assert/strict';
import { Announcer } from '../../www/stage/announcer.js';

test('a readout waits for its second; what is said now drops the readout still waiting', () => {
  mock.timers.enable({ apis: ['setTimeout', 'Date'] });
  const window = /** @type {any} */ (globalThis).window;
  /** @type {any} */ (globalThis).window = globalThis;
  const clock = mock.method(performance, 'now', () => Date.now());
  try {
    mock.timers.tick(10_000);
    const status = { textContent: '' };
    const announcer = new Announcer(/** @type {any} */ (status), () => 'δ̄: 1');
    announcer.announce('Moved');
    assert.equal(status.textContent, 'Moved. δ̄: 1', 'the first readout is said at once');
    announcer.announce('Undone');
    assert.equal(status.textContent, 'Moved. δ̄: 1', 'the next waits for its second');
    mock.timers.tick(400);
    announcer.say('on the footpoint f₄,₅');
    mock.timers.tick(2000);
    assert.equal(status.textContent, 'on the footpoint f₄,₅', 'the waiting readout is dropped');
    announcer.announce('Moved');
    assert.equal(status.textContent, 'Moved. δ̄: 1', 'a readout after it is said');
  } finally {
    clock.mock.restore();
    /** @type {any} */ (globalThis).window = window;
    mock.timers.reset();
  }
});
