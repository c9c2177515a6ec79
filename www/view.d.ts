// Types of `ruledlab/view` (www/view.js): the <ruled-view> element, the Stage and Viewer it is
// made of, the scene contract (www/scene.js) and the helpers a page of one's own needs.

/** Where the wasm comes from: a URL, a fetch Response, the bytes, or a compiled module. */
export type WasmSource = string | URL | Response | BufferSource | WebAssembly.Module;

/** Sets where the wasm comes from and how workers are made; call before the first view starts. */
export function configure(options?: { wasm?: WasmSource; worker?: () => Worker }): void;
/** Starts the core once; resolves when its exports can be called. */
export function start(): Promise<unknown>;

export type ParamValue = number | string | boolean;
export type Params = Record<string, ParamValue>;

/** One parameter of a scene: one control, one key in the link. */
export interface Param {
  key: string;
  type: "range" | "select" | "checkbox" | "text";
  /** i18n key of its label. */
  label: string;
  value: ParamValue;
  min?: number;
  max?: number;
  step?: number;
  exact?: boolean;
  play?: boolean;
  options?: () => Array<[string, string]>;
  maxLength?: number;
  refit?: boolean;
  sets?: (value: ParamValue, params: Params) => Params;
  /** The i18n key of the reason the control does nothing for `params`, or null. */
  unless?: (params: Params) => string | null;
}

export interface LegendEntry {
  style: string;
  label: string;
  when?: (params: Params) => boolean;
}

export interface ImportedData {
  segments: Float64Array;
  rows?: number;
  cols?: number;
}

export interface Context {
  t: (key: string, vars?: Record<string, string | number>) => string;
  format: (x: number | string | boolean | null | undefined) => string;
  data?: ImportedData;
  refine?: (
    segments: Float64Array,
    options: object,
    onProgress: (fraction: number) => void,
    draw?: number,
  ) => Promise<{ segments: Float32Array; rulings: number; drawn: number }>;
}

export interface Layer {
  kind: "segments" | "polyline" | "points" | "mesh";
  style: string;
  positions: Float32Array;
  indices?: Uint32Array;
  /** mesh: 3 per vertex (the core's meshNormalsF32 or focalSheetF32); shaded smoothly. */
  normals?: Float32Array;
  closed?: boolean;
  transform?: Float32Array | Float64Array;
  /** A lighter stand-in drawn while the camera moves (level of detail); the layer once it rests. */
  moving?: Layer;
}

export interface Label {
  at: number[];
  text: string;
}

export interface Readout {
  label: string;
  value: number | string;
  exactZero?: boolean;
}

export interface Download {
  label: string;
  filename: string;
  content: string | (() => string);
  type: string;
}

/** What a scene's create() returns. */
export interface Built {
  bounds: { min: number[]; max: number[] };
  camera?: { yaw?: number; pitch?: number };
  layers: Layer[];
  labels?: Label[];
  keepClear?: Float32Array;
  readouts?: Readout[];
  description: string;
  figure?: () => SVGElement;
  downloads?: Download[];
  data?: { segments: Float64Array; grid?: { rows: number; cols: number } };
  note?: string;
  /** The comparative sentences that apply here, each checked against the readout's numbers. */
  claims?: Claim[];
  later?: (onProgress: (fraction: number) => void) => Promise<Built>;
}

/** A comparative sentence of the page (i18n key), and whether the readout bears it out here. */
export interface Claim {
  text: string;
  holds: boolean;
}

/** A figure or example of the paper as a preset of a scene (www/paper.js). */
export interface PaperPreset {
  /** fig1 … fig18, ex1 … ex6 (fig5-orthogonal, fig13-right: a figure's second case). */
  id: string;
  /** i18n key of its name ("Fig. 3: discrete central curve"). */
  label: string;
  scene: string;
  params: Params;
  /** i18n key of the paper's caption. */
  caption: string;
  /** i18n key: what ruledlab shows, and whose data. */
  note: string;
  /** i18n key: where ruledlab goes beyond or corrects the paper. */
  beyond?: string;
  data: "paper" | "partly" | "none";
}
/** Every figure (1–18) and example (1–6) of the paper. */
export const PRESETS: PaperPreset[];
export function findPreset(id: string | null | undefined): PaperPreset | undefined;

/** A scene: what it declares, and create(). */
export interface Scene {
  id: string;
  title: string;
  text: string;
  params: Param[];
  legend: LegendEntry[];
  paper?: boolean;
  create(params: Params, context: Context): Built;
  fieldOf?: (option: string) => string | null;
}

/** Every scene of ruledlab, in menu order. */
export const SCENES: Scene[];
/** Hash keys the page uses itself. */
export const RESERVED_KEYS: readonly string[];
/** Checks a scene against the contract and returns it. */
export function defineScene(scene: Scene): Scene;
/** Runs `body` with `own`, freeing every wasm object it registered afterwards. */
export function scoped<T>(body: (own: <O extends { free(): void }>(object: O) => O) => T): T;
/** Bounding box of flat xyz arrays. */
export function bounds(...arrays: ArrayLike<number>[]): { min: number[]; max: number[] };
/** A scene's parameters from a query, with notes on values that could not be used. */
export function readParams(scene: Scene, query: URLSearchParams): { params: Params; notes: Array<{ key: string; note: string }> };
/** The defaults of a scene's parameters. */
export function defaults(scene: Scene): Params;

/** The state of a view in a URL hash. */
export interface ViewState {
  scene: Scene;
  params: Params;
  camera: number[] | null;
  lang: string | null;
  embed: boolean;
  controls: boolean;
  text: boolean;
  autoplay: boolean;
  data: ImportedData | null;
  notes: Array<{ key: string; note: string }>;
  /** The figure or example of the paper shown (a PRESETS id), if any. */
  paper?: string | null;
}
export function readState(hash: string, scenes: Scene[]): ViewState;
export function writeState(state: Omit<ViewState, "notes">): string;

export type Style =
  | { kind: "line"; color: string; width: number; alpha?: number; dash?: number[]; bw: { gray: number; width: number; dash?: number[] } }
  | { kind: "point"; color: string; size: number; bw: { gray: number; size: number; hollow?: boolean } }
  | { kind: "area"; color: string; back: string; alpha: number; bw: { gray: number; back: number } };
export const STYLES: Record<string, Style>;
export const PALETTE: Record<string, string>;

export interface Translator {
  lang: string;
  t(key: string, vars?: Record<string, string | number>): string;
  has(key: string): boolean;
  format(x: number | string | boolean | null | undefined): string;
}
export function translator(lang: string): Translator;
export function pickLanguage(wanted?: string | null): string;
export const LANGUAGE_CODES: string[];

/** An orbit camera (z up). */
export interface OrbitCamera {
  target: number[];
  distance: number;
  yaw: number;
  pitch: number;
  toArray(): number[];
  fromArray(values: number[]): void;
  reset(): void;
}

/** The WebGL2 view of a scene. */
export class Viewer {
  constructor(canvas: HTMLCanvasElement, labelLayer: HTMLElement);
  readonly canvas: HTMLCanvasElement;
  readonly camera: OrbitCamera;
  built: Built | null;
  onFrame: ((frames: number) => void) | null;
  onCameraChange: ((ended: boolean) => void) | null;
  show(built: Built, options?: { fit?: boolean }): void;
  fit(): void;
  requestRender(): void;
  render(): void;
  dispose(): void;
}

export interface StageOptions {
  controls?: boolean;
  text?: boolean;
  lang?: string | null;
  onChange?: (change: { reason: "scene" | "param" | "camera" | "lang" | "reset"; ended: boolean }) => void;
  onError?: (error: unknown) => void;
  onBuilt?: (built: Built) => void;
}

/** A scene on screen with its controls, readout and explanation. */
export class Stage {
  constructor(host: HTMLElement, options?: StageOptions);
  readonly viewer: Viewer;
  scene: Scene | null;
  params: Params;
  data: ImportedData | null;
  /** The figure of the paper shown, if any. */
  paper: PaperPreset | null;
  open(
    scene: Scene,
    params: Params,
    options?: { camera?: number[] | null; fit?: boolean; data?: ImportedData | null; notes?: Array<{ key: string; note: string }>; autoplay?: boolean; paper?: PaperPreset | null },
  ): Promise<void>;
  setParam(key: string, value: ParamValue, ended?: boolean): void;
  setPanel(controls: boolean, text: boolean): void;
  setLanguage(lang: string | null): void;
  reset(): void;
  toggleFullscreen(): void;
  dispose(): void;
}

/** Options of the figure exports. */
export interface FigureOptions {
  /** Black and white, like the paper's figures (default: colour). */
  bw?: boolean;
  /** Draw the legend (default true). */
  legend?: boolean;
  /** Draw the scene's title above (default false). */
  title?: boolean;
  /** Draw the labels (default true). */
  labels?: boolean;
}

export interface SceneChangeDetail {
  scene: string;
  params: Params;
}
export interface ViewChangeDetail {
  yaw: number;
  pitch: number;
  distance: number;
  target: number[];
}
export interface RuledViewErrorDetail {
  message: string;
  code: string | null;
}

/** <ruled-view>: a scene as a custom element (attributes scene, paper, params, controls, text, autoplay, lang). */
export class RuledView extends HTMLElement {
  static readonly observedAttributes: string[];
  scene: string;
  /** A figure or example of the paper (a PRESETS id such as "fig15"), or "". */
  paper: string;
  params: string;
  controls: boolean;
  text: boolean;
  autoplay: boolean;
  lang: string;
  data: ImportedData | null;
  readonly view: Stage | null;
  reset(): void;
  /** The current view as a self-contained SVG 1.1 figure. */
  exportSVG(options?: FigureOptions): string;
  /** The current view as a TikZ picture (`width` in cm, default 12). */
  exportTikZ(options?: FigureOptions & { width?: number }): string;
  /** The current view as a PNG at 1×, 2× or 4× its size, labels and legend drawn in. */
  exportPNG(options?: { scale?: number; legend?: boolean }): Promise<Blob>;
  addEventListener<K extends keyof RuledViewEventMap>(type: K, listener: (this: RuledView, ev: RuledViewEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
}

export interface RuledViewEventMap extends HTMLElementEventMap {
  "scene-change": CustomEvent<SceneChangeDetail>;
  "view-change": CustomEvent<ViewChangeDetail>;
  error: CustomEvent<RuledViewErrorDetail> & ErrorEvent;
}

declare global {
  interface HTMLElementTagNameMap {
    "ruled-view": RuledView;
  }
}
