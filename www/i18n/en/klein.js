// English texts of the Klein quadric scene (beyond the paper): lines as points of P⁵.
// Keys: klein.*
import { sub, m, mr, display, row } from '../mathml.js';

const L1 = sub('L', '1');
const L2 = sub('L', '2');
/** Ω(L₁, L₂) = 𝐝₁ · 𝐦₂ + 𝐝₂ · 𝐦₁ */
const omega = `<mi>Ω</mi><mo>(</mo>${L1}<mo>,</mo>${L2}<mo>)</mo><mo>=</mo>${sub('𝐝', '1')}<mo>·</mo>${sub('𝐦', '2')}<mo>+</mo>${sub('𝐝', '2')}<mo>·</mo>${sub('𝐦', '1')}`;
/** Ω(L_i, L_{i+1}) = −h_{i,i+1} sin φ_{i,i+1} */
const relation = `<mi>Ω</mi><mo>(</mo>${sub('L', 'i')}<mo>,</mo>${sub('L', 'i + 1')}<mo>)</mo><mo>=</mo><mo>−</mo>${sub('h', 'i , i + 1')}${row('sin')}${sub('φ', 'i , i + 1')}`;

export default {
  'klein.title': 'The Klein quadric: lines as points (beyond the paper)',
  'klein.param.mix': 'Mix α of the two spheres (°)',
  'klein.param.turn': 'Turn β of the second sphere (°)',
  'klein.param.unit': 'Unit of length ℓ',
  'klein.param.conic': 'Conic of the plane of the first, middle and last line',
  'klein.param.space': 'The lines in space, beside',
  'klein.param.mark': 'Marked line i: a ruling R_i, or a line of the grid row by row (bold in space, red on M)',
  'klein.param.source': 'Surface or congruence',
  'klein.legend.points': 'rulings R_i as points of M',
  'klein.legend.positive': 'step with Ω(L_i, L_{i+1}) > 0',
  'klein.legend.negative': 'step with Ω < 0 (dashed)',
  'klein.legend.torsal': 'torsal step: Ω = 0, the rulings meet or are parallel',
  'klein.legend.outline': 'the image of M: the spheres bounding it',
  'klein.legend.conic': 'conic: the plane of three rulings on M',
  'klein.legend.gridPoints': 'the congruence’s lines as points of M',
  'klein.legend.gridPositive': 'edge of the net with Ω > 0',
  'klein.legend.gridNegative': 'edge with Ω < 0 (dashed)',
  'klein.legend.gridTorsal': 'torsal edge: Ω = 0, the neighbouring lines meet or are parallel',
  'klein.readout.gridTorsal': 'torsal edges of the net (Ω = 0)',
  'klein.readout.gridMarked': 'Ω of the marked line and the next in its row',
  'klein.readout.gridNoStep': 'the last line of its row: no next one',
  'klein.describe.grid':
    'The {n} × {n} lines of the congruence “{surface}” as points of the Klein quadric M, drawn with α = {mix}°, β = {turn}°, ℓ = {unit}: the image of M is the shell between the spheres of radii {inner} and {outer} about the centre, drawn as grey circles. The points form a net: each is joined to the next line of its row and of its column; torsal edges (Ω = 0: the two lines meet or are parallel): {torsal} of {steps}; the least |Ω| is on the edge between the lines {least} of the grid (row, column): Ω = {omega}. The largest Klein residual is {residual}.',
  'klein.describe.gridMark':
    'Line {i} of the grid (row {row}, column {col}) is marked: bold in space, a red point on M.',
  'klein.param.side': 'Lines a side of the congruence’s grid',
  'klein.reason.congruence': 'A congruence’s grid has its own slider: lines a side.',
  'klein.reason.surface': 'Only a congruence has a grid.',
  'klein.pane.label': 'Klein view: the scene’s lines as points of the Klein quadric M',
  'klein.pane.canvas': 'The Klein quadric',
  'klein.pane.none':
    'This picture has no lines of its own to download, and so none to show on the Klein quadric. The scenes whose lines you can download as data show them here.',
  'klein.pane.tooMany': '{count} lines: more than the Klein view draws ({max}).',
  'klein.pane.marked': 'Line {i} of {count} is marked: bold in space, ringed on M.',
  'klein.pane.failed': 'The Klein view cannot draw these lines: {message}',
  'klein.pane.steer': 'The Klein view’s image of P⁵',
  'klein.pane.steerShort': 'Image α, β, ℓ',
  'klein.pane.mix': 'α',
  'klein.pane.turn': 'β',
  'klein.pane.unit': 'ℓ',
  'klein.pane.slider': 'Klein view: {name}',
  'klein.pane.describe':
    'Beside it, the Klein view: the {count} lines of the scene as points of the Klein quadric M, joined in their order (α = {mix}°, β = {turn}°, ℓ = {unit}). Torsal steps (Ω = 0: consecutive lines meet): {torsal} of {steps}; the least |Ω| is {least}. The largest Klein residual is {residual}; the best-fitting linear complex misses the lines by {complex}.',
  'klein.pane.describeGrid':
    'Beside it, the Klein view: the {rows} × {cols} lines of the grid as points of the Klein quadric M, a net whose edges join neighbouring lines of a row and of a column (α = {mix}°, β = {turn}°, ℓ = {unit}). Torsal edges (Ω = 0: the two lines meet): {torsal} of {steps}; the least |Ω| is {least}. The largest Klein residual is {residual}; the best-fitting linear complex misses the lines by {complex}.',
  'klein.legend.gridConic': 'conic: the plane of the first, middle and last line on M',
  'klein.readout.gridLeast': 'Ω at the edge of least |Ω|',
  'klein.readout.gridPlane': 'largest distance of a line from the conic’s plane',
  'klein.readout.gridNoPlane': 'the three lines span no conic',
  'klein.describe.gridConic':
    'The conic in which the plane of the first, middle and last line cuts M is drawn light blue; the lines lie at most {plane} from that plane.',
  'klein.describe.gridNoConic': 'The first, middle and last line span no plane cutting M in a conic.',
  'klein.readout.residual': 'largest Klein residual |Ω(L, L)|/2',
  'klein.readout.torsal': 'torsal steps (Ω = 0)',
  'klein.readout.least': 'Ω at the step of least |Ω|',
  'klein.readout.marked': 'Ω(L_i, L_{i+1}) of the marked ruling',
  'klein.readout.noStep': 'the last ruling: no next one',
  'klein.readout.plane': 'largest distance of a ruling from the conic’s plane',
  'klein.readout.noPlane': 'the three rulings span no conic',
  'klein.readout.complex': 'largest |Ω(C, L_i)| for the best linear complex C',
  'klein.readout.congruence':
    'residual of the second-best linear complex (0: the lines lie in a linear congruence, a 3-space section of M)',
  'klein.describe':
    'The {n} rulings of the surface “{surface}” as points of the Klein quadric M, drawn with α = {mix}°, β = {turn}°, ℓ = {unit}: the image of M is the shell between the spheres of radii {inner} and {outer} about the centre, drawn as grey circles. The points are joined in order; {torsal} of the {steps} steps are torsal (Ω = 0), the least |Ω| is at step {least}: Ω = {omega}. The largest Klein residual is {residual}.',
  'klein.describe.mark': 'Ruling R_{i} is marked: bold in space, a red point on M.',
  'klein.describe.conic':
    'The conic in which the plane of the first, middle and last ruling cuts M is drawn light blue; the rulings lie at most {plane} from that plane.',
  'klein.describe.noConic': 'The first, middle and last ruling span no plane cutting M in a conic.',
  'klein.describe.space':
    'Left of M as the scene first shows it, the lines in space, scaled about the centre of their box; a surface’s rulings are handles there (Edit).',
  'klein.text': `
<p>A line of space is a point of a quadric in a five-dimensional projective space: an oriented line with
unit direction ${m('<mi>𝐝</mi>')} through a point ${m('<mi>𝐩</mi>')} has the Plücker coordinates
${mr('( 𝐝 , 𝐦 )')}, ${mr('𝐦 = 𝐩 × 𝐝')}, and every such pair satisfies ${mr('𝐝 · 𝐦 = 0')}: the Klein
quadric M. The Klein form ${m(omega)} vanishes exactly when the two lines meet or are parallel.</p>
${display(relation, 'K7')}
<p>For consecutive rulings it is minus the signed distance times the sine of the angle, with the signs
of Section 2: zero at a torsal step, where the rulings meet (every step of a cone or a tangent surface),
and of the sign of −δ elsewhere. The polygon of the rulings' points is coloured by it.</p>
<p>M is four-dimensional; no picture shows it whole. Here the coordinates are split, with a unit of
length ℓ, into two vectors ${mr('𝐱 = ( 𝐝 + 𝐦 / ℓ ) / s')} and ${mr('𝐲 = ( 𝐝 − 𝐦 / ℓ ) / s')} that are
unit vectors exactly on M: M is a pair of spheres, and two lines meet when their points are as far apart
on the first sphere as on the second. The view draws ${mr('cos α 𝐱 + sin α 𝐲')} (the second sphere turned
by β about the vertical): α = 0 shows the first sphere, 90° the second, 45° the direction of the line,
drawn nearer the centre the farther the line passes from the origin. The image is linear: the chord of
two points is a line of the projective space, which lies on M exactly at torsal steps.</p>
<p>The rulings of the hyperboloid are one regulus: the plane that three of them span cuts M in a
conic, which passes through all of them. The rulings of the helical surfaces lie in a linear complex,
a hyperplane section of M: the readout gives how far their points lie from the hyperplane of the
linear complex that fits them best.</p>`,
};
