// English texts of the paper's figures and examples: the menu, the captions (quoted), what ruledlab
// shows for each and where it goes beyond the paper.
// Keys: paper.*

export default {
  'paper.none': '— none —',
  'paper.heading': 'From the paper: {figure}',
  'paper.changed': 'You changed the figure’s settings.',
  'paper.back': 'Back to {figure}',
  'paper.beyondTitle': 'Beyond the paper.',
  'paper.data.paper': 'Data: the paper’s.',
  'paper.data.partly': 'Data: partly the paper’s (see above).',
  'paper.data.none': 'Data: the paper gives none; ruledlab’s choice (see above).',
  'paper.fig1': 'Fig. 1: notation',
  'paper.fig2': 'Fig. 2: striction line and common normals',
  'paper.fig3': 'Fig. 3: discrete central curve',
  'paper.fig4': 'Fig. 4: conoidal model',
  'paper.fig5': 'Fig. 5: helical surface, caption fails',
  'paper.fig5-orthogonal': 'Fig. 5: helical surface, caption holds',
  'paper.fig6': 'Fig. 6: approximate development',
  'paper.fig7': 'Fig. 7: Chaikin’s algorithm',
  'paper.fig8': 'Fig. 8: four-point scheme, w = 1/13',
  'paper.fig9': 'Fig. 9: strip notation',
  'paper.fig10': 'Fig. 10: quartic strip refined',
  'paper.fig11': 'Fig. 11: congruence between two directrices',
  'paper.fig12': 'Fig. 12: butterfly scheme',
  'paper.fig13': 'Fig. 13 left: sphere',
  'paper.fig13-right': 'Fig. 13 right: hyperbolic paraboloid',
  'paper.fig14': 'Fig. 14: congruence notation',
  'paper.fig15': 'Fig. 15: Example 5 refined',
  'paper.fig16': 'Fig. 16: tool path, first step',
  'paper.fig17': 'Fig. 17: tool path, second step',
  'paper.fig18': 'Fig. 18: tool path, third step',
  'paper.ex1': 'Example 1: hyperboloid',
  'paper.ex2': 'Example 2: bending to a conoid',
  'paper.ex3': 'Example 3: quartic strip',
  'paper.ex4': 'Example 4: butterfly on congruences',
  'paper.ex5': 'Example 5: variational congruence',
  'paper.ex6': 'Example 6: milling',
  'paper.fig1.caption': '“Discrete ruled surface model: Notations.”',
  'paper.fig1.note':
    'Three consecutive rulings R_{i−1}, R_i, R_{i+1} with the common perpendiculars N_{i,i+1}, the footpoints f_{i,i+1}, f_{i+1,i}, the angle φ_{i,i+1} and the signed distance h_{i,i+1} (its absolute value is the distance of the two rulings, its sign says how they wind). The paper gives no data; ruledlab uses three rulings of Example 1’s hyperboloid (their spacing and position are sliders).',
  'paper.fig2.caption':
    '“Discrete model of a ruled surface with striction line and sequence of common normals of generators.”',
  'paper.fig2.note':
    'Example 1’s hyperboloid x² + y²/4 − z²/9 = 1 (the paper’s) with the common perpendiculars and the striction polygon m_i of Proposition 2. The number of rulings (36) and the segment length are ruledlab’s choice: the paper gives neither.',
  'paper.fig3.caption': '“Discrete model of ruled surface with discrete central curve.”',
  'paper.fig3.note':
    'The polygon Example 1 describes: the midpoints (f_{i,i+1} + f_{i+1,i})/2 of the common perpendiculars, on the paper’s hyperboloid with 36 rulings (ruledlab’s number).',
  'paper.fig3.beyond':
    'This is not the striction polygon m_i of Proposition 2, which the text uses as the discrete striction curve: it approximates the striction curve between two rulings, at u + H/2, also at second order. Switch the striction polygon on to see both; the readout measures each.',
  'paper.fig4.caption': '“Discrete ruled surface model (left) and conoidal model isometric to the first one (right).”',
  'paper.fig4.note':
    'The hinge chain turned all the way into its conoidal model (t = 1), the surface itself as a faint ghost, drawn in one view rather than side by side (the three-panel layout is Fig. 6). The paper gives no data; ruledlab uses 24 rulings of Example 3’s quartic.',
  'paper.fig5.caption':
    '“Left: Ruled helical surface. Right: Isometric conoidal surface. In this case the result is a helical surface whose generators intersect the axis orthogonally.”',
  'paper.fig5.note':
    'A ruled helical surface bent into its conoidal model. The paper gives no data; ruledlab uses radius 1, pitch 0.4 per radian (z = 0.4 u, so 2π · 0.4 ≈ 2.51 per turn) and rulings at 45°.',
  'paper.fig5-orthogonal.note':
    'The same helix with the rulings turned orthogonal to the striction helix (tan β = −r/p), the case in which the caption holds: the readout ρ tends to 0, the conoidal rulings meet the axis in the limit. The paper gives no data; the surface is ruledlab’s.',
  'paper.fig5.beyond':
    'The caption holds only when the rulings cross the striction curve at a right angle (e·ṡ = 0), which the paper does not say. In general the conoidal rulings touch a cylinder of radius ρ = (e·ṡ)/|e′| about the axis, r + p tan β for these surfaces: 1.4 at 45°, 0 orthogonally. The readout measures ρ and the claims under it are checked.',
  'paper.fig6.caption':
    '“Approximate development of a skew ruled surface based on the discrete representation: Left: Discrete model of a skew ruled surface. In the middle: Isometric conoidal discrete model. Right: Projection of the discrete conoidal surface orthogonal to its generators.”',
  'paper.fig6.note':
    'The three panels of Fig. 6: a strip of Example 1’s hyperboloid, its conoidal model and the development, where the image of the striction polygon is inscribed in the polygon the developed rulings envelop (dashed); the readout gives the conoidal model’s height, the non-developability measure. The paper gives no data; the strip (24 rulings, u from 0 to 2.4) is ruledlab’s.',
  'paper.fig7.caption': '“Chaikin’s algorithm.”',
  'paper.fig7.note':
    'Four steps of Chaikin’s algorithm, every level drawn. The paper gives no control polygon; ruledlab uses eight points in an open zigzag.',
  'paper.fig8.caption': '“Interpolatory subdivision according to Dyn, Levin and Gregory (w = 1/13).”',
  'paper.fig8.note':
    'Four steps of (8) with the paper’s w = 1/13, exactly (type a fraction in the field beside the slider). The paper gives no control polygon; ruledlab uses eight points in an open zigzag.',
  'paper.fig9.caption': '“Basic notations for a subdivided ruled surface strip, the two different triangulations.”',
  'paper.fig9.note':
    'The notation a_i, b_i, A_i, B_i, z_{i,k}, Z_{i,k} on Example 3’s quartic strip with the first triangulation (11); choose the second (12) in the menu (ruledlab draws one at a time). n = 6 rather than Example 3’s 12, so that the triangles can be read.',
  'paper.fig10.caption':
    '“12 generators taken out of a quartic ruled surface R, 11 lines inserted; light gray spheres centered at A_i, dark gray spheres centered at B_i.”',
  'paper.fig10.note':
    'Example 3 with the paper’s data: 12 rulings of (1 + vu², u²/2 + uv, u − v), n = 12, one step of the energy (15) read literally; spheres at A_i (light) and B_i (dark). The intervals u ∈ [−1, 1] and v ∈ [−1, 1] (the rulings’ ends) are ruledlab’s: the paper gives neither.',
  'paper.strip.beyond':
    'Read literally, (15) puts umbrella vectors at the new points only, and its minimiser is exactly the midpoint rule (checked under the readout). ruledlab’s coupled and averaged energies put them at every vertex; the readout compares every scheme at this n: coupled beats the midpoint rule for every n from 5 to 24 (not for n = 3, 4), and the four-point scheme is exact on this surface.',
  'paper.fig11.caption': '“Congruence of lines determined by two directrices.”',
  'paper.fig11.note':
    'Example 5’s lines between the director surface d₁ and d₂, both shaded. The paper’s figure is a sketch; ruledlab takes d₂ as the points p + 0.35 d (the paper gives no segment length).',
  'paper.fig12.caption': '“The butterfly-scheme.”',
  'paper.fig12.note':
    'The stencil of (16) is drawn beside the view with all its weights; the view shows the lines it inserts on the diagonals of Example 5’s grid (one step, as in the paper). The tension w = 1/16 is ruledlab’s choice (it reproduces cubic polynomials): the paper gives no value.',
  'paper.fig13.caption':
    '“Left: part of a sphere with lines of the congruence (black, thin), inserted lines (black, thick). Right: part of a hyperbolic paraboloid, lines of the congruence (black, thin), inserted lines (black, thick).”',
  'paper.fig13.note':
    'Fig. 13 left: lines inserted on the diagonals only, as the paper does, with w = 1/16 in (16) (ruledlab’s choice: the paper gives no value). The paper gives no formulas for Example 4; ruledlab’s sphere carries the directions normal + 0.3 (sin 2v, cos 3u, uv), a generalised offset that is not a normal congruence. Inserted lines are drawn in colour rather than thick black. The readout measures these diagonal lines; the rows “for comparison” are other schemes (the butterfly row inserts on all edges).',
  'paper.fig13-right.note':
    'Fig. 13 right: lines inserted on the diagonals only, with w = 1/16 in (16) (ruledlab’s choice: the paper gives no value). The paper gives no formulas for Example 4; ruledlab’s hyperbolic paraboloid z = xy carries the directions (−v, −u, 1) + 0.3 (cos 2v, sin u, 0). The readout measures these diagonal lines; the rows “for comparison” are other schemes (the butterfly row inserts on all edges).',
  'paper.fig14.caption':
    '“Point scheme on directrix surface d₁ (left), part of the congruence with some notations (right).”',
  'paper.fig14.note':
    'The notation of Section 5.2 on one cell of Example 5: the given lines R_{i,j} with their points p on d₁ and q on d₂, the edge lines T_{i,j} (points r, r′) and S_{i,j} (s, s′), and the face line R̄_{i,j} (points P, Q). T runs over every row, 1 ≤ j ≤ N₂ (the text’s N₂ − 1 would leave out the last).',
  'paper.fig15.caption': '“Discrete congruence of lines (left), inserted lines (black thick) (right).”',
  'paper.fig15.note':
    'Example 5 with the paper’s data: d₁ = (u, v, ½ sin(2u + 1.5v)), directions (u, v, sin u + 1.3 cos v), 8 × 7 lines on [−1.1, 1.1]², K = 6, refined once by the paper’s variational scheme read literally: midpoint edge lines, each face line the average of its eight neighbours. Read so, K has no effect on the result: every K gives the same lines.',
  'paper.congruence.beyond':
    'Read literally, the energies (15) and (21) give plain averages; ruledlab also offers “two-stage” (its coupled strip energy on the edges), “coupled” (all new lines in one sparse solve) and the butterfly scheme on all edges. The readout measures the scheme shown and, for comparison, all four at one step; on every built-in congruence the butterfly scheme on all edges is the most accurate (checked under the readout).',
  'paper.fig16.caption': '“First step of the refinement.”',
  'paper.fig16.note':
    'Example 6 after one step: given tool axes dark, inserted ones light, the tool as a ball-end cylinder, the barycentre curve dashed, the swept ball over the part. The paper gives no data; the profile, the seven poses and the tool (radius 0.25, length 1.5) are ruledlab’s.',
  'paper.fig17.caption': '“Second step of the refinement.”',
  'paper.fig17.note': 'Example 6 after two steps (ruledlab’s data, as in Fig. 16).',
  'paper.fig18.caption': '“Third step of the refinement.”',
  'paper.fig18.note': 'Example 6 after three steps (ruledlab’s data, as in Fig. 16).',
  'paper.milling.beyond':
    'The paper refines the path “as described in section 4”; read literally that energy is the midpoint rule (“linear” in the menu). ruledlab uses its coupled energy instead; the readout gives every scheme’s deviation from the profile, and the claims under it say where the variational schemes come closest.',
  'paper.ex1.caption':
    'Example 1: a discretised regulus of the hyperboloid x² + y²/4 − z²/9 = 1 with its striction line.',
  'paper.ex1.note':
    'Both discrete striction polygons, m_i of Proposition 2 and the perpendicular midpoints Example 1’s text describes, against the exact striction curve; the readout measures each. The hyperboloid is the paper’s, the 36 rulings ruledlab’s.',
  'paper.ex2.caption': 'Example 2: any ruled surface can be mapped isometrically onto a conoidal ruled surface.',
  'paper.ex2.note':
    'The hinge chain of Example 3’s quartic half-way (t = 0.5) between the surface and its conoidal model; slide t or press play. The edge-length readout shows that the bending is isometric to rounding. The paper gives no data.',
  'paper.ex3.caption':
    'Example 3: N = 12 generators of the quartic ruled surface (1 + vu², u²/2 + uv, u − v), n = 12, one step of the variational subdivision.',
  'paper.ex3.note':
    'Example 3 with the paper’s data, the first triangulation and the exact surface shown faintly; the readout measures the distance of the inserted rulings from the surface for every scheme. The intervals u ∈ [−1, 1] and v ∈ [−1, 1] (the rulings’ ends) are ruledlab’s: the paper gives neither.',
  'paper.ex4.caption':
    'Example 4: the butterfly scheme on congruences with two different director surfaces d₁; d₂, a generalised offset surface, is not plotted in the paper.',
  'paper.ex4.note':
    'The sphere of Fig. 13 with lines inserted on the diagonals only (w = 1/16, ruledlab’s choice: the paper gives no value), and d₂ (which the paper does not plot) shaded too. The paper gives no formulas for Example 4; the congruence is ruledlab’s. The readout measures the diagonal lines shown; the rows “for comparison” are other schemes (the butterfly row inserts on all edges).',
  'paper.ex5.caption':
    'Example 5: d₁ = (u, v, ½ sin(2u + 1.5v)), lines parallel to (u, v, sin u + 1.3 cos v), 8 × 7 values on [−1.1, 1.1]², K = 6.',
  'paper.ex5.note':
    'Example 5 with the paper’s data, refined once by the paper’s scheme read literally, with both director surfaces (d₂ = p + 0.35 d: the paper gives no segment length). Read literally, K = 6 has no effect on the result: every K gives the same lines (so does ruledlab’s coupled scheme; only two-stage depends on K).',
  'paper.ex6.caption':
    'Example 6: a few positions of a milling tool along a profile, refined into a smooth path by the variational subdivision of Section 4.',
  'paper.ex6.note':
    'Two steps, the tool further along the path. The paper gives no data; the profile, the poses and the tool are ruledlab’s.',
};
