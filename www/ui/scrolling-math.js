// Display equations in an explanation: one wider than its column scrolls sideways (ui/css.js) and
// is then a tab stop, so that the keyboard can scroll it (WCAG 2.1.1, axe's
// "scrollable-region-focusable"); one that fits is not a stop the keyboard must pass. Decided after
// each layout that changes an equation's size (a ResizeObserver: no layout is forced for it).

/** The observer of each container's equations (going with the container). @type {WeakMap<Element, ResizeObserver>} */
const observers = new WeakMap();

/** Whether `math` scrolls decides whether it is a tab stop. @param {Element} math */
function mark(math) {
  if (math.scrollWidth > math.clientWidth + 1) math.setAttribute('tabindex', '0');
  else math.removeAttribute('tabindex');
}

/**
 * Watches the display equations now in `container` (its equations watched before are let go).
 * @param {Element} container
 */
export function watchMath(container) {
  if (typeof ResizeObserver !== 'function') return;
  let observer = observers.get(container);
  if (!observer) {
    observer = new ResizeObserver((entries) => {
      for (const { target } of entries) mark(target);
    });
    observers.set(container, observer);
  }
  observer.disconnect();
  for (const math of container.querySelectorAll('math[display="block"]')) observer.observe(math);
}
