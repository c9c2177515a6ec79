// Every German text of the page and of <ruled-view>, by key (the terms of line geometry after
// ../shared/paper/GLOSSARY-de.md). Scene explanations (markup) are in de-texts.js.
export default {};
