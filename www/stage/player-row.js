// The player of a stage: the play button of a parameter (in its control row) sweeps it, the
// player row under the controls offers the speed and a single step, Space and "." do the same
// from the view. A parameter an exercise holds is not played. The values go to the stage as any
// other change of a parameter (`set`, a dispatch), so the link, the readout and the picture
// follow; the row draws from the state (render).
import { Player } from '../ui/player.js';
import { heldReason } from '../store.js';

/**
 * What the player asks of its stage.
 * @typedef {object} PlayerPorts
 * @property {() => import('../store.js').StageState} state
 * @property {() => import('../i18n/index.js').Translator} i18n
 * @property {(key: string, value: number, ended: boolean) => void} set   a value played (ended: the last)
 * @property {() => void} announce   the readout said, once an interaction ends
 * @property {(key: string | null) => void} playing   the controls mark the parameter playing
 */

export class PlayerRow {
  /**
   * @param {HTMLElement} row   its place under the controls
   * @param {PlayerPorts} ports
   */
  constructor(row, ports) {
    this.row = row;
    this.ports = ports;
    this.player = new Player((key, value) => {
      const p = this.param(key);
      if (p) ports.set(key, Number(value.toFixed(Player.stepped(p) ? 0 : 4)), false);
    });
  }

  /** @param {string} key */
  param(key) {
    return this.ports.state().scene?.params.find((p) => p.key === key);
  }

  get playing() {
    return this.player.playing;
  }

  /** The parameter Space plays and "." steps: the one playing, or the first that may move now. */
  playableKey() {
    const state = this.ports.state();
    const { scene, params } = state;
    return (
      this.player.param?.key ??
      scene?.params.find((p) => p.play && !p.unless?.(params) && !heldReason(state, p.key))?.key
    );
  }

  /** The row — speed and single step — shown when the scene has a parameter to play. @param {import('../store.js').StageState} state */
  render(state) {
    const row = this.row;
    const { t, lang } = this.ports.i18n();
    const doc = row.ownerDocument;
    // (not a parameter an exercise holds)
    const playable =
      state.scene?.params.filter((p) => p.play && heldReason(state, p.key) !== 'task.reason.locked') ?? [];
    row.hidden = playable.length === 0;
    row.replaceChildren();
    if (!playable.length) return;
    const speedLabel = Object.assign(doc.createElement('label'), { textContent: t('player.speed') });
    const speed = doc.createElement('select');
    for (const s of [0.25, 0.5, 1, 2, 4])
      speed.add(new Option(`${lang === 'de' ? String(s).replace('.', ',') : s}×`, String(s)));
    speed.value = String(this.player.speed);
    speed.addEventListener('change', () => (this.player.speed = Number(speed.value)));
    speedLabel.append(' ', speed);
    const step = Object.assign(doc.createElement('button'), { type: 'button', textContent: t('player.step') });
    step.addEventListener('click', () => this.step());
    row.append(speedLabel, step);
  }

  /** One step of the playable parameter. */
  step() {
    const key = this.playableKey();
    const p = key ? this.param(key) : undefined;
    if (!key || !p) return;
    this.stop();
    this.player.step(p, Number(this.ports.state().params[key]));
    this.ports.announce();
  }

  /** Plays or pauses parameter `key`. */
  toggle(/** @type {string} */ key) {
    const p = this.param(key);
    if (!p || heldReason(this.ports.state(), key)) return;
    if (this.player.playing && this.player.param?.key === key) {
      this.stop();
      this.ports.announce();
      return;
    }
    this.player.play(p, Number(this.ports.state().params[key]));
    this.ports.playing(key);
  }

  /** Stops playing (the value reached is the change that ends). */
  stop() {
    const key = this.player.playing ? this.player.param?.key : null;
    this.player.stop();
    if (key) this.ports.set(key, Number(this.ports.state().params[key]), true);
    this.ports.playing(null);
  }
}
