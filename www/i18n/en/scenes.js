// English texts of the scenes of ruled surfaces (Sections 2–3, your surface, your data, large
// models) and the labels scenes share. Labels may use R_{i,i+1}-style subscripts
// (ui/richtext.js).
// Keys: param.*, legend.*, readout.*, describe.*, claim.*, surface.*, striction.*, notation.*,
//   convergence.*, isometry.*, formula.*, data.*, large.*

export default {
  // shared labels
  'param.surface': 'Surface',
  'param.rulings': 'Rulings N',
  'param.strip': 'Surface strip',
  'param.scheme': 'Scheme',
  'param.steps': 'Steps',

  'legend.rulings': 'rulings R_i',
  'legend.rulings3': 'rulings R_{i−1}, R_i, R_{i+1}',
  'legend.normals': 'common perpendiculars N_{i,i+1} and footpoints',
  'legend.striction': 'striction polygon m_i (thick, with points)',
  'legend.perpendicularMidpoints': 'polygon of perpendicular midpoints (Example 1’s polygon, dashed)',
  'legend.complexAxis': 'axis of the linear complex (dash-dot)',
  'legend.exactStriction': 'exact striction curve s(u) (wide)',

  'readout.exact': 'exact',
  'readout.rulings': 'rulings N',
  'readout.parallelPairs': 'parallel pairs',
  'readout.midpointError': 'max |m_i − s(u_i)|',
  'readout.footpointError': 'max |f_{i,i+1} − s(u_i)|',
  'readout.perpendicularMidpointError': 'max |Example 1’s polygon − s(u_i + H/2)|',
  'readout.meanDelta': 'δ̄ at the middle ruling',
  'striction.label.meanDelta': 'δ̄ (m_{{i}})',
  'readout.none': 'none (an error is 0 or undefined)',

  'describe.closed': 'closed',
  'describe.open': 'open',
  'describe.nothingElse': 'the rulings only',

  'claim.title': 'Claims of the text, checked against the readout',
  'claim.holds': 'holds here',
  'claim.fails': 'does not hold at these settings',

  'surface.hyperboloid': 'Hyperboloid x² + y²/4 − z²/9 = 1 (Example 1)',
  'surface.quartic': 'Quartic surface (1 + vu², u²/2 + uv, u − v) (Example 3)',
  'surface.helicoid': 'Right helicoid',
  'surface.helical': "Ruled helical surface, rulings at 45° (ruledlab's, for Fig. 5)",
  'surface.helical-orthogonal':
    "Ruled helical surface, rulings orthogonal to the striction helix (ruledlab's, for Fig. 5)",
  'surface.pluecker-conoid': 'Plücker\u2019s conoid',
  'surface.hyperbolic-paraboloid': 'Hyperbolic paraboloid z = xy',
  'surface.cone': 'Elliptic cone',
  'surface.cylinder': 'Elliptic cylinder',
  'surface.helix-tangent': 'Tangent surface of a helix (developable)',
  'surface.moebius': 'Möbius band',
  'surface.formula': 'your surface',

  // Figs. 2–3
  'striction.title': 'Striction polygon (Figs. 2–3, Example 1)',
  'striction.param.normals': 'Common perpendiculars N_{i,i+1}',
  'striction.param.polygon': 'Striction polygon m_i',
  'striction.param.midpoints': 'Perpendicular midpoints (Example 1’s polygon)',
  'striction.param.axis': 'Axis of the linear complex (beyond the paper)',
  'striction.param.exact': 'Exact striction curve s(u)',
  'striction.describe':
    'Surface: {surface}, {closed}, {n} rulings; shown: {shown}. The striction polygon is {midpoint} from the exact striction curve at the rulings; a single footpoint is up to {footpoint} away. δ̄ at the middle ruling m_{{mid}} is {mean}; the smallest |δ| of a pair of rulings is {least}.',
  'striction.describe.normals': 'the common perpendiculars with their footpoints',
  'striction.describe.polygon': 'the striction polygon of footpoint midpoints',
  'striction.describe.midpoints': 'the polygon of the perpendiculars\u2019 midpoints',
  'striction.describe.exact': 'the exact striction curve',
  'striction.readout.order.footpoint': 'measured order N → 2N: footpoint',
  'striction.readout.order.midpoint': 'measured order N → 2N: striction polygon m_i',
  'striction.readout.order.perpendicular': 'measured order N → 2N: Example 1’s polygon',
  'striction.claim.orders':
    'On the hyperboloid and the quartic, from 20 rulings on, doubling N halves the footpoint error and quarters the errors of both polygons: measured orders within 0.25 of 1, 2 and 2.',
  'striction.describeEdited':
    'Your edit of {n} rulings of {surface}; shown: {shown}. δ̄ at the middle ruling m_{{mid}} is {mean}; the smallest |δ| of a pair of rulings is {least}; {parallel:pair is:pairs are} parallel. Without the exact surface there are no errors to measure.',

  // Fig. 1
  'notation.title': 'Notation: angle, perpendicular, footpoints (Fig. 1)',
  'notation.param.spacing': 'Ruling spacing H',
  'notation.param.u': 'Parameter u of R_i',
  'notation.legend.parallel': 'parallel to R_{i+1} through f_{i,i+1} (dashed)',
  'notation.legend.midpoint': 'midpoint m_i of the footpoints on R_i',
  'notation.readout.angle': 'angle φ_{i,i+1} (rad)',
  'notation.readout.distance': 'signed distance h_{i,i+1}',
  'notation.readout.delta': 'δ_{i,i+1} = h / φ',
  'notation.describe':
    'Three consecutive rulings of the hyperboloid of Example 1, {spacing} apart in the parameter, with their common perpendiculars, footpoints and the midpoint m_i; the angle between R_i and R_{i+1} is {angle} rad and their signed distance h_{i,i+1} is {distance} (its absolute value is the distance of the two lines), so δ_{i,i+1} = h/φ is {delta}.',
  'notation.describeEdited':
    'Your edit of three consecutive rulings, with their common perpendiculars, footpoints and the midpoint m_i; the angle between R_i and R_{i+1} is {angle} rad and their signed distance h_{i,i+1} is {distance} (its absolute value is the distance of the two lines), so δ_{i,i+1} = h/φ is {delta}.',

  // Propositions 1–2
  'convergence.title': 'Convergence orders (Propositions 1–2)',
  'convergence.param.u': 'Parameter u',
  'convergence.param.h0': 'Largest step H₀',
  'convergence.param.levels': 'Halvings',
  'convergence.legend.rulings': 'R(u − H), R(u), R(u + H) for the largest H',
  'convergence.legend.midpoint': 'midpoint m_i of the footpoints on R(u)',
  'convergence.legend.tangent': 'central tangent s(u) + [e_3(u)] (4) (dashed)',
  'convergence.series.footpoint': 'footpoint f_{i,i+1} (order {order})',
  'convergence.series.midpoint': 'midpoint m_i (order {order})',
  'convergence.series.distribution': 'δ_{i,i+1} (order {order})',
  'convergence.series.distributionMean': 'averaged δ̄_i (order {order})',
  'convergence.series.centralNormal': 'common perpendicular (order {order})',
  'convergence.plot.x': 'step H',
  'convergence.plot.y': 'error',
  'convergence.plot.title': 'Errors of the discrete invariants against the step H (log-log)',
  'convergence.plot.slope': 'slope {k}',
  'convergence.readout.footpoint': 'order of f_{i,i+1}',
  'convergence.readout.midpoint': 'order of the midpoint m_i',
  'convergence.readout.delta': 'order of δ_{i,i+1}',
  'convergence.readout.deltaMean': 'order of the averaged δ̄_i',
  'convergence.readout.normal': 'order of N_{i,i+1} → central tangent',
  'convergence.describe':
    'Errors of the discrete invariants at u = {u}, for steps from {h0} over {levels} halvings: the footpoint converges with order {footpoint}, the midpoint of the footpoints with order {midpoint}.',
  'convergence.describeEdited':
    'Your edit of the three rulings, with their common perpendiculars, footpoints and striction point; the mean distribution parameter at the middle ruling is {delta}.',
  'convergence.editedNote':
    'The orders are measured against the exact surface, which your edit does not have: “Back to the built-in input” measures them again.',
  'convergence.readout.delta01': 'δ_{0,1}',
  'convergence.readout.delta12': 'δ_{1,2}',
  'convergence.readout.deltaMeanEdited': 'mean δ at the middle ruling',

  // Figs. 4–6
  'isometry.title': 'Isometric bending and development (Figs. 4–6)',
  'isometry.param.layout': 'View',
  'isometry.layout.bend': 'Bend to the conoidal model',
  'isometry.layout.panels': 'Three panels: surface | conoidal | development (Fig. 6)',
  'isometry.param.t': 'Bending t',
  'isometry.param.ghost': 'Original surface (faint)',
  'isometry.reason.panels': 'The three-panel view always shows t = 1.',
  'isometry.reason.flat': 'At t = 0 the surface is the original.',
  'isometry.legend.striction': 'striction polygon (in the development: its image)',
  'isometry.legend.envelope':
    'in the development: the polygon the rulings envelop, image of Example 1’s polygon (dashed)',
  'isometry.legend.ghost': 'original surface (dashed)',
  'isometry.readout.nonDevelopability': 'non-developability (height of the conoidal model)',
  'isometry.readout.isometry': 'max relative change of an edge length',
  'isometry.describe':
    'Surface: {surface}, {n} rulings, bent isometrically to t = {t} toward its conoidal model; the conoidal model is {height} high.',
  'isometry.describe.cone.one':
    'Ruling {i} meets neither of its neighbours (up to {distance} apart); every other pair of consecutive rulings meets, as on a cone.',
  'isometry.describe.cone.some':
    'Rulings {list} meet neither of their neighbours (up to {distance} apart); every other pair of consecutive rulings meets.',
  'isometry.describe.cone.pairs': 'The consecutive rulings {list} do not meet (up to {distance} apart).',
  'isometry.describe.cone.all': 'Every pair of consecutive rulings meets, as on a cone.',
  'isometry.describePanels':
    'Surface: {surface}, {n} rulings (left), its conoidal model (middle) and its approximate development (right); the conoidal model is {height} high.',
  'isometry.download.development': 'Download the development (SVG)',
  'isometry.download.title': 'Approximate development (ruledlab)',
  'isometry.readout.radius': 'ρ, radius of curvature of the developed rulings’ envelope (middle ruling)',
  'isometry.readout.radiusFiner': 'ρ with 2N − 1 rulings',
  'isometry.claim.helical':
    'Fig. 5’s caption fails here: with 6 rulings or more ρ is within 0.1 of r + p tan β = 1.4, so the conoidal rulings touch a cylinder of that radius and miss the axis.',
  'isometry.claim.orthogonal':
    'Here the caption holds in the limit: ρ tends to 0 at second order (with twice as many rulings it drops to between a third and a fifth).',
  'isometry.readout.delta': 'δ of the middle pair of rulings',

  // your surface
  'formula.title': 'Your surface (formulas)',
  'formula.param.preset': 'Start from',
  'formula.param.umin': 'u from',
  'formula.param.umax': 'u to',
  'formula.param.vmin': 'v from',
  'formula.param.vmax': 'v to',
  'formula.param.closed': 'Closed in u',
  'formula.param.a': 'Parameter a',
  'formula.param.b': 'Parameter b',
  'formula.param.c': 'Parameter c',
  'formula.param.tool': 'Tool',
  'formula.tool.striction': 'Striction polygon (Section 2)',
  'formula.tool.convergence': 'Convergence orders (Propositions 1–2)',
  'formula.tool.bending': 'Bending to the conoidal model (Section 3)',
  'formula.tool.development': 'Approximate development (Fig. 6)',
  'formula.tool.subdivision': 'Subdivision (Section 4)',
  'formula.reason.tool': 'Not used by the chosen tool.',
  'formula.problem.notClosed':
    '“Closed in u” follows the last ruling by the first, but this surface does not close: its ruling at u = {umax} is not the one at u = {umin} ({gap} apart, at {angle} rad). Uncheck it for a surface that does not close.',
  'formula.scheme.fourPoint': 'Four-point w = 1/16',
  'formula.scheme.chaikin': 'Chaikin',
  'formula.scheme.variational': 'Variational (coupled)',
  'formula.scheme.lines': 'Four-point in line space',
  'formula.legend.given': 'sampled rulings',
  'formula.legend.inserted': 'inserted rulings',
  'formula.describeSubdivision':
    'Your surface as {n} rulings, refined by {steps:step:steps} into {total} rulings; the inserted rulings are at most {distance} from the exact surface.',
  // the fields’ names in messages: "the z component of e(u)", "the field “u from”"
  'formula.param.ax.field': 'the x component of a(u)',
  'formula.param.ay.field': 'the y component of a(u)',
  'formula.param.az.field': 'the z component of a(u)',
  'formula.param.ex.field': 'the x component of e(u)',
  'formula.param.ey.field': 'the y component of e(u)',
  'formula.param.ez.field': 'the z component of e(u)',
  'formula.param.umin.field': 'the field “u from”',
  'formula.param.umax.field': 'the field “u to”',
  'formula.param.vmin.field': 'the field “v from”',
  'formula.param.vmax.field': 'the field “v to”',

  // your data
  'data.title': 'Your data',
  'data.param.closed': 'Closed (last ruling followed by the first)',
  'data.legend.rulings': 'your rulings',
  'data.legend.strictionDetail': 'striction curve, through the rulings drawn',
  'data.note.closedGrid':
    '“Closed” follows the last ruling of a surface by the first; a grid of lines is shown as it is, not closed.',
  'data.note.detail':
    'Level of detail: the strip and the striction curve go through one ruling in {every} ({drawn} of them), and one ruling in {lines} is drawn as a line; the numbers are of every ruling. Rulings can be dragged in models of up to {max}.',
  'data.note.computing': 'The invariants of all {n} rulings are being computed in the background (Cancel stops it).',
  'data.note.cancelled':
    'The invariants of the {n} rulings were not computed (cancelled): change a setting to compute them.',
  'data.note.focalRulings': 'Focal surfaces are those of a grid of lines; your rulings are a surface, which has none.',
  'data.readout.lines': 'lines (congruence)',
  'data.describe':
    'Your ruled surface of {n} rulings ({parallel} parallel pairs), with its common perpendiculars and striction polygon; the smallest |δ| of a pair of rulings is {least}.',
  'data.describeDetail':
    'Your ruled surface of {n} rulings ({parallel} parallel pairs), drawn at a level of detail with its striction curve; the smallest |δ| of a pair of rulings is {least}.',
  'data.describeCancelled': 'Your ruled surface of {n} rulings; its invariants were not computed (cancelled).',
  'data.describePending': 'Your ruled surface of {n} rulings; its invariants are being computed.',
  'data.describeCongruence': 'Your line congruence of {rows} × {cols} lines.',

  // large models
  'large.title': 'Large models in a Web Worker',
  'large.param.steps': 'Four-point steps',
  'large.param.rulings': 'Rulings as lines',
  'large.legend.strip': 'helicoid strip',
  'large.readout.rulings': 'rulings of the model',
  'large.readout.drawn': 'rulings in the drawn strip',
  'large.readout.lines': 'rulings drawn as lines',
  'large.note.lod': 'Level of detail: the strip is drawn through one ruling in {every} ({drawn} of them).',
  'large.note.lines': 'One ruling in {every} is drawn as a line, so that the lines stay apart on screen.',
  'large.describe': 'A helicoid of {rulings} rulings, {drawn} of them drawn.',
};
