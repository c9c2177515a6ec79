// Files a scene's data can be saved as, all written by the core at full precision
// (RuledSurface.export, LineCongruence.export): CSV and JSON of the segments, OBJ (vertices,
// ruling lines, the quads of a strip), the invariants of Section 2 as JSON or CSV.
import { LineCongruence, RuledSurface } from '../../pkg/ruledlab.js';
import { scoped } from '../scene.js';

/** @typedef {'csv' | 'json' | 'obj' | 'invariants-csv' | 'invariants-json'} FileFormat */

/**
 * A scene's segments as a file: a surface, or a congruence's lines when a grid shape is known
 * (no invariants then).
 * @param {Float64Array} segments
 * @param {FileFormat} format
 * @param {{ grid?: { rows: number, cols: number }, name?: string }} [options]
 */
export function dataFile(segments, format, { grid, name } = {}) {
  return scoped((own) => {
    if (grid) {
      if (format !== 'csv' && format !== 'json' && format !== 'obj')
        throw new Error(`a congruence has no ${format} file`);
      return own(LineCongruence.fromGrid(grid.rows, grid.cols, segments)).export(format, { name });
    }
    return own(RuledSurface.fromSegments(segments)).export(format, { name });
  });
}
