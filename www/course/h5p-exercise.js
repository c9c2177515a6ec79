// The exercises of an H5P content's parameters, read the same way by the content type (in the
// course system's page) and by the .h5p file's reader (course/h5p-package.js).
import { readTask, TaskError } from '../task/format.js';
import { builtInTask } from '../task/builtin.js';
import { MAX_PACKAGE_TASKS, MAX_TASK_ID } from '../limits.js';

/** The content type's name in H5P. */
export const H5P_LIBRARY = 'H5P.RuledlabExercise';

/**
 * The exercise of H5P's parameters (content.json, or what H5P's editor saved): a built-in id or
 * JSON, which H5P may have stored escaped for HTML (&quot;); throws a TaskError when it is none.
 * @param {unknown} exercise
 */
export function h5pExercise(exercise) {
  const raw = typeof exercise === 'string' ? exercise.trim() : '';
  if (!raw.startsWith('{')) {
    const task = builtInTask(raw);
    if (!task) throw new TaskError('task.error.unknownBuiltIn', { id: raw.slice(0, MAX_TASK_ID) });
    return task;
  }
  let json;
  try {
    json = JSON.parse(raw);
  } catch {
    // (readTask says why, if it is no JSON escaped either)
    return readTask(
      raw
        .replace(/&quot;/g, '"')
        .replace(/&#0?39;/g, "'")
        .replace(/&lt;/g, '<')
        .replace(/&gt;/g, '>')
        .replace(/&amp;/g, '&'),
    );
  }
  return readTask(json);
}

/**
 * The exercises of H5P's parameters: `exercise`, then each of `more` (a problem set: one
 * activity, the score their sum); throws a TaskError for one that cannot be read, or for too many.
 * @param {any} params   content.json's parameters
 */
export function h5pExercises(params) {
  const more = Array.isArray(params?.more) ? params.more : [];
  if (more.length + 1 > MAX_PACKAGE_TASKS)
    throw new TaskError('task.error.count', { key: 'more', max: MAX_PACKAGE_TASKS - 1 });
  return [params?.exercise, ...more].map(h5pExercise);
}
