// English texts of the paper-models scene: developable strips and their flat patterns (Section 3,
// beyond the paper).
// Keys: developable.*

export default {
  'developable.title': 'Paper models: developable strips',
  'developable.param.kind': 'Strip',
  'developable.kind.tangent': 'tangent surface of a helix',
  'developable.kind.cone': 'cone over a helix',
  'developable.kind.cylinder': 'cylinder over a helix',
  'developable.kind.rectifying': 'rectifying developable of a helix',
  'developable.kind.hyperboloid': 'hyperboloid (not developable)',
  'developable.param.turns': 'Turns of the helix',
  'developable.param.width': 'Width of the strip',
  'developable.param.repair': 'Keep neighbours coplanar',
  'developable.legend.pattern': 'flat pattern',
  'developable.legend.overlap': 'faces that overlap in the plane',
  'developable.readout.delta': 'largest |δ| of a pair',
  'developable.readout.isometry': 'largest relative change of a length, pattern against strip',
  'developable.readout.pieces': 'pieces to cut',
  'developable.readout.turns': 'turns of the helix',
  'developable.readout.gap': 'largest gap h of a pair',
  'developable.readout.climb': 'the gaps added up (the climb)',
  'developable.describe':
    'The {kind} with {n} rulings, every pair of consecutive rulings coplanar, beside its exact flat pattern (pieces to cut: {pieces}).',
  'developable.describeApproximate':
    'The {kind} with {n} rulings beside Section 3’s approximate development, which leaves a gap at every pair of rulings; pieces to cut: {pieces}.',
  'developable.download.svg': 'Flat pattern (SVG, 1:1 in mm)',
  'developable.download.dxf': 'Flat pattern (DXF R12, for laser cutters)',
  'developable.download.a4': 'Flat pattern on A4 pages (zip of SVGs, with registration marks)',
  'developable.download.letter': 'Flat pattern on Letter pages (zip of SVGs, with registration marks)',
  'developable.from': 'the {kind}',
  'developable.text': `
<p>A ruled surface is <em>developable</em> when it can be flattened without stretching: a sheet of
paper bent, not crumpled. Discretely, every two consecutive rulings lie in one plane (their
distribution parameter δ is 0), so each face between them is a flat quadrilateral, and the strip
unfolds onto the plane face by face, every length and angle kept.</p>
<p>The strips here are built that way from a helix: its <em>tangent surface</em> (the rulings along
the polygon's edges), a <em>cone</em> and a <em>cylinder</em> over it, and its <em>rectifying
developable</em>, on which the helix is a geodesic and unfolds onto a straight line. Drag a ruling:
the strip follows, and the core turns its neighbours until every pair is coplanar again. With
<em>Keep neighbours coplanar</em> off, the strip stays as you drag it: make it developable by hand,
snapping an end of a ruling onto the next ruling (two lines that meet lie in one plane).</p>
<p>The flat pattern is drawn beside the strip. Where it overlaps itself (a tangent surface over
more than a turn of its unrolled edge) it is cut into pieces that do not, glued along a ruling.
Download it as SVG at 1:1 in millimetres, with a 100 mm square to check the print, tiled on A4 or
Letter pages with registration marks, or as DXF for a laser cutter, and build the model.</p>
<p>The <em>hyperboloid</em> is not developable: its consecutive rulings are skew. Section 3
develops it approximately, through its conoidal model; the pattern keeps every ruling's length but
drops the distance h between consecutive rulings. A paper model of it cannot close: the gaps add up
along the strip.</p>`,
};
