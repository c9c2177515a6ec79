// The page's entry point (index.html): starts the page; a failure to start is shown, not thrown away.
import { startPage, showStartFailure } from './app.js';

startPage().catch(showStartFailure);
