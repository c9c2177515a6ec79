// Deutsche Texte der Lernplattformen: die Leiste eines SCORM-Pakets (seine Aufgaben, die Punkte,
// ob die Lernplattform sie angenommen hat), die Meldungen des H5P-Inhaltstyps, und warum sich ein
// Paket nicht machen oder lesen lässt.
// Keys: course.*

export default {
  'course.bar': 'Kursaktivität',
  'course.exercise': 'Aufgabe',
  'course.score': 'Bisher: {raw} von {max} Bedingungen erfüllt.',
  'course.noRuntime': 'Hier zeichnet keine Lernplattform auf: Die Aufgaben funktionieren, aufgezeichnet wird nichts.',
  'course.connected':
    'Die Lernplattform (SCORM {standard}) zeichnet jede Prüfung auf; der Versuch bleibt offen, bis alle Aufgaben gelöst sind oder Sie ihn beenden.',
  'course.scoreRecorded': 'In diesem Versuch gespeichert: {raw} von {max} Bedingungen erfüllt.',
  'course.ended': 'Sie haben diesen Versuch beendet: Was Sie jetzt prüfen, wird nicht aufgezeichnet.',
  'course.review':
    'Die Lernplattform hat diesen Versuch zur Ansicht geöffnet: Sie sehen Ihre gespeicherte Arbeit, und nichts, was Sie jetzt tun, wird aufgezeichnet.',
  'course.browse':
    'Die Lernplattform hat diese Aktivität zum Durchsehen geöffnet: Nichts, was Sie tun, wird aufgezeichnet.',
  'course.noCredit':
    'Dieser Versuch wird nicht bewertet (die Lernplattform rechnet ihn nicht an): Ihre Arbeit bleibt, Punkte werden nicht aufgezeichnet.',
  'course.restored':
    'Ihre Arbeit wurde aus diesem Browser wiederhergestellt: Die Lernplattform hatte sie nicht behalten (ihr letztes Speichern schlug fehl).',
  'course.end': 'Versuch beenden',
  'course.endConfirm':
    'Den Versuch mit {raw} von {max} erfüllten Bedingungen beenden? Ihre Punkte sind dann endgültig, und die Lernplattform öffnet ihn danach zur Ansicht.',
  'course.endYes': 'Beenden',
  'course.endNo': 'Weiterarbeiten',
  'course.notStarted':
    'Die Lernplattform hat die Sitzung nicht begonnen ({call}: Fehler {code}, „{text}“): Nichts, was Sie hier tun, wird aufgezeichnet. Laden Sie die Seite neu oder sagen Sie es Ihrer Lehrperson.',
  'course.startThrew':
    'Die Lernplattform ist nicht erreichbar ({call}: „{text}“): Nichts, was Sie hier tun, wird aufgezeichnet. Laden Sie die Seite neu oder sagen Sie es Ihrer Lehrperson.',
  'course.shownDescription': '(Lösung gezeigt: zählt nicht)',
  'course.h5pPending':
    'Aufgezeichnet, wenn Sie die Aufgabe lösen oder den Versuch beenden (bisher {raw} von {max} Bedingungen erfüllt).',
  'course.h5pRecorded':
    'Aufgezeichnet: {raw} von {max} Bedingungen erfüllt. „Neu beginnen“ startet einen neuen Versuch.',
  'course.activityTitle': 'Titel der Aktivität (wie der Kurs ihn zeigt)',
  'course.solution': 'Die Lösung darf gezeigt werden',
  'course.solution.after': 'nach {count:Prüfung:Prüfungen} ohne Lösung',
  'course.solution.never': 'nie',
  'course.solution.atOnce': 'sofort',
  'course.draw': 'Gezogene Zahlen',
  'course.draw.attempt': 'für jeden Versuch neu',
  'course.draw.learner': 'für jede Person fest (bei jedem ihrer Starts dieselben; auch die Ansicht zeigt sie)',
  'course.packageOf.scorm12': 'SCORM-1.2-Paket von {what}',
  'course.packageOf.scorm2004': 'SCORM-2004-Paket von {what}',
  'course.packageOf.h5p': 'H5P-Datei von {what}',
  'course.what.one': '‚{title}‘',
  'course.what.more': '‚{title}‘ + {count} weitere',
  'course.what.titled': '„{title}“ ({count:Aufgabe:Aufgaben})',
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
