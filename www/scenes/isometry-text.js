// Teaching text of the Section 3 scene.
export const text = `
<h2>Bending a ruled surface without stretching it</h2>
<p>Take two consecutive rulings <math><msub><mi>R</mi><mi>i</mi></msub></math>,
<math><msub><mi>R</mi><mrow><mi>i</mi><mo>+</mo><mn>1</mn></mrow></msub></math> together with their
common perpendicular as one rigid body, and let every ruling act as a <em>hinge</em> between the
two bodies it belongs to. Turning the hinges moves the rulings, but no polygon
<math><msub><mi>p</mi><mi>i</mi></msub><mo>∈</mo><msub><mi>R</mi><mi>i</mi></msub></math> changes
the length of any edge: this kinematic chain is the discrete model of the
<em>Minding isometries</em>, which map rulings to rulings. The readout shows the largest relative
change of an edge length: rounding, nothing more.</p>
<p><strong>Example 2.</strong> Keep <math><msub><mi>R</mi><mn>0</mn></msub></math> and
<math><msub><mi>R</mi><mn>1</mn></msub></math> fixed and turn each following body about its hinge
until its common perpendicular points the same way as the first one,
<math><msub><mi>n</mi><mrow><mn>0</mn><mo>,</mo><mn>1</mn></mrow></msub></math>. Then every ruling is
orthogonal to that direction: the surface has become <em>conoidal</em> (all rulings parallel to one
plane). Slide <em>t</em> from 0 to 1 to watch the bending; the picture is turned so that
<math><msub><mi>n</mi><mrow><mn>0</mn><mo>,</mo><mn>1</mn></mrow></msub></math> points up, and the
conoidal rulings become horizontal, stacked at heights
<math><msub><mi>H</mi><mi>i</mi></msub><mo>=</mo><munder><mo>∑</mo><mrow><mi>k</mi><mo>&lt;</mo><mi>i</mi></mrow></munder><msub><mi>h</mi><mrow><mi>k</mi><mo>,</mo><mi>k</mi><mo>+</mo><mn>1</mn></mrow></msub></math>.</p>
<p><strong>Approximate development (Fig. 6).</strong> Project the conoidal model straight down onto a
plane parallel to its rulings. Each ruling keeps its length, and the two footpoints of every pair
fall onto one point, so the image of the striction polygon is the polygon the projected rulings
envelop — just as the regression curve is the envelope in the development of a developable
surface. The spread of the heights,
<math><mo>max</mo><msub><mi>H</mi><mi>i</mi></msub><mo>−</mo><mo>min</mo><msub><mi>H</mi><mi>i</mi></msub></math>,
measures how far the surface is from developable: 0 for the cone, tiny (and shrinking like
<math><msup><mi>H</mi><mn>2</mn></msup></math> as rulings are added) for the tangent surface,
clearly positive for the hyperboloid strip.</p>
<p><strong>A remark on Fig. 5.</strong> The paper shows the conoidal image of a ruled helical
surface as a helicoid whose rulings meet the axis orthogonally. Measured here, that holds only when
the striction curve crosses the rulings at a right angle. In general the conoidal rulings touch a
cylinder about the axis of radius <math><mfrac><mrow><mi>e</mi><mo>·</mo><mover><mi>s</mi><mo>˙</mo></mover></mrow><mrow><mo>|</mo><msup><mi>e</mi><mo>′</mo></msup><mo>|</mo></mrow></mfrac></math>,
1.4 for the surface shown (radius 1, pitch 0.4, rulings at 45°).</p>
`;
