// Example 6, Figs. 16–18: a few 5-axis tool poses refined by a strip scheme into a smooth tool
// path; the ball-end tool (drawn at one pose, Fig. 16) sweeps a tube whose lower half is the
// machined surface. The part, the envelope and the tool are meshes built by the core.
import { ToolPath } from '../../pkg/ruledlab.js';
import { defineScene, scoped, bounds, f32 } from '../scene.js';
import { POST_PARAMS, givenPath, postOf, programFile, deviationFigure } from '../figures/toolpath.js';
import { poseSet, poseValues } from '../edit/sets.js';

/** @type {Record<string, Partial<import('../../pkg/ruledlab.js').SubdivideOptions>>} */
const SCHEMES = {
  variational: { scheme: 'variational', variant: 'coupled' },
  averaged: { scheme: 'variational', variant: 'averaged' },
  'four-point': { scheme: 'four-point' },
  linear: { scheme: 'bspline', degree: 1 },
};

/**
 * Whether the schemes turn the tool as the text says: the midpoint rule in the smallest largest
 * steps (it halves each turn) but least evenly (the largest second difference), the averaged
 * variational scheme most evenly (the smallest second difference).
 * @param {Record<string, {maxAngleStep: number, maxSecondDifference: number}>} turns   per scheme
 */
function turnsAsSaid(turns) {
  const others = Object.entries(turns).filter(([k]) => k !== 'linear');
  const { linear, averaged } = turns;
  return (
    others.every(
      ([, q]) => linear.maxAngleStep < q.maxAngleStep && linear.maxSecondDifference > q.maxSecondDifference,
    ) && others.every(([k, q]) => k === 'averaged' || averaged.maxSecondDifference < q.maxSecondDifference)
  );
}

/** Largest |deviation| of the machined surface from the target profile. */
function maxDeviation(
  /** @type {import('../../pkg/ruledlab.js').ToolPath} */ path,
  /** @type {Float64Array} */ profile,
) {
  return path.deviation(profile).reduce((m, d) => Math.max(m, Math.abs(d)), 0);
}

export const scene = defineScene({
  id: 'milling',
  title: 'milling.title',
  text: 'milling.text',
  paper: true,
  // an edit of the poses replaces the example's
  fixed: ['poses'],
  params: [
    { key: 'poses', label: 'milling.param.poses', type: 'range', min: 4, max: 12, step: 1, value: 7 },
    { key: 'steps', label: 'milling.param.steps', type: 'range', min: 0, max: 3, step: 1, value: 1, play: true },
    {
      key: 'scheme',
      label: 'param.scheme',
      type: 'select',
      value: 'variational',
      refit: false,
      options: () => Object.keys(SCHEMES).map((s) => [s, `milling.scheme.${s}`]),
      unless: (p) => (Number(p.steps) === 0 ? 'milling.reason.steps' : null),
    },
    { key: 'tool', label: 'milling.param.tool', type: 'checkbox', value: true },
    {
      key: 'at',
      label: 'milling.param.at',
      type: 'range',
      min: 0,
      max: 1,
      step: 0.01,
      value: 0.35,
      play: true,
      unless: (p) => (p.tool ? null : 'milling.reason.tool'),
    },
    { key: 'envelope', label: 'milling.param.envelope', type: 'checkbox', value: true },
    { key: 'part', label: 'milling.param.part', type: 'checkbox', value: true },
    ...POST_PARAMS,
  ],
  legend: [
    { style: 'exact', label: 'milling.legend.profile' },
    { style: 'given', label: 'milling.legend.given' },
    { style: 'insertedAxis', label: 'milling.legend.inserted', when: (p) => Number(p.steps) > 0 },
    { style: 'barycentre', label: 'milling.legend.barycentre' },
    { style: 'envelope', label: 'milling.legend.envelope', when: (p) => !!p.envelope },
    { style: 'tool', label: 'milling.legend.tool', when: (p) => !!p.tool },
    { style: 'part', label: 'milling.legend.part', when: (p) => !!p.part },
  ],
  create(p, { t, data, input }) {
    return scoped((own) => {
      const steps = Number(p.steps);
      // your imported tool poses, or the example of Figs. 16–18 (its profile and part with it)
      const { path: base, imported } = givenPath(own, data, Number(p.poses));
      // the given poses as the reader moved them (the same tool)
      const edited = input?.poses;
      const path = edited ? own(ToolPath.fromSegments(edited, base.tool)) : base;
      const refined = own(path.refine({ ...SCHEMES[/** @type {keyof typeof SCHEMES} */ (p.scheme)], steps }));
      // the given axes as the poses were given: an edited axis point stays where the reader put
      // it (the tool keeps its length along that direction)
      const given = edited ? f32(edited) : path.segmentsF32();
      const all = refined.segmentsF32();
      const profile = imported ? null : ToolPath.exampleProfile(400);
      const deviation = profile ? maxDeviation(refined, profile) : Number.NaN;
      const quality = refined.quality();
      // every scheme's deviation and orientation at these steps, for the comparisons the text
      // makes (and their claims)
      /** @type {Record<string, number>} */
      const compare = {};
      /** @type {Record<string, {maxAngleStep: number, maxSecondDifference: number}>} */
      const turns = {};
      if (profile)
        for (const [k, o] of Object.entries(SCHEMES)) {
          const other = own(path.refine({ ...o, steps }));
          compare[k] = maxDeviation(other, profile);
          turns[k] = other.quality();
        }
      const given0 = profile ? maxDeviation(path, profile) : Number.NaN;
      const centres = refined.barycentres();
      const perPose = profile ? refined.deviationPerPose(profile) : null;
      /** @type {import('../scene.js').Layer[]} */
      const layers = [
        ...(profile
          ? [/** @type {import('../scene.js').Layer} */ ({ kind: 'polyline', style: 'exact', positions: f32(profile) })]
          : []),
        { kind: 'segments', style: 'given', positions: given },
        { kind: 'polyline', style: 'barycentre', positions: f32(centres) },
        { kind: 'points', style: 'barycentrePoint', positions: f32(centres) },
      ];
      if (steps > 0)
        layers.push({ kind: 'segments', style: 'insertedAxis', positions: refined.insertedF32(2 ** steps) });
      if (p.envelope) {
        const { positions, indices } = refined.envelopeMesh(14);
        layers.push({ kind: 'mesh', style: 'envelope', positions, indices });
      }
      if (p.tool) {
        const { positions, indices } = refined.toolMesh(Math.round(Number(p.at) * (refined.length - 1)), 20);
        layers.push({ kind: 'mesh', style: 'tool', positions, indices });
      }
      if (p.part && !imported) {
        const { positions, indices } = ToolPath.examplePart(60, 30);
        layers.push({ kind: 'mesh', style: 'part', positions, indices });
      }
      // the G-code post for the machine, dialect and mode chosen
      const { result: post, error: postError } = postOf(refined, p);
      const exports = {
        json: refined.export('json'),
        csv: refined.export('csv'),
      };
      return {
        bounds: profile ? bounds(given, all, profile) : bounds(given, all),
        camera: { yaw: -1.9, pitch: 0.55 },
        layers,
        readouts: [
          { label: 'milling.readout.poses', value: refined.length },
          ...(profile ? [{ label: 'milling.readout.deviation', value: deviation }] : []),
          { label: 'milling.readout.angleStep', value: quality.maxAngleStep },
          { label: 'milling.readout.secondDifference', value: quality.maxSecondDifference },
          ...(profile ? [{ label: 'milling.readout.compare.given', value: given0 }] : []),
          ...(steps > 0 && profile
            ? Object.entries(compare).map(([k, v]) => ({ label: `milling.readout.compare.${k}`, value: v }))
            : []),
          ...(post
            ? [
                { label: 'milling.readout.inserted', value: post.inserted },
                { label: 'milling.readout.linearTip', value: post.before.tip },
                { label: 'milling.readout.linearAxis', value: post.before.axis },
              ]
            : [
                {
                  label: 'milling.readout.post',
                  value: postError instanceof Error ? postError.message : String(postError),
                },
              ]),
        ],
        // the claims are about the example's own poses, not an edit of them
        claims: edited
          ? []
          : [
              ...(steps > 0 && profile
                ? [
                    {
                      text: 'milling.claim.refined',
                      holds: Math.max(compare.variational, compare.averaged, compare['four-point']) < given0,
                    },
                  ]
                : []),
              ...(steps > 0 && profile
                ? [
                    {
                      text: 'milling.claim.turns',
                      holds: turnsAsSaid(turns),
                    },
                  ]
                : []),
              ...(steps > 0 && profile && Number(p.poses) >= 7
                ? [
                    {
                      text: 'milling.claim.variational',
                      holds:
                        Math.max(compare.variational, compare.averaged) <
                        Math.min(compare['four-point'], compare.linear),
                    },
                  ]
                : []),
            ],
        description: imported
          ? t(edited ? 'milling.describeImportedEdited' : 'milling.describeImported', {
              poses: path.length,
              steps,
              scheme: t(`milling.scheme.${p.scheme}`),
              total: refined.length,
            })
          : t(edited ? 'milling.describeEdited' : 'milling.describe', {
              poses: Number(p.poses),
              steps,
              scheme: t(`milling.scheme.${p.scheme}`),
              total: refined.length,
              deviation,
            }),
        figure: deviationFigure({
          perPose,
          stride: 2 ** steps,
          post,
          t,
        }),
        // the handles: every given pose's tip (it carries the tool) and a point on its axis (it
        // turns the tool about the tip)
        input: {
          sets: [poseSet(edited ?? path.segments())],
          values: poseValues(path.quality().angleStep, perPose, 2 ** steps, t),
          from: imported
            ? t('edit.from.importedPoses', { poses: path.length })
            : t('edit.from.poses', { poses: Number(p.poses) }),
        },
        downloads: [
          {
            label: 'milling.download.json',
            filename: 'toolpath.json',
            content: exports.json,
            type: 'application/json',
          },
          { label: 'milling.download.csv', filename: 'toolpath.csv', content: exports.csv, type: 'text/csv' },
          ...(post
            ? [
                {
                  label: 'milling.download.gcode',
                  filename: programFile(String(p.dialect)),
                  content: post.text,
                  type: 'text/plain',
                },
              ]
            : []),
        ],
        data: { segments: refined.segments() },
      };
    });
  },
});
