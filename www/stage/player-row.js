// The player of a stage: the play button of a parameter (in its control row) sweeps it, the
// player row under the controls offers the speed and a single step, Space and "." do the same
// from the view. A parameter an exercise holds is not played. The values go to the stage as any
// other change of a parameter (Stage.setParam), so the link, the readout and the picture follow.
import { Player } from '../ui/player.js';

export class PlayerRow {
  /** @param {import('../stage.js').Stage} stage */
  constructor(stage) {
    this.stage = stage;
    this.player = new Player((key, value) => {
      const p = this.param(key);
      if (p) stage.setParam(key, Number(value.toFixed(Player.stepped(p) ? 0 : 4)), false);
    });
  }

  /** @param {string} key */
  param(key) {
    return this.stage.scene?.params.find((p) => p.key === key);
  }

  get playing() {
    return this.player.playing;
  }

  /** The parameter Space plays and "." steps: the one playing, or the first that may move now. */
  playableKey() {
    const { scene, params } = this.stage;
    return (
      this.player.param?.key ??
      scene?.params.find((p) => p.play && !p.unless?.(params) && !this.stage.heldReason(p.key))?.key
    );
  }

  /** The row: speed and single step, shown when the scene has a parameter to play. */
  build() {
    const stage = this.stage;
    const row = stage.els.player;
    const { t, lang } = stage.i18n;
    const doc = row.ownerDocument;
    // (not a parameter an exercise holds)
    const playable =
      stage.scene?.params.filter((p) => p.play && stage.heldReason(p.key) !== 'task.reason.locked') ?? [];
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
    this.player.step(p, Number(this.stage.params[key]));
    this.stage.announce();
  }

  /** Plays or pauses parameter `key`. */
  toggle(/** @type {string} */ key) {
    const p = this.param(key);
    if (!p || this.stage.heldReason(key)) return;
    if (this.player.playing && this.player.param?.key === key) {
      this.stop();
      this.stage.announce();
      return;
    }
    this.player.play(p, Number(this.stage.params[key]));
    this.stage.controls?.playing(key);
  }

  /** Stops playing (the value reached is the change that ends). */
  stop() {
    if (this.player.playing) this.stage.report('param', true);
    this.player.stop();
    this.stage.controls?.playing(null);
  }
}
