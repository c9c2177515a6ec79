// Whether the main pointer is a finger (a phone or tablet): hints and the shortcuts' dialog
// speak of gestures then.

/** Whether the main pointer is a finger. */
export function touchScreen() {
  return typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
}
