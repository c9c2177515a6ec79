// A classic script (it runs where module scripts cannot, e.g. from file://): says what to do
// when the page's modules cannot load, instead of leaving a blank page. The page's module
// removes the message when it starts.
(() => {
  const box = document.getElementById('boot');
  if (!box) return;
  // the page's language: the link's (#lang=de), else the browser's
  var wanted = /(?:^#|&)lang=([a-zA-Z-]+)/.exec(location.hash);
  var de = /^de\b/i.test(wanted ? wanted[1] : navigator.language || '');
  var text = {
    file: de
      ? 'Diese Seite besteht aus einzelnen Dateien, die ein Browser nicht von der Festplatte lädt. Starten Sie „npm start“ im Ordner von ruledlab und öffnen Sie die angezeigte Adresse, oder öffnen Sie dist/ruledlab.html, die Fassung in einer Datei, die auch von der Festplatte und in Lernplattformen läuft.'
      : 'This page is made of separate files that a browser does not load from disk. Run “npm start” in the ruledlab folder and open the address it prints, or open dist/ruledlab.html, the one-file build, which works from disk and in course systems.',
    slow: de
      ? 'ruledlab startet nicht. Der Browser braucht WebAssembly, ES-Module und WebGL2 (aktuelle Versionen von Firefox, Chrome, Edge und Safari haben sie).'
      : 'ruledlab does not start. It needs WebAssembly, ES modules and WebGL2, which current Firefox, Chrome, Edge and Safari provide.',
  };
  if (location.protocol === 'file:') {
    box.textContent = text.file;
    box.className = 'boot boot-problem';
    return;
  }
  setTimeout(() => {
    // (a start that failed has said why already, in the page's language: that stays)
    var root = document.documentElement;
    if (document.getElementById('boot') && !root.hasAttribute('data-started') && !root.hasAttribute('data-failed')) {
      box.textContent = text.slow;
      box.className = 'boot boot-problem';
    }
  }, 15000);
})();
