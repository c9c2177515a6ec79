// English explanations of the scenes: markup (HTML with MathML) from the project's own files.
// Keys: striction.text, notation.text, convergence.text, isometry.text, curves.text, strip.text,
//   congruence.text, milling.text, formula.text, focal.text, formulaCongruence.text, lines.text,
//   large.text, data.text
// The page's limits are quoted from limits.js, never retyped.
import { sub, m, mr, display, frac, row, fii1, fiim, Ri, grouped } from '../mathml.js';
import { DRAW_LIMIT, MAX_LINK_RULINGS, TURNING_FROM, TURNING_STEPS } from '../../limits.js';

export default {
  'striction.text': `
<h2>Difference geometry of a ruled surface</h2>
<p>A discrete ruled surface is a sequence of lines ${m(Ri)}. Two consecutive rulings enclose the
angle ${m(sub('φ', 'i , i + 1'))} and have one common perpendicular ${m(sub('N', 'i , i + 1'))}. It
meets ${m(Ri)} at the footpoint ${m(fii1)}, and the two footpoints of a pair are
${m(`<mo>|</mo>${sub('h', 'i , i + 1')}<mo>|</mo>`)} apart: ${m(sub('h', 'i , i + 1'))} is their signed distance, its sign telling how the two
rulings wind. The <em>discrete distribution parameter</em> is</p>
${display(`${sub('δ', 'i , i + 1')}<mo>=</mo>${frac(sub('h', 'i , i + 1'), sub('φ', 'i , i + 1'))}`, '1')}
<p>Each ruling carries two footpoints, ${m(fiim)} and ${m(fii1)}. Both tend to the <em>striction
point</em> ${mr('s ( u )')} as the rulings get closer, but only at first order (Proposition 1).
Their midpoint</p>
${display(`${sub('m', 'i')}<mo>=</mo>${frac('<mn>1</mn>', '<mn>2</mn>')}<mo>(</mo>${fiim}<mo>+</mo>${fii1}<mo>)</mo>`, '7')}
<p>converges at second order (Proposition 2): the first-order errors of the two footpoints are
equal and opposite. The <em>striction polygon</em> joins these midpoints.</p>
<p><strong>Two polygons, not one.</strong> Read literally, Example 1 describes a different polygon: the
midpoints ${m(`<mo>(</mo>${fii1}<mo>+</mo>${sub('f', 'i + 1 , i')}<mo>)</mo><mo>/</mo><mn>2</mn>`)} of
the common perpendiculars (switch it on). It approximates the striction curve at the parameter
<em>between</em> two rulings, ${mr('u + H / 2')}, also at second order; the striction polygon
${m(sub('m', 'i'))} approximates it at the rulings themselves. The readout measures both.</p>
<p><strong>Try it.</strong> Double the number of rulings and watch the readout: the footpoint error
halves, the errors of both polygons drop to a quarter (on the hyperboloid and the quartic from
about 20 rulings on; the readout measures the orders from N to 2N rulings). On the hyperboloid of Example 1 the
striction curve is not the waist ellipse; on the cone all common perpendiculars meet in the apex;
on the cylinder consecutive rulings are parallel, the common perpendicular is not unique, and
ruledlab says so (no value, the pair counted as parallel) rather than guess.</p>
<p class="rl-paper-data">Data: Example 1's hyperboloid x² + y²/4 − z²/9 = 1 is the paper's; the
number of rulings (36) and the segment length are ruledlab's choice.</p>`,

  'notation.text': `
<h2>Fig. 1: the notation</h2>
<p>Three consecutive rulings ${m(sub('R', 'i − 1'))}, ${m(Ri)}, ${m(sub('R', 'i + 1'))} of the
hyperboloid of Example 1. Each pair has exactly one common perpendicular ${m(sub('N', 'i , i + 1'))};
it meets ${m(Ri)} in the footpoint ${m(fii1)} and ${m(sub('R', 'i + 1'))} in ${m(sub('f', 'i + 1 , i'))}.
Its length is the distance of the two rulings; with a sign (how the two rulings wind about each other)
it is the signed distance ${m(sub('h', 'i , i + 1'))} of the readout. The dashed line through ${m(fii1)} is parallel to
${m(sub('R', 'i + 1'))}: it encloses the angle ${m(sub('φ', 'i , i + 1'))} with ${m(Ri)}. Every ruling
carries two footpoints, one from each neighbour; their midpoint ${m(sub('m', 'i'))} is the discrete
striction point. Shrink the spacing and watch the two footpoints close in on it.</p>`,

  'convergence.text': `
<h2>How fast the discrete invariants converge</h2>
<p>Take the rulings ${mr('R ( u − H )')}, ${mr('R ( u )')}, ${mr('R ( u + H )')} of an analytic
surface and shrink H. Proposition 1: the footpoint ${m(fii1)} tends to the striction point
${mr('s ( u )')} and ${m(`${sub('δ', 'i , i + 1')}<mo>=</mo>${row('h / φ')}`)} to the distribution
parameter, both with errors proportional to H (slope 1 in the plot), and the common perpendicular
tends to the <em>central tangent</em> through ${mr('s ( u )')}:</p>
${display(`${mr('s ( u ) +')}<mo>[</mo>${sub('e', '3')}${mr('( u )')}<mo>]</mo><mo>=</mo><munder><mo>lim</mo>${row('h → 0')}</munder>${sub('N', 'i , i + 1')}`, '4')}
<p>(the dashed line in the view). Proposition 2: the midpoint of the two footpoints on
${mr('R ( u )')} and the average of the two δ are far better: their first-order errors cancel,
leaving errors proportional to ${m('<msup><mi>H</mi><mn>2</mn></msup>')} (slope 2). The plot is
measured by the core, not drawn from the formulas.</p>
<p>Try the helical surface: there the two footpoints are exactly symmetric about
${mr('s ( u )')}, so the midpoint is exact (the readout says "exact"), and δ is second order
because the discrete δ is an even function of H. On Plücker's conoid the footpoints lie on the axis
exactly.</p>`,

  'isometry.text': `
<h2>Bending a ruled surface without stretching it</h2>
<p>Take two consecutive rulings ${m(Ri)}, ${m(sub('R', 'i + 1'))} together with their common
perpendicular as one rigid body, and let every ruling act as a <em>hinge</em> between the two
bodies it belongs to. Turning the hinges moves the rulings, but no polygon
${m(`${sub('p', 'i')}<mo>∈</mo>${Ri}`)} changes the length of any edge: this kinematic chain is the
discrete model of the <em>Minding isometries</em>, which map rulings to rulings. The readout shows
the largest relative change of an edge length: rounding, nothing more.</p>
<p><strong>Example 2.</strong> Keep ${m(sub('R', '0'))} and ${m(sub('R', '1'))} fixed and turn each
following body about its hinge until its common perpendicular points the same way as the first one,
${m(sub('n', '0 , 1'))}. Then every ruling is orthogonal to that direction: the surface has become
<em>conoidal</em> (all rulings parallel to one plane). Slide <em>t</em> from 0 to 1 (or press play)
to watch the bending; the picture is turned so that ${m(sub('n', '0 , 1'))} points up, and the
conoidal rulings become horizontal, stacked at heights
${m(`${sub('ζ', 'i')}<mo>=</mo><munder><mo>∑</mo>${row('k < i')}</munder>${sub('h', 'k , k + 1')}`)}.</p>
<p><strong>Approximate development (Fig. 6).</strong> Project the conoidal model orthogonally onto a
plane parallel to its rulings. Each ruling keeps its length. The common perpendiculars of the
conoidal model all point the same way, so the two footpoints of every pair fall onto one point,
where the two projected rulings meet: these points form the polygon the projected rulings envelop
(dashed; the image of Example 1's polygon of perpendicular midpoints), just as the regression curve is
the envelope in the development of a developable surface. The image of the striction polygon is
inscribed in it: ${m(sub('m', 'i'))} lies midway between the two footpoints on ${m(Ri)}, so its image
is the midpoint of the envelope polygon's edge on that ruling. The spread of the heights,
${m(`<mo>max</mo>${sub('ζ', 'i')}<mo>−</mo><mo>min</mo>${sub('ζ', 'i')}`)}, measures how far the
surface is from developable: 0 for the cone, tiny (shrinking like
${m('<msup><mi>H</mi><mn>2</mn></msup>')} as rulings are added) for the tangent surface, clearly
positive for the hyperboloid strip.</p>
<p class="rl-beyond"><strong>Beyond the paper: when Fig. 5's caption holds.</strong> The paper shows
the conoidal image of a ruled helical surface as a helicoid whose rulings meet the axis
orthogonally. Measured here, that holds only when the striction curve crosses the rulings at a
right angle. In general the conoidal rulings touch a cylinder about the axis of radius
${m(frac(row('e · ṡ'), row('| e′ |')))}: 1.4 for the surface with rulings at 45° (radius 1, pitch
0.4 per radian: z = 0.4 u). The readout measures it discretely: ρ, the step between the two footpoints on a ruling over
the angle the rulings turn there, is the radius of curvature of the envelope of the developed
rulings, and tends to ${m(frac(row('e · ṡ'), row('| e′ |')))} at second order. Choose "rulings
orthogonal to the striction helix" (β = −atan(r/p)) and ρ tends to 0: the caption's helicoid
appears in the limit.</p>
<p class="rl-paper-data">The paper gives no data for Figs. 4–6; ruledlab uses Example 3's quartic,
a ruled helical surface (radius 1, pitch 0.4 per radian, so 2π · 0.4 ≈ 2.51 per turn) and a strip of Example 1's hyperboloid.</p>`,

  'curves.text': `
<h2>Subdivision of polygons</h2>
<p><strong>Chaikin's algorithm</strong> (Fig. 7) replaces every edge by the points at ¼ and ¾ of its
length. The polygons converge to the quadratic B-spline with the original points as control
points; it touches every interior edge at its midpoint. The paper counts the algorithms of de
Casteljau and de Boor among the subdivision algorithms of this type, which do not keep all the
input points (de Casteljau's keeps the two end points): repeated, they converge to a Bézier or a
B-spline curve. Their rules are their own, not Chaikin's cuts at ¼ and ¾, except for degree 2:
inserting the midpoints of uniform knots into a quadratic B-spline is Chaikin's algorithm.</p>
<p><strong>The four-point scheme</strong> of Dyn, Levin and Gregory (Fig. 8) keeps every point and
inserts a new one on each edge:</p>
${display(`${sub('p', 'i + 1/2')}<mo>=</mo><mo>(</mo>${frac('<mn>1</mn>', '<mn>2</mn>')}<mo>+</mo><mi>w</mi><mo>)</mo><mo>(</mo>${sub('p', 'i')}<mo>+</mo>${sub('p', 'i + 1')}<mo>)</mo><mo>−</mo><mi>w</mi><mo>(</mo>${sub('p', 'i − 1')}<mo>+</mo>${sub('p', 'i + 2')}<mo>)</mo>`, '8')}
<p>The limit interpolates the data. The paper's Fig. 8 uses w = 1/13 (type it exactly in the field
beside the slider), and w = 1/16 reproduces cubic polynomials; slide w to 0 and the limit is the
polygon itself. The paper calls the limit C¹ for 0 &lt; w &lt; ⅛: that is the sufficient condition
Dyn, Levin and Gregory proved in 1987, not the place where kinks appear. Dyn, Gregory and Levin
(1991) prove C¹ for 0 &lt; w &lt; (√5 − 1)/8 ≈ 0.155. The sharp bound is known: the limit is C¹
exactly for 0 &lt; w &lt; w* ≈ 0.19273, the real root of 32w³ + 4w − 1 = 0 (J. Hechler, B. Mößner
and U. Reif, <em>C¹-continuity of the generalized four-point scheme</em>, Linear Algebra Appl.
430, 2009, pp. 3019–3029), where the joint spectral radius of the scheme of the divided differences reaches 1.</p>
<p><strong>Watch the polygons straighten out.</strong> The readout and the plot give the largest
turning angle of the refined polygon, the largest angle between an edge and the next, after each
step up to ${TURNING_STEPS}, more than are drawn. Where it falls towards 0 the polygons straighten out; it
shows how fast they do, not whether the limit is C¹. On this polygon, closed, it is smaller after
${TURNING_STEPS} steps than after ${TURNING_FROM} for every w up to 0.17, but near there it no longer falls steadily: at
w = 0.17 it is 1.15, 1.04, 1.19 and 1.00 rad after ${TURNING_FROM - 2}, ${TURNING_FROM}, ${TURNING_STEPS - 2} and ${TURNING_STEPS} steps. From w = 0.171 on, the
polygon still turns by more than 1 rad somewhere after ${TURNING_STEPS} steps: slow convergence, or a cusp of
the limit where its derivative vanishes — a C¹ limit may have one, and the angles cannot tell the
two apart. Past w* ≈ 0.193 (the slider goes on to 0.2) there is no C¹ limit. On an open polygon the end edges use ghost points extrapolated from the
last four points, ruledlab's end rule (the paper gives none), and it gives out first: there the
angle falls only up to w = 0.126, while the closed polygon, which has no ends, still straightens
out beyond.</p>
<p class="rl-paper-data">The paper gives no control polygon for Figs. 7–8; ruledlab uses eight points
in an open zigzag (the checkbox closes it).</p>`,

  'strip.text': `
<h2>Variational subdivision of a ruled strip (Example 3)</h2>
<p>Refining the two boundary curves separately ignores the surface between them. The variational
scheme inserts a ruling ${m(`${sub('A', 'i')}${sub('B', 'i')}`)} between every pair of rulings,
divides all segments into <em>n</em> parts,</p>
${display(`${sub('z', 'i , k')}<mo>=</mo>${frac(row('n − k'), '<mi>n</mi>')}${sub('a', 'i')}<mo>+</mo>${frac('<mi>k</mi>', '<mi>n</mi>')}${sub('b', 'i')}`, '9')}
<p>and triangulates the refined strip in the two ways of Fig. 9. At a vertex with six neighbours
the <em>umbrella vector</em> (13) is the vertex minus the mean of its neighbours, a discrete mean
curvature; the new endpoints minimise</p>
${display(`<mi>F</mi><mo>=</mo><munder><mo>∑</mo>${row('i , k')}</munder><mo>(</mo><msubsup><mi>U</mi>${row('i , k')}<mn>2</mn></msubsup><mo>+</mo><msubsup><mover><mi>U</mi><mo>~</mo></mover>${row('i , k')}<mn>2</mn></msubsup><mo>)</mo>`, '15')}
<p>a quadratic function, so one linear solve.</p>
<p class="rl-beyond"><strong>What ruledlab adds.</strong> Read literally, with umbrellas at the new
points only, the minimiser is just the midpoint rule (choose "literal": the readout equals the
midpoint rule's). ruledlab's <em>coupled</em> energy puts umbrellas at every interior vertex, old
ones included, so the new rulings couple and, for every n from 5 to 24 (the slider runs from 3 to 24), follow
the surface more closely than the midpoint rule (for n = 3, 4 they do not). The <em>averaged</em>
variant averages the two triangulations' umbrellas before squaring: the energy (15) contains a
twist term from the sheared neighbours of the two triangulations, and averaging cancels it. On
this surface the four-point scheme is best of all at the worst ruling: its boundary curves are
quadratic, which w = 1/16 reproduces exactly. The readout measures the distance of the inserted
rulings from the exact surface, for every scheme at this n; the claims under it are checked
against those numbers.</p>
<p class="rl-paper-data">Data: the paper's: 12 rulings of the quartic surface
(1 + vu², u²/2 + uv, u − v), n = 12; the intervals u ∈ [−1, 1] and v ∈ [−1, 1] (the rulings' ends) are
ruledlab's (the paper gives neither).</p>`,

  'congruence.text': `
<h2>Refining a congruence of lines</h2>
<p>A <em>line congruence</em> is a two-parameter family of lines, such as the axis positions of a
milling tool over a surface. Its discrete model is a grid of lines ${m(sub('R', 'i , j'))}, each
given by its points ${m(sub('p', 'i , j'))} and ${m(sub('q', 'i , j'))} on two director surfaces
${m(sub('d', '1'))} and ${m(sub('d', '2'))} (Fig. 11). Refining the congruence means refining both
point grids.</p>
<p><strong>Butterfly scheme (Fig. 12).</strong> Triangulate the grid by the diagonals and insert on
each diagonal</p>
${display(`${sub('p̄', 'i , j')}<mo>=</mo>${frac('<mn>1</mn>', '<mn>2</mn>')}<mo>(</mo>${sub('p', 'i , j')}<mo>+</mo>${sub('p', 'i + 1 , j + 1')}<mo>)</mo><mo>+</mo><mn>2</mn><mi>w</mi><mo>(</mo>${sub('p', 'i + 1 , j')}<mo>+</mo>${sub('p', 'i , j + 1')}<mo>)</mo><mo>−</mo><mi>w</mi><mo>(</mo>${sub('p', 'i , j − 1')}<mo>+</mo>${sub('p', 'i − 1 , j')}<mo>+</mo>${sub('p', 'i + 1 , j + 2')}<mo>+</mo>${sub('p', 'i + 2 , j + 1')}<mo>)</mo>`, '16')}
<p>The paper inserts only these diagonal lines (Fig. 13, "diagonals only") and gives no value of the
tension w; ruledlab uses w = 1/16, which reproduces cubic polynomials.</p>
<p><strong>Variational subdivision (Section 5.2, Fig. 15).</strong> Each row and column of lines is
a ruled surface: the strip scheme inserts the lines T and S on the edges, and each face gets the
line whose umbrella vector (20) over its eight neighbours vanishes in every layer: their average.
Read literally (umbrellas at the new points only), the strip scheme gives the midpoint rule, so the
paper's scheme ("paper") is bilinear averaging of the four corners.</p>
<p class="rl-beyond"><strong>Beyond the paper.</strong> "Butterfly, all edges" applies (16)'s stencil
to the other two edge directions too, so one step doubles the grid. "Two-stage" makes the edge lines
with ruledlab's coupled strip energy; "coupled" lets all new lines settle together in one sparse
solve. The readout measures the scheme shown against the exact congruence and, for comparison, the
four schemes of the menu that refine the whole grid, at one step: the butterfly scheme on all edges is
the most accurate on these examples.</p>
<p class="rl-paper-data">Data: Example 5 is the paper's (d₁ = (u, v, ½ sin(2u + 1.5v)), directions
(u, v, sin u + 1.3 cos v), 8 × 7 lines on [−1.1, 1.1]², K = 6; read literally, the scheme gives the
same lines for every K, so K has no effect on the result). The paper gives no formulas for
Example 4's two congruences; ruledlab's sphere and hyperbolic paraboloid are its own choice, and the
segment length (0.35 of the direction vector) too.</p>`,

  'milling.text': `
<h2>Example 6: a smooth path for a milling tool</h2>
<p>A few positions of a ball-end tool are given along a profile to be milled. Each is a segment
from the tool tip along the tool axis, so the positions form a discrete ruled surface, and refining
that surface refines the motion. After one step (Fig. 16) the path already follows the profile
more closely; two and three steps (Figs. 17, 18) make the orientation change smoothly. The dashed curve
joins the tool's barycentres; the translucent tube is the envelope of the ball, whose lower half is
the machined surface. The tool itself is drawn at one pose (slide or play its position).</p>
<p>The readout measures what a CAM engineer cares about: how far the machined surface misses the
target profile (positive leaves material, negative gouges), the largest change of tool orientation
between two poses, and its second difference (how evenly the orientation turns). Compare the schemes
with the readout: with seven poses or more the variational schemes leave the smallest deviation from
the profile (fewer, and four-point can be closer); the midpoint rule turns the tool in the smallest
steps (it halves each turn) but least evenly, the averaged variational scheme most evenly. The plot
shows the deviation along the path: per pose, how far the ball stands off the profile; per block of
the G-code, how far the controller's linear interpolation strays from the path (tip, and axis times
the tool length, in mm at 1 unit = 10 mm).</p>
<p>The buttons export the path as JSON, CSV, or G-code for the machine, controller (LinuxCNC,
Heidenhain, Sinumerik) and kinematics chosen: machine coordinates computed by ruledlab, or the
tool-centre point left to the controller. The post inserts poses until the interpolation stays within
0.01 mm, and the program starts and ends with safe moves along the tool axis (the book’s part “CAM”).
Your own tool poses — a CSV of tip x, y, z and axis i, j, k per row, JSON, or the files exported
here — are pasted or uploaded in the data panel ("tool poses") and open in this scene.</p>
<p class="rl-paper-data">The paper gives no data for Example 6; the profile on the part surface
z = 0.3 sin x cos 0.7y, the seven poses and the tool (radius 0.25, length 1.5) are ruledlab's.</p>`,

  'formula.text': `
<h2>Your own ruled surface</h2>
<p>Type the directrix ${mr('a ( u )')} and the ruling direction ${mr('e ( u )')}: the surface is
${m(`${row('x ( u , v )')}<mo>=</mo>${row('a ( u ) + v e ( u )')}`)}. Formulas use numbers,
<code>u</code>, the parameters <code>a</code>, <code>b</code>, <code>c</code> (sliders),
<code>pi</code>, <code>e</code>, the operators <code>+ - * / ^</code> and the functions
sin cos tan asin acos atan atan2 sinh cosh tanh exp ln log sqrt abs (log is the natural logarithm).
A mistake is shown next to its field, with its column.</p>
<p>The core differentiates the formulas exactly (automatic differentiation, no step size), so the
<em>exact</em> striction curve ${mr('s ( u )')}, distribution parameter and central tangent are as
exact as for the built-in surfaces, and every tool of Sections 2–4 works on your surface: the
striction polygon, the convergence orders, bending, the approximate development and subdivision.
The formulas are part of the link: share it as an exercise.</p>`,

  'focal.text': `
<h2>Focal surfaces of a line congruence</h2>
<p class="rl-beyond"><strong>Beyond the paper.</strong> The paper refines congruences (Section 5)
but does not compute their geometry. Along a line ${mr('p + t e')} of a congruence
${mr('p ( u , v ) + t e ( u , v )')}, with ${m('<mi>e</mi>')} of unit length, the <em>focal points</em>
are where the line meets its infinitely near neighbours in the two torsal directions (below): the
roots of</p>
${display(`<mo>det</mo><mo>(</mo>${sub('p', 'u')}<mo>+</mo><mi>t</mi>${sub('e', 'u')}<mo>,</mo>${sub('p', 'v')}<mo>+</mo><mi>t</mi>${sub('e', 'v')}<mo>,</mo><mi>e</mi><mo>)</mo><mo>=</mo><mn>0</mn>`, 'F1')}
<p>Two real roots make the line <em>hyperbolic</em> (solid), none <em>elliptic</em> (dashed), a double
one <em>parabolic</em>. (Neighbours in any other direction do not meet the line: they come closest
at its <em>central points</em>, which range between the two limit points.) As the line moves, its two focal points sweep the two <em>focal surfaces</em>
(shaded where real). Along a <em>torsal direction</em> ${mr('( du : dv )')} the lines form a
developable strip through one focal point,</p>
${display(`<mo>det</mo><mo>(</mo>${sub('p', 'u')}<mi>du</mi><mo>+</mo>${sub('p', 'v')}<mi>dv</mi><mo>,</mo><mi>e</mi><mo>,</mo>${sub('e', 'u')}<mi>du</mi><mo>+</mo>${sub('e', 'v')}<mi>dv</mi><mo>)</mo><mo>=</mo><mn>0</mn>`, 'F2')}
<p>(strokes on the director surface ${m(sub('d', '1'))}). The <em>normality</em> is |cos| of the angle
between the two focal planes: 0 for the normals of a surface, whose focal points are the centres
of principal curvature — try the ellipsoid. A 5-axis tool-axis field is a congruence: where a focal
surface comes close to the part, neighbouring axes (nearly) meet there; where its lines turn
elliptic, they have no real focal points, and neighbouring axes twist past each other.</p>
<p>ruledlab computes all of this from the lines alone: their Plücker coordinates, differenced
over the grid (central inside, over three lines at the edge). The result does not depend on where
the points p and q sit on their lines, moves exactly with rigid motions, and converges at second
order, at the boundary too (the book, “Focal geometry and linear complexes”). The readout also fits the
<em>linear complex</em> ${m(`<mi>c</mi><mo>·</mo><mi>m</mi><mo>+</mo><mover><mi>c</mi><mo>‾</mo></mover><mo>·</mo><mi>d</mi><mo>=</mo><mn>0</mn>`)}
that holds the lines best: the lines meeting two skew lines lie in two (a linear congruence).</p>
<p class="rl-paper-data">Data: Example 5's congruence is the paper's; Example 4's two congruences
(the paper gives no data for them), the ellipsoid (semi-axes 1.6, 1.2, 0.8), the two skew lines
and the elliptic congruence are ruledlab's choices.</p>`,

  'formulaCongruence.text': `
<h2>Your own line congruence</h2>
<p>Type a point ${mr('p ( u , v )')} of the director surface ${m(sub('d', '1'))} and the line
direction ${mr('e ( u , v )')}: the congruence holds the lines ${mr('p ( u , v ) + t e ( u , v )')}.
The grid of lines (rows along u, columns along v) is refined by the schemes of Section 5. The
presets include the normals of an ellipsoid (a normal congruence) and the lines meeting two skew
lines.</p>`,

  'lines.text': `
<h2>Refining the lines, not their endpoints</h2>
<p>Every scheme of Section 4 works on two chosen points per ruling. Slide those points along their
rulings (slider) and the lines do not change, but the surface refined by the four-point scheme on
the endpoints (dashed) does: it depends on a choice that is not part of the geometry.</p>
<p class="rl-beyond"><strong>Beyond the paper.</strong> ruledlab can also refine the lines themselves.
An oriented line with direction e through p is the dual unit vector ${mr('e + ε ( p × e )')}. The
four-point rule (8) is applied to these vectors and each result is pushed back onto the dual unit
sphere: a new line. The refined lines then depend on the given lines only, and the construction
commutes with rigid motions; it is of fourth order, like the endpoint scheme. The readout shows how
far the new rulings of each scheme turned because of the slide.</p>`,

  'large.text': `
<h2>Large models</h2>
<p>A helicoid of up to 10 000 rulings, refined by up to seven steps of the four-point scheme: up to
1 280 000 rulings (the library's limit is 4 194 304 per surface, refused with a clear message
above). Small jobs are computed at once; anything larger runs in a Web Worker with its own copy of
the WebAssembly module, so the page keeps drawing and answering while the progress bar fills
(Cancel stops it). Above ${grouped(DRAW_LIMIT)} rulings the view draws every k-th ruling, a level of detail, and
says so below the readout.</p>`,

  'data.text': `
<h2>Your own rulings</h2>
<p>Your rulings, or your grid of lines, come from the page's data panel, from "Edit as data" in a
scene typed as formulas, or from a notebook (NumPy arrays sent by <code>View.from_segments</code> or
<code>View.from_grid</code>). In the data panel, paste or upload a CSV file with six numbers per line
(a.x a.y a.z b.x b.y b.z; a header line is fine) or JSON: <code>[[ax, ay, az, bx, by, bz], …]</code>, or
<code>{"rows": r, "cols": c, "segments": […]}</code> for a congruence. A malformed file is rejected
with the line and column of the problem, and the data shown before stays. A ruled surface is shown
with its striction polygon and common perpendiculars, a grid of lines with its director surface (and
its focal surfaces, if you choose them); the export buttons save it again, or its invariants. On the
page, small imports (up to ${MAX_LINK_RULINGS} rulings) are kept in the link; larger ones in this
browser tab's session storage.</p>`,
};
