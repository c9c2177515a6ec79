// What an exercise tells the page around it (a course system, an LTI tool): each check, the
// moment it is solved, and a solution shown, as a message to the parent window. Its shape (the
// book: teaching/exercises.md):
//   { source: "ruledlab", version: 1, type: "task-check" | "task-solved" | "task-solution",
//     task, title, solved, counted, shown, passed, of, conditions: [{ holds, value, target }],
//     answers, state: { scene, params, input } }
// An answer's own value is never in `conditions` (null there); the answers typed are. A grade
// takes nothing from a message whose `counted` is false: the solution shown, and every check
// after it in the same attempt.

/**
 * Posts a check or a solution to the parent window, when there is one (a frame); false otherwise.
 * @param {'check' | 'solved' | 'solution'} type
 * @param {import('./panel.js').TaskReport} report
 * @param {{scene: string, params: Record<string, unknown>, input: string | null}} state
 */
export function postToParent(type, report, state) {
  if (typeof window === 'undefined' || window.parent === window) return false;
  try {
    window.parent.postMessage({ source: 'ruledlab', version: 1, type: `task-${type}`, ...report, state }, '*');
    return true;
  } catch {
    return false;
  }
}
