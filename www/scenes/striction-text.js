// Teaching text of the Section 2 scene (MathML, rendered natively by the browser).
const sub = (base, index) => `<msub><mi>${base}</mi><mrow>${index}</mrow></msub>`;
const ii1 = '<mi>i</mi><mo>,</mo><mi>i</mi><mo>+</mo><mn>1</mn>';
const iim = '<mi>i</mi><mo>,</mo><mi>i</mi><mo>−</mo><mn>1</mn>';

export const text = `
<h2>Difference geometry of a ruled surface</h2>
<p>A discrete ruled surface is a sequence of lines ${inline(sub('R', '<mi>i</mi>'))}. Two consecutive
rulings enclose the angle ${inline(sub('φ', ii1))} and have one common perpendicular
${inline(sub('N', ii1))} (green). It meets ${inline(sub('R', '<mi>i</mi>'))} at the footpoint
${inline(sub('f', ii1))}, and the footpoints are ${inline(sub('h', ii1))} apart. The
<em>discrete distribution parameter</em> is</p>
<math display="block">${sub('δ', ii1)}<mo>=</mo><mfrac>${sub('h', ii1)}${sub('φ', ii1)}</mfrac><mspace width="1em"/><mtext>(1)</mtext></math>
<p>Each ruling carries two footpoints, ${inline(sub('f', iim))} and ${inline(sub('f', ii1))}. Both tend
to the <em>striction point</em> s(u) as the rulings get closer, but only at first order
(Proposition 1). Their midpoint</p>
<math display="block">${sub('m', '<mi>i</mi>')}<mo>=</mo><mfrac><mn>1</mn><mn>2</mn></mfrac><mo>(</mo>${sub('f', iim)}<mo>+</mo>${sub('f', ii1)}<mo>)</mo><mspace width="1em"/><mtext>(7)</mtext></math>
<p>converges at second order (Proposition 2): the first-order errors of the two footpoints are
equal and opposite. The red polygon joins these midpoints.</p>
<p><strong>Try it.</strong> Double the number of rulings and watch the readout: the footpoint error
halves, the midpoint error drops to a quarter. Turn on the exact striction curve to compare.
On the hyperboloid of Example 1 the striction curve is not the waist ellipse; on the cone all
common perpendiculars meet in the apex; on the cylinder consecutive rulings are parallel, the
common perpendicular is not unique, and ruledlab says so (NaN, flagged) rather than guess.</p>
`;

function inline(mathml) {
  return `<math>${mathml}</math>`;
}
