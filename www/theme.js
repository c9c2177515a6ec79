// Colours shared by every scene (RGBA, 0–1), and their CSS for the legend.
export const COLORS = {
  ruling: [0.13, 0.18, 0.33, 1],
  normal: [0.09, 0.55, 0.33, 1],
  foot: [0.05, 0.3, 0.18, 1],
  striction: [0.84, 0.16, 0.17, 1],
  exact: [0.98, 0.72, 0.16, 0.9],
  ghost: [0.45, 0.48, 0.55, 0.35],
  inserted: [0.85, 0.35, 0.2, 0.6],
  insertedAxis: [0.42, 0.58, 0.85, 1],
  endpointScheme: [0.9, 0.45, 0.15, 1],
  lineScheme: [0.15, 0.38, 0.75, 1],
  sphereLight: [0.82, 0.84, 0.88, 1],
  sphereDark: [0.3, 0.32, 0.38, 1],
  mesh: [0.35, 0.4, 0.5, 0.45],
  strip: { front: [0.45, 0.64, 0.9, 0.55], back: [0.98, 0.76, 0.5, 0.55] },
};

export function css(rgba) {
  const [r, g, b] = rgba.map((x) => Math.round(x * 255));
  return `rgb(${r} ${g} ${b})`;
}
