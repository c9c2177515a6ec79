// The styles of a view with its controls, shared by the page (adopted into the document) and
// every <ruled-view> (adopted into its shadow root): one stylesheet, no inline style attributes,
// so a strict Content-Security-Policy needs no 'unsafe-inline'.

export const CSS = `
.rl-stage { --ink: #1d2435; --muted: #535c70; --paper: #fbfaf7; --panel: #ffffff; --line: #e1ded5; --focus: #0b5cad;
  display: flex; width: 100%; height: 100%; min-height: 0; color: var(--ink); background: var(--paper);
  font: 15px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; }
.rl-stage *, .rl-stage *::before, .rl-stage *::after { box-sizing: border-box; }
.rl-stage [hidden] { display: none !important; }
.rl-no-controls .rl-controls, .rl-no-controls .rl-player, .rl-no-controls .rl-readout, .rl-no-controls .rl-claims, .rl-no-controls .rl-readout-note, .rl-no-controls .rl-caption, .rl-no-controls .rl-downloads, .rl-no-controls .rl-figure { display: none !important; }
.rl-view { position: relative; flex: 1 1 auto; min-width: 0; min-height: 240px; overflow: hidden; background: var(--paper); }
/* narrow (stage.js layout()): the view over its panel, the view keeping 58 % of the box; the
   panel scrolls inside the box, so every control is reachable within it */
.rl-stage.rl-narrow { flex-direction: column; }
.rl-stage.rl-narrow:not(.rl-no-panel) > .rl-view { flex: 0 0 58%; min-height: 160px; }
.rl-stage.rl-narrow > .rl-panel { flex: 1 1 0; min-height: 0; max-width: none; overflow-y: auto; border-left: 0; border-top: 1px solid var(--line); }
/* the page on a phone: the page itself scrolls and the view stays at the top of the screen */
.rl-stage.rl-page.rl-narrow { display: block; height: auto; }
.rl-stage.rl-page.rl-narrow:not(.rl-no-panel) > .rl-view { position: sticky; top: 0; z-index: 3; height: max(240px, 58svh); border-bottom: 1px solid var(--line); }
.rl-stage.rl-page.rl-narrow > .rl-panel { overflow: visible; border-top: 0; }
.rl-stage.rl-narrow .rl-note { display: flex; gap: .5rem; align-items: flex-start; }
.rl-note > span { flex: 1; }
.rl-stage .rl-note-close { flex: none; min-height: 24px; min-width: 24px; padding: 0 .35rem; line-height: 1; }
.rl-hint { display: none; }
.rl-stage.rl-narrow .rl-legend { top: .35rem; left: .35rem; max-width: calc(100% - .7rem); max-height: 38%; padding: .2rem .45rem; }
.rl-stage.rl-narrow .rl-legend li { display: inline-flex; margin-right: .7rem; }
.rl-stage.rl-narrow .rl-bar { left: .35rem; right: .35rem; bottom: .35rem; }
.rl-view canvas { position: absolute; inset: 0; width: 100%; height: 100%; display: block; touch-action: none; outline: none; }
.rl-view canvas:focus-visible { outline: 3px solid var(--focus); outline-offset: -3px; }
.rl-view:has(> canvas:focus-visible)::after { content: ""; position: absolute; inset: 0; border: 3px solid var(--focus); pointer-events: none; }
.rl-labels { position: absolute; inset: 0; pointer-events: none; overflow: hidden; }
.rl-klein { position: absolute; top: 0; right: 0; bottom: 0; left: 50%; overflow: hidden; border-left: 1px solid var(--line); background: var(--paper); }
.rl-split > .rl-view > canvas { right: 50%; width: 50%; }
.rl-split > .rl-view::after { right: 50%; }
.rl-stage.rl-narrow.rl-split > .rl-view::after { right: 0; bottom: 50%; }
.rl-split > .rl-view > .rl-legend { max-width: calc(50% - 1.2rem); }
.rl-stage.rl-narrow.rl-split > .rl-view > canvas { right: 0; width: 100%; bottom: 50%; height: 50%; }
.rl-stage.rl-narrow.rl-split > .rl-view > .rl-legend { max-width: calc(100% - .7rem); max-height: 19%; }
.rl-stage.rl-narrow .rl-klein { left: 0; top: 50%; border-left: 0; border-top: 1px solid var(--line); }
.rl-klein-note { position: absolute; inset: 1rem; margin: 0; color: var(--muted); }
.rl-klein-steer { position: absolute; bottom: 3.2rem; right: .5rem; padding: .25rem .5rem; font-size: .8rem; background: rgb(255 255 255 / .88); border: 1px solid var(--line); border-radius: 4px; }
.rl-klein-steer-grid { display: grid; grid-template-columns: auto minmax(4rem, 6rem) 2.4rem; align-items: center; gap: .1rem .4rem; }
.rl-klein-steer[hidden] { display: none; }
.rl-klein-steer:not(.rl-klein-steer-folded) > summary { display: none; }
.rl-klein-steer-folded > summary { cursor: pointer; min-height: 24px; display: flex; align-items: center; }

.rl-klein-steer input { width: 100%; margin: 0; min-height: 24px; }
.rl-klein-name { font-style: italic; font-family: "Times New Roman", "STIX Two Text", serif; font-size: 1rem; }
.rl-klein-value { font-variant-numeric: tabular-nums; text-align: right; }
.rl-stage .rl-klein-steer.rl-klein-steer-panel { position: static; margin: 0 0 .7rem; background: none; }
.rl-stage .rl-klein-steer.rl-klein-steer-panel .rl-klein-steer-grid { grid-template-columns: auto 1fr 3rem; }
.rl-stage .rl-klein-steer.rl-klein-steer-panel input { min-height: 44px; }
.rl-klein-ring { position: absolute; pointer-events: none; left: -11px; top: -11px; width: 22px; height: 22px; border-radius: 50%; border: 3px solid #d55e00; background: rgb(255 255 255 / .25); }
.rl-line-mark { position: absolute; left: 0; top: 0; pointer-events: none; overflow: hidden; }
.rl-line-mark line { stroke: #d55e00; stroke-width: 4; stroke-linecap: round; }
.rl-label { position: absolute; left: 0; top: 0; font: italic 15px/1 "Times New Roman", "STIX Two Text", serif; color: var(--ink);
  background: rgb(251 250 247 / .8); padding: 1px 3px; border-radius: 3px; white-space: nowrap; }
.rl-stage sub, .rl-stage sup { font-size: max(12px, .72em); line-height: 1; }
.rl-stage math :is(msub, msup, msubsup, munder, mover, munderover) > :not(:first-child), .rl-stage math mfrac > * { font-size: max(12px, .71em); }
.rl-legend { position: absolute; left: .6rem; top: .5rem; margin: 0; padding: .35rem .6rem; list-style: none; max-width: calc(100% - 1.2rem); max-height: 45%; overflow-y: auto;
  background: rgb(255 255 255 / .88); border-radius: 6px; font-size: max(12px, .8rem); line-height: 1.35; }
.rl-stage .rl-legend.rl-legend-panel { position: static; max-width: none; max-height: none; overflow: visible; margin: 0 0 .7rem; padding: .3rem .5rem;
  background: var(--paper); border: 1px solid var(--line); }
.rl-legend li { display: flex; align-items: center; gap: .45rem; }
.rl-swatch { flex: none; }
.rl-bar { position: absolute; z-index: 1; left: .6rem; right: .5rem; bottom: .5rem; display: flex; align-items: flex-end; gap: .3rem .8rem; pointer-events: none; }
.rl-bar > * { pointer-events: auto; }
/* toolbar buttons: their word, or in a narrow box their sign (the accessible name stays the word) */
.rl-btn-sign { display: none; }
.rl-narrow :is(.rl-toolbar, .rl-modes, .rl-editbar) .rl-btn-sign { display: inline; font-size: 1.05rem; line-height: 1; }
.rl-narrow :is(.rl-toolbar, .rl-modes, .rl-editbar) .rl-btn-word { display: none; }
.rl-toolbar { display: flex; gap: .3rem; flex-wrap: wrap; justify-content: flex-end; margin-left: auto; }
.rl-stage button, .rl-stage select, .rl-stage input[type=text] { font: inherit; font-size: .85rem; color: var(--ink); }
.rl-stage select { min-height: 28px; }
.rl-stage button { min-height: 28px; min-width: 28px; padding: .2rem .6rem; border: 1px solid #c9c5ba; border-radius: 6px;
  background: rgb(255 255 255 / .92); cursor: pointer; }
.rl-stage button:hover { border-color: var(--focus); }
.rl-stage button:disabled { opacity: .45; cursor: default; }
.rl-stage :focus-visible { outline: 3px solid var(--focus); outline-offset: 2px; }
.rl-progress { position: absolute; left: 50%; top: .6rem; transform: translateX(-50%); display: flex; gap: .4rem; align-items: center;
  background: rgb(255 255 255 / .92); padding: .2rem .5rem; border-radius: 6px; font-size: .8rem; }
.rl-progress progress { width: 10rem; height: .6rem; }
.rl-error { position: absolute; inset: auto .6rem 3.4rem .6rem; margin: 0; background: #fff0ee; color: #7d1710; padding: .5rem .7rem;
  border: 1px solid #e6b2aa; border-radius: 6px; font-size: .88rem; white-space: pre-wrap; }
.rl-note { position: absolute; inset: auto .6rem 6.6rem .6rem; margin: 0; background: #fff8e6; color: #5a4000; padding: .4rem .7rem;
  border: 1px solid #ead79b; border-radius: 6px; font-size: .82rem; }
.rl-hint { flex: 0 1 auto; min-width: 0; margin: 0; pointer-events: none !important; color: var(--muted); font-size: .75rem; background: rgb(251 250 247 / .8); border-radius: 4px; padding: 0 .25rem; }
.rl-stale canvas { opacity: .55; }
/* a scene opening in steps (the page's first), or a course package's page until its course system
   is connected: the panel's parts wait, in their places, until all are there */
.rl-opening > .rl-panel > :not(h2), .rl-opening .rl-legend, .rl-waiting > .rl-panel > :not(h2) { visibility: hidden; }
.rl-sr-only { position: absolute !important; width: 1px; height: 1px; padding: 0; margin: -1px; overflow: hidden; clip: rect(0 0 0 0); white-space: nowrap; border: 0; }
.rl-panel { flex: 0 0 24rem; max-width: 46%; overflow-y: auto; background: var(--panel); border-left: 1px solid var(--line); padding: .8rem 1rem 1.2rem; }
.rl-panel h2 { font-size: 1.05rem; margin: .2rem 0 .6rem; }
.rl-controls { display: grid; grid-template-columns: minmax(6rem, 38%) minmax(0, 1fr); gap: .35rem .7rem; align-items: center; font-size: .9rem; }
.rl-row { display: contents; }
.rl-tiny .rl-controls { grid-template-columns: minmax(0, 1fr); gap: .15rem; }
.rl-tiny .rl-row > label { padding-top: .45rem; }
.rl-tiny .rl-row.rl-checkbox { display: flex; flex-direction: row-reverse; justify-content: flex-end; align-items: center; gap: .5rem; }
.rl-tiny .rl-row.rl-checkbox > label { padding-top: 0; }
.rl-tiny .rl-row.rl-checkbox > .rl-cell { flex: none; }
.rl-view-small .rl-hint { display: none; }
.rl-row > label { padding: .15rem 0; }
/* a field with a message under it: its label stays beside the field, not beside the message */
.rl-row:has(.rl-fielderror:not([hidden])) > label { align-self: start; padding-top: .4rem; }
.rl-cell { display: flex; align-items: center; gap: .4rem; flex-wrap: wrap; min-width: 0; }
.rl-line { display: flex; align-items: center; gap: .3rem .4rem; flex: 1 1 100%; min-width: 0; flex-wrap: wrap; }
.rl-cell select { flex: 1; min-width: 0; min-height: 28px; }
.rl-cell input[type=range] { flex: 1 1 5rem; min-width: 4rem; height: 24px; margin: 0; touch-action: pan-y; }
.rl-cell input[type=checkbox] { width: 24px; height: 24px; margin: 0; }
.rl-cell output { font-variant-numeric: tabular-nums; color: var(--muted); min-width: 3.2rem; text-align: right; font-size: .85rem; }
.rl-unit { color: var(--muted); font-size: .85rem; white-space: nowrap; margin-left: -.15rem; }
.rl-exact { width: 4.6rem; min-height: 28px; padding: 0 .3rem; border: 1px solid #c9c5ba; border-radius: 5px; }
.rl-formula { flex: 1; min-width: 0; min-height: 30px; padding: .15rem .4rem; font-family: ui-monospace, "SFMono-Regular", Menlo, monospace !important;
  border: 1px solid #c9c5ba; border-radius: 5px; }
.rl-formula[aria-invalid=true], .rl-exact[aria-invalid=true] { border-color: #b3261e; background: #fff4f2; }
.rl-reason { flex-basis: 100%; color: var(--muted); font-size: .78rem; }
.rl-fielderror { flex-basis: 100%; color: #8c1d14; font-size: .8rem; }
.rl-disabled > label { color: #8c93a3; }
.rl-play { padding: 0 .45rem !important; }
.rl-player { display: flex; gap: .5rem; align-items: center; flex-wrap: wrap; margin: .6rem 0 0; font-size: .85rem; }
.rl-player[hidden] { display: none; }
.rl-readout { display: grid; grid-template-columns: 1fr auto; gap: .15rem .8rem; margin: .8rem 0; padding: .5rem .7rem; background: var(--paper);
  border-radius: 6px; font-size: .86rem; }
.rl-readout dt { color: var(--muted); }
.rl-readout dd { margin: 0; font-variant-numeric: tabular-nums; text-align: right; }
.rl-paper { margin: .2rem 0 .9rem; padding: .55rem .75rem; border: 1px solid #d8d3c4; border-radius: 6px; background: #fffdf7; font-size: .86rem; line-height: 1.45; }
.rl-paper[hidden] { display: none; }
.rl-paper h3 { font-size: .95rem; margin: 0; }
.rl-paper .rl-paper-toggle { all: unset; box-sizing: border-box; display: block; width: 100%; cursor: pointer; min-height: 24px; padding: .1rem 0 .35rem; font-weight: 700; }
/* (the arrows are not part of the button's name: an empty alternative text where browsers take one) */
.rl-paper .rl-paper-toggle::before { content: "▸ "; content: "▸ " / ""; font-weight: 400; }
.rl-paper .rl-paper-toggle[aria-expanded=true]::before { content: "▾ "; content: "▾ " / ""; }
.rl-paper .rl-paper-toggle:focus-visible { outline: 3px solid var(--focus); outline-offset: 2px; }
.rl-paper .rl-paper-toggle[aria-expanded=false] { padding-bottom: .1rem; }
.rl-paper blockquote { margin: 0 0 .45rem; padding-left: .6rem; border-left: 3px solid #8a8f99; font-style: italic; }
.rl-paper p { margin: .35rem 0; }
.rl-paper .rl-paper-data { color: var(--muted); }
.rl-paper .rl-beyond { border-left: 3px solid #0072b2; background: #f1f6fb; padding: .3rem .6rem; }
.rl-paper .rl-paper-changed { display: flex; gap: .5rem; align-items: center; flex-wrap: wrap; }
.rl-paper button { font: inherit; font-size: .84rem; min-height: 32px; }
.rl-claims { list-style: none; margin: -.4rem 0 .8rem; padding: 0; font-size: .84rem; }
.rl-claims[hidden] { display: none; }
.rl-claims li { display: flex; gap: .4rem; margin: .2rem 0; }
.rl-claims .rl-mark { flex: none; width: 1.1em; font-weight: 700; }
.rl-claims .rl-holds .rl-mark { color: #1a6b3c; }
.rl-claims .rl-fails { color: #8c1d14; }
.rl-caption, .rl-readout-note { font-size: .85rem; color: var(--muted); margin: .4rem 0 .8rem; }
.rl-downloads { display: flex; gap: .4rem; flex-wrap: wrap; margin: 0 0 .8rem; }
.rl-downloads:empty { display: none; }
.rl-figure { margin: 0 0 .8rem; }
.rl-figure:empty { display: none; }
.rl-text { font-size: .92rem; line-height: 1.55; }
/* the explanation is laid out and painted when it comes near the screen (below the view on a phone: not before the first picture) */
.rl-text { content-visibility: auto; contain-intrinsic-size: auto 40rem; }
.rl-text h2 { font-size: 1.05rem; margin: .6rem 0 .4rem; }
.rl-text math[display=block] { margin: .5rem 0; overflow-x: auto; }
.rl-text .rl-beyond { border-left: 3px solid #0072b2; background: #f1f6fb; padding: .3rem .6rem; margin: .6rem 0; }
.rl-text .rl-paper-data { border-left: 3px solid #8a8f99; background: #f6f5f1; padding: .3rem .6rem; margin: .6rem 0; }
/* a figure never shrinks below its own size (its smallest text stays 12.5 px): a narrow panel scrolls it sideways */
.rl-figure { overflow-x: auto; }
.rl-figure > svg { background: var(--paper); border-radius: 6px; width: 100%; min-width: 340px; height: auto; }
.rl-shortcuts { max-width: 30rem; border: 1px solid var(--line); border-radius: 8px; padding: 1rem 1.2rem; color: var(--ink); }
.rl-shortcuts-close { float: right; margin: 0 0 .4rem .8rem; }
.rl-shortcuts::backdrop { background: rgb(0 0 0 / .25); }
.rl-shortcuts table { border-collapse: collapse; font-size: .9rem; }
.rl-shortcuts td { padding: .2rem .6rem .2rem 0; vertical-align: top; }
.rl-shortcuts kbd { font: .85rem ui-monospace, monospace; border: 1px solid #c9c5ba; border-bottom-width: 2px; border-radius: 4px; padding: 0 .3rem; background: #fff; }
/* editing (edit/editor.js): handles are rings over the view (the one under the pointer bigger and
   orange, the selected one vermillion and thick), the coordinates beside the handle moved, the
   move modes over the toolbar, the edit's note in the panel */
.rl-handles { position: absolute; inset: 0; pointer-events: none; overflow: hidden; }
.rl-handle { position: absolute; left: -7px; top: -7px; width: 14px; height: 14px; border-radius: 50%;
  background: rgb(255 255 255 / .55); border: 2px solid #1f2430; box-shadow: 0 0 0 1.5px rgb(255 255 255 / .9); }
.rl-handle.rl-hover { left: -10px; top: -10px; width: 20px; height: 20px; border: 3px solid #e69f00; background: rgb(255 255 255 / .35); }
.rl-handle.rl-selected { left: -11px; top: -11px; width: 22px; height: 22px; border: 4px solid #d55e00; background: rgb(255 255 255 / .25); }
.rl-handle-tip { position: absolute; z-index: 2; left: 0; top: 0; padding: .15rem .45rem; border-radius: 5px; background: rgb(31 36 48 / .9);
  color: #fff; font-size: .8rem; font-variant-numeric: tabular-nums; white-space: nowrap; }
.rl-handle-tip { max-width: min(24rem, calc(100% - 8px)); white-space: normal; }
.rl-handle-tip > * { display: block; }
.rl-handle-tip > * + * { font-size: .8rem; }
.rl-handle-tip .rl-tip-values .rl-tip-value { display: inline-block; margin-right: .5rem; white-space: nowrap; }
.rl-handle-tip .rl-tip-snap { color: #ffd27a; }
.rl-handle-tip .rl-tip-held { color: #ffc2b3; }
.rl-handle-tip .rl-tip-value.rl-holds { color: #a6e3c8; }
/* where a drag snapped: a small vermillion diamond (the tip says onto what) */
.rl-snap-mark { position: absolute; left: -6px; top: -6px; width: 12px; height: 12px; background: #d55e00;
  border: 2px solid #fff; box-shadow: 0 0 0 1px #1f2430; }
/* handles on top of each other: the list to choose one from, beside the finger */
.rl-pick { position: absolute; left: 0; top: 0; z-index: 3; max-width: 16rem; padding: .35rem; border: 1px solid #1f2430;
  border-radius: 6px; background: #fff; box-shadow: 0 2px 8px rgb(0 0 0 / .25); }
.rl-pick-heading { margin: 0 0 .3rem; font-size: .85rem; }
.rl-pick-list { display: grid; gap: .2rem; max-height: 14rem; overflow-y: auto; }
.rl-pick-list button { text-align: left; }
/* the chosen point in the panel: its coordinates (typed) and values */
.rl-coords { margin: .2rem 0 .8rem; padding: .45rem .7rem; border: 1px solid #c9c5ba; border-left: 4px solid #d55e00;
  border-radius: 6px; font-size: .86rem; }
.rl-coords h3 { font-size: .95rem; margin: 0 0 .35rem; }
.rl-coords-fields { display: flex; flex-wrap: wrap; gap: .3rem .7rem; align-items: center; }
.rl-coords-fields > span { display: inline-flex; gap: .3rem; align-items: center; }
.rl-coords-fields input { width: 6.5em; font: inherit; font-variant-numeric: tabular-nums; }
.rl-coords-message { margin: .3rem 0 0; }
.rl-coords-values { display: grid; grid-template-columns: auto 1fr; gap: .1rem .7rem; margin: .45rem 0 0; }
.rl-coords-values dd { margin: 0; font-variant-numeric: tabular-nums; }
.rl-view canvas.rl-grab { cursor: grab; }
.rl-view canvas.rl-grab:active { cursor: grabbing; }
.rl-editbar { flex: 1 1 auto; min-width: 0; display: flex; flex-wrap: wrap; gap: .3rem; align-items: center; }
.rl-editing .rl-hint { display: none; }
/* in a narrow box, while editing, the toolbar is the edit toolbar, one row of signs: the move modes,
   snapping, then Fit, ✎ (pressed: press again to stop), ↶ ↷ — Reset, full screen, ? and Done wait
   until editing ends; the row is packed tight to stay one row on a phone: eight 44-px targets are
   352 px, so at 360 px the bar reaches to 2 px of the edges and each group's buttons touch, as
   segments (the groups kept apart by a pixel) */
.rl-narrow .rl-editbar-label { display: none; }
.rl-narrow .rl-view.rl-editing .rl-toolbar > :is(.rl-reset, .rl-fullscreen, .rl-help, .rl-klein-toggle) { display: none; }
.rl-narrow .rl-view.rl-editing .rl-bar { left: 2px; right: 2px; gap: 1px; }
.rl-narrow .rl-view.rl-editing :is(.rl-toolbar, .rl-modes) { gap: 0; }
.rl-narrow .rl-view.rl-editing .rl-editbar { gap: 1px; }
.rl-narrow .rl-view.rl-editing .rl-modes { padding: 0; }
.rl-narrow .rl-view.rl-editing .rl-done { display: none; }
.rl-narrow .rl-editbar { flex: 0 1 auto; container-type: normal; }
.rl-modes { display: flex; flex-wrap: wrap; gap: .25rem; align-items: center; background: rgb(255 255 255 / .92); border-radius: 6px; padding: .15rem .3rem; }
.rl-editbar-label { font-size: .8rem; color: var(--muted); padding: 0 .2rem; }
/* where the bar beside the toolbar is too short for the label, the buttons and Done on one row, the label goes (the group keeps it as its name) */
.rl-editbar { container-type: inline-size; }
@container (max-width: 36rem) { .rl-editbar-label { display: none; } }
/* (Done repeats the pressed Edit button beside it: it goes first when the row is short) */
@container (max-width: 30rem) { .rl-done { display: none; } }
@container (max-width: 26rem) { .rl-modes .rl-btn-sign { display: inline; } .rl-modes .rl-btn-word { display: none; } }
.rl-stage button[aria-pressed=true] { background: #1f2430; color: #fff; border-color: #1f2430; }
.rl-edited { margin: .2rem 0 .8rem; padding: .45rem .7rem; border: 1px solid #e6c47a; border-left: 4px solid #e69f00; border-radius: 6px;
  background: #fffaf0; font-size: .86rem; }
.rl-edited p { margin: .1rem 0 .35rem; }
.rl-edited .rl-edited-note { color: var(--muted); }
.rl-problems { margin: -.3rem 0 .8rem; padding: .35rem .7rem .35rem 1.6rem; font-size: .84rem; color: #7d1710; background: #fff4f2;
  border-radius: 6px; }
.rl-problems[hidden] { display: none; }
.rl-as-data { margin: .6rem 0 0; }
/* an exercise (task/panel.js): its prompt, the answer fields, Check, hints, how each condition stands */
.rl-task { margin: .2rem 0 .9rem; padding: .6rem .8rem; border: 1px solid #b9c7dd; border-left: 4px solid #0072b2; border-radius: 6px;
  background: #f4f8fc; font-size: .9rem; }
.rl-task[hidden] { display: none; }
.rl-task h3 { font-size: 1rem; margin: 0 0 .35rem; }
.rl-task-kind { color: var(--muted); font-weight: 600; }
.rl-task-prompt { margin: 0 0 .6rem; line-height: 1.5; white-space: pre-wrap; }
.rl-task-answers { display: grid; gap: .35rem; margin: 0 0 .6rem; }
.rl-task-curve { border: 0; padding: 0; margin: 0; display: grid; gap: .3rem; }
.rl-task-curve legend { font-weight: 600; padding: 0; margin-bottom: .2rem; }
.rl-task-field { display: flex; gap: .5rem; align-items: center; flex-wrap: wrap; }
.rl-task-field > span { min-width: 4.5rem; }
.rl-task-field input { flex: 1 1 10rem; min-width: 0; min-height: 30px; padding: .15rem .4rem; border: 1px solid #c9c5ba; border-radius: 5px;
  font: inherit; font-family: ui-monospace, "SFMono-Regular", Menlo, monospace; }
.rl-task-buttons { display: flex; gap: .4rem; flex-wrap: wrap; margin: 0 0 .5rem; }
.rl-task-check { font-weight: 600; }
.rl-task-hints { margin: .2rem 0 .5rem; padding-left: 1.3rem; }
.rl-task-hints li { margin: .2rem 0; }
.rl-task-results { list-style: none; margin: .3rem 0; padding: 0; }
.rl-task-results li { display: flex; gap: .4rem; margin: .25rem 0; }
.rl-task-results .rl-mark { flex: none; width: 1.1em; font-weight: 700; }
.rl-task-results .rl-holds .rl-mark { color: #1a6b3c; }
.rl-task-results .rl-fails { color: #8c1d14; }
.rl-task-verdict { margin: .4rem 0 0; font-weight: 600; }
.rl-task-held { margin: .5rem 0 0; color: var(--muted); font-size: .82rem; }
.rl-task-verdict.rl-task-solved { color: #14532d; background: #e8f5ec; border: 1px solid #9fd3b0; border-radius: 5px; padding: .3rem .5rem; }
.rl-task-drawn { margin: 0 0 .6rem; font-weight: 600; }
.rl-task-history h4 { margin: .6rem 0 .15rem; font-size: .85rem; }
.rl-task-history ol, .rl-task-history p { margin: 0; font-size: .82rem; color: var(--muted); }
.rl-task-history ol { padding-left: 1.8rem; }
/* "Make an exercise" (task/author.js) */
.rl-author { margin: .2rem 0 .9rem; padding: .6rem .8rem; border: 1px solid #d8c9a6; border-left: 4px solid #e69f00; border-radius: 6px;
  background: #fffbf2; font-size: .88rem; }
.rl-author[hidden] { display: none; }
.rl-author h3 { font-size: 1rem; margin: 0 0 .35rem; }
.rl-author fieldset { border: 1px solid var(--line); border-radius: 6px; margin: .5rem 0; padding: .3rem .6rem .5rem; min-width: 0; }
.rl-author legend { font-weight: 600; padding: 0 .2rem; }
.rl-author-field { display: grid; gap: .2rem; margin: .35rem 0; }
.rl-author-field input, .rl-author-field textarea, .rl-author-field select, .rl-author-row input, .rl-author-row select {
  font: inherit; min-height: 28px; border: 1px solid #c9c5ba; border-radius: 5px; padding: .1rem .35rem; max-width: 100%; }
.rl-author-check { display: flex; gap: .35rem; align-items: center; margin: .2rem 0; }
.rl-author-check input { flex: none; }
.rl-author-row { display: flex; flex-wrap: wrap; gap: .3rem; align-items: center; margin: .35rem 0; }
.rl-author-row select { flex: 1 1 12rem; min-width: 0; }
.rl-author-row input { width: 6rem; }
.rl-author-status { flex-basis: 100%; margin: 0; color: var(--muted); font-size: .82rem; }
.rl-author-states p { margin: .4rem 0 .2rem; }
.rl-author-out { display: flex; flex-wrap: wrap; gap: .4rem; margin-top: .6rem; }
.rl-author-result { flex-basis: 100%; }
.rl-author-snippet { display: grid; gap: .2rem; margin: .4rem 0; }
.rl-author-snippet textarea { width: 100%; font: 12px ui-monospace, monospace; }
.rl-author-problem { color: #8c1d14; margin: .3rem 0; }
.rl-author-answer { display: flex; flex-wrap: wrap; gap: 0 .6rem; align-items: end; padding: .3rem 0; border-bottom: 1px dashed var(--line); }
.rl-author-answer .rl-author-field { flex: 1 1 9rem; }
.rl-author-draw { display: flex; flex-wrap: wrap; gap: 0 .6rem; margin: 0 0 .4rem 1rem; }
.rl-author-draw .rl-author-field, .rl-author-answer .rl-author-field { min-width: 0; grid-template-columns: minmax(0, 1fr); }
.rl-author-draw .rl-author-field { flex: 1 1 4rem; }
.rl-author-draw input, .rl-author-answer :is(input, select), .rl-author-params select { width: 100%; box-sizing: border-box; }
.rl-author-note { flex-basis: 100%; margin: 0; color: var(--muted); font-size: .82rem; }
.rl-author-warnings { margin: .5rem 0; padding: .3rem .7rem; background: #fff3ef; border-left: 4px solid #d55e00; border-radius: 5px; }
.rl-author-warnings h4 { margin: .2rem 0; font-size: .88rem; }
.rl-author-warning { margin: .25rem 0; }
/* slider steppers (controls.js): − / + and a number field where the range has more values than the slider pixels */
.rl-step { min-width: 28px; padding: 0 !important; font-weight: 600; }
.rl-fine .rl-exact { display: inline-block; }
/* fingers: every target at least 44 × 44 CSS px (WCAG 2.5.5); otherwise at least 24 × 24 (2.5.8) */
@media (pointer: coarse) {
  .rl-stage button, .rl-stage select, .rl-stage input[type=text], .rl-stage summary { min-height: 44px; min-width: 44px; }
  .rl-task-field input { min-height: 44px; }
  .rl-stage .rl-paper .rl-paper-toggle { min-height: 44px; }
  .rl-stage input[type=checkbox] { width: 44px; height: 44px; }
  .rl-stage input[type=range] { height: 44px; }
  .rl-exact { min-height: 44px; }
  .rl-controls { gap: .45rem .7rem; }
}
@media print { .rl-toolbar, .rl-hint, .rl-progress { display: none; } .rl-panel { overflow: visible; } }
`;

/** The stylesheet, built once (constructable stylesheets are shared between shadow roots). */
let sheet = /** @type {CSSStyleSheet | null} */ (null);

/** Adds the view's stylesheet to a document or shadow root. */
export function adoptStyles(/** @type {Document | ShadowRoot} */ root) {
  sheet ??= new CSSStyleSheet();
  if (!sheet.cssRules.length) sheet.replaceSync(CSS);
  if (!root.adoptedStyleSheets.includes(sheet)) root.adoptedStyleSheets = [...root.adoptedStyleSheets, sheet];
}
