// Deutsche Texte zum Bearbeiten der Geometrie: die Anfasser, ihre Namen, Schaltflächen, Tasten
// und Hinweise (www/edit/).

export default {
  'edit.button': 'Bearbeiten',
  'edit.buttonTitle':
    'Die Punkte der Figur mit der Tastatur verschieben (E); mit Maus oder Finger lassen sie sich jederzeit ziehen',
  'edit.undo': 'Rückgängig',
  'edit.undoTitle': 'Letzte Verschiebung rückgängig machen (Strg+Z)',
  'edit.redo': 'Wiederholen',
  'edit.redoTitle': 'Wiederholen (Strg+Umschalt+Z oder Strg+Y)',
  'edit.moveLabel': 'Ziehen verschiebt einen Punkt',
  'edit.mode.view': 'quer zum Blick',
  'edit.mode.viewTitle': 'in der Ebene durch den Punkt, die Ihnen zugewandt ist',
  'edit.mode.line': 'längs seiner Geraden',
  'edit.mode.lineTitle': 'längs der Erzeugenden oder Achse, zu der er gehört (oder beim Ziehen Umschalt halten)',
  'edit.mode.vertical': 'auf und ab',
  'edit.mode.verticalTitle': 'längs der z-Achse (oder beim Ziehen Alt halten)',
  'edit.done': 'Fertig',
  'edit.asData': 'Als Daten bearbeiten',
  'edit.from': 'Bearbeitet aus: {from}.',
  'edit.restore': 'Zurück zur eingebauten Eingabe',
  'edit.reason.fixed': 'Durch Ihre Bearbeitung festgelegt: „Zurück zur eingebauten Eingabe“ gibt es frei.',
  'edit.tooLarge': 'Diese Bearbeitung hat mehr als 200 Punkte: Der Link enthält sie nicht; dieser Tab bewahrt sie auf.',
  'edit.tooLargeNoStorage':
    'Diese Bearbeitung hat mehr als 200 Punkte: Der Link enthält sie nicht, und diese Seite kann sie nicht aufbewahren (Neuladen verliert sie).',
  'edit.entered':
    'Bearbeiten von {count:Punkt:Punkten}: Tab geht von Punkt zu Punkt, die Pfeiltasten verschieben einen, Escape beendet.',
  'edit.left': 'Bearbeiten beendet.',
  'edit.undone': 'Rückgängig gemacht',
  'edit.redone': 'Wiederholt',
  'edit.restored': 'Zurück zur eingebauten Eingabe',
  'edit.cancelled': 'Verschiebung abgebrochen',
  'view.hintEdit':
    'Ziehen: drehen · Punkt ziehen: verschieben · Umschalt/Rechts-Ziehen: Ansicht verschieben · Mausrad: zoomen · E: bearbeiten · ?: Tasten',

  'view.hintTouchEdit': 'ein Finger: drehen oder einen Punkt ziehen · zwei Finger: verschieben und zoomen',

  'share.editTooLarge':
    'Ihre Bearbeitung hat mehr als 200 Punkte: Link und Ausschnitte enthalten sie nicht (der Download als eine Datei schon).',

  'handle.ruling': 'Erzeugende {i}, Ende {end}',
  'handle.end.a': 'a',
  'handle.end.b': 'b',
  'handle.line': 'Gerade ({row}, {col}), Punkt {end}',
  'handle.end.p': 'p',
  'handle.end.q': 'q',
  'handle.pose': 'Werkzeuglage {i}, {end}',
  'handle.end.tip': 'Spitze',
  'handle.end.axis': 'Achsenende',
  'handle.point': 'Kontrollpunkt {i}',

  'problem.parallel': 'Die Erzeugenden {i} und {j} sind parallel: δ ist dort nicht definiert.',
  'problem.parallelMany':
    '{count} Paare aufeinanderfolgender Erzeugender sind parallel (das erste: {i} und {j}): δ ist dort nicht definiert.',
  'note.badInput': 'Die bearbeitete Eingabe im Link passt nicht zu dieser Szene; die eingebaute Eingabe wird gezeigt.',

  'keys.editTitle': 'Punkte bearbeiten (E)',
  'keys.edit': 'Bearbeiten der Punkte beginnen oder beenden',
  'keys.editStep': 'nächster oder voriger Punkt',
  'keys.editMove': 'Punkt quer zum Blick verschieben',
  'keys.editDepth': 'von Ihnen weg oder zu Ihnen hin verschieben',
  'keys.editFine': 'zusammen mit einer Verschiebung: ein Zehntel des Schritts',
  'keys.editEnd': 'Verschiebung abschließen (ein Schritt zum Rückgängigmachen)',
  'keys.editCancel': 'Verschiebung abbrechen; noch einmal: Bearbeiten beenden',
  'keys.undo': 'rückgängig machen',
  'keys.redo': 'wiederholen',
  'touch.handle': 'ein Finger auf einem Punkt',
  'touch.handleWhat': 'ihn ziehen',
  'touch.hold': 'einen Punkt halten',
  'touch.holdWhat': 'seine Koordinaten sehen',

  'edit.from.surface': '{surface}, {n:Erzeugende:Erzeugende}',
  'edit.from.notation': 'drei Erzeugende des Hyperboloids aus Beispiel 1 um u = {u}, im Abstand {spacing}',
  'edit.from.convergence': 'drei Erzeugende von {surface} um u = {u}',
  'edit.from.curves': 'das Kontrollpolygon der Abb. 7–8',
  'edit.from.strip': '12 Erzeugende der Quartik aus Beispiel 3',
  'edit.from.congruence': '{congruence}, {rows} × {cols} Geraden',
  'edit.from.lines': 'neun Erzeugende von {surface} mit verschobenen Endpunkten',
  'edit.from.poses': 'die {poses} Werkzeuglagen aus Beispiel 6',
  'edit.from.data': 'Ihre importierten Daten',
  'edit.from.example': 'der Beispielstreifen',
  'edit.describe': 'Ihre Bearbeitung der Eingabe. {description}',
  'edit.edited': 'Ihre Bearbeitung von {what}',
  'striction.describeEdited':
    'Ihre Bearbeitung von {n} Erzeugenden von {surface}; gezeigt: {shown}. Ohne die exakte Fläche gibt es keine Fehler zu messen.',
  'notation.describeEdited':
    'Ihre Bearbeitung dreier aufeinanderfolgender Erzeugender mit ihren gemeinsamen Loten, Fußpunkten und dem Mittelpunkt m_i; der Winkel zwischen R_i und R_{i+1} beträgt {angle} rad, ihr Abstand {distance}.',
  'convergence.describeEdited':
    'Ihre Bearbeitung der drei Erzeugenden mit ihren gemeinsamen Loten, Fußpunkten und dem Kehlpunkt; der gemittelte Drall an der mittleren Erzeugenden ist {delta}.',
  'convergence.editedNote':
    'Die Ordnungen werden an der exakten Fläche gemessen, die Ihre Bearbeitung nicht hat: „Zurück zur eingebauten Eingabe“ misst sie wieder.',
  'convergence.readout.delta01': 'δ_{0,1}',
  'convergence.readout.delta12': 'δ_{1,2}',
  'convergence.readout.deltaMeanEdited': 'gemitteltes δ an der mittleren Erzeugenden',
  'strip.describeEdited':
    'Ihre Bearbeitung der 12 gegebenen Erzeugenden, 11 Erzeugende eingefügt durch {scheme}, n = {n}; ohne die Quartik gibt es keinen Abstand zu messen.',
  'congruence.describeEdited':
    'Ihre Bearbeitung von {congruence}: {rows} × {cols} gegebene Geraden, durch {scheme} zu {lines} Geraden verfeinert.',
  'lines.describeEdited':
    'Ihre Bearbeitung der neun gegebenen Erzeugenden von {surface}; gegenüber den Erzeugenden, die die Verfahren aus der unverschobenen Fläche machen, drehten sich die neuen Erzeugenden des Endpunktverfahrens um bis zu {endpointTurn} rad, die des Geradenraum-Verfahrens um {lineTurn}.',
  'milling.describeEdited':
    'Ihre Bearbeitung der {poses} gegebenen Lagen eines Kugelfräsers, verfeinert mit {steps:Schritt:Schritten} „{scheme}“ zu {total} Lagen; die gefräste Fläche verfehlt das Sollprofil um höchstens {deviation}.',
  'edit.from.importedPoses': 'Ihre {poses} importierten Werkzeuglagen',
  'milling.describeImportedEdited':
    'Ihre Bearbeitung von {poses} importierten Werkzeuglagen, verfeinert mit {steps:Schritt:Schritten} „{scheme}“ zu {total} Lagen.',
};
