// What a course page can read from an editable <ruled-view>: the scene's input after each edit
// (`change`, detail.data: one Float64Array per handle set) and the readouts computed on it.
const view = document.querySelector('ruled-view');
const report = document.getElementById('report');
view?.addEventListener('change', (event) => {
  const { data, readouts } = /** @type {CustomEvent} */ (event).detail;
  const rulings = data.rulings.length / 6;
  const delta = readouts.find((/** @type {{key: string}} */ r) => r.key === 'readout.meanDelta');
  if (report) report.textContent = `${rulings} rulings edited; δ̄ at the middle ruling: ${delta?.value ?? '—'}`;
});
