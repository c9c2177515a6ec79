// Deutsche Texte der Lernplattformen: die Leiste eines SCORM-Pakets (seine Aufgaben, die Punkte,
// ob die Lernplattform sie angenommen hat), die Meldungen des H5P-Inhaltstyps, und warum sich ein
// Paket nicht machen oder lesen lässt.
// Keys: course.*

export default {
  'course.bar': 'Kursaktivität',
  'course.exercise': 'Aufgabe',
  'course.score': 'Bisher: {raw} von {max} Bedingungen erfüllt.',
  'course.noRuntime': 'Hier zeichnet keine Lernplattform auf: Die Aufgaben funktionieren, aufgezeichnet wird nichts.',
  'course.connected': 'Die Lernplattform (SCORM {standard}) zeichnet jede Prüfung auf.',
  'course.recorded': 'Um {time} im Kurs gespeichert.',
  'course.learner': 'Studierende/r: {name}.',
  'course.broken':
    'Die Aufgaben dieses Pakets lassen sich nicht lesen ({reason}): Bitten Sie Ihre Lehrperson um ein neues Paket.',
  'course.refused':
    'Die Lernplattform hat das Ergebnis nicht angenommen ({call}: Fehler {code}, „{text}“). Ihre Arbeit bleibt hier und wird mit Ihrer nächsten Prüfung erneut gesendet.',
  'course.threw':
    'Die Lernplattform ist gescheitert ({call}: „{text}“). Ihre Arbeit bleibt hier und wird mit Ihrer nächsten Prüfung erneut gesendet.',
  'course.h5pBroken': 'Diese Aufgabe lässt sich nicht zeigen: {reason}.',
  'course.h5pRefused': 'Die Lernplattform hat das Ergebnis nicht angenommen ({detail}). Ihre Arbeit bleibt hier.',
  'course.readers': 'Was Lesende dürfen',
  'course.reader.edit': 'die Punkte ziehen (die Geometrie bearbeiten)',
  'course.reader.controls': 'die Bedienelemente sehen und benutzen',
  'course.reader.text': 'die Erklärung sehen',
  'course.reader.leave': 'die Aufgabe verlassen',
  'course.packages':
    'Für eine Lernplattform, die Noten aufzeichnet: ein SCORM-Paket (jede Lernplattform nimmt es auf) oder eine H5P-Datei (Moodle, ILIAS; eine Administratorin erlaubt ihren Inhaltstyp einmal).',
  'course.package.scorm12': 'SCORM-1.2-Paket',
  'course.package.scorm2004': 'SCORM-2004-Paket',
  'course.package.h5p': 'H5P-Datei',
  'course.made.scorm':
    'Gemacht: Laden Sie die Zip-Datei als SCORM-Paket hoch (ruledlabs Buch, „In a course system“, sagt wie).',
  'course.made.h5p':
    'Gemacht: Laden Sie die .h5p-Datei als H5P-Inhalt hoch (ruledlabs Buch, „In a course system“, sagt wie).',
  'course.more': 'Weitere Aufgaben im SCORM-Paket (eine Aktivität, die Punkte ihre Summe; bis zu {max} insgesamt)',
  'course.notMade': 'Nicht gemacht: {reason}.',
  'course.error.notZip': 'das ist keine Zip-Datei: {detail}',
  'course.error.tooLarge': 'das Paket ist größer als {max} MB',
  'course.error.badName': 'das Paket enthält eine Datei außerhalb seines Ordners: „{name}“',
  'course.error.missing': 'dem Paket fehlt „{name}“',
  'course.error.noTasks': 'ein Paket braucht 1 bis {max} Aufgaben',
  'course.error.standard': 'der Standard ist „scorm12“ oder „scorm2004“, nicht „{standard}“',
  'course.error.notOneFile': 'die übergebene Seite ist nicht ruledlabs Ein-Datei-Fassung',
  'course.error.noPage': 'ruledlabs Ein-Datei-Seite (dist/ruledlab.html) ist nicht da, um ins Paket zu gehen',
  'course.error.noScript':
    'ruledlabs Einbettungsskript (dist/ruledlab-embed.js) ist nicht da, um in die Datei zu gehen',
  'course.error.notH5p': 'diese .h5p-Datei enthält keine Aufgabe von ruledlab ({detail})',
};
