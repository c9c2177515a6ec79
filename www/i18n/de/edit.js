// Deutsche Texte zum Bearbeiten der Geometrie: die Anfasser, ihre Namen, Schaltflächen und
// Hinweise (www/edit/), und was eine bearbeitete Eingabe undefiniert lässt.
// Keys: edit.*, handle.*, problem.*

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
  'edit.tooLarge':
    'Diese Bearbeitung hat mehr als {max} Punkte: Der Link enthält sie nicht; dieser Tab bewahrt sie auf.',
  'edit.tooLargeNoStorage':
    'Diese Bearbeitung hat mehr als {max} Punkte: Der Link enthält sie nicht, und diese Seite kann sie nicht aufbewahren (Neuladen verliert sie).',
  'edit.entered':
    'Bearbeiten von {count:Punkt:Punkten}: Tab geht von Punkt zu Punkt, die Pfeiltasten verschieben einen, Escape beendet.',
  'edit.left': 'Bearbeiten beendet.',
  'edit.undone': 'Rückgängig gemacht',
  'edit.redone': 'Wiederholt',
  'edit.restored': 'Zurück zur eingebauten Eingabe',
  'edit.cancelled': 'Verschiebung abgebrochen',
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
  'edit.from.importedPoses': 'Ihre {poses} importierten Werkzeuglagen',

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
};
