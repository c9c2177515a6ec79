// English texts of the subdivision scenes: curves, the strip, line space and the tool path
// (Sections 4 and 6). Labels may use R_{i,i+1}-style subscripts (ui/richtext.js).
// Keys: curves.*, strip.*, lines.*, milling.*

// The texts said by key with no caller to fill a placeholder (readout labels, claims) quote
// the page's limits from limits.js.
import { TURNING_FROM, TURNING_STEPS } from '../../limits.js';

export default {
  // Figs. 7–8
  'curves.title': 'Curve subdivision (Figs. 7–8)',
  'curves.scheme.chaikin': 'Chaikin (Fig. 7)',
  'curves.scheme.fourPoint': 'Four-point, Dyn–Levin–Gregory (Fig. 8)',
  'curves.scheme.bspline': 'Cubic B-spline (de Boor)',
  'curves.param.w': 'Tension w',
  'curves.param.closed': 'Closed polygon',
  'curves.param.levels': 'Show every level',
  'curves.reason.w': 'w is the tension of the four-point scheme only.',
  'curves.reason.levels': 'There is one level at most.',
  'curves.legend.control': 'control polygon (with points)',
  'curves.legend.levels': 'intermediate levels (thin)',
  'curves.legend.refined': 'refined polygon',
  'curves.readout.points': 'points',
  'curves.readout.w': 'tension w',
  'curves.readout.turning': 'largest turning angle of the polygon drawn (rad)',
  'curves.readout.turningLate': `largest turning angle after ${TURNING_FROM} → ${TURNING_STEPS} steps (rad)`,
  'curves.plot.x': 'steps',
  'curves.plot.y': 'largest turning angle (rad)',
  'curves.plot.title': 'Largest turning angle of the refined polygon after each step (logarithmic)',
  'curves.claim.falls': `On this polygon the largest turning angle is smaller after ${TURNING_STEPS} steps than after ${TURNING_FROM} for every w with 0 < w ≤ 0.17 (closed) or 0 < w ≤ 0.126 (open).`,
  'curves.claim.sharp': `From w = 0.171 (closed) or w = 0.127 (open) up to 0.2 the polygon still turns by more than 1 rad (57°) somewhere after ${TURNING_STEPS} steps.`,
  'curves.describe':
    '{scheme}, {steps:step:steps} on an eight-point polygon: {points} points; the largest turning angle is {angle} rad ({late} rad after {last} steps).',

  // Figs. 9–10
  'strip.title': 'Variational strip subdivision (Figs. 9–10, Example 3)',
  'strip.scheme.literal': 'Variational, literal (13)–(15): the midpoint rule',
  'strip.scheme.coupled': 'Variational, coupled (beyond the paper)',
  'strip.scheme.averaged': 'Variational, averaged umbrellas (beyond the paper)',
  'strip.scheme.fourPoint': 'Four-point w = 1/16 on both boundaries',
  'strip.param.n': 'Parts per segment n',
  'strip.param.triangulation': 'Triangulation',
  'strip.triangulation.first': 'first (11)',
  'strip.triangulation.second': 'second (12)',
  'strip.triangulation.none': 'none',
  'strip.param.labels': 'Notation of Fig. 9',
  'strip.param.exact': 'Exact surface (faint)',
  'strip.reason.n': 'The four-point scheme does not divide the segments.',
  'strip.legend.given': 'given rulings (12 of Example 3)',
  'strip.legend.inserted': 'inserted rulings A_i B_i',
  'strip.legend.a': 'A_i (light, large points)',
  'strip.legend.b': 'B_i (dark, large points)',
  'strip.legend.triangulation': 'triangulation of the refined strip (thin)',
  'strip.readout.distance': 'max distance of inserted rulings from the surface',
  'strip.describe':
    '12 rulings of the quartic surface of Example 3 with 11 rulings inserted by {scheme}, n = {n}; the inserted rulings are at most {distance} from the exact surface.',
  'strip.readout.compare.midpoint': 'midpoint rule: max distance',
  'strip.readout.compare.literal': 'literal (15): max distance',
  'strip.readout.compare.coupled': 'coupled: max distance',
  'strip.readout.compare.averaged': 'averaged: max distance',
  'strip.readout.compare.fourPoint': 'four-point: max distance',
  'strip.claim.literal': 'Read literally, (15) is the midpoint rule: their distances are equal for every n.',
  'strip.claim.coupled':
    'For every n from 5 to 24 (the slider’s range) the coupled energy comes closer to the surface than the midpoint rule; for n = 3, 4 it does not.',
  'strip.claim.fourPoint':
    'The four-point scheme is exact on this surface, the best of all at the worst ruling: its boundary curves are quadratic, which w = 1/16 reproduces.',
  'strip.describeEdited':
    'Your edit of the 12 given rulings with 11 rulings inserted by {scheme}, n = {n}; without the quartic there is no distance to measure.',

  // line space
  'lines.title': 'Subdivision in line space (beyond the paper)',
  'lines.param.slide': 'Slide the given endpoints',
  'lines.legend.given': 'given rulings (endpoints slid)',
  'lines.legend.endpoints': 'four-point on the endpoints (dashed)',
  'lines.legend.lines': 'four-point on the lines',
  'lines.readout.endpoints': 'endpoint scheme: new rulings turned by (rad)',
  'lines.readout.lines': 'line-space scheme: turned by (rad)',
  'lines.describe':
    'Nine rulings of the {surface} with their endpoints slid along the rulings by {slide} of the pattern; the endpoint scheme\u2019s new rulings turned by up to {endpointTurn} rad, the line-space scheme\u2019s by {lineTurn}.',
  'lines.describeEdited':
    'Your edit of the nine given rulings of the {surface}; against the schemes\u2019 rulings of the unslid surface, the endpoint scheme\u2019s new rulings turned by up to {endpointTurn} rad, the line-space scheme\u2019s by {lineTurn}.',

  // Figs. 16–18
  'milling.title': '5-axis tool path (Example 6, Figs. 16–18)',
  'milling.param.poses': 'Given poses',
  'milling.param.steps': 'Steps (Figs. 16–18)',
  'milling.scheme.variational': 'Variational (coupled)',
  'milling.scheme.averaged': 'Variational (averaged)',
  'milling.scheme.four-point': 'Four-point w = 1/16',
  'milling.scheme.linear': 'Linear (midpoints)',
  'milling.reason.steps': 'With no steps the given poses are shown.',
  'milling.param.tool': 'Tool (Fig. 16)',
  'milling.param.at': 'Tool position along the path',
  'milling.reason.tool': 'The tool is hidden.',
  'milling.param.envelope': 'Swept ball (machined surface)',
  'milling.param.part': 'Part surface',
  'milling.legend.profile': 'target profile (wide)',
  'milling.legend.given': 'given tool axes',
  'milling.legend.inserted': 'inserted tool axes',
  'milling.legend.barycentre': 'barycentre curve (dashed)',
  'milling.legend.envelope': 'envelope of the ball',
  'milling.legend.tool': 'tool, a ball-end cylinder',
  'milling.legend.part': 'part surface',
  'milling.readout.poses': 'poses',
  'milling.readout.deviation': 'max |deviation| from the profile',
  'milling.readout.angleStep': 'max orientation step (rad)',
  'milling.readout.secondDifference': 'max 2nd difference of the axis',
  'milling.describe':
    '{poses} given poses of a ball-end tool refined by {steps:step:steps} of {scheme} into {total} poses; the machined surface misses the target profile by at most {deviation}.',
  'milling.download.json': 'Download JSON',
  'milling.download.csv': 'Download CSV',
  'milling.download.gcode': 'Download G-code',
  'milling.readout.compare.given': 'given poses only: max |deviation|',
  'milling.readout.compare.variational': 'variational (coupled): max |deviation|',
  'milling.readout.compare.averaged': 'variational (averaged): max |deviation|',
  'milling.readout.compare.four-point': 'four-point: max |deviation|',
  'milling.readout.compare.linear': 'linear (midpoints): max |deviation|',
  'milling.claim.refined':
    'The smoothing schemes (both variational ones and four-point) machine closer to the profile than the given poses alone; the midpoint rule need not.',
  'milling.claim.turns':
    'The midpoint rule turns the tool in the smallest steps (it halves each turn) but least evenly: its largest second difference is the largest of the four schemes; the averaged variational scheme turns it most evenly.',
  'milling.claim.variational':
    'With 7 given poses or more, both variational schemes leave a smaller deviation than four-point and the midpoint rule, at every number of steps.',
  'milling.param.machine': 'Machine',
  'milling.machine.table-table-ac': 'table-table A/C (trunnion)',
  'milling.machine.table-table-bc': 'table-table B/C',
  'milling.machine.head-table-bc': 'head-table B/C',
  'milling.machine.head-head-ac': 'head-head A/C (fork head)',
  'milling.param.dialect': 'Controller (G-code)',
  'milling.dialect.linuxcnc': 'LinuxCNC',
  'milling.dialect.heidenhain': 'Heidenhain Klartext',
  'milling.dialect.sinumerik': 'Siemens Sinumerik 840D',
  'milling.param.mode': 'Kinematics',
  'milling.mode.machine': 'machine coordinates (ruledlab)',
  'milling.mode.tcp': 'tool-centre point (the controller)',
  'milling.readout.inserted': 'poses the G-code post inserted',
  'milling.readout.linearTip': 'linear interpolation, max tip deviation before (mm)',
  'milling.readout.linearAxis': 'linear interpolation, max axis deviation before (mm)',
  'milling.readout.post': 'G-code',
  'milling.plot.title': 'Deviation along the path',
  'milling.plot.x': 'position along the path (given poses)',
  'milling.plot.y': 'deviation (mm)',
  'milling.plot.pose': 'ball from the profile, per pose',
  'milling.plot.tip': 'interpolated tip, per block',
  'milling.plot.axis': 'interpolated axis, per block',
  'milling.describeImported': 'Your {poses} tool poses refined by {steps:step:steps} of {scheme} into {total} poses.',
  'milling.describeEdited':
    'Your edit of the {poses} given poses of a ball-end tool, refined by {steps:step:steps} of {scheme} into {total} poses; the machined surface misses the target profile by at most {deviation}.',
  'milling.describeImportedEdited':
    'Your edit of {poses} imported tool poses, refined by {steps:step:steps} of {scheme} into {total} poses.',
};
