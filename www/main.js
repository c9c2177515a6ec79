// The page's entry point (index.html): starts the page; a failure to start is shown, not thrown away.
import { startPage } from './app.js';

startPage().catch((e) => {
  const box = document.getElementById('boot') ?? document.body.appendChild(document.createElement('p'));
  box.className = 'boot boot-problem';
  box.textContent = `ruledlab could not start: ${String(e?.message ?? e)}`;
  throw e;
});
