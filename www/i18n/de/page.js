// Deutsche Texte der Seite um die Ansicht: Titel und Auswahl, der Teilen-Dialog, Import und
// Export, die Meldungen, wenn sie nicht starten kann, die Hinweise des Elements <ruled-view> und
// die Hinweise zu Werten des Links, die nicht verwendet wurden.
// Keys: app.*, boot.*, share.*, io.*, export.*, element.*, note.*

export default {
  'app.title': 'ruledlab',
  'app.subtitle': 'Diskrete Modelle von Regelflächen und Geradenkongruenzen, nach Odehnal & Pottmann',
  'app.scene': 'Szene',
  'app.language': 'Sprache',
  'app.figures': 'Abbildungen der Arbeit',
  'app.share': 'Teilen',
  'app.onefile': 'Diese Ansicht als eine HTML-Datei herunterladen',
  'app.onefileMissing':
    'Die Fassung in einer Datei liegt hier nicht vor: Führen Sie npm run build aus, oder verwenden Sie die heruntergeladene ruledlab.html.',
  'app.skip': 'Zu den Bedienelementen springen',
  'app.exercises': 'Aufgaben',
  'app.menu': 'Menü',

  'boot.noWebgl2':
    'ruledlab konnte nicht starten: Dieser Browser (oder dieses Gerät) bietet kein WebGL2, das die 3D-Ansicht braucht. Aktuelle Versionen von Firefox, Chrome, Edge und Safari bieten es; ein Browser mit abgeschalteter Hardwarebeschleunigung unter Umständen nicht.',
  'boot.cspWasm':
    "ruledlab konnte nicht starten: Die Seite, in der es steht, verbietet WebAssembly. Ihre Content-Security-Policy braucht 'wasm-unsafe-eval' in script-src (im Handbuch von ruledlab: „In a course system“).",
  'boot.noWasm':
    'ruledlab konnte nicht starten: Dieser Browser kann sein WebAssembly nicht ausführen (nötig ist WebAssembly mit SIMD: Chrome 91, Firefox 89, Safari 16.4 oder neuer).',
  'boot.load':
    'ruledlab konnte nicht starten: Eine seiner Dateien wurde nicht geladen. Laden Sie die Seite neu; wird sie in einer anderen Seite gezeigt, blockiert diese sie vielleicht.',
  'boot.technical': 'Was der Browser meldete',
  'boot.failed': 'ruledlab konnte nicht starten.',

  'share.title': 'Diese Ansicht teilen',
  'share.intro': 'Jedes Feld enthält die aktuelle Szene, ihre Parameter, die Sprache und die Kamera.',
  'share.introTask':
    'Jedes Feld enthält die Aufgabe, die Sprache und was Lesende dürfen – nicht die Kamera dieser Ansicht und nicht die hier getippten Antworten; alle Lesenden ziehen ihre eigenen Zahlen.',
  'share.fromFile':
    'Diese Seite wurde aus einer Datei geöffnet und hat keine Adresse, die andere öffnen könnten. Um diese Ansicht zu teilen, laden Sie sie als eine HTML-Datei herunter und laden diese in Ihren Kurs hoch, oder setzen Sie das Element unten in eine eigene Seite.',
  'share.noAddress':
    'Diese Ansicht wird in einer anderen Seite gezeigt und hat keine eigene Adresse, die andere öffnen könnten. Um sie zu teilen, laden Sie sie als eine HTML-Datei herunter, oder setzen Sie das Element unten in eine eigene Seite.',
  'share.elementServed':
    'Das Skript kommt von dieser Website und lädt auch auf Seiten jeder anderen Website; kopieren Sie es auf Ihren eigenen Server, falls diese Website verschwinden könnte.',
  'share.elementModule':
    'Diese Website hat keine Fassung in einer Datei (npm run build erzeugt sie), daher lädt das Element das Modul ruledlab/view: Auf anderen Websites geht das nur, wenn dieser Server ihnen das Laden seiner Skripte erlaubt (Access-Control-Allow-Origin).',
  'share.elementUpload':
    'Laden Sie {file} (die Schaltfläche darunter lädt sie herunter) neben Ihre Seite hoch. Liegt die Datei woanders, ändern Sie src="{file}" in ihre Adresse.',
  'share.embedDownload': '{file} herunterladen',
  'share.embedMissing':
    'Diese Kopie der Seite kann {file} nicht ausgeben; nehmen Sie die Datei aus dist/ des ruledlab-Pakets.',
  'share.onefileNote':
    'Die ganze Seite mit dieser Ansicht in einer Datei: Sie läuft direkt von der Festplatte und in einer Lernplattform hochgeladen.',
  'share.framed':
    'Wird nichts gespeichert, erlaubt die Seite um diese Ansicht keine Downloads: Öffnen Sie die Ansicht auf einer eigenen Seite.',
  'share.copyWhat': 'Kopieren: {what}',
  'share.selectCopy': 'Markiert: Drücken Sie Strg+C (⌘C) zum Kopieren.',
  'share.link': 'Link',
  'share.taskLink': 'Link zur Aufgabe',
  'share.iframe': 'Mit einem iframe einbetten',
  'share.element': 'Mit <ruled-view> einbetten',
  'share.copy': 'Kopieren',
  'share.copied': 'Kopiert.',
  'share.close': 'Schließen',
  'share.editTooLarge':
    'Ihre Bearbeitung hat mehr als {max} Punkte: Link und Ausschnitte enthalten sie nicht (der Download als eine Datei schon).',

  'io.summary': 'Import und Export',
  'io.paste': 'CSV (6 Zahlen je Erzeugende oder Werkzeuglage) oder JSON einfügen',
  'io.upload': 'Eine CSV- oder JSON-Datei hochladen',
  'io.show': 'In der Ansicht zeigen',
  'io.staleExample': 'Die Beispieldaten bleiben zu sehen.',
  'io.stale': 'Gezeigt werden weiterhin die zuvor importierten Daten: Dieser Text konnte nicht gelesen werden.',
  'io.notStored':
    'Dieser Import hat mehr als {max} Erzeugende: zu viele für den Link, und diese Seite hat hier keinen Speicher (sie wird in einem abgeschotteten Rahmen gezeigt), daher bleibt er nur, bis die Seite geschlossen wird.',
  'io.stored': 'Dieser Import hat mehr als {max} Erzeugende: Er steht im Sitzungsspeicher dieses Tabs, nicht im Link.',
  'io.exports': 'Das Gezeigte speichern',
  'io.printWidth': 'Druckbreite der SVG- und TikZ-Abbildungen (cm)',
  'io.kind': 'Der Text enthält',
  'io.kind.auto': 'erkennen',
  'io.kind.segments': 'Strecken (Erzeugende, Geraden)',
  'io.kind.poses': 'Werkzeuglagen (Spitze x, y, z und Werkzeugachse i, j, k; oder x, y, z und Drehwinkel a, b, c)',
  'io.kind.target': 'eine Sollkurve zu den Werkzeuglagen (x, y, z)',
  'io.units': 'in',
  'io.unitsName': 'in: die Einheiten der Werkzeuglagen',
  'io.units.auto': 'den Einheiten der Datei (Millimeter, wenn sie nichts sagt)',
  'io.units.mm': 'Millimetern',
  'io.units.inch': 'Zoll',
  'io.targetNeedsPoses': 'Eine Sollkurve wird an Ihren Werkzeuglagen gemessen: Importieren Sie diese zuerst.',
  'io.heldInTask':
    'Die Datendateien (OBJ, CSV, JSON, Invarianten) lassen sich speichern, sobald Sie die Aufgabe verlassen: Sie enthielten die Antwort.',

  'export.png': 'PNG',
  'export.svg': 'Abbildung (SVG)',
  'export.svgBw': 'Abbildung (SVG, schwarz-weiß)',
  'export.tikz': 'Abbildung (TikZ)',
  'export.tikzBw': 'Abbildung (TikZ, schwarz-weiß)',
  'export.png2': 'PNG 2×',
  'export.png4': 'PNG 4×',
  'export.obj': 'OBJ',
  'export.csv': 'CSV',
  'export.json': 'JSON',
  'export.invariants': 'Invarianten (JSON)',
  'export.invariantsCsv': 'Invarianten (CSV)',
  'export.plot': 'Diagramm (SVG)',

  'element.unknownScene': 'Eine Szene „{scene}“ gibt es nicht. Die Szenen sind: {known}.',
  'element.unknownPaper':
    'Eine Abbildung oder ein Beispiel der Arbeit namens „{paper}“ gibt es nicht. Es gibt: {known}.',
  'element.note.notOnOff':
    'Der Wert von „{key}“ im Attribut params ist weder ein noch aus; es gilt die Voreinstellung.',
  'element.note.notNumber': 'Der Wert von „{key}“ im Attribut params ist keine Zahl; es gilt die Voreinstellung.',
  'element.note.clamped':
    'Der Wert von „{key}“ im Attribut params liegt außerhalb des Bereichs; es gilt der nächste erlaubte Wert.',
  'element.note.unknownChoice':
    'Der Wert von „{key}“ im Attribut params ist keine der Auswahlmöglichkeiten; es gilt die Voreinstellung.',
  'element.note.tooLong': 'Der Wert von „{key}“ im Attribut params ist zu lang; es gilt die Voreinstellung.',
  'element.note.unknownParam': 'Diese Szene hat keinen Parameter „{key}“; ihre Parameter sind: {known}.',
  // dasselbe für einen Wert, den setParams() erhielt
  'element.set.notOnOff':
    'Der Wert, den setParams für „{key}“ erhielt, ist weder ein noch aus; es gilt die Voreinstellung.',
  'element.set.notNumber': 'Der Wert, den setParams für „{key}“ erhielt, ist keine Zahl; es gilt die Voreinstellung.',
  'element.set.clamped':
    'Der Wert, den setParams für „{key}“ erhielt, liegt außerhalb des Bereichs; es gilt der nächste erlaubte Wert.',
  'element.set.unknownChoice':
    'Der Wert, den setParams für „{key}“ erhielt, ist keine der Auswahlmöglichkeiten; es gilt die Voreinstellung.',
  'element.set.tooLong': 'Der Wert, den setParams für „{key}“ erhielt, ist zu lang; es gilt die Voreinstellung.',
  'element.set.unknownParam': 'Diese Szene hat keinen Parameter „{key}“; ihre Parameter sind: {known}.',
  'element.note.badInput': 'Das Attribut input passt nicht zu dieser Szene; die eingebaute Eingabe wird gezeigt.',
  'element.note.badKlein':
    'Der Wert des Attributs klein besteht nicht aus drei Zahlen α,β,ℓ; die Klein-Ansicht wird im eigenen Bild der Szene gezeichnet.',
  'element.note.kleinHeld':
    'Eine Zahl des Attributs klein lag außerhalb ihres Bereichs oder zwischen zwei Stufen und wird auf dem nächsten Wert gehalten, den der Schieberegler der Klein-Ansicht annimmt.',
  'element.badCamera':
    'Das Attribut camera ist nicht lesbar (sechs Zahlen: Gier, Neigung, Abstand, x, y, z); die Ansicht wird an die Szene angepasst.',
  'element.note.badTask': 'Das Attribut task ließ sich nicht lesen ({reason}); die Szene wird ohne es gezeigt.',
  'element.note.badSolution':
    'Das Attribut solution ist weder \u201enever\u201c noch eine ganze Zahl von Prüfungen von 0 bis {max}; die Lösung wird nach einer ersten Prüfung angeboten.',
  'element.note.badSeed': 'Das Attribut seed ist keine ganze Zahl von 0 bis {max}; neue Zahlen wurden gezogen.',

  'note.notOnOff': 'Der Wert von „{key}“ im Link ist weder ein noch aus; es gilt die Voreinstellung.',
  'note.notNumber': 'Der Wert von „{key}“ im Link ist keine Zahl; es gilt die Voreinstellung.',
  'note.clamped': 'Der Wert von „{key}“ im Link liegt außerhalb des Bereichs; es gilt der nächste erlaubte Wert.',
  'note.unknownChoice': 'Der Wert von „{key}“ im Link ist keine der Auswahlmöglichkeiten; es gilt die Voreinstellung.',
  'note.tooLong': 'Der Wert von „{key}“ im Link ist zu lang; es gilt die Voreinstellung.',
  'note.linkTooLong':
    'Dieser Link ist länger als {max} KiB und wurde nicht gelesen; die Seite beginnt mit ihren Voreinstellungen.',
  'note.unknownScene': 'Der Link nennt eine Szene, die es nicht gibt; die erste Szene wird gezeigt.',
  'note.badCamera': 'Die Kamera im Link konnte nicht gelesen werden; die Ansicht wird an die Szene angepasst.',
  'note.badKlein':
    'Das Bild der Klein-Ansicht im Link besteht nicht aus drei Zahlen α,β,ℓ; die Klein-Ansicht wird im eigenen Bild der Szene gezeichnet.',
  'note.kleinHeld':
    'Eine Zahl des Bildes der Klein-Ansicht im Link lag außerhalb ihres Bereichs oder zwischen zwei Stufen und wird auf dem nächsten Wert gehalten, den der Schieberegler der Klein-Ansicht annimmt.',
  'note.badData': 'Die Daten im Link konnten nicht gelesen werden; die Beispieldaten werden gezeigt.',
  'note.unknownFigure':
    'Der Link nennt eine Abbildung der Arbeit, die ruledlab nicht kennt; die Szene wird ohne sie gezeigt.',
  'note.badInput': 'Die bearbeitete Eingabe im Link passt nicht zu dieser Szene; die eingebaute Eingabe wird gezeigt.',
  'note.badTask': 'Die Aufgabe im Link ließ sich nicht lesen ({reason}); die Szene wird ohne sie gezeigt.',
  'note.badSeed': 'Der Startwert (seed) im Link ist keine ganze Zahl von 0 bis {max}; neue Zahlen wurden gezogen.',
  'note.badSolution':
    'Die Regel für die Lösung im Link ist weder \u201enever\u201c noch eine ganze Zahl von Prüfungen von 0 bis {max}; die Lösung wird nach einer ersten Prüfung angeboten.',
};
