// Section 5, Figs. 11–15: line congruences between two director surfaces, refined by the
// butterfly scheme (16) or variationally (Section 5.2); given lines thin, inserted lines in
// colour, the director surface d₁ shaded (and d₂ on request).
import { AnalyticCongruence, LineCongruence } from '../../pkg/ruledlab.js';
import { defineScene, scoped } from '../scene.js';
import { congruenceLayers, fig14Applies, givenGrid, SCHEME_PARAMS, LEGEND } from '../layers/congruence.js';
import { lineSet } from '../edit/sets.js';
import { congruenceOptions } from '../catalogue.js';

/** @typedef {{congruence: string, scheme: string, steps: number, director: boolean, second: boolean, labels: boolean}} CongruenceParams */

export const scene = defineScene({
  id: 'congruence',
  title: 'congruence.title',
  text: 'congruence.text',
  paper: true,
  // an edit of the given lines replaces the congruence they sample
  fixed: ['congruence'],
  params: [
    {
      key: 'congruence',
      label: 'congruence.param.congruence',
      type: 'select',
      value: 'example5',
      options: congruenceOptions,
    },
    ...SCHEME_PARAMS,
    {
      key: 'labels',
      label: 'congruence.param.labels',
      type: 'checkbox',
      value: false,
      unless: (p) =>
        fig14Applies({ scheme: String(p.scheme), steps: Number(p.steps) }) ? null : 'congruence.reason.labels',
    },
  ],
  legend: LEGEND,
  /** @param {CongruenceParams} p */
  create(p, ctx) {
    return scoped((own) => {
      const name = String(p.congruence);
      const analytic = own(AnalyticCongruence.byName(name));
      const given = givenGrid(own, analytic);
      const edited = ctx.input?.lines;
      const grid = edited ? own(LineCongruence.fromGrid(given.rows, given.cols, edited)) : given;
      const built = congruenceLayers(own, grid, edited ? null : analytic, p, ctx, name, true);
      // the handles: p and q of every given line
      const from = ctx.t('edit.from.congruence', {
        congruence: ctx.t(`congruence.${name}`),
        rows: given.rows,
        cols: given.cols,
      });
      return { ...built, input: { sets: [lineSet(grid.segments(), grid.cols)], from } };
    });
  },
});
