// The page's shell: the static structure the production page (scripts/web.mjs) and the one-file
// build (scripts/onefile.mjs) carry in their HTML — the header, the stage with its view and the
// linked scene's heading — so that the first paint shows the heading and the scripts, when they
// arrive, take these elements over where they are (page/chrome.js, stage/elements.js): nothing
// painted moves. A few lines that run first (`firstScript`, a classic script in the head) choose
// what the link's hash asks for before that paint: the scene's heading and the
// scene menu's choice, the language of the header, the phone's arrangement (the same rule as
// stage/layout.js), a view in a frame without its header. What follows the heading (controls,
// readout, explanation) comes with the scripts, under it, moving nothing.
import { SCENES } from '../scenes/index.js';
import { PRESETS } from '../paper.js';
import { translator, LANGUAGE_CODES } from '../i18n/index.js';
import { NARROW, PORTRAIT } from '../limits.js';
import { chromeHtml, htmlText, plainTitle } from './chrome.js';
import { parseRich } from '../ui/richtext.js';
import { STATE_ID } from './onefile.js';

/** The keys of the header's texts the first lines set in another language. */
const HEADER = [
  'app.subtitle',
  'app.skip',
  'app.scene',
  'app.figures',
  'app.exercises',
  'app.language',
  'app.share',
  'app.menu',
];

/** A title with its R_{i}-style scripts as <sub>/<sup> (as ui/richtext.js's appendRich makes it). */
export const richHtml = (/** @type {string} */ text) =>
  parseRich(text)
    .map((p) => (p.kind === 'text' ? htmlText(p.text) : `<${p.kind}>${htmlText(p.text)}</${p.kind}>`))
    .join('');

/**
 * The body of the shell before any script, in English, showing the first scene: the skip link and
 * header, the stage (its view with "Loading ruledlab …" over it, its panel with the heading), and
 * what a browser without scripts says.
 */
export function shellHtml() {
  const en = translator('en');
  return [
    chromeHtml(en),
    '<main id="main"><div class="rl-stage rl-page">',
    '<div class="rl-view"><p id="boot" class="boot">Loading ruledlab …</p></div>',
    `<div class="rl-panel"><h2>${richHtml(en.t(SCENES[0].title))}</h2></div>`,
    '</div></main>',
    '<noscript><p class="boot boot-problem" lang="en">ruledlab needs JavaScript, which is turned off here (a page that shows it in a frame may have turned it off: an iframe sandbox without allow-scripts). <span lang="de">ruledlab braucht JavaScript, das hier ausgeschaltet ist (eine Seite, die es in einem Rahmen zeigt, hat es vielleicht ausgeschaltet: ein iframe-sandbox ohne allow-scripts).</span></p></noscript>',
  ].join('');
}

/**
 * The first lines: a classic script (no module, no import: it runs as soon as it is parsed,
 * before the first paint) with what it needs written into it — every scene's heading in every
 * language, the figures' scenes, the header's texts, the phone's limits — and, for the
 * production page, its module (`entry`), the chunks it imports and the core's file, fetched once
 * the first paint is done.
 * @param {{wasm?: string, entry?: string, chunks?: string[]}} [options]
 */
export function firstScript({ wasm = '', entry = '', chunks = /** @type {string[]} */ ([]) } = {}) {
  const data = {
    wasm,
    entry,
    chunks,
    first: SCENES[0].id,
    headings: Object.fromEntries(
      SCENES.map((s) => [s.id, Object.fromEntries(LANGUAGE_CODES.map((l) => [l, richHtml(translator(l).t(s.title))]))]),
    ),
    options: Object.fromEntries(
      LANGUAGE_CODES.map((l) => [l, SCENES.map((s) => plainTitle(translator(l).t(s.title)))]),
    ),
    figures: Object.fromEntries(PRESETS.map((p) => [p.id, p.scene])),
    header: Object.fromEntries(LANGUAGE_CODES.map((l) => [l, HEADER.map((k) => translator(l).t(k))])),
    languages: LANGUAGE_CODES,
    narrow: NARROW,
    portrait: PORTRAIT,
    state: STATE_ID,
  };
  return `(${first.toString()})(${JSON.stringify(data).replace(/</g, '\\u003c')});`;
}

/**
 * What the first lines do (serialized into the page by firstScript: it must use nothing but `d`
 * and the browser).
 * @param {{wasm: string, entry: string, chunks: string[], first: string, headings: Record<string, Record<string, string>>, options: Record<string, string[]>,
 *   figures: Record<string, string>, header: Record<string, string[]>, languages: string[], narrow: number,
 *   portrait: number, state: string}} d
 */
function first(d) {
  const doc = document;
  // the link: the address's hash, or the one-file build's state block (above this script)
  let hash = location.hash;
  if (!hash) {
    try {
      hash = `#${JSON.parse(doc.getElementById(d.state)?.textContent || '{}').hash || ''}`;
    } catch {
      hash = '';
    }
  }
  const link = new URLSearchParams(hash.replace(/^#/, ''));
  // the language: the link's, else the browser's first that is offered (i18n/translate.js)
  const offered = (/** @type {string | null | undefined} */ code) => {
    const base = String(code ?? '')
      .toLowerCase()
      .split('-')[0];
    return d.languages.includes(base) ? base : null;
  };
  const lang =
    offered(link.get('lang')) ?? (navigator.languages ?? [navigator.language]).map(offered).find(Boolean) ?? 'en';
  const scene = [link.get('scene'), d.figures[link.get('paper') ?? '']].find((id) => id && d.headings[id]) ?? d.first;
  const embed = link.has('embed');
  const controls = !embed || link.has('controls');
  const text = !embed || link.has('text');
  // the phone: the panel under the view (stage/layout.js's rule for the page's screen)
  const narrow = innerWidth > 0 && (innerWidth < d.narrow || (innerHeight > innerWidth && innerWidth < d.portrait));
  doc.documentElement.lang = lang;
  /** @param {string} selector */
  const find = (selector) => /** @type {HTMLElement | null} */ (doc.querySelector(selector));
  const done = new Set();
  /** Applies what it can to what the parser has made so far; true once all is done. */
  const apply = () => {
    if (!done.has('body') && doc.body) {
      // a view in a frame (#embed): no header
      doc.body.classList.toggle('embed', embed);
      done.add('body');
    }
    const picker = /** @type {HTMLSelectElement | null} */ (doc.getElementById('share') && doc.getElementById('scene'));
    if (!done.has('header') && picker) {
      if (lang !== 'en') {
        [...picker.options].forEach((option, k) => {
          option.textContent = d.options[lang][k];
        });
        const [subtitle, skip, scenes, figures, exercises, language, share, menu] = d.header[lang];
        /** @type {HTMLElement} */ (find('.page-header .subtitle')).textContent = subtitle;
        /** @type {HTMLElement} */ (find('a.skip')).textContent = skip;
        [scenes, figures, exercises, language].forEach((words, k) => {
          const label = find(`#${['scene', 'paper', 'task', 'lang'][k]}`)?.previousElementSibling;
          if (label) label.textContent = `${words} `;
        });
        /** @type {HTMLElement} */ (find('#share')).textContent = share;
        /** @type {HTMLElement} */ (find('#menu .menu-word')).textContent = menu;
      }
      picker.value = scene;
      /** @type {HTMLSelectElement} */ (doc.getElementById('lang')).value = lang;
      done.add('header');
    }
    const stage = find('.rl-stage');
    const heading = find('.rl-panel > h2');
    if (!done.has('stage') && stage && heading) {
      // its panel only with &controls or &text in a frame (Stage.setPanel)
      stage.classList.toggle('rl-no-controls', !controls);
      stage.classList.toggle('rl-no-panel', !controls && !text);
      stage.classList.toggle('rl-narrow', narrow);
      /** @type {HTMLElement} */ (heading.parentElement).hidden = !controls && !text;
      // an exercise's heading and a view in a frame wait for the scripts (page/app.js does the same)
      heading.innerHTML = embed || link.has('task') ? '' : d.headings[scene][lang];
      done.add('stage');
    }
    return done.size === 3;
  };
  // the page's module, its chunks and the core's file, fetched once the shell is painted: on a
  // slow line they would share it with the stylesheet the first paint waits for
  if (d.entry)
    requestAnimationFrame(() =>
      setTimeout(() => {
        const link = (/** @type {Record<string, string>} */ props) =>
          doc.head.append(Object.assign(doc.createElement('link'), props));
        for (const chunk of d.chunks) link({ rel: 'modulepreload', href: chunk });
        // (the same request as wasm-bindgen's fetch, so that it is used)
        link({ rel: 'preload', href: d.wasm, as: 'fetch', type: 'application/wasm', crossOrigin: 'anonymous' });
        doc.head.append(Object.assign(doc.createElement('script'), { type: 'module', src: d.entry }));
      }),
    );
  // this runs in the head, before the page's stylesheet (a script after it would wait for it, and
  // the browser could paint the shell before it ran): each element is set as the parser makes it,
  // before anything is painted
  if (!apply()) {
    const watch = new MutationObserver(() => {
      if (apply()) watch.disconnect();
    });
    watch.observe(doc, { childList: true, subtree: true });
  }
}
